r"""DNV-RP-O501 (2015): the erosion ratio (kg/kg) E = K U^n F(α),

.. math:: F(\alpha) = 0.6\left(\sin\alpha + 7.2(\sin\alpha - \sin^2\alpha)\right)^{0.6}\left(1 - e^{-20\alpha}\right)

(α in rad from the surface; steel: K = 2e-9 (kg/kg)(m/s)^−n, n = 2.6); F is largest, 0.998, at α = 34.71°. The volume
per impact is E m_p / ρ_plate. SI units; angles θ in degrees from the plate normal, α = 90° − θ.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact import ImpactResult, Material
from contact.theory import sphere_mass
from wear.laws.declaration import Constants, Law, angle_from_surface, need
from wear.laws.records import particle_mass, record_arrays

__all__ = ["LAW", "DnvLaw", "dnv_angle_function", "dnv_erosion_ratio"]

DESCRIPTION = "DNV-RP-O501 (2015) erosion ratio correlation"


def dnv_angle_function(angle) -> np.ndarray:
    """DNV-RP-O501's F(α) of ductile materials at ``angle`` (deg from the normal): 0.6 at normal incidence, 0.998 at
    its peak (α = 34.71° from the surface)."""
    a = angle_from_surface(angle)
    return 0.6 * (np.sin(a) + 7.2 * (np.sin(a) - np.sin(a) ** 2)) ** 0.6 * (1.0 - np.exp(-20.0 * a))


def dnv_erosion_ratio(speed, angle, K: float = 2e-9, n: float = 2.6) -> np.ndarray:
    """DNV-RP-O501 erosion ratio (kg/kg) E = K U^n F(α) at ``speed`` U (m/s) and ``angle`` (deg from the normal)."""
    return K * np.asarray(speed, float) ** n * dnv_angle_function(angle)


def _closed_form(constants: Constants, radius: float, ball_density: float, plate: Material, speed, angle) -> np.ndarray:
    """The eroded volume (m³) of one impact of a ball of ``radius`` (m) and ``ball_density`` (kg/m³): E m / ρ_plate."""
    K, n = need(constants, "dnv", "dnv_K", "dnv_n")
    return dnv_erosion_ratio(speed, angle, K, n) * sphere_mass(radius, ball_density) / plate.density


def _volumes(
    constants: Constants, impact: ImpactResult, *, local: float | None, plate_work: float | None
) -> dict[str, float]:
    """The eroded volume of one impact, from its speed and angle."""
    volume = _closed_form(constants, impact.radius, impact.ball.density, impact.plate, impact.speed, impact.angle)
    return {"dnv": float(volume)}


@dataclass(frozen=True)
class DnvLaw:
    """DNV-RP-O501's erosion ratio per record of a wall (:func:`dnv_erosion_ratio`): ``K`` ((kg/kg)(m/s)^−n),
    ``n``, the plate's ``plate_density`` (kg/m³)."""

    K: float
    n: float
    plate_density: float
    name: str = "dnv"
    description: str = ""

    def __post_init__(self) -> None:
        if not self.description:
            constants = f"K = {self.K:g} (kg/kg)(m/s)^-n, n = {self.n:g}"
            object.__setattr__(self, "description", f"{DESCRIPTION}, per record: {constants}")

    def volume(self, angle_deg, speed_m_s, diameter_m, density_kg_m3, count) -> np.ndarray:
        """Eroded volume (m³) of each record: N m K V^n F(α) / ρ_w."""
        theta, speed, d, rho, n = record_arrays(angle_deg, speed_m_s, diameter_m, density_kg_m3, count)
        return n * (particle_mass(d, rho) * dnv_erosion_ratio(speed, theta, self.K, self.n) / self.plate_density)


def _per_record(constants: Constants, plate: Material) -> DnvLaw:
    """The law per record of a wall of ``plate``."""
    return DnvLaw(constants["dnv_K"], constants["dnv_n"], plate.density)


LAW = Law(
    name="dnv",
    description=DESCRIPTION,
    volumes=_volumes,
    constants=("dnv_K", "dnv_n"),
    scale="dnv_K",
    log_constants=("dnv_K",),
    closed_form=_closed_form,
    per_record=_per_record,
    plate_keys=("rigid", "density", "name"),
)
