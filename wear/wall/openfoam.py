r"""OpenFOAM's ``patchPostProcessing`` cloud-function records (tried with v1912, Debian's ``openfoam``
1912.200626) as an impact table (:class:`wear.wall.records.ImpactRecords`).

The function writes ``<folder>/<time>/<patch>.post`` (gzipped or not): a header line ``# Time currentProc
(coordinates0 ...) (position0 position1 position2) ... facei ... nParticle d ... (U0 U1 U2) rho ...`` naming the
columns, then one line per hit; vectors are in parentheses, one token per component. The columns are the
parcel's property list, which differs between parcel types and with the function's ``fields`` entry, so they are
found by name. Read: ``Time`` (s), ``position0-2`` (m), ``U0-2`` (m/s, before the rebound), ``d`` (m), ``rho``
(kg/m³), ``nParticle`` and ``facei`` (the global mesh face label crossed); with ``coordinates0-3`` and ``tetPti``
also the normal OpenFOAM measured the angle against. A
serial run's record on a patch of the mesh that the wall leaves out (a wall read with some of the case's patches)
is not in the table, only counted (``off_wall`` of :class:`wear.wall.records.ImpactRecords`).

**The recorded normal.** OpenFOAM's ``particleErosion`` (and its patch interaction) take the unit normal of the
triangle of the crossed face in the parcel's tet, not the face normal: with f the face's points, b its tet base
point and t = ``tetPti``, the triangle :math:`(f_b, f_{(b+t) \bmod k}, f_{(b+t+1) \bmod k})`, oriented as the face.
On a non-planar face the triangles' normals differ from the face's. The barycentric ``coordinates`` of the hit in
the tet (cell centre, :math:`f_b`, :math:`f_{b+t}`, :math:`f_{b+t+1}`; coordinates0 = 0 on the face) give b: it is
the base point for which :math:`c_1 P(f_b) + c_2 P(f_{b+t}) + c_3 P(f_{b+t+1})` is the recorded position.

Rows are counted from 1 after the header line (row r is line r + 1); a part of a file is read with ``start_row``
(the first row read is row ``start_row + 1``) and ``max_rows`` (empty lines included), streamed (the file is never
held whole), its rows keeping their numbers in the file. A parallel run's records carry
processor-local face labels and tets: when any record read has ``currentProc`` > 0, every record's face is found
from its position, and its normal is the face normal.
"""

from __future__ import annotations

import gzip
import itertools
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from wear.wall.mesh import Wall
from wear.wall.records import ImpactRecords, check_rows, concat_records, numbers, where

__all__ = ["read_patch_post_processing", "post_files", "scan_post_file", "triangle_normals", "REQUIRED"]

#: The columns read (OpenFOAM's names), by impact-table field.
REQUIRED = {
    "position": ("position0", "position1", "position2"),
    "velocity": ("U0", "U1", "U2"),
    "diameter": ("d",),
    "density": ("rho",),
    "count": ("nParticle",),
    "time": ("Time",),
    "face": ("facei",),
}
_TET = ("coordinates0", "coordinates1", "coordinates2", "coordinates3", "tetPti")


def post_files(path: str | Path) -> list[Path]:
    """The record files of ``path``: a ``.post``/``.post.gz`` file, or the files of every time folder (a folder
    whose name is a number) of a ``patchPostProcessing`` folder, by time then patch name."""
    p = Path(path)
    if p.is_file():
        return [p]
    if not p.is_dir():
        raise ValueError(f"records={str(p)!r}: no such file or folder")
    times = []
    for sub in p.iterdir():
        try:
            times.append((float(sub.name), sub))
        except ValueError:
            continue
    files = [
        f for _, sub in sorted(times) for f in sorted(sub.glob("*.post*")) if f.name.endswith((".post", ".post.gz"))
    ]
    if not files:
        raise ValueError(f"records={str(p)!r} holds no <time>/<patch>.post files of patchPostProcessing")
    return files


def read_patch_post_processing(
    path: str | Path | Sequence[str | Path],
    wall: Wall,
    start_row: int = 0,
    max_rows: int | None = None,
    *,
    serial: bool | None = None,
) -> ImpactRecords:
    """The impact table of OpenFOAM ``patchPostProcessing`` records (a file, a list of files, or the function's
    folder: every write time) on ``wall``, an OpenFOAM wall (:func:`wear.wall.foam.read_polymesh`) whose face labels
    are the mesh's. Each record's face is the wall face of its ``facei``; its normal is OpenFOAM's triangle normal
    (see the module docstring) when the files have the tet columns. If any record was written by a processor other
    than 0, the run was parallel and every record's face is found from its position instead (a parallel run whose
    hits all fell on processor 0 shows as records off their faces or tets: bad input naming the row); ``serial``
    says so for a part of a run (:func:`scan_post_file` of all its files), None: from the records read.
    ``start_row``, ``max_rows``: the part of one file to read (see the module docstring)."""
    check_rows(start_row, max_rows)
    paths = [path] if isinstance(path, (str, Path)) else list(path)
    names = [f for p in paths for f in post_files(p)]
    if (start_row or max_rows is not None) and len(names) != 1:
        raise ValueError(f"start_row={start_row}, max_rows={max_rows}: a part is read of one file, not {len(names)}")
    files = [_PostFile.read(f, start_row, max_rows) for f in names]
    if serial is None:
        serial = not any(np.any(f.column("currentProc", integer=True)) for f in files if "currentProc" in f.header)
    return concat_records([f.records(wall, serial) for f in files])


def scan_post_file(path: str | Path) -> tuple[int, bool]:
    """(rows, parallel) of one record file, streamed: its number of rows after the header line (empty lines
    included: the ``start_row`` / ``max_rows`` range of the whole file) and whether any record was written by a
    processor other than 0 (a parallel run; see :func:`read_patch_post_processing`)."""
    p = Path(path)
    header, lines = _open_post(p)
    proc = header.index("currentProc") if "currentProc" in header else None
    rows, parallel = 0, False
    try:
        with lines as f:
            next(f)
            for line in f:
                rows += 1
                if proc is not None and not parallel:
                    tokens = line.replace("(", " ").replace(")", " ").split(None, proc + 1)
                    parallel = len(tokens) > proc and tokens[proc] not in ("0", "0.0")
    except (OSError, UnicodeDecodeError, EOFError) as err:
        raise ValueError(f"{p} is not a patchPostProcessing text file ({err})") from None
    return rows, parallel


def _open_post(p: Path):
    """The header's column names of a record file and the file opened as text (positioned at its start)."""
    try:
        f = gzip.open(p, "rt", encoding="utf-8") if p.suffix == ".gz" else open(p, encoding="utf-8")
        first = f.readline()
        f.seek(0)
    except (OSError, UnicodeDecodeError, EOFError) as err:
        raise ValueError(f"{p} is not a patchPostProcessing text file ({err})") from None
    if not first.startswith("#"):
        f.close()
        raise ValueError(f"{p}, row 0: no header line '# Time currentProc ...': give a patchPostProcessing file")
    return first[1:].replace("(", " ").replace(")", " ").split(), f


@dataclass(frozen=True)
class _PostFile:
    """One record file as text: its ``name``, the ``header``'s column names, the ``rows`` (counted from 1 after the
    header line) and the ``table`` of values (one tuple of text per column)."""

    name: str
    header: list[str]
    rows: np.ndarray
    table: list[tuple[str, ...]]

    @classmethod
    def read(cls, path: Path, start_row: int = 0, max_rows: int | None = None) -> _PostFile:
        """The rows ``start_row + 1`` ... ``start_row + max_rows`` of the file (all with ``max_rows`` None)."""
        name = str(path)
        header, f = _open_post(path)
        missing = [c for cols in REQUIRED.values() for c in cols if c not in header]
        if missing:
            f.close()
            raise ValueError(f"{name}, header: no column {missing[0]} (the header names {' '.join(header)})")
        try:
            with f:
                next(f)
                stop = None if max_rows is None else start_row + max_rows
                lines = list(itertools.islice(f, start_row, stop))
        except (OSError, UnicodeDecodeError, EOFError) as err:
            raise ValueError(f"{name} is not a patchPostProcessing text file ({err})") from None
        body = [(r, line) for r, line in enumerate(lines, start=start_row + 1) if line.strip()]
        cells = []
        for r, line in body:
            tokens = line.replace("(", " ").replace(")", " ").split()
            if len(tokens) != len(header):
                raise ValueError(
                    f"{where(name, r, header[min(len(tokens), len(header) - 1)])}: the row has "
                    f"{len(tokens)} values for the header's {len(header)} columns"
                )
            cells.append(tokens)
        table = list(zip(*cells, strict=True)) if cells else [() for _ in header]
        return cls(name, header, np.array([r for r, _ in body], dtype=np.int64), table)

    def column(self, c: str, integer: bool = False) -> np.ndarray:
        return numbers(self.table[self.header.index(c)], self.name, self.rows, c, integer)

    def vector(self, cs: Sequence[str]) -> np.ndarray:
        return np.column_stack([self.column(c) for c in cs]) if len(self.rows) else np.zeros((0, 3))

    def records(self, wall: Wall, serial: bool) -> ImpactRecords:
        """The impact table of the file; ``serial``: the face labels and tets are the wall's mesh's."""
        face = np.full(len(self.rows), -1, np.int64)
        normal = None
        position = self.vector(REQUIRED["position"])
        keep = np.ones(len(self.rows), bool)
        if serial:
            label = self.column("facei", integer=True)
            face = wall.index_of_labels(label)
            # a hit on a patch of the mesh the wall leaves out (--patches) is counted, not refused
            keep = (face >= 0) | ~_on_other_patches(wall, label)
            off = np.flatnonzero(keep & (face < 0))
            if len(off):
                raise ValueError(
                    f"{where(self.name, int(self.rows[off[0]]), 'facei')}: {label[off[0]]} is not a face of the "
                    f"wall's patches {', '.join(wall.patch_names)}: give the polyMesh of the run that wrote the records"
                )
            face, position = face[keep], position[keep]
            if all(c in self.header for c in _TET):
                coords = np.column_stack([self.column(c)[keep] for c in _TET[:4]])
                tet_point = self.column("tetPti", integer=True)[keep]
                normal = triangle_normals(wall, face, tet_point, coords, position, self.name, self.rows[keep])
        return ImpactRecords(
            position=position,
            velocity=self.vector(REQUIRED["velocity"])[keep],
            diameter=self.column("d")[keep],
            density=self.column("rho")[keep],
            count=self.column("nParticle")[keep],
            time=self.column("Time")[keep],
            face=face,
            normal=normal,
            files=(self.name,),
            row=self.rows[keep],
            columns={**REQUIRED, "normal": ("coordinates1", "coordinates2", "coordinates3")},
            off_wall=int((~keep).sum()),
        )


def _on_other_patches(wall: Wall, label: np.ndarray) -> np.ndarray:
    """Whether each mesh face label is a face of a patch the wall leaves out (:attr:`Wall.other_patches`)."""
    out = np.zeros(len(label), bool)
    for _, start, n in wall.other_patches:
        out |= (label >= start) & (label < start + n)
    return out


def triangle_normals(
    wall: Wall,
    face: np.ndarray,
    tet_point: np.ndarray,
    coordinates: np.ndarray,
    position: np.ndarray,
    file: str = "records",
    rows: np.ndarray | None = None,
) -> np.ndarray:
    """The unit normal of the tet triangle of each hit (see the module docstring): ``face`` the wall face,
    ``tet_point`` t (``tetPti``), ``coordinates`` (n, 4) the barycentric coordinates, ``position`` (n, 3) the hit
    (m). Raises naming the row when no base point puts the coordinates at the position."""
    rows = np.arange(1, len(face) + 1) if rows is None else rows
    k = wall.sizes[face]
    start = wall.face_offsets[face]
    best = np.full(len(face), np.inf)
    corners = np.zeros((len(face), 3, 3))
    for b in range(int(k.max(initial=3))):
        ok = b < k
        picks = [start + b % k, start + (b + tet_point) % k, start + (b + tet_point + 1) % k]
        p = np.stack([wall.points[wall.face_points[i]] for i in picks], axis=1)
        error = np.linalg.norm(np.einsum("nj,njx->nx", coordinates[:, 1:], p) - position, axis=1)
        better = ok & (error < best)
        best[better] = error[better]
        corners[better] = p[better]
    size = np.sqrt(wall.area[face])
    bad = np.flatnonzero(~(best <= 1e-3 * size) | (tet_point < 1) | (tet_point > k - 2))
    if len(bad):
        i = bad[0]
        raise ValueError(
            f"{where(file, int(rows[i]), ('coordinates1', 'coordinates2', 'coordinates3', 'tetPti'))}: no triangle "
            f"of face {wall.labels[face[i]]} puts the hit's barycentric coordinates at its position (off by "
            f"{best[i]:.3g} m): give the polyMesh of the run that wrote the records"
        )
    n = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    return n / np.linalg.norm(n, axis=1)[:, None]
