r"""The response table the stream erosion interpolates in: footprints of one impact (:mod:`wear.erosion.response`)
computed once on a grid of normal speed × local angle (SI units, deg).

Table layout (:class:`ResponseTable`): every footprint is resampled onto one grid in normalised
coordinates (u/L, v/L), L = that impact's largest contact radius, and stored as a shape of unit integral
(Σ shape Δu Δv = 1) with its volume and L. Interpolating shapes at fixed u/L, v/L keeps the edges of
neighbouring entries together; the volume is interpolated separately, so the eroded mass follows the
(smooth) volume table exactly while the shape error only moves material around (quantified in
tests/test_erosion_table.py).

Interpolation (:func:`table_entries`, the one used by the erosion kernels and :meth:`ResponseTable.interpolate`):
a particle of speed V at local angle θ between the table's angles θ_j ≤ θ ≤ θ_{j+1} (fraction f) is looked up in
each of the two angle columns at the normal speed it would have there, v_j = V cos θ_j — along a line of constant
speed, on which a wear law varies only through its angle function — and within a column between the normal speeds
v_i ≤ v_j ≤ v_{i+1} as a power law,

.. math:: \ln W = (1 - g)\ln W_i + g \ln W_{i+1}, \qquad g = \frac{\ln(v_j / v_i)}{\ln(v_{i+1} / v_i)},

exact for a volume W ∝ v_n^k (Finnie's, Oka's and DNV's laws: W ∝ V^k F(θ)), linear in W where an entry wears
nothing (a threshold), then linearly in θ: W = (1 − f) W(column j) + f W(column j+1). The shape, L and the dent
take the same weights, (1 − f)(1 − g), (1 − f) g, … of the four entries. With the stream's angle a node of the
angle axis (:func:`table_axes`), a flat plate is looked up in one column, so a power-law volume is exact there.
A volume that starts at a threshold inside a speed step (Bitter's deformation wear just above the yield speed) is
neither: within twice the yield speed the 5 default speeds miss it by tens of % (as the linear interpolation did);
more speeds (``erosion.table_speeds``) resolve it.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numba
import numpy as np
from scipy.interpolate import RegularGridInterpolator

from contact.checks import check_array, check_number
from contact.theory import speed_components
from wear.erosion.response import Footprint, ImpactResponse

#: What builds the table's footprints: a callable (normal_speed m/s, angle deg) -> Footprint, or an object with a
#: batched ``many`` (an :class:`ImpactResponse`).
Response = ImpactResponse | Callable[[float, float], Footprint]

__all__ = ["ResponseTable", "build_response_table", "table_axes", "table_entries", "MAX_TABLE_ENTRIES"]

#: Most (normal speed, angle) entries of a response table. Each entry is one impact with its history and wear map:
#: measured ~53 ms and ~0.27 MB each (the default erode case, 2 cores; its table has 85 entries), so 2000 entries take
#: ~2 min and ~0.6 GB, while the extremes of the keys (angle_step 0.1 deg over ±45 deg, 50 speeds: 45050 entries)
#: would take ~40 min and ~12 GB.
MAX_TABLE_ENTRIES = 2000


@dataclass(frozen=True, eq=False)
class ResponseTable:
    """Footprints on a grid of normal speed × local angle, in normalised coordinates (see module docstring).

    ``normal_speed`` (ns,) m/s and ``angle`` (na,) deg: the table axes (increasing). ``u`` (nu,), ``v`` (nv,):
    normalised coordinates (units of L) along and across the tangential direction. ``shape`` (ns, na, nv, nu)
    (1/L² units: Σ shape Δu Δv = 1, or all 0 for an entry that does not wear); ``volume_m3`` (ns, na) worn
    volume; ``cutting_volume_m3`` (all but Bitter's), ``deformation_volume_m3`` (Bitter's) its parts;
    ``length_scale`` (ns, na) L (m);
    ``dent`` (ns, na, nv, nu) dent depth / L or None. ``particle_radius`` (m), ``particle_mass`` (kg),
    ``plate_density`` (kg/m³) for the stream; ``description`` says which model built it.
    """

    normal_speed: np.ndarray
    angle: np.ndarray
    u: np.ndarray
    v: np.ndarray
    shape: np.ndarray
    volume_m3: np.ndarray
    cutting_volume_m3: np.ndarray
    deformation_volume_m3: np.ndarray
    length_scale: np.ndarray
    particle_radius: float
    particle_mass: float
    plate_density: float
    description: str = ""
    dent: np.ndarray | None = None

    @property
    def resolution(self) -> str:
        """One line: axes, ranges and footprint grid of the table."""
        return (
            f"{self.normal_speed.size} normal speeds in [{self.normal_speed[0]:.4g}, {self.normal_speed[-1]:.4g}] m/s"
            f" x {self.angle.size} local angles in [{self.angle[0]:.4g}, {self.angle[-1]:.4g}] deg; footprints on "
            f"{self.u.size} x {self.v.size} points, spacing {self.u[1] - self.u[0]:.4g} L (L = largest contact "
            f"radius, {self.length_scale.min() * 1e6:.4g}-{self.length_scale.max() * 1e6:.4g} um)"
        )

    def rows(self) -> list[tuple[float, ...]]:
        """(normal_speed m/s, angle deg, volume m³, cutting m³, deformation m³, L m) per entry, for a CSV."""
        return [
            (
                float(self.normal_speed[i]),
                float(self.angle[j]),
                float(self.volume_m3[i, j]),
                float(self.cutting_volume_m3[i, j]),
                float(self.deformation_volume_m3[i, j]),
                float(self.length_scale[i, j]),
            )
            for i in range(self.normal_speed.size)
            for j in range(self.angle.size)
        ]

    def interpolate(self, normal_speed: float, angle: float) -> tuple[np.ndarray, float, float]:
        """The table at (``normal_speed`` m/s, ``angle`` deg), clamped to it (:func:`table_entries`): (shape
        (nv, nu) of unit integral or 0, volume m³, L m) — what the erosion kernel stamps."""
        speed = normal_speed / math.cos(math.radians(angle))
        entries, volume, _ = table_entries(self.normal_speed, self.angle, self.volume_m3, speed, angle)
        shape = sum(w * self.shape[a, b] for a, b, w in entries)
        length = sum(w * self.length_scale[a, b] for a, b, w in entries)
        return shape, float(volume), float(length)


#: Relative tolerance of the table's edges: a lookup this close beyond an edge is not counted as clamped.
EDGE_TOLERANCE = 1e-9


@numba.njit(cache=True, inline="always")
def _bracket(axis, value, in_log):
    """(k, g, outside): axis[k] ≤ value ≤ axis[k + 1] at the fraction g ∈ [0, 1] of the interval (of its
    logarithm if ``in_log``), clamped to the axis; ``outside``: beyond it by more than :data:`EDGE_TOLERANCE`."""
    n = axis.size
    if n == 1:
        return 0, 0.0, False
    tol = EDGE_TOLERANCE * max(abs(axis[0]), abs(axis[n - 1]))
    outside = value < axis[0] - tol or value > axis[n - 1] + tol
    k = 0
    while k < n - 2 and value >= axis[k + 1]:
        k += 1
    if value <= axis[k]:
        return k, 0.0, outside
    if value >= axis[k + 1]:
        return k, 1.0, outside
    if in_log:
        return k, math.log(value / axis[k]) / math.log(axis[k + 1] / axis[k]), outside
    return k, (value - axis[k]) / (axis[k + 1] - axis[k]), outside


@numba.njit(cache=True, inline="always")
def _between(low, high, g):
    """The volume at the log fraction ``g`` between the entries ``low`` and ``high``: a power law between two
    positive volumes, linear if either is zero."""
    if low > 0.0 and high > 0.0:
        return low * (high / low) ** g
    return (1.0 - g) * low + g * high


@numba.njit(cache=True)
def table_entries(normal_speeds, angles, volume, speed, angle):
    """The four table entries of a particle at ``speed`` (m/s) and local ``angle`` (deg): ((row, column, weight)
    × 4, interpolated volume m³, outside the table) — see the module docstring. ``normal_speeds`` (m/s) and
    ``angles`` (deg): the table's axes; ``volume`` (m³) its volumes."""
    j, f, outside = _bracket(angles, angle, False)
    j1 = min(j + 1, angles.size - 1)
    last = normal_speeds.size - 1
    i0, g0, out0 = _bracket(normal_speeds, speed * math.cos(math.radians(angles[j])), True)
    i1, g1, out1 = _bracket(normal_speeds, speed * math.cos(math.radians(angles[j1])), True)
    k0, k1 = min(i0 + 1, last), min(i1 + 1, last)
    entries = (
        (i0, j, (1.0 - f) * (1.0 - g0)),
        (k0, j, (1.0 - f) * g0),
        (i1, j1, f * (1.0 - g1)),
        (k1, j1, f * g1),
    )
    w = (1.0 - f) * _between(volume[i0, j], volume[k0, j], g0) + f * _between(volume[i1, j1], volume[k1, j1], g1)
    return entries, w, outside or (f < 1.0 and out0) or (f > 0.0 and out1)


def table_axes(
    speed: float, angle: float, *, angle_margin: float = 20.0, angle_step: float = 2.5, speeds: int = 5
) -> tuple[np.ndarray, np.ndarray]:
    """Axes (normal speeds m/s, local angles deg) covering a stream at ``speed`` (m/s) and ``angle`` (deg
    from the normal) whose local angle may differ by up to ``angle_margin`` (deg): angles in [max(0, θ − margin),
    min(θ + margin, 85)] with θ itself a node and steps of at most ``angle_step`` on either side of it, normal
    speeds V cos θ_l over that range (``speeds`` points, ≥ 2, in geometric progression: even steps of the
    power-law interpolation, :func:`table_entries`; for a stream of one speed the used entries lie on
    v_n = V cos θ_l)."""
    speed = check_number("speed", speed, low=0.0, low_open=True, high=1000.0, units="m/s", what="stream speed")
    angle = check_number("angle", angle, low=0.0, high=85.0, units="deg", what="stream angle from the normal")
    margin = check_number("angle_margin", angle_margin, low=0.0, high=45.0, units="deg")
    step = check_number("angle_step", angle_step, low=0.1, high=15.0, units="deg")
    n_speeds = int(check_number("speeds", speeds, low=2, high=50, what="number of normal speeds"))
    lo, hi = max(0.0, angle - margin), min(angle + margin, 85.0)
    if hi <= lo:
        hi = lo + step
    below = np.linspace(lo, angle, math.ceil((angle - lo) / step) + 1) if angle > lo else np.array([angle])
    above = np.linspace(angle, hi, math.ceil((hi - angle) / step) + 1)
    angles = np.concatenate([below, above[1:]])
    vn = np.geomspace(speed_components(speed, hi)[0], speed_components(speed, lo)[0], n_speeds)
    return vn, angles


def build_response_table(
    response,
    normal_speeds,
    angles,
    *,
    points_per_length: int = 12,
    particle_radius: float | None = None,
    particle_mass: float | None = None,
    plate_density: float | None = None,
    description: str = "",
) -> ResponseTable:
    """Build the :class:`ResponseTable` of ``response`` over ``normal_speeds`` (m/s) × ``angles`` (deg).

    ``response``: callable (normal_speed, angle) -> :class:`Footprint`, or an object with a
    ``many(normal_speeds, angles) -> list[Footprint]`` method (e.g. :class:`ImpactResponse`, batched).
    ``points_per_length``: footprint grid points per L (the largest contact radius of each entry).
    ``particle_radius`` (m), ``particle_mass`` (kg), ``plate_density`` (kg/m³): taken from an
    :class:`ImpactResponse` when not given.
    """
    vn, theta, ppl = _check_axes(normal_speeds, angles, points_per_length)
    particle_radius, particle_mass, plate_density = _particle_and_plate(
        response, particle_radius, particle_mass, plate_density
    )
    prints = _footprints(response, vn, theta)
    du = 1.0 / ppl
    u, v = _normalised_axes(prints, du)
    shape, dent, length, cutting, deform = _resample(prints, vn.size, theta.size, u, v, du)
    return ResponseTable(
        normal_speed=vn,
        angle=theta,
        u=u,
        v=v,
        shape=shape,
        volume_m3=cutting + deform,
        cutting_volume_m3=cutting,
        deformation_volume_m3=deform,
        length_scale=length,
        particle_radius=float(particle_radius),
        particle_mass=float(particle_mass),
        plate_density=float(plate_density),
        description=description or type(response).__name__,
        dent=dent,
    )


def _check_axes(normal_speeds, angles, points_per_length: int) -> tuple[np.ndarray, np.ndarray, int]:
    """The table's normal speeds (m/s) and angles (deg), checked strictly increasing and within
    :data:`MAX_TABLE_ENTRIES` entries, and the footprint grid points per L."""
    vn = check_array("normal_speeds", normal_speeds, low=0.0, low_open=True, units="m/s")
    theta = check_array("angles", angles, low=0.0, high=89.0, units="deg")
    for name, axis in (("normal_speeds", vn), ("angles", theta)):
        if axis.size >= 2 and np.any(np.diff(axis) <= 0.0):
            raise ValueError(f"{name} must be strictly increasing")
    ppl = int(check_number("points_per_length", points_per_length, low=4, high=64))
    if vn.size * theta.size > MAX_TABLE_ENTRIES:
        raise ValueError(
            f"normal_speeds, angles: {vn.size} x {theta.size} = {vn.size * theta.size} table entries (one impact "
            f"each): at most {MAX_TABLE_ENTRIES}; use fewer speeds or a coarser angle step"
        )
    return vn, theta, ppl


def _particle_and_plate(
    response: Response, particle_radius: float | None, particle_mass: float | None, plate_density: float | None
) -> tuple[float, float, float]:
    """The particle radius (m) and mass (kg) and the plate density (kg/m³): as given, else an
    :class:`ImpactResponse`'s; each must be known and positive."""
    if isinstance(response, ImpactResponse):
        particle_radius = response.radius if particle_radius is None else particle_radius
        particle_mass = response.particle_mass if particle_mass is None else particle_mass
        plate_density = response.plate.density if plate_density is None else plate_density
    for name, value, units in (
        ("particle_radius", particle_radius, "m"),
        ("particle_mass", particle_mass, "kg"),
        ("plate_density", plate_density, "kg/m^3"),
    ):
        if value is None:
            raise ValueError(f"{name}=None: give it ({units}) when response is not an ImpactResponse")
        check_number(name, value, low=0.0, low_open=True, units=units)
    return particle_radius, particle_mass, plate_density


def _footprints(response: Response, vn: np.ndarray, theta: np.ndarray) -> list[Footprint]:
    """One :class:`Footprint` per (normal speed, angle), speed-major: batched through ``response.many`` where it
    has one; all with a dent or none."""
    grid_v, grid_a = np.meshgrid(vn, theta, indexing="ij")
    flat_v, flat_a = grid_v.ravel(), grid_a.ravel()
    if hasattr(response, "many"):
        prints = list(response.many(flat_v, flat_a))
    else:
        prints = [response(float(s), float(a)) for s, a in zip(flat_v, flat_a, strict=True)]
    if len(prints) != flat_v.size or not all(isinstance(p, Footprint) for p in prints):
        raise ValueError("response must return one wear.erosion.response.Footprint per (normal_speed, angle)")
    has_dent = prints[0].dent is not None
    if any((p.dent is not None) != has_dent for p in prints):
        raise ValueError("response returned a dent for some footprints only")
    return prints


def _normalised_axes(prints: list[Footprint], du: float) -> tuple[np.ndarray, np.ndarray]:
    """The u and v axes (units of L, spacing ``du``) of a box holding every footprint of ``prints``, with one cell
    of margin, symmetric in v."""
    lo_u = min(float(p.x[0]) / p.length_scale for p in prints)
    hi_u = max(float(p.x[-1]) / p.length_scale for p in prints)
    hi_v = max(float(np.abs(p.y).max()) / p.length_scale for p in prints)
    u = du * np.arange(math.floor(lo_u / du) - 1, math.ceil(hi_u / du) + 2)
    half = math.ceil(hi_v / du) + 1
    v = du * np.arange(-half, half + 1)
    return u, v


def _resample(
    prints: list[Footprint], n_speeds: int, n_angles: int, u: np.ndarray, v: np.ndarray, du: float
) -> tuple[np.ndarray, np.ndarray | None, np.ndarray, np.ndarray, np.ndarray]:
    """The footprints ``prints`` (speed-major) on the normalised grid (``u``, ``v``, spacing ``du``): shapes of
    unit integral (0 where an entry wears nothing), dents / L (or None), L (m), cutting and deformation volumes
    (m³)."""
    has_dent = prints[0].dent is not None
    uu, vv = np.meshgrid(u, v)
    shape = np.zeros((n_speeds, n_angles, v.size, u.size))
    dent = np.zeros_like(shape) if has_dent else None
    length = np.zeros((n_speeds, n_angles))
    cutting = np.zeros_like(length)
    deform = np.zeros_like(length)
    for k, p in enumerate(prints):
        i, j = divmod(k, n_angles)
        L = check_number("length_scale", p.length_scale, low=0.0, low_open=True, units="m")
        length[i, j] = L
        cutting[i, j] = p.cutting_volume_m3
        deform[i, j] = p.deformation_volume_m3
        pts = np.column_stack([(vv * L).ravel(), (uu * L).ravel()])
        resample = RegularGridInterpolator((p.y, p.x), p.wear, bounds_error=False, fill_value=0.0)
        s = np.maximum(resample(pts).reshape(uu.shape), 0.0)
        total = s.sum() * du * du
        if total > 0.0 and p.volume_m3 > 0.0:
            shape[i, j] = s / total
        if has_dent:
            rd = RegularGridInterpolator((p.y, p.x), p.dent, bounds_error=False, fill_value=0.0)
            dent[i, j] = rd(pts).reshape(uu.shape) / L
    return shape, dent, length, cutting, deform
