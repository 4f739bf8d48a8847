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

import math

import numpy as np
from tqdm import tqdm

from contact.checks import check_bool, check_choice, check_number
from contact.theory import speed_components
from wear.erosion.memory import check_patch_memory
from wear.erosion.result import ErosionResult
from wear.erosion.stamp import stamp_impacts, stamp_impacts_numpy
from wear.erosion.stream import Stream, impacts_on_patch
from wear.erosion.table import ResponseTable

__all__ = ["erode", "footprint_on_grid", "MAX_IMPACTS"]

#: Largest number of impacts one run accepts.
MAX_IMPACTS = 2_000_000_000


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
    stream.check_packing(table.particle_mass / (4.0 / 3.0 * math.pi * table.particle_radius**3))
    theta = math.radians(stream.angle)
    vn_nominal = stream.speed * math.cos(theta)
    tol = 1e-9 * stream.speed
    if not (
        table.normal_speed[0] - tol <= vn_nominal <= table.normal_speed[-1] + tol
        and table.angle[0] - 1e-9 <= stream.angle <= table.angle[-1] + 1e-9
    ):
        raise ValueError(
            f"table does not cover the stream: its normal speed {vn_nominal:.6g} m/s and angle {stream.angle:g} deg "
            f"must lie in [{table.normal_speed[0]:.6g}, {table.normal_speed[-1]:.6g}] m/s x "
            f"[{table.angle[0]:g}, {table.angle[-1]:g}] deg (build it with table_axes(speed, angle))"
        )
    _, _, l_nominal = table.interpolate(vn_nominal, stream.angle)
    derived = patch_size is None
    if derived:
        patch_size = n * l_nominal / cells_per_radius
    patch_size = check_number("patch_size", patch_size, low=0.0, low_open=True, high=10.0, units="m")
    h = patch_size / n
    diameter = 2.0 * table.particle_radius
    u_ext = max(abs(table.u[0]), abs(table.u[-1])) + abs(table.v[-1])
    footprint = 2.0 * u_ext * float(table.length_scale.max())
    if derived and (patch_size < diameter or footprint > 0.5 * patch_size):
        needed = max(diameter, 2.0 * footprint)
        raise ValueError(
            f"grid={n} is out of range for this stream: the patch it gives ({patch_size:.6g} m = grid x contact "
            f"radius / {cells_per_radius:g}) must be larger than the particle diameter ({diameter:.6g} m) and twice "
            f"the largest footprint ({footprint:.6g} m): use grid >= {math.ceil(needed * cells_per_radius / l_nominal)}"
            " or set patch_size"
        )
    if patch_size < diameter or footprint > 0.5 * patch_size:
        raise ValueError(
            f"patch_size={patch_size:.6g} is out of range: the patch must be larger than the particle diameter "
            f"({diameter:.6g} m) and twice the largest footprint ({footprint:.6g} m), "
            f"i.e. > {max(diameter, 2 * footprint):.6g} m"
        )
    if float(table.length_scale.min()) < 1.5 * h:
        raise ValueError(
            f"grid={n} is out of range for patch_size={patch_size:.6g} m: the spacing {h:.4g} m must be at most "
            f"2/3 of the smallest contact radius ({table.length_scale.min():.4g} m): use more grid nodes or a "
            f"patch smaller than {n * table.length_scale.min() / 1.5:.4g} m"
        )
    expected = impacts_on_patch(stream, table.particle_mass, patch_size**2)
    if expected > max_impacts:
        raise ValueError(
            f"exposure_time={stream.exposure_time:g} is out of range: it gives {expected:.4g} impacts on the patch "
            f"(more than {max_impacts:g}); shorten it or use a smaller patch"
        )
    n_impacts = int(round(expected))
    if n_impacts < 1:
        raise ValueError(
            f"exposure_time={stream.exposure_time:g} is out of range: it gives {expected:.3g} impacts on the patch "
            "(less than 1); lengthen it or use a larger patch"
        )
    if slope_cells is None:
        slope_cells = max(1, round(l_nominal / h))
    slope_cells = int(
        check_number("slope_cells", slope_cells, low=1, high=n // 4, what="radius of the slope-fit disc (nodes)")
    )

    disc, disc_norm = _slope_disc(slope_cells, h)
    direction = _direction(stream.angle, stream.azimuth)
    wear = np.zeros((n, n))
    has_dent = table.dent is not None
    if initial is not None:
        initial = np.array(initial, dtype=float)
        if initial.shape != (n, n) or not np.all(np.isfinite(initial)):
            raise ValueError(f"initial has shape {initial.shape}: must be a finite ({n}, {n}) depth field (m)")
    # relief: everything of the surface that is not worn (initial shape + dents); the slope sees wear + relief
    relief = np.zeros((n, n)) if initial is None else initial.copy()
    dent_table = np.ascontiguousarray(table.dent) if has_dent else np.zeros((0, 0, 0, 0))
    side = int(math.ceil(footprint / h)) + 4
    scratch = np.zeros(side * side)
    dent_scratch = np.zeros(side * side if has_dent else 1)
    counts = np.zeros(2, dtype=np.int64)
    removed = np.zeros(1)
    du = float(table.u[1] - table.u[0])
    kernel = stamp_impacts if engine == "numba" else stamp_impacts_numpy
    shape = np.ascontiguousarray(table.shape)
    rng = np.random.default_rng(seed)

    sample_at = np.unique(np.round(np.linspace(0, n_impacts, samples + 1)).astype(np.int64))
    frame_at = np.unique(np.round(np.linspace(0, n_impacts, frames + 1)[1:]).astype(np.int64))
    stops = np.union1d(sample_at[1:], frame_at)
    step = max(1, min(50_000, n_impacts // 200))
    stops = np.union1d(stops, np.arange(step, n_impacts, step))
    rows = {"impacts": [0], "mass": [0.0], "max_depth": [0.0], "slope": [0.0]}
    frame_list, frame_impacts = [], []
    bar = None
    if progress:
        bar = tqdm(total=n_impacts, unit="impact", desc="erode", leave=False)
    done = 0
    sample_set, frame_set = set(sample_at.tolist()), set(frame_at.tolist())
    try:
        for stop in stops:
            count = int(stop) - done
            positions = rng.random((count, 2)) * patch_size
            kernel(
                wear,
                relief,
                positions,
                h,
                disc,
                disc_norm,
                direction,
                stream.speed,
                table.normal_speed,
                table.angle,
                shape,
                table.volume_m3,
                table.length_scale,
                dent_table,
                float(table.u[0]),
                float(table.v[0]),
                du,
                scratch,
                dent_scratch,
                counts,
                removed,
            )
            done = int(stop)
            if bar is not None:
                bar.update(count)
            surface = wear + relief
            if done in sample_set:
                rows["impacts"].append(done)
                rows["mass"].append(table.plate_density * h * h * float(wear.sum()))
                rows["max_depth"].append(float(surface.max()))
                rows["slope"].append(_rms_slope(surface, h))
            if done in frame_set:
                frame_list.append(surface.copy())
                frame_impacts.append(done)
    finally:
        if bar is not None:
            bar.close()
    impacts = np.asarray(rows["impacts"], dtype=np.int64)
    delivered = impacts * table.particle_mass
    mass = np.asarray(rows["mass"])
    with np.errstate(invalid="ignore", divide="ignore"):
        rate = np.where(delivered > 0, mass / np.where(delivered > 0, delivered, 1.0), 0.0)
    per_impact = stream.exposure_time / n_impacts
    x = h * np.arange(n)
    return ErosionResult(
        x=x,
        y=x.copy(),
        wear=wear,
        dent=(relief - initial if initial is not None else relief) if has_dent else None,
        initial=initial,
        time=impacts * per_impact,
        impacts=impacts,
        particle_mass_kg=delivered,
        mass_loss_kg=mass,
        erosion_rate=rate,
        max_depth_m=np.asarray(rows["max_depth"]),
        rms_slope=np.asarray(rows["slope"]),
        frame_time=np.asarray(frame_impacts, dtype=float) * per_impact,
        frames=np.asarray(frame_list),
        n_impacts=n_impacts,
        shadowed=int(counts[0]),
        clamped=int(counts[1]),
        removed_m3=float(removed[0]),
        stream=stream,
        table=table,
        seed=int(seed),
    )


def _slope_disc(slope_cells: int, h: float) -> tuple[np.ndarray, float]:
    """Node offsets (p, q) of the disc p² + q² ≤ slope_cells² and 1/(h Σ p²): the least-squares slope weights."""
    k = np.arange(-slope_cells, slope_cells + 1)
    pp, qq = np.meshgrid(k, k)
    inside = pp**2 + qq**2 <= slope_cells**2
    disc = np.ascontiguousarray(np.column_stack([pp[inside], qq[inside]]).astype(np.int64))
    return disc, 1.0 / (h * float(np.sum(disc[:, 0] ** 2)))


def _direction(angle: float, azimuth: float) -> np.ndarray:
    """(sin θ cos ψ, sin θ sin ψ, cos θ, cos ψ, sin ψ) of a particle at ``angle`` θ and ``azimuth`` ψ (deg)."""
    theta, psi = math.radians(angle), math.radians(azimuth)
    return np.array(
        [
            math.sin(theta) * math.cos(psi),
            math.sin(theta) * math.sin(psi),
            math.cos(theta),
            math.cos(psi),
            math.sin(psi),
        ]
    )


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
    h = check_number("patch_size", patch_size, low=0.0, low_open=True, high=10.0, units="m") / n
    check_choice("engine", engine, ("numba", "numpy"))
    relief = np.zeros((n, n)) if surface is None else np.array(surface, dtype=float)
    if relief.shape != (n, n):
        raise ValueError(f"surface has shape {relief.shape}: must be ({n}, {n}) (m)")
    if slope_cells is None:
        _, _, length = table.interpolate(speed_components(speed, angle)[0], angle)
        slope_cells = max(1, round(length / h))
    disc, disc_norm = _slope_disc(int(check_number("slope_cells", slope_cells, low=1, high=n // 4)), h)
    wear = np.zeros((n, n))
    footprint = 2.0 * (max(abs(table.u[0]), abs(table.u[-1])) + abs(table.v[-1])) * float(table.length_scale.max())
    side = int(math.ceil(footprint / h)) + 4
    kernel = stamp_impacts if engine == "numba" else stamp_impacts_numpy
    kernel(
        wear,
        relief,
        np.array([point], dtype=float),
        h,
        disc,
        disc_norm,
        _direction(angle, azimuth),
        speed,
        table.normal_speed,
        table.angle,
        np.ascontiguousarray(table.shape),
        table.volume_m3,
        table.length_scale,
        np.zeros((0, 0, 0, 0)),
        float(table.u[0]),
        float(table.v[0]),
        float(table.u[1] - table.u[0]),
        np.zeros(side * side),
        np.zeros(1),
        np.zeros(2, dtype=np.int64),
        np.zeros(1),
    )
    return wear
