r"""The response table the stream erosion interpolates in: footprints of one impact (:mod:`wear.erosion.response`)
computed once on a grid of normal speed × local angle (SI units, deg).

Table layout (:class:`ResponseTable`): every footprint is resampled onto one grid in normalised
coordinates (u/L, v/L), L = that impact's largest contact radius, and stored as a shape of unit integral
(Σ shape Δu Δv = 1) with its volume and L. Interpolating shapes at fixed u/L, v/L keeps the edges of
neighbouring entries together; the volume is interpolated separately, so the eroded mass follows the
(smooth) volume table exactly while the shape error only moves material around (quantified in
tests/test_erosion_table.py).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from contact.checks import check_array, check_number
from contact.theory import speed_components
from wear.erosion.response import Footprint, ImpactResponse

__all__ = ["ResponseTable", "build_response_table", "table_axes", "MAX_TABLE_ENTRIES"]

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
        """Bilinear interpolation at (``normal_speed`` m/s, ``angle`` deg), clamped to the table:
        (shape (nv, nu) of unit integral or 0, volume m³, L m) — what the erosion kernel stamps."""
        i, fi = _bracket(self.normal_speed, normal_speed)
        j, fj = _bracket(self.angle, angle)
        w = ((1 - fi) * (1 - fj), (1 - fi) * fj, fi * (1 - fj), fi * fj)
        idx = ((i, j), (i, j + 1), (i + 1, j), (i + 1, j + 1))
        shape = sum(wk * self.shape[a, b] for wk, (a, b) in zip(w, idx, strict=True))
        volume = sum(wk * self.volume_m3[a, b] for wk, (a, b) in zip(w, idx, strict=True))
        length = sum(wk * self.length_scale[a, b] for wk, (a, b) in zip(w, idx, strict=True))
        return shape, float(volume), float(length)


def _bracket(axis: np.ndarray, value: float) -> tuple[int, float]:
    if axis.size == 1:
        return 0, 0.0
    k = int(np.clip(np.searchsorted(axis, value, side="right") - 1, 0, axis.size - 2))
    f = float(np.clip((value - axis[k]) / (axis[k + 1] - axis[k]), 0.0, 1.0))
    return k, f


def table_axes(
    speed: float, angle: float, *, angle_margin: float = 20.0, angle_step: float = 2.5, speeds: int = 5
) -> tuple[np.ndarray, np.ndarray]:
    """Axes (normal speeds m/s, local angles deg) covering a stream at ``speed`` (m/s) and ``angle`` (deg
    from the normal) whose local angle may differ by up to ``angle_margin`` (deg): angles every
    ``angle_step`` in [max(0, θ − margin), min(θ + margin, 85)], normal speeds V cos θ_l over that range
    (``speeds`` points, ≥ 2; for a stream of one speed the used entries lie on v_n = V cos θ_l)."""
    speed = check_number("speed", speed, low=0.0, low_open=True, high=1000.0, units="m/s", what="stream speed")
    angle = check_number("angle", angle, low=0.0, high=85.0, units="deg", what="stream angle from the normal")
    margin = check_number("angle_margin", angle_margin, low=0.0, high=45.0, units="deg")
    step = check_number("angle_step", angle_step, low=0.1, high=15.0, units="deg")
    n_speeds = int(check_number("speeds", speeds, low=2, high=50, what="number of normal speeds"))
    lo, hi = max(0.0, angle - margin), min(angle + margin, 85.0)
    n_angles = max(2, math.ceil((hi - lo) / step) + 1) if hi > lo else 2
    if hi <= lo:
        hi = lo + step
    angles = np.linspace(lo, hi, n_angles)
    vn = np.linspace(speed_components(speed, hi)[0], speed_components(speed, lo)[0], n_speeds)
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
    # common normalised box, one cell of margin
    lo_u = min(float(p.x[0]) / p.length_scale for p in prints)
    hi_u = max(float(p.x[-1]) / p.length_scale for p in prints)
    hi_v = max(float(np.abs(p.y).max()) / p.length_scale for p in prints)
    du = 1.0 / ppl
    u = du * np.arange(math.floor(lo_u / du) - 1, math.ceil(hi_u / du) + 2)
    half = math.ceil(hi_v / du) + 1
    v = du * np.arange(-half, half + 1)
    uu, vv = np.meshgrid(u, v)
    shape = np.zeros((vn.size, theta.size, v.size, u.size))
    dent = np.zeros_like(shape) if has_dent else None
    length = np.zeros((vn.size, theta.size))
    cutting = np.zeros_like(length)
    deform = np.zeros_like(length)
    for k, p in enumerate(prints):
        i, j = divmod(k, theta.size)
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
