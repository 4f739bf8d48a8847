"""The reference tables in tests/data: CSV with '#' comment lines (their source), a header row of column names, and
numbers."""

from pathlib import Path

import numpy as np

DATA = Path(__file__).parent / "data"


def read_table(name: str) -> dict[str, np.ndarray]:
    """The columns of ``tests/data/<name>`` by their header names."""
    lines = [line for line in (DATA / name).read_text().splitlines() if not line.startswith("#")]
    values = np.array([[float(v) for v in line.split(",")] for line in lines[1:]])
    return dict(zip(lines[0].split(","), values.T, strict=True))
