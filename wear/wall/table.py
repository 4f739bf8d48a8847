"""The plain impact table: the format users of other codes convert their records to (CSV; Parquet when pyarrow is
installed). One row per record, a header row naming the columns (any order; UTF-8, a byte-order mark is read):

==================================  ========  ===================================================================
column                              unit      meaning
==================================  ========  ===================================================================
``x_m``, ``y_m``, ``z_m``           m         the hit position (required unless ``face`` is given on every row)
``u_m_s``, ``v_m_s``, ``w_m_s``     m/s       the incident velocity, pointing into the wall (required)
``diameter_m``                      m         particle diameter (required)
``density_kg_m3``                   kg/m³     particle density (required)
``particles``                       –         particles per record (default 1)
``time_s``                          s         the time of the hit (default 0)
``face``                            –         the wall face (0-based, in the wall's face order); −1 or absent:
                                              the face nearest to the position
``nx``, ``ny``, ``nz``              –         the unit normal (into the wall) the angle is to be measured
                                              against (default: the face normal)
==================================  ========  ===================================================================

Any other column is refused. Rows are counted from 1 after the header row (empty rows are skipped). Without
position columns a record's position is its face's centre.
"""

from __future__ import annotations

import csv
import importlib.util
import io
from pathlib import Path

import numpy as np

from wear.wall.mesh import Wall
from wear.wall.records import COLUMNS, ImpactRecords, numbers, where

__all__ = ["read_table", "TABLE_COLUMNS", "TABLE_DEFAULTS"]

#: Every column of the plain table, in the order of the impact table's fields.
TABLE_COLUMNS = tuple(c for cs in COLUMNS.values() for c in cs)
#: Defaults of the optional single columns.
TABLE_DEFAULTS = {"particles": 1.0, "time_s": 0.0, "face": -1}


def read_table(path: str | Path, wall: Wall | None = None) -> ImpactRecords:
    """The impact table of a CSV (or, with pyarrow, Parquet) file ``path`` (see the module docstring); ``wall``
    is needed only when the table gives faces without positions."""
    p = Path(path)
    name = str(p)
    columns, rows = _parquet(p) if p.suffix == ".parquet" else _csv(p)
    unknown = [c for c in columns if c not in TABLE_COLUMNS]
    if unknown:
        raise ValueError(f"{name}, header: column {unknown[0]!r} is not one of {', '.join(TABLE_COLUMNS)}")
    n = len(rows)
    if n == 0:
        raise ValueError(f"{name} has no rows: give one row per impact record")

    def field(key: str, integer: bool = False) -> np.ndarray | None:
        names = COLUMNS[key]
        present = [c for c in names if c in columns]
        if not present:
            return None
        if len(present) != len(names):
            missing = next(c for c in names if c not in columns)
            raise ValueError(f"{name}, header: column {missing!r} is missing (give {', '.join(names)} together)")
        values = [numbers(columns[c], name, rows, c, integer) for c in names]
        return values[0] if len(values) == 1 else np.column_stack(values)

    for key in ("velocity", "diameter", "density"):
        if field(key) is None:
            raise ValueError(f"{name}, header: column {COLUMNS[key][0]!r} is missing (a required column)")
    face = field("face", integer=True)
    face = np.full(n, TABLE_DEFAULTS["face"]) if face is None else face
    position = field("position")
    if position is None:
        if wall is None or face.min() < 0:
            i = int(np.argmin(face))
            raise ValueError(
                f"{where(name, int(rows[i]), 'face')}: {face[i]} locates no face and the table has no position "
                "columns x_m y_m z_m: give the face (0-based) or the position of every record"
            )
        if face.max() >= len(wall):
            i = int(np.argmax(face))
            raise ValueError(
                f"{where(name, int(rows[i]), 'face')}: {face[i]} is out of range: the wall has {len(wall)} faces"
            )
        position = wall.centre[face]
    count, time = field("count"), field("time")
    return ImpactRecords(
        position=position,
        velocity=field("velocity"),
        diameter=field("diameter"),
        density=field("density"),
        count=np.full(n, TABLE_DEFAULTS["particles"]) if count is None else count,
        time=np.full(n, TABLE_DEFAULTS["time_s"]) if time is None else time,
        face=face,
        normal=field("normal"),
        files=(name,),
        row=rows,
    )


def _csv(p: Path) -> tuple[dict[str, list[str]], np.ndarray]:
    """The columns of a CSV file as text (header → values) and the row of each value (empty rows are skipped), or
    ValueError naming the file and row."""
    try:
        text = p.read_text(encoding="utf-8-sig")  # a byte-order mark (Excel's "CSV UTF-8") is not a column name
    except (OSError, UnicodeDecodeError) as err:
        raise ValueError(f"{p} is not a CSV text file (UTF-8): {err}") from None
    lines = list(csv.reader(io.StringIO(text, newline="")))
    if not lines:
        raise ValueError(f"{p} is empty: give a header row and one row per impact record")
    header = [h.strip() for h in lines[0]]
    for h in header:
        if header.count(h) > 1:
            raise ValueError(f"{p}, header: column {h!r} appears {header.count(h)} times: give each column once")
    body = [(r, line) for r, line in enumerate(lines[1:], start=1) if any(c.strip() for c in line)]
    for r, line in body:
        if len(line) != len(header):
            raise ValueError(f"{p}, row {r}: {len(line)} values for the header's {len(header)} columns")
    rows = np.array([r for r, _ in body], dtype=np.int64)
    return {h: [line[j].strip() for _, line in body] for j, h in enumerate(header)}, rows


def _parquet(p: Path) -> tuple[dict[str, list], np.ndarray]:
    """The columns of a Parquet file (pyarrow) and their rows (1, 2, ...)."""
    if importlib.util.find_spec("pyarrow") is None:
        raise ValueError(f"{p}: reading Parquet needs pyarrow, which is not installed: install it or give CSV")
    import pyarrow.parquet  # optional: only Parquet tables need it

    try:
        columns = pyarrow.parquet.read_table(p).to_pydict()
    except Exception as err:  # pyarrow raises its own error types for an unreadable file
        raise ValueError(f"{p} is not a Parquet table ({type(err).__name__}: {err})") from None
    return columns, np.arange(1, len(next(iter(columns.values()), [])) + 1)
