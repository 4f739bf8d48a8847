r"""Wear laws of one impact, side by side: the worn volume per impact (m³) by name (SI units; angles in degrees
from the plate normal, θ; the erosion literature's α from the surface is 90° − θ).

- ``"local"``: errata Eq. 15, dw/dt = K p^α v^β over the moving contact patch (:class:`wear.law.WearLaw`;
  Archard's law is α = β = 1). Its volume is :func:`local_volume`.
- ``"finnie"``: Finnie's (1960) micro-cutting volume of a rigid particle of mass m at speed V (Wear 3: 87–103),

  .. math:: W = \frac{c\,m V^2}{p\,\psi K}\left(\sin 2\alpha - \frac{6}{K}\sin^2\alpha\right), \ \tan\alpha \le
            \frac{K}{6}; \qquad W = \frac{c\,m V^2}{p\,\psi K}\,\frac{K\cos^2\alpha}{6}, \ \tan\alpha > \frac{K}{6}

  (p the plastic flow pressure ≈ the hardness, K the ratio of vertical to horizontal force on the particle ≈ 2, ψ
  the ratio of the depth of contact to the depth of cut ≈ 2, c the fraction of particles cutting ideally); its
  maximum is at tan 2α = K/3 (16.8° from the surface for K = 2) and it is zero at normal incidence.
- ``"deformation"``: Bitter's (1963) deformation wear, volume = plastic work / ε (Wear 6: 5–21), the plastic work
  taken from the impact itself: the FE plate's plastic dissipation ∫ σ_y dᾱ dV when the plate is the FE, else the
  normal work ½ m v_n² (1 − e_n²) dissipated by the normal law in use (zero while elastic: below Thornton's yield
  speed, close to Bitter's elastic-limit speed :func:`bitter_threshold_velocity`).
- ``"combined"``: a cutting law (``"local"`` or ``"finnie"``) plus ``"deformation"``, each share reported.
- ``"oka"``: Oka, Okamura & Yoshida (2005), "Practical estimation of erosion damage caused by solid particle
  impact, Part 1: Effects of impact parameters on a predictive equation", Wear 259: 95–101, and Oka & Yoshida
  (2005), "Part 2: Mechanical properties of materials directly associated with erosion damage", Wear 259: 102–109:
  the erosion ratio (kg of plate per kg of particles)

  .. math:: E = E_{90}\left(\frac{V}{V'}\right)^{k_2}\left(\frac{D}{D'}\right)^{k_3} (\sin\alpha)^{n_1}
            \left(1 + H_v(1 - \sin\alpha)\right)^{n_2}, \quad n_1 = 0.71 H_v^{0.14},\ n_2 = 2.4 H_v^{-0.94},\
            k_2 = 2.3 H_v^{0.038}

  (H_v the plate's Vickers hardness in GPa, V' = 104 m/s, D' = 326 µm, k_3 = 0.19; the exponents of silica sand),
  with E_90, the ratio at normal incidence at V' and D', from Part 2's volume correlation for silica sand
  (:func:`oka_e90`) unless given.
- ``"dnv"``: DNV-RP-O501 (2015), E = K U^n F(α), F(α) = 0.6 (sin α + 7.2 (sin α − sin²α))^0.6 (1 − e^{−20α})
  (α in rad from the surface; steel: K = 2e-9 (kg/kg)(m/s)^−n, n = 2.6); F is largest, 0.998, at α = 34.71°.

The correlations give a mass ratio; the volume per impact is E m_p / ρ_plate.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from contact import ImpactResult, Material, effective_modulus
from contact.theory import sphere_mass
from wear.integrate import WearMap, integrate_wear, surface_grid, wear_map
from wear.law import WearLaw
from wear.pressure import PressureHistory
from wear.slip import SlidingSpeed

__all__ = [
    "CLOSED_FORM_LAWS",
    "closed_form_volume",
    "LAWS",
    "LAW_CONSTANTS",
    "CUTTING_LAWS",
    "ImpactWear",
    "bitter_threshold_velocity",
    "deformation_volume",
    "dnv_angle_function",
    "dnv_erosion_ratio",
    "finnie_peak_angle",
    "finnie_volume",
    "flow_pressure_of",
    "impact_wear",
    "local_volume",
    "oka_constants",
    "oka_e90",
    "oka_exponents",
    "pressed_area",
    "oka_erosion_ratio",
    "plastic_work_of",
    "wear_of_impact",
]

#: The wear laws by name, with what each computes.
LAWS = {
    "local": "Eq. 15, dw/dt = K p^alpha v^beta over the moving patch",
    "finnie": "Finnie (1960) micro-cutting from the particle's kinematics",
    "deformation": "Bitter (1963) deformation wear: the impact's plastic work / epsilon",
    "combined": "a cutting law (local or finnie) + deformation",
    "oka": "Oka et al. (2005) erosion ratio correlation",
    "dnv": "DNV-RP-O501 (2015) erosion ratio correlation",
}
CUTTING_LAWS = ("local", "finnie")
#: The laws whose volume is a formula of the particle's mass, speed and angle and the plate's properties: they need
#: no simulated impact (:func:`closed_form_volume`).
CLOSED_FORM_LAWS = ("finnie", "oka", "dnv")
#: The constants of each law (keys of the case's ``[wear]`` table; Finnie's and Oka's also read the plate's hardness;
#: ``combined`` has those of its cutting law and of ``deformation``).
LAW_CONSTANTS = {
    "local": ("K", "alpha", "beta"),
    "finnie": ("cutting_fraction", "force_ratio", "depth_ratio"),
    "deformation": ("deformation_factor",),
    "oka": ("oka_e90", "oka_k2"),
    "dnv": ("dnv_K", "dnv_n"),
}

#: Oka et al. (2005): reference speed (m/s) and particle diameter (m); exponents of silica sand.
OKA_SPEED, OKA_DIAMETER = 104.0, 326e-6
OKA_N1 = (0.71, 0.14)
OKA_N2 = (2.4, -0.94)
OKA_K2 = (2.3, 0.038)
#: Oka & Yoshida (2005, Part 2): the volume eroded at normal incidence per mass of silica sand at V' and D',
#: 65 H_v^−0.12 mm³/kg (H_v in GPa), as (m³/kg, exponent).
OKA_E90 = (65e-9, -0.12)
#: Bitter's (1963) constant of the elastic-limit speed and his pressure factor 1.59 (of Y).
BITTER_FACTOR = math.pi**2 / (2.0 * math.sqrt(10.0))
BITTER_YIELD_FACTOR = 1.59


def _from_surface(angle) -> np.ndarray:
    """Impact angle α (rad) from the surface, from θ (deg) from the normal."""
    return np.radians(90.0 - np.asarray(angle, dtype=float))


def finnie_volume(
    mass,
    speed,
    angle,
    flow_pressure: float,
    force_ratio: float = 2.0,
    depth_ratio: float = 2.0,
    cutting_fraction: float = 0.5,
) -> np.ndarray:
    """Finnie's (1960) cutting volume (m³) of particles of ``mass`` (kg) at ``speed`` (m/s) and ``angle`` (deg from
    the normal) on a plate of plastic ``flow_pressure`` (Pa); see the module docstring.

    At the peak (16.85° from the surface), 0.5 · 1e-6 kg · (10 m/s)² / (1e9 Pa · 2 · 2) · (sin 33.69° − 3 sin² 16.85°):

    >>> f"{float(finnie_volume(1e-6, 10.0, 90.0 - finnie_peak_angle(2.0), 1e9)):.4e}"
    '3.7847e-15'
    """
    a = _from_surface(angle)
    k = force_ratio
    kinetic = np.asarray(mass, float) * np.asarray(speed, float) ** 2
    scale = cutting_fraction * kinetic / (flow_pressure * depth_ratio * k)
    shallow = np.sin(2.0 * a) - 6.0 / k * np.sin(a) ** 2
    steep = k * np.cos(a) ** 2 / 6.0
    return scale * np.where(np.tan(a) <= k / 6.0, shallow, steep)


def finnie_peak_angle(force_ratio: float = 2.0) -> float:
    """Angle (deg, from the surface) of Finnie's maximum: tan 2α = K/3 (16.85° for K = 2)."""
    return math.degrees(0.5 * math.atan(force_ratio / 3.0))


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
    s = np.sin(_from_surface(angle))
    g = s**n1 * (1.0 + hardness / 1e9 * (1.0 - s)) ** n2
    k2 = k2_oka if k2 is None else k2
    return e90 * (np.asarray(speed, float) / OKA_SPEED) ** k2 * (diameter / OKA_DIAMETER) ** k3 * g


def dnv_angle_function(angle) -> np.ndarray:
    """DNV-RP-O501's F(α) of ductile materials at ``angle`` (deg from the normal): 0.6 at normal incidence, 0.998 at
    its peak (α = 34.71° from the surface)."""
    a = _from_surface(angle)
    return 0.6 * (np.sin(a) + 7.2 * (np.sin(a) - np.sin(a) ** 2)) ** 0.6 * (1.0 - np.exp(-20.0 * a))


def dnv_erosion_ratio(speed, angle, K: float = 2e-9, n: float = 2.6) -> np.ndarray:
    """DNV-RP-O501 erosion ratio (kg/kg) E = K U^n F(α) at ``speed`` U (m/s) and ``angle`` (deg from the normal)."""
    return K * np.asarray(speed, float) ** n * dnv_angle_function(angle)


def pressed_area(pressure: PressureHistory, alpha: float) -> np.ndarray:
    """∫ p^α dA = 2πa² ∫₀¹ p(s)^α s ds (Pa^α m²) at each sample of the pressure table (trapezoidal rule in s)."""
    s = pressure.s
    return 2.0 * math.pi * pressure.extent**2 * np.trapezoid(pressure.pressure**alpha * s, s, axis=1)


def local_volume(pressure: PressureHistory, speed: SlidingSpeed, law: WearLaw, area: np.ndarray | None = None) -> float:
    r"""Worn volume (m³) of equation 15 over a whole impact, without the surface grid:
    :math:`V = K \int v^\beta \int p^\alpha\,dA\,dt` (:func:`pressed_area`, given as ``area`` if already known for
    this α), the time integral by the trapezoidal rule (the sliding speed interpolated to the pressure's times). It is
    the volume of :func:`wear.integrate_wear`'s map without its spatial discretisation."""
    if area is None:
        area = pressed_area(pressure, law.alpha)
    v = np.interp(pressure.time, speed.time, speed.speed)
    rate = v**law.beta * area if law.beta > 0.0 else area
    return float(law.K * np.trapezoid(rate, pressure.time))


def plastic_work_of(impact: ImpactResult, plate_work: float | None = None) -> float:
    """The plastic work (J) of an impact: the plate's own (``plate_work``, the FE plate's dissipation) if given,
    else the normal work dissipated by the impact's normal law, ½ m v_n² (1 − e_n²) (0 while elastic)."""
    return max(float(impact.normal_work if plate_work is None else plate_work), 0.0)


@dataclass(frozen=True)
class ImpactWear:
    """The worn volume of one impact by mechanism: ``parts`` (name → m³: ``cutting`` and ``deformation``, or the
    correlation's name), ``law``; :attr:`volume_m3` their sum, :meth:`share` each one's fraction."""

    law: str
    parts: dict[str, float] = field(default_factory=dict)

    @property
    def volume_m3(self) -> float:
        return float(sum(self.parts.values()))

    def share(self, part: str) -> float:
        """Fraction of the volume worn by ``part`` (0 when nothing is worn)."""
        total = self.volume_m3
        return self.parts.get(part, 0.0) / total if total > 0.0 else 0.0


def _need(constants: Mapping[str, float | str | None], law: str, *names: str) -> list[float]:
    values = []
    for name in names:
        value = constants.get(name)
        if value is None:
            raise ValueError(f"wear.{name}=None: the {law} law needs it (see impactwear run --print-default)")
        values.append(value)
    return values


def oka_constants(constants: Mapping[str, float | str | None], plate: Material) -> tuple[float, float]:
    """Oka's (E90 kg/kg, k2) of the ``constants`` (``oka_e90``, ``oka_k2``), each absent one from Oka et al.'s
    formulas at the plate's hardness (:func:`flow_pressure_of`): :func:`oka_e90` (with the plate's density) and
    2.3 H_v^0.038 (:func:`oka_exponents`)."""
    e90, k2 = constants.get("oka_e90"), constants.get("oka_k2")
    if e90 is None or k2 is None:
        hardness = flow_pressure_of(constants, plate)
        e90 = oka_e90(hardness, plate.density) if e90 is None else e90
        k2 = oka_exponents(hardness)[2] if k2 is None else k2
    return float(e90), float(k2)


def flow_pressure_of(constants: Mapping[str, float | str | None], plate: Material) -> float:
    """The plate's plastic flow pressure (Pa): ``hardness`` if given, else 3 × its yield strength (the indentation
    hardness of a rigid–perfectly plastic metal, Tabor 1951)."""
    hardness = constants.get("hardness")
    if hardness is not None:
        return float(hardness)
    if plate.yield_strength is None:
        raise ValueError("plate.hardness=None: give the plate's hardness (Pa), or a yield strength (3 Y is used)")
    return 3.0 * plate.yield_strength


def impact_wear(
    law: str,
    constants: Mapping[str, float | str | None],
    impact: ImpactResult,
    *,
    local: float | None = None,
    plate_work: float | None = None,
) -> ImpactWear:
    """The worn volume of ``impact`` by the wear ``law`` (one of :data:`LAWS`) with ``constants`` (the ``[wear]``
    table's keys plus the plate's ``hardness``). ``local``: the Eq. 15 volume (m³, :func:`local_volume`) where the law
    uses it; ``plate_work``: the FE plate's plastic dissipation (J), if the plate is the FE."""
    if law not in LAWS:
        raise ValueError(f"wear.law={law!r} is not a valid choice: must be one of {', '.join(map(repr, LAWS))}")
    speed, angle = impact.speed, impact.angle

    def cutting(name: str) -> float:
        if name == "local":
            if local is None:
                raise ValueError("the local law needs the impact's Eq. 15 volume (wear.local_volume)")
            return local
        ball, plate = impact.ball, impact.plate
        return float(closed_form_volume("finnie", constants, impact.radius, ball.density, plate, speed, angle))

    def deformation() -> float:
        (epsilon,) = _need(constants, law, "deformation_factor")
        if plate_work is None and impact.normal_model == "hertz":
            raise ValueError(
                f"wear.law={law!r} needs the impact's plastic work: impact.normal_model='hertz' is "
                "elastic (no plastic work); use 'thornton' or the FE plate (fem.coupling)"
            )
        return float(deformation_volume(plastic_work_of(impact, plate_work), epsilon))

    if law in CUTTING_LAWS:
        return ImpactWear(law, {"cutting": cutting(law)})
    if law == "deformation":
        return ImpactWear(law, {"deformation": deformation()})
    if law == "combined":
        return ImpactWear(law, {"cutting": cutting(str(constants.get("cutting"))), "deformation": deformation()})
    volume = closed_form_volume(law, constants, impact.radius, impact.ball.density, impact.plate, speed, angle)
    return ImpactWear(law, {law: float(volume)})


def closed_form_volume(
    law: str,
    constants: Mapping[str, float | str | None],
    radius: float,
    ball_density: float,
    plate: Material,
    speed,
    angle,
) -> np.ndarray:
    """The worn volume (m³) of one impact of a ball of ``radius`` (m) and ``ball_density`` (kg/m³) on ``plate`` at
    each ``speed`` (m/s) and ``angle`` (deg from the normal) by a law of :data:`CLOSED_FORM_LAWS` with ``constants``
    (as :func:`impact_wear`): a formula of the particle's kinematics alone, so that no impact need be simulated."""
    mass = sphere_mass(radius, ball_density)
    if law == "finnie":
        c, k, psi = _need(constants, "finnie", "cutting_fraction", "force_ratio", "depth_ratio")
        return finnie_volume(mass, speed, angle, flow_pressure_of(constants, plate), k, psi, c)
    if law == "oka":
        e90, k2 = oka_constants(constants, plate)
        ratio = oka_erosion_ratio(speed, angle, flow_pressure_of(constants, plate), 2.0 * radius, e90, k2)
    elif law == "dnv":
        K, n = _need(constants, law, "dnv_K", "dnv_n")
        ratio = dnv_erosion_ratio(speed, angle, K, n)
    else:
        raise ValueError(f"wear.law={law!r} has no closed form: one of {', '.join(map(repr, CLOSED_FORM_LAWS))} has")
    return ratio * mass / plate.density


#: The unit-K local laws whose maps give each mechanism's footprint: cutting follows the sliding (α = β = 1: where
#: the friction works), the rest where the plate is pressed (α = 1, β = 0: the time-integrated pressure).
_SHAPES = {"cutting": WearLaw(K=1.0, alpha=1.0, beta=1.0), "pressed": WearLaw(K=1.0, alpha=1.0, beta=0.0)}


def wear_of_impact(
    law: str,
    constants: Mapping[str, float | str | None],
    local_law: WearLaw,
    impact: ImpactResult,
    pressure: PressureHistory,
    speed: SlidingSpeed,
    *,
    density: float,
    points_across: int,
    plate_work: float | None = None,
) -> tuple[WearMap, ImpactWear]:
    """The depth map (m) and the volumes of ``impact`` worn by ``law`` (:func:`impact_wear`). The local law's map is
    Eq. 15 integrated over the moving patch (:func:`wear.integrate_wear` with ``local_law``); every other
    mechanism's volume is laid out like a unit local law: cutting along the sliding (α = β = 1), deformation and the
    correlations where the plate is pressed (α = 1, β = 0; the pressure shape if nothing slides)."""
    cutting_law = law if law in CUTTING_LAWS else constants.get("cutting") if law == "combined" else None
    local_map = None
    if cutting_law == "local":
        local_map = integrate_wear(pressure, speed, local_law, density=density, points_across=points_across)
    wear = impact_wear(
        law, constants, impact, local=None if local_map is None else local_map.volume_m3, plate_work=plate_work
    )
    if law == "local":
        return local_map, wear
    if local_map is not None:
        grid = local_map
    else:
        x, y = surface_grid(pressure, points_across)
        grid = wear_map(x, y, np.zeros((y.size, x.size)), density)
    depth = np.zeros_like(grid.depth)
    for part, volume in wear.parts.items():
        if part == "cutting" and local_map is not None:
            depth += local_map.depth
            continue
        if volume <= 0.0:
            continue
        shape = integrate_wear(
            pressure, speed, _SHAPES["cutting" if part == "cutting" else "pressed"], density=density, on=grid
        )
        if shape.volume_m3 <= 0.0:  # no sliding: the pressure shape
            shape = integrate_wear(pressure, speed, _SHAPES["pressed"], density=density, on=grid)
        depth += volume / shape.volume_m3 * shape.depth
    return wear_map(grid.x, grid.y, depth, density), wear
