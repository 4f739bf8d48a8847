r"""The erosion of a component's wall, from its impact records to its rates, remaining life and worn wall: what
``impactwear wall`` runs (SI units; angles in degrees from the wall normal, into the wall).

:func:`erode_component` reads the wall (:func:`read_wall`), builds the case's wear law per record
(:func:`wear.wall.per_record.wall_law`), sums the records face by face in chunks (:func:`wear.wall.engine.erode_wall`)
and turns the sums into rates over the exposure time (:func:`wear.wall.worn.wall_wear`):

- **Scaling to the real flow.** Each face's eroded volume is multiplied by :math:`\dot m / \dot m_{CFD}`
  (``wall.sand_rate`` / ``wall.cfd_sand_rate``, 1 when not given): a one-way coupled CFD run's impacts scale with the
  sand it injected.
- **Exposure time** T (s): ``wall.exposure``, or else the span of the records' hit times (last minus first), which is
  right for records taken over a window of a steady flow; for the hits of a finite injection, give the time that
  injection stands for (its mass over its rate).
- **Thickness** (remaining life): the wall file's per-face field ``thickness_m`` where it gives one, else
  ``wall.thickness``; a face with neither has no remaining life (NaN).
- **The worn wall** after ``wall.service_time`` (:func:`wear.wall.worn.worn_wall`).
- **The allowable sand rate** for a ``wall.loss_budget`` b (m) over the service time :math:`t_s`: the depths scale
  with the sand rate, so the rate at which the deepest face loses b is :math:`\dot m\, b / \max_f h_f(t_s)` (with
  :math:`\dot m` = ``wall.sand_rate``; without it, the factor :math:`b / \max_f h_f` on the records' own rate).
"""

from __future__ import annotations

import os
import time
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import meshio
import numpy as np

from contact.checks import check_instance, check_path
from wear.case import Case
from wear.case.jobs import default_case
from wear.wall.case_keys import check_law_keys
from wear.wall.engine import WallSums, chunk_rows_for, erode_wall
from wear.wall.foam import DecomposedCaseError, polymesh_folder, read_polymesh
from wear.wall.mesh import Wall, concat_walls, duplicate_faces, read_surface
from wear.wall.options import WallOptions
from wear.wall.per_record import records_refusal, wall_law
from wear.wall.sources import Chunk, plan_chunks, record_files, record_format
from wear.wall.trust import check_exposure, check_records_fit, note_inputs, note_results
from wear.wall.worn import SECONDS_PER_YEAR, HotSpots, WallWear, hot_spots, remaining_life, wall_wear, worn_mesh

__all__ = ["ComponentErosion", "SURFACE_SUFFIXES", "erode_component", "read_wall"]

#: The suffixes of the surface files of a wall folder (a wall split into files, one patch each).
SURFACE_SUFFIXES = (".stl", ".obj", ".vtu", ".vtp", ".vtk", ".ply", ".off")


def read_wall(path: str | Path, patches: Sequence[str] | None = None, flip: bool = False) -> Wall:
    """The wall of ``path``: a surface file meshio reads (one patch, named by the file's stem); an OpenFOAM case, its
    ``constant`` or its polyMesh folder (the wall patches, or ``patches``); or a folder of surface files (a wall split
    into parts: each file a patch, by name). ``flip`` reverses the surfaces' orientation
    (:mod:`wear.wall.mesh`)."""
    wall = _read_wall(check_path("path", path, "a surface file, a folder of them or an OpenFOAM case"), patches, flip)
    twice = duplicate_faces(wall)
    if twice is not None:  # counted twice, they would double the area and halve the worn depth
        f, g, n = twice
        raise ValueError(
            f"wall={str(path)!r}: face {f} (label {wall.labels[f]}) of patch {wall.patch_names[wall.patch[f]]} repeats "
            f"face {g} (label {wall.labels[g]}) of patch {wall.patch_names[wall.patch[g]]} ({n} faces repeat another): "
            "give each face of the wall once"
        )
    return wall


def _read_wall(p: Path, patches: Sequence[str] | None, flip: bool) -> Wall:
    if not p.exists():
        raise ValueError(f"wall={str(p)!r}: no such file or folder")
    if p.is_dir():
        try:
            folder = polymesh_folder(p)
        except DecomposedCaseError:
            raise  # its message says how to reconstruct the case: more use than "no surface file"
        except ValueError:
            folder = None
        if folder is not None:
            if flip:
                raise ValueError(f"--flip: an OpenFOAM wall ({folder}) is oriented by the mesh; leave --flip out")
            return read_polymesh(folder, patches)
        files = sorted(f for f in p.iterdir() if f.suffix.lower() in SURFACE_SUFFIXES)
        if not files:
            raise ValueError(
                f"wall={str(p)!r} holds no OpenFOAM polyMesh and no surface file ({', '.join(SURFACE_SUFFIXES)})"
            )
        parts = [read_surface(f, flip=flip) for f in files]
        return _only_patches(concat_walls(parts), patches, p)
    return _only_patches(read_surface(p, flip=flip), patches, p)


def _only_patches(wall: Wall, patches: Sequence[str] | None, path: Path) -> Wall:
    """``wall`` if ``patches`` is None or names all its patches; a surface wall cannot be cut by patch."""
    if patches is None or set(patches) == set(wall.patch_names):
        return wall
    raise ValueError(
        f"--patches={','.join(patches)}: the wall {path} has the patches {', '.join(wall.patch_names)}; choosing "
        "patches is for an OpenFOAM case's wall patches"
    )


@dataclass(frozen=True, eq=False)
class ComponentErosion:
    """The erosion of a wall (module docstring): the ``case``, the ``wall``, the ``records`` files read, the per-face
    ``sums`` of the records (unscaled), the ``wear`` (rates, scaled to the real flow), ``rate_scale`` (sand rate
    over the CFD's), the ``exposure_s`` and where it came from (``exposure_source``), the per-face
    ``thickness_m`` (NaN where none), the ``service_s`` of the worn wall, the law's ``law_name`` and
    ``law_description``, and the ``seconds`` each part took."""

    case: Case
    wall: Wall
    records: tuple[str, ...]
    sums: WallSums
    wear: WallWear
    rate_scale: float
    exposure_s: float
    exposure_source: str
    thickness_m: np.ndarray
    service_s: float
    law_name: str
    law_description: str
    seconds: dict[str, float]

    @property
    def remaining_life_s(self) -> np.ndarray:
        """Each face's remaining life (s): ``inf`` without wear, NaN without a thickness
        (:func:`wear.wall.worn.remaining_life`)."""
        return remaining_life(self.wear, self.thickness_m)

    def hot_spots(self, n: int = 10) -> HotSpots:
        """The ``n`` faces of fastest thickness loss (:func:`wear.wall.worn.hot_spots`; life NaN without a
        thickness)."""
        return hot_spots(self.wall, self.wear, self.thickness_m, n)

    def face_fields(self) -> dict[str, np.ndarray]:
        """The per-face fields of the wall's files, named with their units: impact statistics, eroded volume and
        mass, rates, remaining life and the depth after the service time."""
        s, w = self.sums, self.wear
        fields = {
            "impacts": s.records,
            "particles": s.particles,
            "particle_mass_kg": s.mass_kg * self.rate_scale,
            "mean_speed_m_s": s.mean_speed_m_s,
            "eroded_volume_m3": w.volume_m3,
            "eroded_mass_kg": w.mass_kg,
            "erosion_rate_kg_m2_s": w.erosion_rate_kg_m2_s,
            "thickness_loss_rate_m_s": w.thickness_loss_rate_m_s,
            "thickness_loss_mm_year": w.thickness_loss_mm_year,
            "thickness_m": self.thickness_m,
            "remaining_life_s": self.remaining_life_s,
            "remaining_life_year": self.remaining_life_s / SECONDS_PER_YEAR,
            "wear_depth_m": w.depth_m(self.service_s),
        }
        edges = s.angle_edges_deg
        for b in range(len(edges) - 1):
            fields[f"particles_angle_{edges[b]:g}_{edges[b + 1]:g}_deg"] = s.angle_histogram[:, b]
        return fields

    def worn_mesh(self) -> meshio.Mesh:
        """The worn wall after the service time (:func:`wear.wall.worn.worn_mesh`), with the face fields."""
        return worn_mesh(self.wall, self.wear, self.service_s, self.thickness_m, self.face_fields())

    def summary(self) -> dict:
        """The numbers of ``summary.json`` (SI units)."""
        s, w = self.sums, self.wear
        kept = int(s.records.sum())
        rate = w.thickness_loss_mm_year
        worst = int(np.argmax(rate))
        life = self.remaining_life_s
        shortest = float(np.nanmin(life)) if np.isfinite(life).any() else None
        deepest = float(w.depth_m(self.service_s).max())
        budget, sand_rate = self.case.wall.loss_budget, self.case.wall.sand_rate
        factor = budget / deepest if budget is not None and deepest > 0.0 else None
        return {
            "records": {
                "files": list(self.records),
                "read": s.records_read,
                "on_wall": kept,
                "skipped": dict(s.skipped),
                "particles": float(s.particles.sum()),
                "particle_mass_kg": float(s.mass_kg.sum()),
                "time_first_s": s.time_first_s,
                "time_last_s": s.time_last_s,
            },
            "wall": {
                "faces": len(self.wall),
                "patches": list(self.wall.patch_names),
                "area_m2": float(self.wall.area.sum()),
                "faces_hit": int((s.records > 0).sum()),
            },
            "law": {"name": self.law_name, "description": self.law_description},
            "exposure_s": self.exposure_s,
            "exposure_source": self.exposure_source,
            "rate_scale": self.rate_scale,
            "service_time_s": self.service_s,
            "results": {
                "eroded_volume_m3": float(w.volume_m3.sum()),
                "eroded_mass_kg": float(w.mass_kg.sum()),
                "erosion_ratio_kg_per_kg": float(w.mass_kg.sum() / (s.mass_kg.sum() * self.rate_scale))
                if s.mass_kg.sum() > 0
                else 0.0,
                "max_thickness_loss_mm_year": float(rate[worst]),
                "max_thickness_loss_rate_m_s": float(w.thickness_loss_rate_m_s[worst]),
                "max_thickness_loss_face": worst,
                "max_thickness_loss_position_m": self.wall.centre[worst].tolist(),
                "min_remaining_life_s": shortest,
                "min_remaining_life_year": None if shortest is None else shortest / SECONDS_PER_YEAR,
                "max_wear_depth_m": deepest,
                "allowable_rate_factor": factor,
                "allowable_sand_rate_kg_s": None if factor is None or sand_rate is None else factor * sand_rate,
            },
            "seconds": dict(self.seconds),
        }


def _note_worn_through(depth: np.ndarray, thickness: np.ndarray, service_s: float) -> None:
    """A warning when the depth after the service time reaches the wall thickness on some face."""
    through = np.flatnonzero(depth >= thickness)  # NaN thickness: never
    if len(through):
        f = through[np.argmax(depth[through] / thickness[through])]
        warnings.warn(
            f"the wall is worn through on {len(through)} faces after wall.service_time={service_s:g} s (face {f}: "
            f"{depth[f]:.3g} m deep in a {thickness[f]:.3g} m wall); the worn wall is moved that far all the same: "
            "for a worn wall to mesh, give a wall.service_time within the shortest remaining life",
            stacklevel=3,
        )


def erode_component(
    case: Case,
    records: str | Path | Sequence[str | Path],
    wall: Wall,
    options: WallOptions | None = None,
    *,
    progress: bool = True,
    chunk_rows: int | None = None,
) -> ComponentErosion:
    r"""The erosion of ``wall`` by the impact records of ``records`` (files or folders: :mod:`wear.wall.sources`)
    with ``case``'s wear law, plate and ``[wall]`` table (module docstring). ``options``
    (:class:`wear.wall.options.WallOptions`: where the chunks are summed, how the records are placed on the wall)
    and ``progress``: as :func:`wear.wall.engine.erode_wall`'s;
    ``chunk_rows``: records per chunk (default: the largest that fits the memory budget). A key of the case that
    the law does not read, at a value other than the default of ``impactwear wall``, is refused
    (:func:`wear.wall.case_keys.check_law_keys`), and so are records that do not lie on the wall as a CFD run's do
    and an exposure too short for the rates, before any work (:mod:`wear.wall.trust`, which also warns of values
    that look like other units).

    Examples
    --------
    A 40 × 30 mm flat wall of two triangles (normal −z: the flow above) hit by four sand particles (0.3 mm) at
    20 m/s, 30° from the normal, under ``impactwear wall``'s default law (DNV-RP-O501): the face below the
    diagonal y = 0.75 x gets three of them, and the worn volume is 4 × E m / ρ_plate with the law's closed form
    E = K U^n F(α), F(α) = 0.6 (sin α + 7.2 (sin α − sin²α))^0.6 (1 − e^(−20α)), α from the surface (DNV 2015):

    >>> import math, tempfile
    >>> from pathlib import Path
    >>> from wear.case import default_case
    >>> from wear.wall import Wall
    >>> wall = Wall(points=[[0, 0, 0], [0.04, 0, 0], [0.04, 0.03, 0], [0, 0.03, 0]], face_points=[0, 3, 2, 0, 2, 1],
    ...             face_offsets=[0, 3, 6], patch=[0, 0], patch_names=("plate",), labels=[0, 1])
    >>> u, w = 20.0 * math.sin(math.radians(30.0)), -20.0 * math.cos(math.radians(30.0))  # m/s
    >>> rows = [f"{x},{y},0,{u},0,{w},3e-4,2650,{t}" for t, (x, y) in enumerate([(0.01, 0.005), (0.03, 0.02),
    ...                                                                           (0.02, 0.025), (0.035, 0.005)])]
    >>> header = "x_m,y_m,z_m,u_m_s,v_m_s,w_m_s,diameter_m,density_kg_m3,time_s"
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = Path(folder) / "hits.csv"
    ...     _ = path.write_text("\n".join([header, *rows]), encoding="utf-8")
    ...     run = erode_component(default_case("wall").with_(wall={"exposure": 1.0}), path, wall, progress=False)
    >>> run.sums.records.tolist()
    [1, 3]
    >>> a = math.radians(60.0)
    >>> ratio = 2e-9 * 20.0**2.6 * 0.6 * (math.sin(a) + 7.2 * (math.sin(a) - math.sin(a) ** 2)) ** 0.6 * (
    ...     1.0 - math.exp(-20.0 * a))  # kg/kg
    >>> particle = 2650.0 * math.pi * 3e-4**3 / 6.0  # kg
    >>> bool(abs(run.sums.volume_m3.sum() / (4 * ratio * particle / 7850.0) - 1) < 1e-9)
    True
    """
    options = WallOptions() if options is None else options
    _check_arguments(case, wall, options)
    spec = case.wall
    if spec.exposure is not None:
        check_exposure(spec.exposure, "wall.exposure")
    chunks = _plan_records(records, wall, chunk_rows)
    # before the law's table, which may take half a minute
    check_records_fit(chunks, wall, options, records_refusal(case))
    thickness, from_file = _thickness(wall, spec.thickness)
    note_inputs(case, thickness, from_file)
    seconds: dict[str, float] = {}
    t0 = time.perf_counter()
    law = wall_law(case, progress)
    seconds["law"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    sums = erode_wall(chunks, wall, law, options, progress=progress)
    seconds["records"] = time.perf_counter() - t0
    exposure, source = _exposure(spec.exposure, sums)
    check_exposure(exposure, source)
    scale = spec.rate_scale()
    wear = wall_wear(wall, sums.volume_m3 * scale, exposure, case.plate.density)
    note_results(float(wear.mass_kg.sum()), float(sums.mass_kg.sum()) * scale, sums.records > 0, thickness)
    _note_worn_through(wear.depth_m(spec.service_time), thickness, spec.service_time)
    return ComponentErosion(
        case=case,
        wall=wall,
        records=tuple(dict.fromkeys(c.path for c in chunks)),
        sums=sums,
        wear=wear,
        rate_scale=scale,
        exposure_s=float(exposure),
        exposure_source=source,
        thickness_m=thickness,
        service_s=spec.service_time,
        law_name=case.wear.law,
        law_description=getattr(law, "description", case.wear.law),
        seconds=seconds,
    )


def _check_arguments(case: Case, wall: Wall, options: WallOptions) -> None:
    """Refuse a ``case`` that is not a Case or sets keys its law does not read, a ``wall`` that is not a Wall (a
    path is named as such), and ``options`` that are not a WallOptions (whose fields it checked itself)."""
    check_instance("case", case, Case, "a wear.Case: wear.case.default_case('wall') or wear.case.load_case(path)")
    if isinstance(wall, (str, os.PathLike)):
        raise ValueError(f"wall={str(wall)!r} is a path: give the Wall it holds, wear.wall.read_wall({str(wall)!r})")
    check_instance("wall", wall, Wall, "a wear.wall.Wall: wear.wall.read_wall(path)")
    check_instance("options", options, WallOptions, "a wear.wall.options.WallOptions(workers=..., skip_bad=..., ...)")
    check_law_keys(case, default_case("wall"))


def _plan_records(records: str | Path | Sequence[str | Path], wall: Wall, chunk_rows: int | None) -> list[Chunk]:
    """The chunks of ``chunk_rows`` records each (default: the most that fit the memory budget for every format
    among the files) of the record files ``records`` names."""
    paths = record_files(records)
    if chunk_rows is None:
        formats = {record_format(p) for p in paths}
        chunk_rows = min(chunk_rows_for(wall, None, f) for f in formats)
    return plan_chunks(paths, chunk_rows)


def _thickness(wall: Wall, thickness: float | None) -> tuple[np.ndarray, bool]:
    """Each face's wall thickness (m): the wall file's ``thickness_m`` where finite, else ``thickness`` (the
    ``wall.thickness`` key; NaN without it); and whether the file gave any."""
    per_face = np.full(len(wall), np.nan if thickness is None else thickness)
    from_file = wall.thickness_m is not None and bool(np.isfinite(wall.thickness_m).any())
    if wall.thickness_m is not None:
        per_face = np.where(np.isfinite(wall.thickness_m), wall.thickness_m, per_face)
    return per_face, from_file


def _exposure(exposure: float | None, sums: WallSums) -> tuple[float, str]:
    """The exposure time (s) the records stand for and where it came from: ``exposure`` (``wall.exposure``) if
    given, else the span of the records' hit times, which must be positive."""
    if exposure is not None:
        return exposure, "wall.exposure"
    span = sums.time_last_s - sums.time_first_s
    if not span > 0.0:
        raise ValueError(
            f"wall.exposure: the records span {max(span, 0.0):g} s (first hit {sums.time_first_s:g} s, last "
            f"{sums.time_last_s:g} s), so they give no time to turn volumes into rates; give wall.exposure (s)"
        )
    return span, "the records' time span"
