"""The patch :func:`wear.erosion.patch.erode` wears and what its stamping kernels take on it (SI units, degrees).

:func:`patch_grid` checks and sizes the patch (:class:`PatchGrid`: nodes, side, spacing, footprint extent, impacts,
slope-fit radius) for a stream and a response table; :func:`stamp_arguments` gathers the kernels' arguments
(:class:`StampArguments`) for particles of one direction and speed on it.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from contact.checks import check_number
from wear.erosion.stream import Stream, impacts_on_patch
from wear.erosion.table import ResponseTable

__all__ = [
    "PatchGrid",
    "StampArguments",
    "footprint_extent",
    "impact_count",
    "nominal_contact_radius",
    "particle_direction",
    "patch_grid",
    "slope_disc",
    "stamp_arguments",
]


@dataclass(frozen=True)
class PatchGrid:
    """The patch :func:`erode` wears: ``nodes`` per side, side ``size`` (m) and node ``spacing`` h (m), the
    ``footprint`` extent (m: twice the table's largest reach from the impact point), the ``impacts`` it receives
    over the exposure time and the radius ``slope_cells`` (nodes) of the slope-fit disc."""

    nodes: int
    size: float
    spacing: float
    footprint: float
    impacts: int
    slope_cells: int


@dataclass(frozen=True, eq=False)
class StampArguments:
    """What the stamping kernels (:mod:`wear.erosion.stamp`) take besides the surface and the impact points, in their
    order: grid spacing ``h`` (m), slope ``disc`` and ``disc_norm``, the particle ``direction`` and ``speed`` (m/s),
    the table's axes and arrays (``normal_speed`` m/s, ``angle`` deg, ``shape``, ``volume`` m³, ``length`` m,
    ``dent_table``; footprint grid origin ``u0``, ``v0`` and spacing ``du`` in units of L), the work arrays and the
    accumulators ``counts`` [shadowed, clamped] and ``removed`` [m³], which the kernels update in place."""

    h: float
    disc: np.ndarray
    disc_norm: float
    direction: np.ndarray
    speed: float
    normal_speed: np.ndarray
    angle: np.ndarray
    shape: np.ndarray
    volume: np.ndarray
    length: np.ndarray
    dent_table: np.ndarray
    u0: float
    v0: float
    du: float
    scratch: np.ndarray
    dent_scratch: np.ndarray
    counts: np.ndarray
    removed: np.ndarray

    def stamp(self, kernel: Callable[..., None], wear: np.ndarray, relief: np.ndarray, positions: np.ndarray) -> None:
        """Apply ``kernel`` for the impact points ``positions`` (k, 2) (m) to ``wear`` and ``relief`` (m)."""
        kernel(
            wear,
            relief,
            positions,
            self.h,
            self.disc,
            self.disc_norm,
            self.direction,
            self.speed,
            self.normal_speed,
            self.angle,
            self.shape,
            self.volume,
            self.length,
            self.dent_table,
            self.u0,
            self.v0,
            self.du,
            self.scratch,
            self.dent_scratch,
            self.counts,
            self.removed,
        )


def nominal_contact_radius(table: ResponseTable, stream: Stream) -> float:
    """The contact radius L (m) of the stream's impact on the flat plate, which the table must cover (normal speed
    and angle, to a rounding)."""
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
    return l_nominal


def footprint_extent(table: ResponseTable) -> float:
    """Twice the farthest a footprint of ``table`` reaches from its impact point along either axis (m)."""
    u_ext = max(abs(table.u[0]), abs(table.u[-1])) + abs(table.v[-1])
    return 2.0 * u_ext * float(table.length_scale.max())


def patch_grid(
    table: ResponseTable,
    stream: Stream,
    n: int,
    patch_size: float | None,
    cells_per_radius: float,
    slope_cells: int | None,
    max_impacts: int,
) -> PatchGrid:
    """The checked patch of ``n`` × ``n`` nodes (see :func:`erode` for the arguments): its size, spacing, footprint
    extent, impacts and slope-fit radius."""
    stream.check_packing(table.particle_mass / (4.0 / 3.0 * math.pi * table.particle_radius**3))
    l_nominal = nominal_contact_radius(table, stream)
    derived = patch_size is None
    if derived:
        patch_size = n * l_nominal / cells_per_radius
    patch_size = check_number("patch_size", patch_size, low=0.0, low_open=True, high=10.0, units="m")
    h = patch_size / n
    diameter = 2.0 * table.particle_radius
    footprint = footprint_extent(table)
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
    n_impacts = impact_count(table, stream, patch_size, max_impacts)
    if slope_cells is None:
        slope_cells = max(1, round(l_nominal / h))
    slope_cells = int(
        check_number("slope_cells", slope_cells, low=1, high=n // 4, what="radius of the slope-fit disc (nodes)")
    )
    return PatchGrid(n, patch_size, h, footprint, n_impacts, slope_cells)


def impact_count(table: ResponseTable, stream: Stream, patch_size: float, max_impacts: int) -> int:
    """The number of particles (1 to ``max_impacts``) the stream delivers to a patch of side ``patch_size`` (m) over
    its exposure time."""
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
    return n_impacts


def stamp_arguments(
    table: ResponseTable, patch: PatchGrid, direction: np.ndarray, speed: float, with_dent: bool
) -> StampArguments:
    """The kernels' arguments for particles along ``direction`` (:func:`particle_direction`) at ``speed`` (m/s) on
    ``patch``, from ``table``, with its dents if ``with_dent``; fresh work arrays and zero accumulators."""
    h = patch.spacing
    disc, disc_norm = slope_disc(patch.slope_cells, h)
    side = int(math.ceil(patch.footprint / h)) + 4  # the footprint's bounding box in nodes, with a margin
    return StampArguments(
        h=h,
        disc=disc,
        disc_norm=disc_norm,
        direction=direction,
        speed=speed,
        normal_speed=table.normal_speed,
        angle=table.angle,
        shape=np.ascontiguousarray(table.shape),
        volume=table.volume_m3,
        length=table.length_scale,
        dent_table=np.ascontiguousarray(table.dent) if with_dent else np.zeros((0, 0, 0, 0)),
        u0=float(table.u[0]),
        v0=float(table.v[0]),
        du=float(table.u[1] - table.u[0]),
        scratch=np.zeros(side * side),
        dent_scratch=np.zeros(side * side if with_dent else 1),
        counts=np.zeros(2, dtype=np.int64),
        removed=np.zeros(1),
    )


def slope_disc(slope_cells: int, h: float) -> tuple[np.ndarray, float]:
    """Node offsets (p, q) of the disc p² + q² ≤ slope_cells² and 1/(h Σ p²): the least-squares slope weights."""
    k = np.arange(-slope_cells, slope_cells + 1)
    pp, qq = np.meshgrid(k, k)
    inside = pp**2 + qq**2 <= slope_cells**2
    disc = np.ascontiguousarray(np.column_stack([pp[inside], qq[inside]]).astype(np.int64))
    return disc, 1.0 / (h * float(np.sum(disc[:, 0] ** 2)))


def particle_direction(angle: float, azimuth: float) -> np.ndarray:
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
