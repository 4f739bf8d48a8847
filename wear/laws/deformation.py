r"""Bitter's (1963) deformation wear, volume = plastic work / ε (Wear 6: 5–21), the plastic work taken from the
impact itself: the FE plate's plastic dissipation ∫ σ_y dᾱ dV when the plate is the FE, else the normal work
½ m v_n² (1 − e_n²) dissipated by the normal law in use (zero while elastic: below Thornton's yield speed, close to
Bitter's elastic-limit speed :func:`bitter_threshold_velocity`). SI units.
"""

from __future__ import annotations

import math

import numpy as np

from contact import ImpactResult, Material, effective_modulus
from wear.laws.declaration import Constants, Law, need

__all__ = ["LAW", "bitter_threshold_velocity", "deformation_of", "deformation_volume", "plastic_work_of"]

#: Bitter's (1963) constant of the elastic-limit speed and his pressure factor 1.59 (of Y).
BITTER_FACTOR = math.pi**2 / (2.0 * math.sqrt(10.0))
BITTER_YIELD_FACTOR = 1.59


def deformation_volume(plastic_work, deformation_factor: float) -> np.ndarray:
    """Bitter's deformation wear: volume (m³) = ``plastic_work`` (J, clipped at 0) / ``deformation_factor`` ε
    (J/m³)."""
    return np.maximum(np.asarray(plastic_work, float), 0.0) / deformation_factor


def bitter_threshold_velocity(ball: Material, plate: Material) -> float:
    r"""Bitter's (1963) elastic-limit normal speed (m/s) of a ``ball`` (the particle) on a ``plate`` of yield strength
    Y: :math:`K_B = \frac{\pi^2}{2\sqrt{10}} \frac{(1.59\,Y)^{5/2}}{\sqrt{\rho_p}} \left(\frac{1}{E^*}\right)^2`
    (the speed at which the Hertz peak pressure reaches 1.59 Y)."""
    if plate.yield_strength is None:
        raise ValueError("plate.yield_strength=None: Bitter's elastic-limit speed needs the plate yield strength (Pa)")
    compliance = 1.0 / effective_modulus(ball, plate)
    return BITTER_FACTOR * (BITTER_YIELD_FACTOR * plate.yield_strength) ** 2.5 / math.sqrt(ball.density) * compliance**2


def plastic_work_of(impact: ImpactResult, plate_work: float | None = None) -> float:
    """The plastic work (J) of an impact: the plate's own (``plate_work``, the FE plate's dissipation) if given,
    else the normal work dissipated by the impact's normal law, ½ m v_n² (1 − e_n²) (0 while elastic)."""
    return max(float(impact.normal_work if plate_work is None else plate_work), 0.0)


def deformation_of(constants: Constants, impact: ImpactResult, plate_work: float | None, law: str) -> float:
    """The deformation wear (m³) of one impact by the wear ``law`` (by name, for the messages) of which it is part:
    its plastic work (:func:`plastic_work_of`) over ``deformation_factor``."""
    (epsilon,) = need(constants, law, "deformation_factor")
    if plate_work is None and impact.normal_model == "hertz":
        raise ValueError(
            f"wear.law={law!r} needs the impact's plastic work: impact.normal_model='hertz' is "
            "elastic (no plastic work); use 'thornton' or the FE plate (fem.coupling)"
        )
    return float(deformation_volume(plastic_work_of(impact, plate_work), epsilon))


def _volumes(
    constants: Constants, impact: ImpactResult, *, local: float | None, plate_work: float | None
) -> dict[str, float]:
    """The deformation wear of one impact."""
    return {"deformation": deformation_of(constants, impact, plate_work, "deformation")}


LAW = Law(
    name="deformation",
    description="Bitter (1963) deformation wear: the impact's plastic work / epsilon",
    volumes=_volumes,
    constants=("deformation_factor",),
    scale="deformation_factor",
    scale_power=-1.0,
    log_constants=("deformation_factor",),
    uses_work=True,
)
