r"""Erosion of a plate patch by a stream of particles (:class:`wear.erosion.stream.Stream`), with surface feedback:
:func:`erode`.

The patch is a square, periodic cell of a uniformly exposed plate: a height field on ``grid`` × ``grid``
nodes of spacing h = ``patch_size``/``grid`` holding the worn depth w(x, y) (m, into the plate) and, if the
response table has one, the dent d(x, y). The stream (:class:`Stream`) has speed V, angle θ from the plate
normal, azimuth ψ of its tangential direction from the grid x axis, and a mass concentration c (kg/m³) or
a mass flux q = cV (kg m⁻² s⁻¹ through a plane normal to the stream). Over the exposure time T the plate
receives

.. math:: N = \operatorname{round}\!\left(\frac{q\cos\theta\,A\,T}{m_p}\right)

particles on the patch area A (m_p = 4/3 π R³ ρ_p). Impact points are uniform on the patch (numpy
``default_rng(seed)``: the same seed gives the same result bit for bit). Each impact in turn:

1. the local surface normal n ∝ (∂s/∂x, ∂s/∂y, 1) of the current surface s = w + d: the slope of the
   least-squares plane through the nodes within one contact radius (``slope_cells``) of the node nearest to
   the impact point (a disc, so that the estimate does not prefer the grid axes);
2. the local angle cos θ_l = −d̂·n and normal speed v_n = V cos θ_l of the particle direction d̂; the
   footprint's u axis is the horizontal projection of the tangential velocity d̂ − (d̂·n)n (the stream
   azimuth at normal local incidence); particles with θ_l ≥ 89° (shadowed) do not hit;
3. the footprint is interpolated in the :class:`wear.erosion.table.ResponseTable` at (V, θ_l)
   (:func:`wear.erosion.table.table_entries`: along the speed V between the angle columns, a power law of the
   normal speed within one; clamped to the table, counted in ``clamped``), sampled bilinearly at every node it
   covers in the rotated frame, rescaled so that the nodes receive exactly the interpolated volume, and added
   (wrapping across the periodic edges).

Approximations: the footprint is laid on the horizontal grid and removed vertically, which is exact on a
flat surface and in error by O(slope²) on a tilted one (1% at a slope of 0.1); the slope is the average over
one contact diameter; the footprint of an impact on a curved surface is that of a flat plate at the local
angle. Mass loss = ρ_plate h² Σ w; erosion rate = mass loss / mass of particles delivered (kg/kg).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from tqdm import tqdm

from contact.checks import check_bool, check_choice, check_number
from contact.theory import speed_components
from wear.erosion.memory import check_patch_memory
from wear.erosion.patch_grid import (
    PatchGrid,
    StampArguments,
    footprint_extent,
    particle_direction,
    patch_grid,
    stamp_arguments,
)
from wear.erosion.result import ErosionResult
from wear.erosion.stamp import stamp_impacts, stamp_impacts_numpy
from wear.erosion.stream import Stream
from wear.erosion.table import ResponseTable

__all__ = ["erode", "footprint_on_grid", "MAX_IMPACTS"]

#: Largest number of impacts one run accepts.
MAX_IMPACTS = 2_000_000_000

#: The stamping kernels by engine name (same arguments, same update).
KERNELS: dict[str, Callable[..., None]] = {"numba": stamp_impacts, "numpy": stamp_impacts_numpy}


def _rms_slope(surface: np.ndarray, h: float) -> float:
    gx = (np.roll(surface, -1, axis=1) - np.roll(surface, 1, axis=1)) / (2 * h)
    gy = (np.roll(surface, -1, axis=0) - np.roll(surface, 1, axis=0)) / (2 * h)
    return float(np.sqrt(np.mean(gx**2 + gy**2)))


def erode(
    table: ResponseTable,
    stream: Stream,
    *,
    grid: int = 512,
    patch_size: float | None = None,
    cells_per_radius: float = 4.0,
    seed: int = 0,
    frames: int = 10,
    samples: int = 100,
    slope_cells: int | None = None,
    engine: str = "numba",
    progress: bool = False,
    max_impacts: int = MAX_IMPACTS,
    initial: np.ndarray | None = None,
) -> ErosionResult:
    """Erode a periodic ``grid`` × ``grid`` patch by ``stream`` with footprints from ``table`` (see module
    docstring; SI units, degrees).

    ``patch_size``: side of the patch (m); default ``grid`` × h with h = L/``cells_per_radius``, L the contact
    radius of the nominal impact (from the table). ``seed``: random seed of the impact points.
    ``frames``: surfaces kept for the time series (≥ 1, the last at the end); ``samples``: rows of the
    mass-loss time series. ``slope_cells``: radius (nodes) of the slope-fit disc, default one contact radius.
    ``engine``: ``"numba"`` or ``"numpy"`` (the reference, slow). ``progress``: tqdm bar on stderr.
    ``initial``: initial surface depth (m, shape (grid, grid), positive into the plate; default flat), e.g. the
    surface of a previous run (its worn mass is not counted again).
    Raises ValueError naming the parameter for an impossible stream (``concentration``/``mass_flux`` denser
    than close-packed particles), a patch smaller than a particle or a footprint (``patch_size``), a grid
    that does not resolve the contact (``grid``/``patch_size``), patch arrays beyond
    :func:`wear.case.budget.memory_budget` (``grid``/``frames``), or too many impacts (``exposure_time``).
    """
    if not isinstance(table, ResponseTable):
        raise ValueError(f"table={table!r} is not a wear.erosion.table.ResponseTable (build_response_table)")
    if not isinstance(stream, Stream):
        raise ValueError(f"stream={stream!r} is not a wear.erosion.stream.Stream")
    n = int(check_number("grid", grid, low=16, high=8192, what="grid nodes per side"))
    check_number("cells_per_radius", cells_per_radius, low=1.0, high=64.0)
    check_choice("engine", engine, ("numba", "numpy"))
    check_bool("progress", progress)
    frames = int(check_number("frames", frames, low=1, high=1000))
    samples = int(check_number("samples", samples, low=1, high=100000))
    check_patch_memory(n, frames)
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise ValueError(f"seed={seed!r} is out of range: must be an integer >= 0")
    patch = patch_grid(table, stream, n, patch_size, cells_per_radius, slope_cells, max_impacts)
    has_dent = table.dent is not None
    args = stamp_arguments(table, patch, particle_direction(stream.angle, stream.azimuth), stream.speed, has_dent)
    if initial is not None:
        initial = np.array(initial, dtype=float)
        if initial.shape != (n, n) or not np.all(np.isfinite(initial)):
            raise ValueError(f"initial has shape {initial.shape}: must be a finite ({n}, {n}) depth field (m)")
    wear = np.zeros((n, n))
    # relief: everything of the surface that is not worn (initial shape + dents); the slope sees wear + relief
    relief = np.zeros((n, n)) if initial is None else initial.copy()
    series = _run_stream(
        KERNELS[engine], args, wear, relief, patch, table.plate_density, seed, samples, frames, progress
    )
    dent = (relief - initial if initial is not None else relief) if has_dent else None
    return _erosion_result(table, stream, patch, series, args, wear, dent, initial, int(seed))


@dataclass(frozen=True)
class StreamSeries:
    """What :func:`_run_stream` records: per sample row the ``impacts`` so far, the worn ``mass`` (kg), the
    ``max_depth`` of the surface (m) and its RMS ``slope``; the ``frames`` (surface depth, m) and the impacts at
    each (``frame_impacts``)."""

    impacts: list[int]
    mass: list[float]
    max_depth: list[float]
    slope: list[float]
    frames: list[np.ndarray]
    frame_impacts: list[int]


def _erosion_result(
    table: ResponseTable,
    stream: Stream,
    patch: PatchGrid,
    series: StreamSeries,
    args: StampArguments,
    wear: np.ndarray,
    dent: np.ndarray | None,
    initial: np.ndarray | None,
    seed: int,
) -> ErosionResult:
    """The :class:`ErosionResult` of a run: the time series in time (s), delivered particle mass (kg) and erosion
    rate (kg/kg, 0 before the first particle), and the kernels' counts."""
    impacts = np.asarray(series.impacts, dtype=np.int64)
    delivered = impacts * table.particle_mass
    mass = np.asarray(series.mass)
    with np.errstate(invalid="ignore", divide="ignore"):
        rate = np.where(delivered > 0, mass / np.where(delivered > 0, delivered, 1.0), 0.0)
    per_impact = stream.exposure_time / patch.impacts
    x = patch.spacing * np.arange(patch.nodes)
    return ErosionResult(
        x=x,
        y=x.copy(),
        wear=wear,
        dent=dent,
        initial=initial,
        time=impacts * per_impact,
        impacts=impacts,
        particle_mass_kg=delivered,
        mass_loss_kg=mass,
        erosion_rate=rate,
        max_depth_m=np.asarray(series.max_depth),
        rms_slope=np.asarray(series.slope),
        frame_time=np.asarray(series.frame_impacts, dtype=float) * per_impact,
        frames=np.asarray(series.frames),
        n_impacts=patch.impacts,
        shadowed=int(args.counts[0]),
        clamped=int(args.counts[1]),
        removed_m3=float(args.removed[0]),
        stream=stream,
        table=table,
        seed=seed,
    )


def _stops(n_impacts: int, samples: int, frames: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Impact counts at which the run samples the time series and keeps a frame, and every count at which it
    stops stamping: those two and regular steps in between (so that the progress bar moves)."""
    sample_at = np.unique(np.round(np.linspace(0, n_impacts, samples + 1)).astype(np.int64))
    frame_at = np.unique(np.round(np.linspace(0, n_impacts, frames + 1)[1:]).astype(np.int64))
    stops = np.union1d(sample_at[1:], frame_at)
    step = max(1, min(50_000, n_impacts // 200))
    stops = np.union1d(stops, np.arange(step, n_impacts, step))
    return sample_at, frame_at, stops


def _run_stream(
    kernel: Callable[..., None],
    args: StampArguments,
    wear: np.ndarray,
    relief: np.ndarray,
    patch: PatchGrid,
    plate_density: float,
    seed: int,
    samples: int,
    frames: int,
    progress: bool,
) -> StreamSeries:
    """Stamp the patch's impacts at uniform random points (``default_rng(seed)``, drawn batch by batch in this
    order so that a seed gives the same run) onto ``wear`` and ``relief`` (m, in place), recording the time series
    and the frames."""
    sample_at, frame_at, stops = _stops(patch.impacts, samples, frames)
    h = patch.spacing
    rng = np.random.default_rng(seed)
    rows = {"impacts": [0], "mass": [0.0], "max_depth": [0.0], "slope": [0.0]}
    frame_list, frame_impacts = [], []
    bar = None
    if progress:
        bar = tqdm(total=patch.impacts, unit="impact", desc="erode", leave=False)
    done = 0
    sample_set, frame_set = set(sample_at.tolist()), set(frame_at.tolist())
    try:
        for stop in stops:
            count = int(stop) - done
            positions = rng.random((count, 2)) * patch.size
            args.stamp(kernel, wear, relief, positions)
            done = int(stop)
            if bar is not None:
                bar.update(count)
            surface = wear + relief
            if done in sample_set:
                rows["impacts"].append(done)
                rows["mass"].append(plate_density * h * h * float(wear.sum()))
                rows["max_depth"].append(float(surface.max()))
                rows["slope"].append(_rms_slope(surface, h))
            if done in frame_set:
                frame_list.append(surface.copy())
                frame_impacts.append(done)
    finally:
        if bar is not None:
            bar.close()
    return StreamSeries(rows["impacts"], rows["mass"], rows["max_depth"], rows["slope"], frame_list, frame_impacts)


def footprint_on_grid(
    table: ResponseTable,
    speed: float,
    angle: float,
    *,
    azimuth: float = 0.0,
    point: tuple[float, float] = (0.0, 0.0),
    grid: int = 128,
    patch_size: float,
    surface: np.ndarray | None = None,
    slope_cells: int | None = None,
    engine: str = "numba",
) -> np.ndarray:
    """Worn depth (m, shape (grid, grid), periodic) of one particle at ``speed`` (m/s), ``angle`` and
    ``azimuth`` (deg) hitting the patch at ``point`` (m): the update :func:`erode` applies per impact.
    ``surface``: the depth field (m) it meets (default flat); ``slope_cells``: radius of the slope-fit disc
    (nodes; default one contact radius of the nominal impact)."""
    speed = check_number("speed", speed, low=0.0, low_open=True, high=1000.0, units="m/s")
    angle = check_number("angle", angle, low=0.0, high=85.0, units="deg")
    check_number("azimuth", azimuth, low=-360.0, high=360.0, units="deg")
    n = int(check_number("grid", grid, low=16, high=8192))
    size = check_number("patch_size", patch_size, low=0.0, low_open=True, high=10.0, units="m")
    h = size / n
    check_choice("engine", engine, ("numba", "numpy"))
    relief = np.zeros((n, n)) if surface is None else np.array(surface, dtype=float)
    if relief.shape != (n, n):
        raise ValueError(f"surface has shape {relief.shape}: must be ({n}, {n}) (m)")
    if slope_cells is None:
        _, _, length = table.interpolate(speed_components(speed, angle)[0], angle)
        slope_cells = max(1, round(length / h))
    slope_cells = int(check_number("slope_cells", slope_cells, low=1, high=n // 4))
    # one impact: no time series, no impact count; the dents are left out (the worn depth only)
    patch = PatchGrid(n, size, h, footprint_extent(table), 1, slope_cells)
    args = stamp_arguments(table, patch, particle_direction(angle, azimuth), speed, with_dent=False)
    wear = np.zeros((n, n))
    args.stamp(KERNELS[engine], wear, relief, np.array([point], dtype=float))
    return wear
