r"""The footprint of one particle impact and the response table the stream erosion interpolates in.

A particle of a stream meets the plate at a local angle θ (deg from the local surface normal) with the
normal speed v_n; its footprint is the worn depth (and optionally the dent) it leaves, in its own frame:
u along the tangential direction of its velocity from the first-contact point, v across. The stream erosion
(:mod:`wear.erosion.patch`) needs the footprint of thousands of slightly different impacts, so it is computed
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
The footprints are tabulated over (v_n, θ) in :mod:`wear.erosion.table`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact import Material, simulate_impacts
from contact.checks import check_array, check_bool, check_choice, check_number
from contact.materials import effective_modulus
from contact.theory import sphere_mass
from wear.integrate import wear_from_impact
from wear.law import WearLaw

__all__ = ["Footprint", "ImpactResponse", "bitter_threshold_velocity", "bitter_volume"]

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
