"""Impact records read in chunks: a plan of small, picklable :class:`Chunk` s over record files, each read on its own
(in any process) with :func:`read_chunk`, so that no process ever holds all the records.

============  ==============================================  ==============================================
format        files                                           a chunk
============  ==============================================  ==============================================
``openfoam``  ``.post``, ``.post.gz`` (patchPostProcessing),  ``chunk_rows`` rows of one file
              or their folder (every write time's files)
``csv``       ``.csv``, ``.csv.gz`` (the plain table)         ``chunk_rows`` rows of one file (a plain
                                                              file: from the byte its first row starts at)
``parquet``   ``.parquet`` (the plain table, pyarrow)         one row group (write the file with row
                                                              groups of the chunk size wanted)
============  ==============================================  ==============================================

Each reader reads only its rows (:func:`wear.wall.table.read_table`,
:func:`wear.wall.openfoam.read_patch_post_processing` with ``start_row`` and ``max_rows``), and the rows keep their
numbers in the file, so that a bad value is named by its file and row wherever it is read. Planning reads each
text file once (counting its lines; for OpenFOAM also whether the run was parallel, which decides for every chunk
how a record's face is found) and a Parquet file's metadata only. A gzipped file cannot be entered in the middle: a
chunk of a ``.csv.gz`` or ``.post.gz`` file decompresses the rows before its own, so that reading such a file in k
chunks costs about k/2 readings of it; give very large tables as plain CSV or Parquet.
"""

from __future__ import annotations

import gzip
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from contact.checks import check_count, check_path, fmt_argument
from wear.wall.fluent import count_fluent_rows, read_fluent_dpm
from wear.wall.mesh import Wall
from wear.wall.openfoam import post_files, read_patch_post_processing, scan_post_file
from wear.wall.records import ImpactRecords
from wear.wall.table import is_parquet, parquet_file, read_table

__all__ = ["Chunk", "FORMATS", "RECORD_SUFFIXES", "plan_chunks", "read_chunk", "record_files", "record_format"]

#: The record formats, by name.
FORMATS = ("openfoam", "csv", "parquet", "fluent")
#: The suffixes of the record files of a folder that is not OpenFOAM's.
RECORD_SUFFIXES = (".csv", ".csv.gz", ".parquet", ".dpm", ".dpm.gz")
_BLOCK = 1 << 22


@dataclass(frozen=True)
class Chunk:
    """A part of one record file: ``rows`` rows after its first ``start_row`` (rows counted from 1 after the
    header: the chunk reads rows ``start_row + 1`` ... ``start_row + rows``). ``offset``: the byte at which row
    ``start_row + 1`` starts (a plain CSV file; else None); ``serial``: an OpenFOAM run's records carry the
    mesh's face labels (see :func:`wear.wall.openfoam.read_patch_post_processing`; None for the plain table)."""

    path: str
    format: str
    start_row: int
    rows: int
    offset: int | None = None
    serial: bool | None = None


def record_format(path: str | Path) -> str:
    """The format of a record file or an OpenFOAM folder (one of :data:`FORMATS`), by its suffix, or for a file
    without a known suffix by its first line (OpenFOAM's begins with ``#``, Fluent's with ``(``; else CSV)."""
    p = Path(path)
    name = p.name.lower()
    if p.is_dir() or name.endswith((".post", ".post.gz")):
        return "openfoam"
    if name.endswith((".dpm", ".dpm.gz")):
        return "fluent"
    if name.endswith((".csv", ".csv.gz")):
        return "csv"
    if is_parquet(p):
        return "parquet"
    try:
        with gzip.open(p, "rb") if name.endswith(".gz") else open(p, "rb") as f:
            start = f.read(1)
    except (OSError, EOFError) as err:
        raise ValueError(f"records={str(p)!r} cannot be read ({err})") from None
    return {b"#": "openfoam", b"(": "fluent"}.get(start, "csv")


def plan_chunks(paths: str | Path | Sequence[str | Path], chunk_rows: int) -> list[Chunk]:
    """The chunks of at most ``chunk_rows`` rows covering every row of the record files ``paths`` (a file or
    folder, or several) exactly once, in order (a Parquet file: one chunk per row group, whatever its size)."""
    check_count("chunk_rows", chunk_rows, low=1, what="rows per chunk")
    chunks: list[Chunk] = []
    files = record_files(paths)
    for path in files:
        kind = record_format(path)
        if kind == "openfoam":
            posts = post_files(path)
            scans = [scan_post_file(f) for f in posts]
            serial = not any(parallel for _, parallel in scans)
            for f, (rows, _) in zip(posts, scans, strict=True):
                chunks += [
                    Chunk(str(f), kind, s, min(chunk_rows, rows - s), serial=serial) for s in range(0, rows, chunk_rows)
                ]
        elif kind == "csv":
            chunks += _csv_chunks(Path(path), chunk_rows)
        elif kind == "fluent":
            rows = count_fluent_rows(path)
            if rows == 0:
                raise ValueError(f"{path} has no rows: give a DPM sample file with one row per parcel")
            chunks += [Chunk(str(path), kind, s, min(chunk_rows, rows - s)) for s in range(0, rows, chunk_rows)]
        else:
            chunks += _parquet_chunks(Path(path))
    if not sum(c.rows for c in chunks):  # an OpenFOAM file may be a header alone: refused as an empty table is
        shown = ", ".join(str(p) for p in files)
        raise ValueError(f"records={shown!r} hold no rows, only headers: give one row per impact record")
    return chunks


def read_chunk(chunk: Chunk, wall: Wall | None) -> ImpactRecords:
    """The impact records of ``chunk``, their rows numbered as in the file."""
    if chunk.format == "openfoam":
        return read_patch_post_processing(chunk.path, wall, chunk.start_row, chunk.rows, serial=chunk.serial)
    if chunk.format in ("csv", "parquet"):
        return read_table(chunk.path, wall, chunk.start_row, chunk.rows, offset=chunk.offset)
    if chunk.format == "fluent":
        return read_fluent_dpm(chunk.path, wall, chunk.start_row, chunk.rows)
    raise ValueError(f"format={chunk.format!r} is not one of {', '.join(FORMATS)}")


def record_files(paths: str | Path | Sequence[str | Path]) -> list[Path]:
    """The record files and OpenFOAM folders of ``paths`` (a file or folder, or several): each file and OpenFOAM
    folder itself, and of another folder its record files (:data:`RECORD_SUFFIXES`), by name."""
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    elif not isinstance(paths, Sequence) or not paths:
        raise ValueError(
            f"records={fmt_argument(paths)} is not a record file or folder: give a path (str or pathlib.Path) or a "
            "non-empty list of them"
        )
    return [f for path in paths for f in _record_files(check_path("records", path, "a record file or folder"))]


def _record_files(p: Path) -> list[Path]:
    if not p.exists():
        raise ValueError(f"records={str(p)!r}: no such file or folder")
    if not p.is_dir() or any(sub.is_dir() for sub in p.iterdir()):
        return [p]
    files = sorted(f for f in p.iterdir() if f.is_file() and f.name.lower().endswith(RECORD_SUFFIXES))
    if not files:
        raise ValueError(
            f"records={str(p)!r} holds no record files ({', '.join(RECORD_SUFFIXES)}) and no OpenFOAM "
            "write-time folders"
        )
    return files


def _csv_chunks(p: Path, chunk_rows: int) -> list[Chunk]:
    """Chunks of a CSV file: its lines counted in one pass (a row is a line), with the byte offset of each chunk's
    first row in a plain file."""
    plain = not p.name.lower().endswith(".gz")
    starts: list[np.ndarray] = []  # byte offset of every chunk_rows-th row (rows 1, 1 + chunk_rows, ...)
    lines, position, last = 0, 0, b""
    try:
        with open(p, "rb") if plain else gzip.open(p, "rb") as f:
            while block := f.read(_BLOCK):
                ends = np.flatnonzero(np.frombuffer(block, np.uint8) == ord("\n"))
                number = lines + 1 + np.arange(len(ends))  # line `number` ends at `ends`: row `number` follows
                starts.append(position + ends[(number - 1) % chunk_rows == 0] + 1)
                lines += len(ends)
                position += len(block)
                last = block[-1:]
    except (OSError, EOFError) as err:
        raise ValueError(f"records={str(p)!r} cannot be read ({err})") from None
    rows = lines - 1 + (last not in (b"\n", b""))  # the last row may end without a newline
    if rows <= 0:
        raise ValueError(f"{p} has no rows: give a header row and one row per impact record")
    offsets = np.concatenate(starts).tolist()
    return [
        Chunk(str(p), "csv", s, min(chunk_rows, rows - s), offset=offsets[i] if plain else None)
        for i, s in enumerate(range(0, rows, chunk_rows))
    ]


def _parquet_chunks(p: Path) -> list[Chunk]:
    """One chunk per row group of a Parquet file (its metadata only)."""
    meta = parquet_file(p).metadata
    if meta.num_rows == 0:
        raise ValueError(f"{p} has no rows: give one row per impact record")
    chunks, first = [], 0
    for g in range(meta.num_row_groups):
        size = meta.row_group(g).num_rows
        if size:
            chunks.append(Chunk(str(p), "parquet", first, size))
        first += size
    return chunks
