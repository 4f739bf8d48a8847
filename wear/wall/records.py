r"""The impact table: one row per particle–wall hit record of a CFD or DEM run, whatever code wrote it (SI units).

=============  =======  ==================================================================================
column         unit     meaning
=============  =======  ==================================================================================
``position``   m        the hit point (n, 3), on the wall face
``velocity``   m/s      the particle's incident velocity (n, 3), before the rebound; it points into the wall
``diameter``   m        particle diameter d, in (0, 0.1]
``density``    kg/m³    particle density ρ_p, in (0, 30000]
``count``      –        particles the record stands for (a CFD parcel's nParticle; 1 for one particle), > 0
``time``       s        the time of the hit
``face``       –        index of the hit face in the wall (:class:`wear.wall.mesh.Wall`), −1: found from
                        ``position`` (:func:`wear.wall.hits.hits_on_wall`)
``normal``     –        optional (n, 3): the unit normal the source code measured the angle against at the hit,
                        pointing into the wall (OpenFOAM: the normal of the triangle of the crossed face)
=============  =======  ==================================================================================

The mass of one particle is :math:`m = \rho_p \pi d^3 / 6` and a record delivers ``count`` · m.

Each record keeps where it came from (``files``, ``file_index``, ``row``: rows counted from 1 after the header
line) and the source's column names (``columns``), so that a bad value is one line naming the file, the row and the
column: :func:`where` writes that prefix, and the checks of :class:`ImpactRecords` raise ``ValueError`` with it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np

from contact.checks import check_count

__all__ = [
    "COLUMNS",
    "ImpactRecords",
    "check_rows",
    "concat_records",
    "numbers",
    "where",
    "DIAMETER_RANGE",
    "DENSITY_RANGE",
    "SPEED_MAX",
]

#: The impact table's fields: the source column names a reader reports when it names none (the plain table's).
COLUMNS = {
    "position": ("x_m", "y_m", "z_m"),
    "velocity": ("u_m_s", "v_m_s", "w_m_s"),
    "diameter": ("diameter_m",),
    "density": ("density_kg_m3",),
    "count": ("particles",),
    "time": ("time_s",),
    "face": ("face",),
    "normal": ("nx", "ny", "nz"),
}
#: Valid particle diameter (m) and density (kg/m³): wider than any sand or shot, narrow enough to catch µm or g/cm³.
DIAMETER_RANGE = (0.0, 0.1)
DENSITY_RANGE = (0.0, 30000.0)
#: Fastest impact (m/s) a record may carry: above any particle a flow drives (a jet cutter's abrasive is under
#: 1000 m/s), below the speeds of velocities written in mm/s (a 20 m/s hit is 20000 mm/s).
SPEED_MAX = 2000.0


def check_rows(start_row: int, max_rows: int | None) -> None:
    """Refuse (``ValueError`` naming the argument) a part of a record file that is not rows ``start_row + 1`` to
    ``start_row + max_rows``: ``start_row`` an integer >= 0, ``max_rows`` one >= 1 or None (all the rest)."""
    check_count("start_row", start_row, low=0, what="rows to skip")
    if max_rows is not None:
        check_count("max_rows", max_rows, low=1, what="rows to read, or None: all the rest")


def where(file: str, row: int, column: str | Sequence[str]) -> str:
    """The prefix of a bad-value message: ``"FILE, row ROW, column COLUMN"`` (several columns joined by spaces)."""
    name = column if isinstance(column, str) else " ".join(column)
    return f"{file}, row {row}, column{'s' if not isinstance(column, str) else ''} {name}"


def numbers(texts: Sequence[str], file: str, rows: np.ndarray, column: str, integer: bool = False) -> np.ndarray:
    """The numbers of a column of text (``rows``: the row of each value), or ``ValueError`` naming the first value
    that is not a number (or not an integer)."""
    try:
        values = np.array(texts, dtype=float)
    except ValueError:
        values = None
    bad = np.zeros(len(texts), bool) if values is not None else np.array([not _is_number(t) for t in texts])
    if values is not None and integer:
        bad = ~np.isfinite(values) | (values != np.round(values))
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        kind = "an integer" if integer else "a number"
        raise ValueError(f"{where(file, int(rows[i]), column)}: {texts[i]!r} is not {kind}")
    return values.astype(np.int64) if integer else values


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


@dataclass(frozen=True, eq=False)
class ImpactRecords:
    """The impact table (see the module docstring for the columns and units). Arrays are copied to float64 /
    int64; the checks run on construction and raise ``ValueError`` naming the file, row and column of the first bad
    value (a NaN or infinity, a diameter, density or particle count out of range, a zero velocity, a face index
    below −1, a normal that is not a unit vector, a speed above :data:`SPEED_MAX`). ``off_wall``: the records
    read that hit patches of the mesh left out of the wall (an OpenFOAM run's other patches); they are not in the
    table, only counted."""

    position: np.ndarray
    velocity: np.ndarray
    diameter: np.ndarray
    density: np.ndarray
    count: np.ndarray
    time: np.ndarray
    face: np.ndarray
    normal: np.ndarray | None = None
    files: tuple[str, ...] = ("records",)
    file_index: np.ndarray | None = None
    row: np.ndarray | None = None
    columns: Mapping[str, tuple[str, ...]] = field(default_factory=lambda: dict(COLUMNS))
    off_wall: int = 0

    def __post_init__(self) -> None:
        n = len(np.asarray(self.diameter))
        set_ = object.__setattr__
        for name in ("position", "velocity", "normal"):
            value = getattr(self, name)
            if value is not None:
                set_(self, name, np.array(value, dtype=float).reshape(n, 3))
        for name in ("diameter", "density", "count", "time"):
            set_(self, name, np.array(getattr(self, name), dtype=float).reshape(n))
        set_(self, "face", np.array(self.face, dtype=np.int64).reshape(n))
        set_(self, "file_index", np.zeros(n, np.int64) if self.file_index is None else np.asarray(self.file_index))
        set_(self, "row", np.arange(1, n + 1) if self.row is None else np.asarray(self.row))
        set_(self, "columns", {**COLUMNS, **self.columns})
        self._check()

    def __len__(self) -> int:
        return len(self.diameter)

    @property
    def mass(self) -> np.ndarray:
        """Mass of one particle of each record, ρ_p π d³ / 6 (kg)."""
        return self.density * math.pi * self.diameter**3 / 6.0

    @property
    def speed(self) -> np.ndarray:
        """Incident speed :math:`|v|` of each record (m/s)."""
        return np.linalg.norm(self.velocity, axis=1)

    def where(self, i: int, field_name: str) -> str:
        """The message prefix naming the file, row and source column(s) of record ``i``'s field ``field_name``."""
        columns = self.columns[field_name]
        return where(self.files[self.file_index[i]], int(self.row[i]), columns[0] if len(columns) == 1 else columns)

    def _fail(self, bad: np.ndarray, field_name: str, what: str) -> None:
        """Raise naming the first record flagged in ``bad`` (if any); ``what`` follows its value."""
        hit = np.flatnonzero(bad)
        if len(hit):
            i = hit[0]
            value = getattr(self, field_name)[i]
            text = f"{value:.6g}" if np.ndim(value) == 0 else "(" + " ".join(f"{v:.6g}" for v in value) + ")"
            more = f" ({len(hit) - 1} more such records)" if len(hit) > 1 else ""
            raise ValueError(f"{self.where(i, field_name)}: {text} {what}{more}")

    def _check(self) -> None:
        for name in ("position", "velocity", "diameter", "density", "count", "time", "normal"):
            value = getattr(self, name)
            if value is not None:
                finite = np.isfinite(value) if value.ndim == 1 else np.isfinite(value).all(axis=1)
                self._fail(~finite, name, "is not a finite number")
        lo, hi = DIAMETER_RANGE
        self._fail(
            (self.diameter <= lo) | (self.diameter > hi),
            "diameter",
            f"is out of range: give the diameter in m, in ({lo:g}, {hi:g}]",
        )
        lo, hi = DENSITY_RANGE
        self._fail(
            (self.density <= lo) | (self.density > hi),
            "density",
            f"is out of range: give the particle density in kg/m^3, in ({lo:g}, {hi:g}]",
        )
        self._fail(self.count <= 0.0, "count", "is out of range: the particles per record must be > 0")
        self._fail(~(self.speed > 0.0), "velocity", "is out of range: an impact's velocity (m/s) must not be zero")
        self._fail(
            self.speed > SPEED_MAX,
            "velocity",
            f"is out of range: an impact's speed is at most {SPEED_MAX:g} m/s (give the velocity in m/s, not mm/s)",
        )
        self._fail(self.face < -1, "face", "is out of range: a face index is >= 0 (or -1: found from the position)")
        if self.normal is not None:
            length = np.linalg.norm(self.normal, axis=1)
            self._fail(np.abs(length - 1.0) > 1e-6, "normal", "is not a unit vector (|n| must be 1 within 1e-6)")


def concat_records(parts: Sequence[ImpactRecords]) -> ImpactRecords:
    """One table of several (e.g. the files of all write times), in order; their files are kept apart. The parts
    must name the same columns and all carry a normal or none."""
    if not parts:
        raise ValueError("no impact records: give at least one file with records")
    first = parts[0]
    for part in parts[1:]:
        if dict(part.columns) != dict(first.columns) or (part.normal is None) != (first.normal is None):
            raise ValueError(
                f"{part.files[0]} has other columns than {first.files[0]}: give records of one format in one table"
            )
    files: list[str] = []
    index = []
    for part in parts:
        index.append(part.file_index + len(files))
        files.extend(part.files)

    def cat(name: str) -> np.ndarray:
        return np.concatenate([getattr(p, name) for p in parts])

    return ImpactRecords(
        position=cat("position"),
        velocity=cat("velocity"),
        diameter=cat("diameter"),
        density=cat("density"),
        count=cat("count"),
        time=cat("time"),
        face=cat("face"),
        normal=None if first.normal is None else cat("normal"),
        files=tuple(files),
        file_index=np.concatenate(index),
        row=cat("row"),
        columns=first.columns,
        off_wall=sum(p.off_wall for p in parts),
    )
