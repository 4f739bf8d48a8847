r"""The footprint of one particle impact and the response table the stream erosion interpolates in.

A particle of a stream meets the plate at a local angle θ (deg from the local surface normal) with the
normal speed v_n; its footprint is the worn depth (and optionally the dent) it leaves, in its own frame:
u along the tangential direction of its velocity from the first-contact point, v across. The stream erosion
(:mod:`wear.erosion.stream`) needs the footprint of thousands of slightly different impacts, so it is computed
once on a grid of (v_n, θ) — the **response table** — by any per-impact model, and interpolated.

The model is a callable ``response(normal_speed, angle) -> Footprint`` (SI units, deg). The default,
:class:`ImpactResponse`, is the single-impact chain of this toolkit: ``contact.simulate_impacts`` (one
batched run for the whole table) and :func:`wear.wear_from_impact` with a selectable pressure source
(``"hertz"``, ``"paper"``, ``"thornton"``; ``"fe"`` needs the FE pressure table of each impact, so the
coupled pipeline plugs in as its own callable). A callable with a ``many(normal_speeds, angles)`` method
is asked for the whole table at once.

Optional deformation wear (Bitter 1963, Part 1, Wear 6: 5-21), off by default to stay with the paper:

.. math:: W_D = \frac{m_p\,(v_n - K_B)^2}{2\,\varepsilon}\quad (v_n > K_B), \qquad
          K_B = \frac{\pi^2}{2\sqrt{10}}\,\frac{(1.59\,Y)^{5/2}}{\sqrt{\rho_p}}
                \left(\frac{1-\nu_p^2}{E_p} + \frac{1-\nu_t^2}{E_t}\right)^2

W_D worn volume (m³), m_p particle mass (kg), v_n normal speed (m/s), K_B Bitter's elastic-limit normal
speed (m/s: the speed at which the Hertz peak pressure reaches 1.59 Y of the plate), ε the deformation
wear factor (J/m³: the energy absorbed per unit volume removed; a material constant fitted to erosion at
normal incidence, no default). The sliding-wear law (Eq. 15) alone gives no wear at normal incidence
(no sliding), while ductile metals do erode there. W_D is spread as the paraboloid (1 − r²/a²) over the
largest contact radius a, centred on the contact point at the largest overlap.

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

from contact import Material, simulate_impacts
from contact.checks import check_array, check_bool, check_choice, check_number
from contact.materials import effective_modulus
from contact.theory import sphere_mass
from wear.integrate import wear_from_impact
from wear.law import WearLaw

__all__ = [
    "Footprint",
    "ImpactResponse",
    "ResponseTable",
    "build_response_table",
    "bitter_threshold_velocity",
    "bitter_volume",
    "table_axes",
]

#: Bitter's (1963) constant of the elastic-limit speed and his pressure factor 1.59 (of Y).
BITTER_FACTOR = math.pi**2 / (2.0 * math.sqrt(10.0))
BITTER_YIELD_FACTOR = 1.59


@dataclass(frozen=True, eq=False)
class Footprint:
    """What one impact leaves on the plate, in the impact frame (SI units).

    ``x`` (nx,) m along the tangential direction of the particle velocity, 0 at the first-contact point;
    ``y`` (ny,) m across; ``wear`` (ny, nx) worn depth (m, ≥ 0, material removed); ``dent`` (ny, nx) plastic
    dent depth (m, positive into the plate, pile-up negative) or None; ``length_scale`` L (m, the largest
    contact radius: sets the normalised table coordinates); ``sliding_volume_m3`` and
    ``deformation_volume_m3`` split the worn volume (m³) into Eq. 15 and Bitter's term.
    """

    x: np.ndarray
    y: np.ndarray
    wear: np.ndarray
    length_scale: float
    sliding_volume_m3: float = 0.0
    deformation_volume_m3: float = 0.0
    dent: np.ndarray | None = None

    @property
    def volume_m3(self) -> float:
        """Worn volume (m³) = sliding + deformation parts."""
        return self.sliding_volume_m3 + self.deformation_volume_m3

    @classmethod
    def from_wear_map(cls, wear_map, length_scale: float, dent=None) -> Footprint:
        """A footprint from a :class:`wear.WearMap` (x along the impact direction, y across; m) and the
        largest contact radius ``length_scale`` (m); ``dent`` (same grid, m) optional — e.g. from the coupled
        pipeline's result, to plug the FE pressure and the residual dent into the stream erosion."""
        return cls(
            x=wear_map.x, y=wear_map.y, wear=wear_map.depth, length_scale=float(length_scale),
            sliding_volume_m3=float(wear_map.volume_m3), dent=dent,
        )  # fmt: skip


def bitter_threshold_velocity(ball: Material, plate: Material) -> float:
    """Bitter's (1963) elastic-limit normal speed K_B (m/s) of a ``ball`` (the particle) on the ``plate``
    (its yield strength Y, Pa, is needed): see the module docstring."""
    if plate.yield_strength is None:
        raise ValueError("plate.yield_strength=None: Bitter's deformation wear needs the plate yield strength (Pa)")
    compliance = 1.0 / effective_modulus(ball, plate)
    return BITTER_FACTOR * (BITTER_YIELD_FACTOR * plate.yield_strength) ** 2.5 / math.sqrt(ball.density) * compliance**2


def bitter_volume(particle_mass: float, normal_speed, threshold: float, wear_factor: float):
    """Bitter's deformation-wear volume W_D = m_p (v_n − K_B)² / (2ε) (m³), 0 below K_B.

    ``particle_mass`` m_p (kg), ``normal_speed`` v_n (m/s), ``threshold`` K_B (m/s), ``wear_factor`` ε (J/m³)."""
    excess = np.maximum(np.asarray(normal_speed, dtype=float) - threshold, 0.0)
    return particle_mass * excess**2 / (2.0 * wear_factor)


@dataclass(frozen=True)
class ImpactResponse:
    """The default per-impact model: ``contact.simulate_impacts`` + :func:`wear.wear_from_impact`.

    ``radius`` particle radius (m); ``ball`` particle material; ``plate`` plate material; ``friction`` μ;
    ``law`` :class:`WearLaw`; ``pressure`` source ``"hertz"``, ``"paper"`` or ``"thornton"``; ``speed_model``
    ``"sliding"`` or ``"kinematic"``; ``restitution``, ``normal_model`` (``"hertz"``/``"thornton"``),
    ``tangential_model`` as in ``contact.simulate_impact``; ``points_across`` wear-grid points across the
    contact diameter; ``deformation_wear`` switches Bitter's term on (needs ``deformation_wear_factor`` ε in
    J/m³ and the plate yield strength; ``deformation_threshold`` K_B in m/s defaults to Bitter's formula).
    """

    radius: float
    ball: Material
    plate: Material
    friction: float
    law: WearLaw
    pressure: str = "hertz"
    speed_model: str = "sliding"
    restitution: float = 1.0
    normal_model: str = "hertz"
    tangential_model: str = "hdd"
    points_across: int = 64
    deformation_wear: bool = False
    deformation_wear_factor: float | None = None
    deformation_threshold: float | None = None

    def __post_init__(self) -> None:
        check_number("radius", self.radius, low=0.0, low_open=True, high=10.0, units="m", what="particle radius")
        check_number("friction", self.friction, low=0.0, high=10.0, what="friction coefficient")
        if not isinstance(self.law, WearLaw):
            raise ValueError(f"law={self.law!r} is not a wear.WearLaw")
        check_choice("pressure", self.pressure, ("hertz", "paper", "thornton"))
        check_choice("speed_model", self.speed_model, ("sliding", "kinematic"))
        if check_bool("deformation_wear", self.deformation_wear):
            if self.deformation_wear_factor is None:
                raise ValueError(
                    "deformation_wear_factor=None: deformation_wear=true needs Bitter's deformation wear factor "
                    "epsilon (J/m^3)"
                )
            check_number(
                "deformation_wear_factor",
                self.deformation_wear_factor,
                low=1e3,
                high=1e15,
                units="J/m^3",
                what="Bitter deformation wear factor",
            )
            if self.deformation_threshold is None:
                bitter_threshold_velocity(self.ball, self.plate)  # raises if the plate has no yield strength
            else:
                check_number(
                    "deformation_threshold",
                    self.deformation_threshold,
                    low=0.0,
                    high=1000.0,
                    units="m/s",
                    what="elastic-limit normal speed",
                )

    @property
    def particle_mass(self) -> float:
        """Particle mass m_p = 4/3 π R³ ρ_p (kg)."""
        return sphere_mass(self.radius, self.ball.density)

    @property
    def threshold(self) -> float:
        """Bitter's elastic-limit normal speed K_B in use (m/s)."""
        if self.deformation_threshold is not None:
            return float(self.deformation_threshold)
        return bitter_threshold_velocity(self.ball, self.plate)

    def __call__(self, normal_speed: float, angle: float) -> Footprint:
        return self.many([normal_speed], [angle])[0]

    def many(self, normal_speeds, angles) -> list[Footprint]:
        """Footprints of impacts at ``normal_speeds`` (m/s) and local ``angles`` (deg), one batched run."""
        vn = check_array("normal_speed", normal_speeds, low=0.0, low_open=True, units="m/s")
        theta = check_array("angle", angles, low=0.0, high=89.0, units="deg")
        speed = vn / np.cos(np.radians(theta))
        batch = simulate_impacts(
            self.radius,
            self.ball,
            self.plate,
            speed,
            theta,
            self.friction,
            restitution=self.restitution,
            normal_model=self.normal_model,
            tangential_model=self.tangential_model,
            histories=True,
        )
        out = []
        for i in range(speed.size):
            impact = batch[i]
            wm = wear_from_impact(
                impact, self.law, pressure=self.pressure, speed=self.speed_model, points_across=self.points_across
            )
            depth = wm.depth.copy()
            a_max = float(impact.max_contact_radius)
            deformation = 0.0
            if self.deformation_wear:
                deformation = float(
                    bitter_volume(self.particle_mass, vn[i], self.threshold, self.deformation_wear_factor)
                )
                if deformation > 0.0:
                    h = impact.history
                    xc = float(h.contact_x[int(np.argmax(h.overlap))])
                    r2 = (wm.x[None, :] - xc) ** 2 + wm.y[:, None] ** 2
                    bowl = np.maximum(1.0 - r2 / a_max**2, 0.0)
                    depth += deformation * bowl / (bowl.sum() * wm.spacing**2)
            out.append(
                Footprint(
                    x=wm.x,
                    y=wm.y,
                    wear=depth,
                    length_scale=a_max,
                    sliding_volume_m3=wm.volume_m3,
                    deformation_volume_m3=deformation,
                )
            )
        return out


@dataclass(frozen=True, eq=False)
class ResponseTable:
    """Footprints on a grid of normal speed × local angle, in normalised coordinates (see module docstring).

    ``normal_speed`` (ns,) m/s and ``angle`` (na,) deg: the table axes (increasing). ``u`` (nu,), ``v`` (nv,):
    normalised coordinates (units of L) along and across the tangential direction. ``shape`` (ns, na, nv, nu)
    (1/L² units: Σ shape Δu Δv = 1, or all 0 for an entry that does not wear); ``volume_m3`` (ns, na) worn
    volume; ``sliding_volume_m3``, ``deformation_volume_m3`` its parts; ``length_scale`` (ns, na) L (m);
    ``dent`` (ns, na, nv, nu) dent depth / L or None. ``particle_radius`` (m), ``particle_mass`` (kg),
    ``plate_density`` (kg/m³) for the stream; ``description`` says which model built it.
    """

    normal_speed: np.ndarray
    angle: np.ndarray
    u: np.ndarray
    v: np.ndarray
    shape: np.ndarray
    volume_m3: np.ndarray
    sliding_volume_m3: np.ndarray
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
        """(normal_speed m/s, angle deg, volume m³, sliding m³, deformation m³, L m) per entry, for a CSV."""
        return [
            (
                float(self.normal_speed[i]),
                float(self.angle[j]),
                float(self.volume_m3[i, j]),
                float(self.sliding_volume_m3[i, j]),
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
    vn = np.linspace(speed * math.cos(math.radians(hi)), speed * math.cos(math.radians(lo)), n_speeds)
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
    sliding = np.zeros_like(length)
    deform = np.zeros_like(length)
    for k, p in enumerate(prints):
        i, j = divmod(k, theta.size)
        L = check_number("length_scale", p.length_scale, low=0.0, low_open=True, units="m")
        length[i, j] = L
        sliding[i, j] = p.sliding_volume_m3
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
        volume_m3=sliding + deform,
        sliding_volume_m3=sliding,
        deformation_volume_m3=deform,
        length_scale=length,
        particle_radius=float(particle_radius),
        particle_mass=float(particle_mass),
        plate_density=float(plate_density),
        description=description or type(response).__name__,
        dent=dent,
    )
