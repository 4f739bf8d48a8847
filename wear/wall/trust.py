r"""Whether the impact records, the wall and the ``[wall]`` keys agree, checked before the work; and notes (Python
warnings, the command's ``note:`` lines) on values that look like other units (SI units throughout).

**The records against the wall** (:func:`check_records_fit`), on the first rows of the first record file (at most
:data:`SAMPLE_ROWS`), before any work:

- *The distance of the hits from the wall.* A CFD or DEM code records a hit on the wall face (to round-off; a
  DEM contact point within a particle radius), so the typical (median) distance of the hits from their faces is a
  small part of the face size :math:`\sqrt{\mathrm{median}\,A_f}`. Above :data:`TYPICAL_DISTANCE` of it, the records
  and the wall are in other units or of other runs: refused. (Each record farther than a quarter of the face size
  is refused anyway, naming its row; this catches the records that are not that far but none on the wall.)
- *The span of the hits.* Records in m on a wall in mm lie in a corner of the wall 1000 times smaller than it
  and, on a flat wall, on it: the distance does not tell. When at least :data:`SPREAD_RECORDS` distinct hit points
  span less than :data:`SPAN_RATIO` of the wall's extent (the diagonals of their bounding boxes), refused.

- *What the law takes.* A response table's law (:func:`wear.wall.per_record.records_refusal`) refuses a record outside
  its speeds or of another particle density: found here rather than after the table's half minute.

**Exposure.** The rates are volume / (area × exposure): an exposure below :data:`EXPOSURE_MIN` (no CFD or DEM
run's hits stand for less than a nanosecond; far below, the rates overflow) is refused (:func:`check_exposure`).

**Notes** (:func:`note_inputs`, :func:`note_results`): a particle density below :data:`DENSITY_NOTE` (g/cm³ given
for kg/m³?), a wall thickness above :data:`THICKNESS_NOTE` (mm given for m?), a loss budget larger than the wall
thickness, an erosion ratio above 1 kg of wall per kg of particles, and hit faces without a thickness on a wall
whose other faces have one.
"""

from __future__ import annotations

import dataclasses
import warnings
from collections.abc import Callable, Sequence

import numpy as np

from wear.case import Case
from wear.wall.hits import hits_on_wall
from wear.wall.mesh import Wall
from wear.wall.options import WallOptions
from wear.wall.sources import Chunk, read_chunk
from wear.wall.sums import refuse_records

__all__ = [
    "DENSITY_NOTE",
    "EXPOSURE_MIN",
    "SAMPLE_ROWS",
    "SPAN_RATIO",
    "SPREAD_RECORDS",
    "THICKNESS_NOTE",
    "TYPICAL_DISTANCE",
    "check_exposure",
    "check_records_fit",
    "note_inputs",
    "note_results",
]

#: Rows of the first record file read to check the records against the wall.
SAMPLE_ROWS = 10_000
#: Largest median distance of the hits from their faces, over the median face size √(median area).
TYPICAL_DISTANCE = 0.1
#: Smallest span of the hits over the wall's extent (with at least SPREAD_RECORDS distinct hit points): a factor
#: 1000 (mm against m) gives at most 1e-3.
SPAN_RATIO = 2e-3
#: Distinct hit points needed before their span is judged (a few hits may well fall on one spot).
SPREAD_RECORDS = 10
#: Shortest exposure (s) the rates are computed for.
EXPOSURE_MIN = 1e-9
#: Particle density (kg/m³) below which a note asks whether it was given in g/cm³ (sand: 2650 kg/m³, 2.65 g/cm³).
DENSITY_NOTE = 100.0
#: Wall thickness (m) above which a note asks whether it was given in mm (a 5 mm wall given as 5).
THICKNESS_NOTE = 0.5

_UNITS = "other units (a wall in mm and records in m, or the reverse)? give both in m"


def check_records_fit(
    chunks: Sequence[Chunk],
    wall: Wall,
    options: WallOptions | None = None,
    refused: Callable[[np.ndarray, np.ndarray], tuple[int, str, str] | None] | None = None,
) -> None:
    """Refuse (``ValueError``, one line naming the records file) records that do not lie on ``wall`` as a CFD run's do
    (module docstring), from the first :data:`SAMPLE_ROWS` rows of the first of ``chunks``; note a particle density that
    looks like g/cm³. ``options``: the run's (:class:`wear.wall.options.WallOptions`: its ``normal``; the records far
    from the wall or leaving it are the run's to refuse or skip). A bad row among them is refused as the run would
    refuse it, and so is one the law will refuse: ``refused(speed_m_s, density_kg_m3)``
    (:func:`wear.wall.per_record.records_refusal`), which gives the first such record as (index, field, why) or None."""
    if not chunks:
        return
    first = chunks[0]
    records = read_chunk(dataclasses.replace(first, rows=min(first.rows, SAMPLE_ROWS)), wall)
    if not len(records):
        return
    # every hit's distance, however far: the records far from the wall or leaving it are the run's to refuse
    placed = dataclasses.replace(options or WallOptions(), tolerance=np.inf, skip_bad=True)
    hits = hits_on_wall(records, wall, placed)
    size = float(np.sqrt(np.median(wall.area)))
    typical = float(np.median(hits.distance))
    if typical > TYPICAL_DISTANCE * size:
        raise ValueError(
            f"records={first.path!r}: the hits lie typically {typical:.3g} m from the wall's faces, "
            f"{typical / size:.3g} of a face's size ({size:.3g} m), where a CFD code records them on the face: {_UNITS}"
        )
    points = np.unique(records.position, axis=0)
    span = float(np.linalg.norm(np.ptp(points, axis=0)))
    extent = float(np.linalg.norm(np.ptp(wall.points[wall.face_points], axis=0)))
    if len(points) >= SPREAD_RECORDS and span < SPAN_RATIO * extent:
        raise ValueError(
            f"records={first.path!r}: the {len(points)} hit points span {span:.3g} m, {span / extent:.2g} of the "
            f"wall's extent ({extent:.3g} m), all on {len(np.unique(hits.face[hits.kept]))} of its {len(wall)} "
            f"faces: {_UNITS}"
        )
    refuse_records(refused, records, hits)
    light = np.flatnonzero(records.density < DENSITY_NOTE)
    if len(light):
        i = light[0]
        warnings.warn(
            f"{records.where(i, 'density')}: a particle density of {records.density[i]:g} kg/m^3 (below "
            f"{DENSITY_NOTE:g}): was it given in g/cm^3? (densities are in kg/m^3: sand is 2650)",
            stacklevel=2,
        )


def check_exposure(exposure_s: float, source: str) -> None:
    """Refuse an exposure (s) below :data:`EXPOSURE_MIN`; ``source``: where it came from (the key, or the records'
    time span)."""
    if exposure_s < EXPOSURE_MIN:
        keyed = source.startswith("wall.")
        what = f"{source}={exposure_s:g} s" if keyed else f"the exposure {exposure_s:g} s ({source})"
        raise ValueError(
            f"{what} is out of range: give at least {EXPOSURE_MIN:g} s (no CFD or DEM run's hits stand for less; "
            "the rates, volume / (area x exposure), would overflow)"
        )


def note_inputs(case: Case, thickness_m: np.ndarray, from_file: bool) -> None:
    """Notes before the work: a thickness (m, per face) that looks like mm, a loss budget above the thickness."""
    given = thickness_m[np.isfinite(thickness_m)]
    if not len(given):
        return
    source = "the wall file's thickness_m" if from_file else "wall.thickness"
    if given.max() > THICKNESS_NOTE:
        warnings.warn(
            f"a wall thickness of {given.max():g} m ({source}), thicker than {THICKNESS_NOTE:g} m: was it given in mm? "
            "(thicknesses are in m)",
            stacklevel=2,
        )
    budget = case.wall.loss_budget
    if budget is not None and budget > given.min():
        warnings.warn(
            f"wall.loss_budget={budget:g} m is more than the wall's thickness ({given.min():g} m, {source}): the "
            "allowable sand rate lets the wall wear through",
            stacklevel=2,
        )


def note_results(mass_kg: float, particle_mass_kg: float, hit: np.ndarray, thickness_m: np.ndarray) -> None:
    """Notes after the work: an erosion ratio above 1 (``mass_kg`` of wall eroded by ``particle_mass_kg`` of
    particles on it), and faces ``hit`` (bool per face) without a thickness where other faces have one."""
    if particle_mass_kg > 0.0 and mass_kg > particle_mass_kg:
        warnings.warn(
            f"the wall loses {mass_kg / particle_mass_kg:.4g} kg per kg of particles that hit it, more than 1: check "
            "the records' units (m/s, m, kg/m^3), the law's constants and the plate's density",
            stacklevel=2,
        )
    bare = hit & np.isnan(thickness_m)
    if bare.any() and np.isfinite(thickness_m).any():
        warnings.warn(
            f"{int(bare.sum())} of the {int(hit.sum())} faces hit have no thickness (face {int(np.argmax(bare))}): "
            "they have no remaining life; give wall.thickness for the faces the wall file gives none",
            stacklevel=2,
        )
