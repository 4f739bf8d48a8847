"""The plain impact table: the format users of other codes convert their records to (CSV; Parquet when pyarrow is
installed, known by its suffix ``.parquet`` or its content). One row per record, a header row naming the columns
(any order; UTF-8, a byte-order mark is read):

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
position columns a record's position is its face's centre. A CSV file may be gzipped (``.csv.gz``).

A part of a table is read with ``start_row`` (the rows before it are skipped: the first row read is row
``start_row + 1``) and ``max_rows`` (at most so many rows, empty ones included); rows keep their numbers in the
file. A CSV part is streamed (the file is never held whole; with ``offset``, the byte where row ``start_row + 1``
starts in a plain CSV file, the rows before it are not even read); a Parquet part reads only the row groups it
overlaps.
"""

from __future__ import annotations

import csv
import gzip
import importlib.util
import io
import itertools
from pathlib import Path

import numpy as np

from wear.wall.mesh import Wall
from wear.wall.records import COLUMNS, ImpactRecords, check_rows, numbers, where

__all__ = ["read_table", "is_parquet", "parquet_file", "TABLE_COLUMNS", "TABLE_DEFAULTS"]

#: Every column of the plain table, in the order of the impact table's fields.
TABLE_COLUMNS = tuple(c for cs in COLUMNS.values() for c in cs)
#: Defaults of the optional single columns.
TABLE_DEFAULTS = {"particles": 1.0, "time_s": 0.0, "face": -1}


def read_table(
    path: str | Path,
    wall: Wall | None = None,
    start_row: int = 0,
    max_rows: int | None = None,
    *,
    offset: int | None = None,
) -> ImpactRecords:
    """The impact table of a CSV (or, with pyarrow, Parquet) file ``path`` (see the module docstring); ``wall``
    is needed only when the table gives faces without positions. ``start_row``, ``max_rows``, ``offset``: read a
    part of the file (see the module docstring)."""
    check_rows(start_row, max_rows)
    p = Path(path)
    name = str(p)
    if is_parquet(p):
        columns, rows = _parquet(p, start_row, max_rows)
    else:
        columns, rows = _csv(p, start_row, max_rows, offset)
    unknown = [c for c in columns if c not in TABLE_COLUMNS]
    if unknown:
        raise ValueError(f"{name}, header: column {unknown[0]!r} is not one of {', '.join(TABLE_COLUMNS)}")
    n = len(rows)
    if n == 0 and start_row == 0 and max_rows is None:
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
    if position is None and n:
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
    position = np.zeros((0, 3)) if position is None else position
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


def _csv(
    p: Path, start_row: int = 0, max_rows: int | None = None, offset: int | None = None
) -> tuple[dict[str, list[str]], np.ndarray]:
    """The columns of (a part of) a CSV file as text (header → values) and the row of each value (empty rows are
    skipped), or ValueError naming the file and row. The file is streamed: only the part's rows are held."""
    opener = gzip.open if p.name.endswith(".gz") else open
    try:
        # a byte-order mark (Excel's "CSV UTF-8") is not a column name
        with opener(p, "rt", encoding="utf-8-sig", newline="") as f:
            header = next(csv.reader(f), None)
            if header is not None and offset is None:
                lines = list(itertools.islice(csv.reader(f), start_row, _stop(start_row, max_rows)))
        if header is not None and offset is not None:
            with open(p, "rb") as raw:
                raw.seek(offset)
                text = io.TextIOWrapper(raw, encoding="utf-8", newline="")
                lines = list(itertools.islice(csv.reader(text), max_rows))
    except (OSError, UnicodeDecodeError, EOFError, csv.Error) as err:
        raise ValueError(f"{p} is not a CSV text file (UTF-8): {err}") from None
    if header is None:
        raise ValueError(f"{p} is empty: give a header row and one row per impact record")
    header = [h.strip() for h in header]
    for h in header:
        if header.count(h) > 1:
            raise ValueError(f"{p}, header: column {h!r} appears {header.count(h)} times: give each column once")
    body = [(r, line) for r, line in enumerate(lines, start=start_row + 1) if any(c.strip() for c in line)]
    for r, line in body:
        if len(line) != len(header):
            raise ValueError(f"{p}, row {r}: {len(line)} values for the header's {len(header)} columns")
    rows = np.array([r for r, _ in body], dtype=np.int64)
    return {h: [line[j].strip() for _, line in body] for j, h in enumerate(header)}, rows


def _stop(start_row: int, max_rows: int | None) -> int | None:
    return None if max_rows is None else start_row + max_rows


def is_parquet(path: str | Path) -> bool:
    """Whether ``path`` is a Parquet file: its suffix ``.parquet``, or its first bytes (``PAR1``)."""
    p = Path(path)
    if p.suffix.lower() == ".parquet":
        return True
    try:
        with open(p, "rb") as f:
            return f.read(4) == b"PAR1"
    except OSError:
        return False  # the reader that opens it says why


def parquet_file(p: Path):
    """The ``pyarrow.parquet.ParquetFile`` of ``p`` (its metadata read, no rows), or ValueError naming the file."""
    if importlib.util.find_spec("pyarrow") is None:
        raise ValueError(f"{p}: reading Parquet needs pyarrow, which is not installed: install it or give CSV")
    import pyarrow.parquet  # optional: only Parquet tables need it

    try:
        return pyarrow.parquet.ParquetFile(p)
    except Exception as err:  # pyarrow raises its own error types for an unreadable file
        raise ValueError(f"{p} is not a Parquet table ({type(err).__name__}: {err})") from None


def _parquet(p: Path, start_row: int = 0, max_rows: int | None = None) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """The columns of (a part of) a Parquet file (pyarrow; only the row groups the part overlaps are read) and
    their rows (counted from 1)."""
    pf = parquet_file(p)
    import pyarrow  # optional, and found by parquet_file

    try:
        n = pf.metadata.num_rows
        stop = n if max_rows is None else min(n, start_row + max_rows)
        parts, first = [], 0
        for g in range(pf.num_row_groups):
            size = pf.metadata.row_group(g).num_rows
            if first < stop and first + size > start_row:
                lo = max(start_row - first, 0)
                parts.append(pf.read_row_group(g).slice(lo, min(size, stop - first) - lo))
            first += size
        table = pyarrow.concat_tables(parts) if parts else pf.schema_arrow.empty_table()
        columns = {c: table.column(c).to_numpy(zero_copy_only=False) for c in table.column_names}
    except Exception as err:  # pyarrow raises its own error types for an unreadable file
        raise ValueError(f"{p} is not a Parquet table ({type(err).__name__}: {err})") from None
    return columns, np.arange(start_row + 1, max(stop, start_row) + 1)
