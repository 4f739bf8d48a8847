"""Measured wear for a calibration (:mod:`wear.chain.calibrate`): a CSV file read and checked into
:class:`CalibrationData`. SI units; angles in degrees from the plate normal.

One row per measurement — ``angle_deg`` (from the normal), ``speed_m_s``, one measured quantity
(:data:`QUANTITIES`: the erosion ratio kg/kg, the mass or the volume worn per impact), and optionally case keys per
row as extra columns named as in the schema (``ball.radius``, ``impact.friction``, ``plate.hardness``, ...; those a
calibration would not read are refused by :func:`wear.chain.calibrate.check_data_keys`). A row whose measured value
is empty is predicted, not fitted. The file is UTF-8 text (a byte-order mark, as Excel writes, is read); each column
is named once.
"""

from __future__ import annotations

import csv
import io
import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from wear.case import TABLES

__all__ = ["QUANTITIES", "CalibrationData", "read_data"]

#: Measured quantities a data file may hold (column name → what it is).
QUANTITIES = {
    "erosion_kg_per_kg": "erosion ratio: mass of plate worn per mass of particles (kg/kg)",
    "mass_per_impact_kg": "mass of plate worn per impact (kg)",
    "volume_per_impact_m3": "volume of plate worn per impact (m^3)",
}


@dataclass(frozen=True, eq=False)
class CalibrationData:
    """Measurements: ``angle`` (deg from the normal), ``speed`` (m/s), ``measured`` (NaN where only predicted) of
    ``quantity`` (:data:`QUANTITIES`), ``keys`` (dotted case key → per-row values), ``source`` (where they came
    from)."""

    angle: np.ndarray
    speed: np.ndarray
    quantity: str
    measured: np.ndarray
    keys: dict[str, np.ndarray]
    source: str = ""

    @property
    def fitted(self) -> np.ndarray:
        """Rows with a measured value."""
        return np.isfinite(self.measured)


def _number(text: str, column: str, row: int) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{column}={text!r} in row {row} is not a number") from None
    if math.isnan(value) or math.isinf(value):
        raise ValueError(f"{column}={text!r} in row {row} is not finite")
    return value


def read_data(path: str | os.PathLike) -> CalibrationData:
    r"""Read and check a data file (CSV with a header row; see the module docstring). Errors are one line naming
    the file, the column and the row (rows counted from 1 after the header).

    Examples
    --------
    A table written in a temporary folder: the row without a measured value is kept, to be predicted, not fitted;
    a cell that is not a number is named by its column and row:

    >>> import tempfile
    >>> from pathlib import Path
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = Path(folder) / "data.csv"
    ...     _ = path.write_text("angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-5\n60,20,1.2e-5\n45,30,\n")
    ...     data = read_data(path)
    ...     _ = path.write_text("angle_deg,speed_m_s,erosion_kg_per_kg\n30,fast,1e-5\n")
    ...     read_data(path)
    Traceback (most recent call last):
    ...
    ValueError: data='...data.csv': speed_m_s='fast' in row 1 is not a number
    >>> data.quantity, data.angle.tolist(), data.speed.tolist(), data.fitted.tolist()
    ('erosion_kg_per_kg', [30.0, 60.0, 45.0], [20.0, 20.0, 30.0], [True, True, False])
    """
    p = Path(path)
    rows = _read_rows(p)
    header, body = [h.strip() for h in rows[0]], [r for r in rows[1:] if any(c.strip() for c in r)]
    quantity, keys = _check_columns(header, p)
    if not body:
        raise ValueError(f"data={str(p)!r} has no rows: give one row per measurement")
    try:  # a bad cell is named by its column and row, and the file
        angle, speed, value, extra = _parse_rows(header, body, quantity, keys)
    except ValueError as exc:
        raise ValueError(f"data={str(p)!r}: {exc}") from None
    data = CalibrationData(
        np.array(angle),
        np.array(speed),
        quantity,
        np.array(value),
        {k: np.array(v) for k, v in extra.items()},
        str(p),
    )
    if not data.fitted.any():
        raise ValueError(f"{quantity} is empty in every row of data={str(p)!r}: no measured row to fit")
    return data


def _read_rows(p: Path) -> list[list[str]]:
    """The CSV rows of the UTF-8 text file ``p`` (at least the header row)."""
    if not p.is_file():
        raise ValueError(f"data={str(p)!r} is not a file")
    try:
        # utf-8-sig: a byte-order mark (Excel's "CSV UTF-8") is not part of the first column's name
        with open(p, newline="", encoding="utf-8-sig") as f:
            text = f.read()
        if "\x00" in text:  # no text file holds a NUL (UTF-16 text does: it is not UTF-8)
            raise UnicodeError
        rows = list(csv.reader(io.StringIO(text, newline="")))
    except (UnicodeError, csv.Error):
        raise ValueError(
            f"data={str(p)!r} is not a CSV text file (UTF-8): give a header row and one row per measurement"
        ) from None
    if not rows:
        raise ValueError(f"data={str(p)!r} is empty: give a header row and one row per measurement")
    return rows


def _check_columns(header: list[str], p: Path) -> tuple[str, list[str]]:
    """The measured quantity's column of ``header`` (the columns of the file ``p``) and its case-key columns:
    each column named once, angle and speed present, exactly one of :data:`QUANTITIES`, and the rest numeric case
    keys."""
    for name in header:
        if header.count(name) > 1:
            raise ValueError(
                f"column {name!r} appears {header.count(name)} times in data={str(p)!r}: give each column once"
            )
    measured = [h for h in header if h in QUANTITIES]
    for need in ("angle_deg", "speed_m_s"):
        if need not in header:
            raise ValueError(
                f"column {need!r} is missing from data={str(p)!r}: the columns are angle_deg, speed_m_s, "
                f"one of {', '.join(QUANTITIES)} and optional case keys (table.key)"
            )
    if len(measured) != 1:
        raise ValueError(
            f"data={str(p)!r} has {len(measured)} measured columns {measured}: give exactly one of "
            f"{', '.join(QUANTITIES)}"
        )
    keys = [h for h in header if h not in ("angle_deg", "speed_m_s", measured[0])]
    for k in keys:
        table, _, name = k.partition(".")
        if table not in TABLES or name not in TABLES[table].keys():
            raise ValueError(
                f"column {k!r} of data={str(p)!r} is not a case key (table.key, e.g. ball.radius) nor "
                f"angle_deg, speed_m_s or a measured quantity"
            )
        if TABLES[table].keys()[name].type not in (int, float):
            raise ValueError(f"column {k!r} of data={str(p)!r} is not a numeric case key")
    return measured[0], keys


def _parse_rows(
    header: list[str], body: list[list[str]], quantity: str, keys: list[str]
) -> tuple[list[float], list[float], list[float], dict[str, list[float]]]:
    """Angles (deg), speeds (m/s), measured values (NaN where empty: predicted only) and the case keys' values of
    the data rows ``body``, checked cell by cell; a ValueError names the column and the row (from 1)."""
    angle, speed, value = [], [], []
    extra: dict[str, list[float]] = {k: [] for k in keys}
    for i, row in enumerate(body, start=1):
        if len(row) != len(header):
            raise ValueError(f"row {i} has {len(row)} values for {len(header)} columns")
        cells = dict(zip(header, (c.strip() for c in row), strict=True))
        a = _number(cells["angle_deg"], "angle_deg", i)
        if not 0.0 <= a < 90.0:
            raise ValueError(
                f"angle_deg={a:g} in row {i} is out of range: the angle from the normal must be in [0, 90) deg"
            )
        v = _number(cells["speed_m_s"], "speed_m_s", i)
        if not 0.0 < v <= 1000.0:
            raise ValueError(f"speed_m_s={v:g} in row {i} is out of range: must be in (0, 1000] m/s")
        angle.append(a)
        speed.append(v)
        value.append(_measured(cells[quantity], quantity, i))
        for k in keys:
            extra[k].append(_number(cells[k], k, i))
    return angle, speed, value, extra


def _measured(text: str, quantity: str, row: int) -> float:
    """The measured value of a cell: NaN if empty (the row is predicted, not fitted), else a number > 0."""
    if text == "":
        return math.nan
    m = _number(text, quantity, row)
    if m <= 0.0:
        raise ValueError(
            f"{quantity}={m:g} in row {row} is out of range: must be > 0 (its log is fitted); "
            "leave it empty to predict the row"
        )
    return m
