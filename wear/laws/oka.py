r"""Oka, Okamura & Yoshida (2005), "Practical estimation of erosion damage caused by solid particle impact, Part 1:
Effects of impact parameters on a predictive equation", Wear 259: 95–101, and Oka & Yoshida (2005), "Part 2:
Mechanical properties of materials directly associated with erosion damage", Wear 259: 102–109: the erosion ratio
(kg of plate per kg of particles)

.. math:: E = E_{90}\left(\frac{V}{V'}\right)^{k_2}\left(\frac{D}{D'}\right)^{k_3} (\sin\alpha)^{n_1}
          \left(1 + H_v(1 - \sin\alpha)\right)^{n_2}, \quad n_1 = 0.71 H_v^{0.14},\ n_2 = 2.4 H_v^{-0.94},\
          k_2 = 2.3 H_v^{0.038}

(H_v the plate's Vickers hardness in GPa, V' = 104 m/s, D' = 326 µm, k_3 = 0.19; the exponents of silica sand; α
from the surface), with E_90, the ratio at normal incidence at V' and D', from Part 2's volume correlation for silica
sand (:func:`oka_e90`) unless given. The volume per impact is E m_p / ρ_plate. SI units; angles θ in degrees from the
plate normal, α = 90° − θ.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact import ImpactResult, Material
from contact.theory import sphere_mass
from wear.laws.declaration import Constants, Law, angle_from_surface, flow_pressure_of
from wear.laws.records import particle_mass, record_arrays

__all__ = ["LAW", "OkaLaw", "oka_constants", "oka_e90", "oka_erosion_ratio", "oka_exponents"]

DESCRIPTION = "Oka et al. (2005) erosion ratio correlation"

#: Oka et al. (2005): reference speed (m/s) and particle diameter (m); exponents of silica sand.
OKA_SPEED, OKA_DIAMETER = 104.0, 326e-6
OKA_N1 = (0.71, 0.14)
OKA_N2 = (2.4, -0.94)
OKA_K2 = (2.3, 0.038)
#: Oka & Yoshida (2005, Part 2): the volume eroded at normal incidence per mass of silica sand at V' and D',
#: 65 H_v^−0.12 mm³/kg (H_v in GPa), as (m³/kg, exponent).
OKA_E90 = (65e-9, -0.12)


def oka_exponents(hardness: float) -> tuple[float, float, float]:
    """Oka et al. (2005) exponents (n1, n2, k2) of silica sand on a plate of Vickers ``hardness`` (Pa)."""
    hv = hardness / 1e9
    return OKA_N1[0] * hv ** OKA_N1[1], OKA_N2[0] * hv ** OKA_N2[1], OKA_K2[0] * hv ** OKA_K2[1]


def oka_e90(hardness: float, density: float) -> float:
    r"""Oka & Yoshida's (2005, Part 2) erosion ratio (kg/kg) at normal incidence, 104 m/s and 326 µm, of silica sand
    on a plate of Vickers ``hardness`` H (Pa) and ``density`` ρ (kg/m³): their volume per particle mass,
    65 H_v^−0.12 mm³/kg with H_v = H / 10⁹ Pa in GPa, times ρ (1 mm³ = 10⁻⁹ m³):
    :math:`E_{90} = 65\times10^{-9}\,(H/10^9)^{-0.12}\,\rho`.

    A carbon steel of H_v 1.7 GPa, 7850 kg/m³: 65e-9 · 1.7^−0.12 · 7850 = 4.788e-4.

    >>> f"{oka_e90(1.7e9, 7850.0):.4e}"
    '4.7877e-04'
    """
    return OKA_E90[0] * (hardness / 1e9) ** OKA_E90[1] * density


def oka_erosion_ratio(
    speed, angle, hardness: float, diameter: float, e90: float, k2: float | None = None, k3: float = 0.19
) -> np.ndarray:
    """Oka et al. (2005) erosion ratio (kg/kg) at ``speed`` (m/s) and ``angle`` (deg from the normal): ``hardness``
    (Pa, Vickers; H_v = hardness / 1e9 in GPa in the formulas), particle ``diameter`` (m), ``e90`` the ratio (kg/kg)
    at normal incidence at 104 m/s and 326 µm (:func:`oka_e90`); ``k2`` (default 2.3 H_v^0.038) and ``k3`` the speed
    and size exponents."""
    n1, n2, k2_oka = oka_exponents(hardness)
    s = np.sin(angle_from_surface(angle))
    g = s**n1 * (1.0 + hardness / 1e9 * (1.0 - s)) ** n2
    k2 = k2_oka if k2 is None else k2
    return e90 * (np.asarray(speed, float) / OKA_SPEED) ** k2 * (diameter / OKA_DIAMETER) ** k3 * g


def oka_constants(constants: Constants, plate: Material) -> tuple[float, float]:
    """Oka's (E90 kg/kg, k2) of the ``constants`` (``oka_e90``, ``oka_k2``), each absent one from Oka et al.'s
    formulas at the plate's hardness (:func:`wear.laws.declaration.flow_pressure_of`): :func:`oka_e90` (with the
    plate's density) and 2.3 H_v^0.038 (:func:`oka_exponents`)."""
    e90, k2 = constants.get("oka_e90"), constants.get("oka_k2")
    if e90 is None or k2 is None:
        hardness = flow_pressure_of(constants, plate)
        e90 = oka_e90(hardness, plate.density) if e90 is None else e90
        k2 = oka_exponents(hardness)[2] if k2 is None else k2
    return float(e90), float(k2)


def _closed_form(constants: Constants, radius: float, ball_density: float, plate: Material, speed, angle) -> np.ndarray:
    """The eroded volume (m³) of one impact of a ball of ``radius`` (m) and ``ball_density`` (kg/m³): E m / ρ_plate."""
    e90, k2 = oka_constants(constants, plate)
    ratio = oka_erosion_ratio(speed, angle, flow_pressure_of(constants, plate), 2.0 * radius, e90, k2)
    return ratio * sphere_mass(radius, ball_density) / plate.density


def _volumes(
    constants: Constants, impact: ImpactResult, *, local: float | None, plate_work: float | None
) -> dict[str, float]:
    """The eroded volume of one impact, from its speed and angle."""
    volume = _closed_form(constants, impact.radius, impact.ball.density, impact.plate, impact.speed, impact.angle)
    return {"oka": float(volume)}


@dataclass(frozen=True)
class OkaLaw:
    """Oka et al.'s (2005) erosion ratio per record of a wall (:func:`oka_erosion_ratio`): the plate's Vickers
    ``hardness`` (Pa) and ``plate_density`` (kg/m³), ``e90`` (kg/kg), the speed exponent ``k2``."""

    hardness: float
    plate_density: float
    e90: float
    k2: float
    name: str = "oka"
    description: str = ""

    def __post_init__(self) -> None:
        if not self.description:
            constants = f"Hv = {self.hardness:g} Pa, E90 = {self.e90:g} kg/kg, k2 = {self.k2:g}, k3 = 0.19"
            object.__setattr__(self, "description", f"{DESCRIPTION}, per record: {constants}")

    def volume(self, angle_deg, speed_m_s, diameter_m, density_kg_m3, count) -> np.ndarray:
        """Eroded volume (m³) of each record: N m E(V, θ, d) / ρ_w (at each record's own diameter: not proportional
        to the mass, as E ∝ d^0.19)."""
        theta, speed, d, rho, n = record_arrays(angle_deg, speed_m_s, diameter_m, density_kg_m3, count)
        ratio = oka_erosion_ratio(speed, theta, self.hardness, d, self.e90, self.k2)
        return n * (particle_mass(d, rho) * ratio / self.plate_density)


def _per_record(constants: Constants, plate: Material) -> OkaLaw:
    """The law per record of a wall of ``plate``."""
    e90, k2 = oka_constants(constants, plate)
    return OkaLaw(flow_pressure_of(constants, plate), plate.density, e90, k2)


def _absent_values(constants: Constants, plate: Material) -> dict[str, float]:
    """E90 (kg/kg) and k2 where absent: :func:`oka_constants`."""
    return dict(zip(("oka_e90", "oka_k2"), oka_constants(constants, plate), strict=True))


LAW = Law(
    name="oka",
    description=DESCRIPTION,
    volumes=_volumes,
    constants=("oka_e90", "oka_k2"),
    scale="oka_e90",
    log_constants=("oka_e90",),
    closed_form=_closed_form,
    per_record=_per_record,
    absent_values=_absent_values,
    plate_keys=("rigid", "density", "hardness", "yield_strength", "name"),
)
