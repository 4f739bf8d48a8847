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

The wear law is any of :mod:`wear.laws` (``[wear] law``): Eq. 15 alone (``"local"``) wears nothing at normal
incidence (no sliding), while ductile metals do erode there: Bitter's deformation wear (``"deformation"``,
``"combined"``) needs the impact's plastic work, i.e. a normal law that yields (``normal_model="thornton"``).

The footprints are tabulated over (v_n, θ) in :mod:`wear.erosion.table`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from contact import Material, simulate_impacts
from contact.checks import check_array, check_choice, check_friction, check_number
from contact.theory import sphere_mass
from wear.law import WearLaw
from wear.laws.impact import wear_of_impact
from wear.laws.registry import LAWS
from wear.pressure import pressure_history
from wear.slip import sliding_speed

__all__ = ["Footprint", "ImpactResponse"]


@dataclass(frozen=True, eq=False)
class Footprint:
    """The worn depth (m, positive into the plate) of one impact on a grid ``x`` (along the tangential direction
    from the first-contact point) × ``y`` (across), m; ``length_scale`` L (m): its largest contact radius;
    ``cutting_volume_m3`` and ``deformation_volume_m3`` split the worn volume (m³) into the part that is not
    Bitter's deformation wear (cutting, equation 15 or a correlation) and Bitter's; ``dent`` (m) optional.
    """

    x: np.ndarray
    y: np.ndarray
    wear: np.ndarray
    length_scale: float
    cutting_volume_m3: float = 0.0
    deformation_volume_m3: float = 0.0
    dent: np.ndarray | None = None

    @property
    def volume_m3(self) -> float:
        """Worn volume (m³) = cutting + deformation parts."""
        return self.cutting_volume_m3 + self.deformation_volume_m3

    @classmethod
    def from_wear_map(cls, wear_map, length_scale: float, dent=None) -> Footprint:
        """A footprint from a :class:`wear.WearMap` (x along the impact direction, y across; m) and the
        largest contact radius ``length_scale`` (m); ``dent`` (same grid, m) optional — e.g. from the coupled
        pipeline's result, to plug the FE pressure and the residual dent into the stream erosion."""
        return cls(
            x=wear_map.x,
            y=wear_map.y,
            wear=wear_map.depth,
            length_scale=float(length_scale),
            cutting_volume_m3=float(wear_map.volume_m3),
            dent=dent,
        )


@dataclass(frozen=True)
class ImpactResponse:
    """The default per-impact model: ``contact.simulate_impacts`` + a wear law of :mod:`wear.laws`.

    ``radius`` particle radius (m); ``ball`` particle material; ``plate`` plate material; ``friction`` μ;
    ``law`` the local law (Eq. 15, :class:`WearLaw`); ``pressure`` source ``"hertz"``, ``"paper"`` or
    ``"thornton"``; ``speed_model`` ``"sliding"`` or ``"kinematic"``; ``restitution``, ``normal_model``
    (``"hertz"``/``"thornton"``), ``tangential_model`` as in ``contact.simulate_impact``; ``points_across``
    wear-grid points across the contact diameter; ``wear_law`` the law by name (:data:`wear.laws.registry.LAWS`) and
    ``constants`` its constants (the ``[wear]`` keys and the plate's ``hardness``); ``limiting_pressure`` (Pa),
    ``scheme`` and ``time_step`` (s) of the impacts, as in ``contact.simulate_impacts``.
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
    wear_law: str = "local"
    constants: Mapping[str, float | str | None] = field(default_factory=dict)
    limiting_pressure: float | None = None
    scheme: str = "verlet"
    time_step: float | None = None

    def __post_init__(self) -> None:
        check_number("radius", self.radius, low=0.0, low_open=True, high=10.0, units="m", what="particle radius")
        check_friction("friction", self.friction)
        if not isinstance(self.law, WearLaw):
            raise ValueError(f"law={self.law!r} is not a wear.WearLaw")
        check_choice("pressure", self.pressure, ("hertz", "paper", "thornton"))
        check_choice("speed_model", self.speed_model, ("sliding", "kinematic"))
        check_choice("wear_law", self.wear_law, LAWS)

    @property
    def particle_mass(self) -> float:
        """Particle mass m_p = 4/3 π R³ ρ_p (kg)."""
        return sphere_mass(self.radius, self.ball.density)

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
            limiting_pressure=self.limiting_pressure,
            scheme=self.scheme,
            time_step=self.time_step,
            histories=True,
        )
        constants = {**self.constants, "K": self.law.K, "alpha": self.law.alpha, "beta": self.law.beta}
        out = []
        for i in range(speed.size):
            impact = batch[i]
            ph = pressure_history(impact, self.pressure)
            wm, worn = wear_of_impact(
                self.wear_law,
                constants,
                self.law,
                impact,
                ph,
                sliding_speed(impact, self.speed_model),
                density=self.plate.density,
                points_across=self.points_across,
            )
            deformation = worn.parts.get("deformation", 0.0)
            out.append(
                Footprint(
                    x=wm.x,
                    y=wm.y,
                    wear=wm.depth,
                    length_scale=float(impact.max_contact_radius),
                    cutting_volume_m3=worn.volume_m3 - deformation,
                    deformation_volume_m3=deformation,
                )
            )
        return out
