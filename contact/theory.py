r"""Closed-form contact mechanics of a sphere on a flat (SI units throughout).

Hertz (errata Eqs. 4, 10-11, 16-17), first yield (Eq. 18, with the paper's C = 1.6 and the exact
C(ν)), Thornton's (1997) yield velocity and elastic-perfectly plastic restitution, and the
Mesarovic & Johnson (2000) elastic unloading from a flattened pressure (Eq. 19).

Symbols: R ball radius (m), E* effective modulus (Pa, see :func:`contact.effective_modulus`),
δ overlap (m), F normal force (N), a contact radius (m), p₀ peak pressure (Pa), Y yield
strength (Pa), ν Poisson's ratio of the yielding body. All functions accept numpy arrays where
that makes sense.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from scipy.optimize import minimize_scalar
from scipy.special import gamma

from contact.checks import check_number
from contact.materials import Material, effective_modulus

__all__ = [
    "PAPER_YIELD_COEFFICIENT",
    "HERTZ_CONTACT_TIME_FACTOR",
    "hertz_force",
    "hertz_overlap",
    "hertz_contact_radius",
    "hertz_contact_radius_from_force",
    "hertz_peak_pressure",
    "HertzImpact",
    "hertz_impact",
    "yield_coefficient",
    "yield_depth_ratio",
    "green_yield_coefficient",
    "FirstYield",
    "first_yield",
    "default_limiting_pressure",
    "yield_velocity",
    "thornton_restitution",
    "hertz_pressure",
    "hertz_surface_displacement",
    "mesarovic_johnson_pressure",
    "mesarovic_johnson_force",
    "mesarovic_johnson_overlap",
    "sphere_mass",
    "speed_components",
]

#: The paper's p_max/Y at first yield (its Eq. 18 text: "P_max reaches 1.6 S_y").
PAPER_YIELD_COEFFICIENT = 1.6

#: t_c = 2.9433 δ_max / v_n; 4Γ(2/5)√π / (5Γ(9/10)) (errata Eqs. 10-11).
HERTZ_CONTACT_TIME_FACTOR = 4.0 * gamma(0.4) * math.sqrt(math.pi) / (5.0 * gamma(0.9))


def speed_components(speed, angle):
    r"""Normal and tangential components (m/s) of an impact at ``speed`` (m/s) and ``angle`` θ (deg from the plate
    normal): V_n = V cos θ towards the plate, V_t = V sin θ along it in the plane of incidence. Floats for scalars,
    arrays (broadcast) for arrays.

    >>> speed_components(2.0, 60.0)
    (1.0000000000000002, 1.7320508075688772)
    """
    theta = np.radians(angle)
    normal, tangential = speed * np.cos(theta), speed * np.sin(theta)
    if np.ndim(normal) == 0:
        return float(normal), float(tangential)
    return normal, tangential


def sphere_mass(radius: float, density: float) -> float:
    """Mass (kg) of a solid sphere of ``radius`` (m) and ``density`` (kg/m³)."""
    return 4.0 / 3.0 * math.pi * radius**3 * density


def hertz_force(overlap, radius, effective_modulus):
    r"""Hertz normal force (N): :math:`F = \tfrac43 E^* \sqrt{R}\,\delta^{3/2}` (errata equation 4).

    Negative overlaps (no contact) give zero.

    >>> round(float(hertz_force(1e-6, radius=0.01, effective_modulus=1e11)), 6)  # 4/3 · 1e11 · 0.1 · 1e-9 N
    13.333333
    """
    d = np.maximum(np.asarray(overlap, dtype=float), 0.0)
    return 4.0 / 3.0 * effective_modulus * np.sqrt(radius) * d**1.5


def hertz_overlap(force, radius, effective_modulus):
    r"""Overlap (m) at a Hertz force F (N): :math:`\delta = (3F / (4E^*\sqrt R))^{2/3}`."""
    f = np.maximum(np.asarray(force, dtype=float), 0.0)
    return (3.0 * f / (4.0 * effective_modulus * math.sqrt(radius))) ** (2.0 / 3.0)


def hertz_contact_radius(overlap, radius):
    r"""Contact radius (m) at an overlap δ (m): :math:`a = \sqrt{R\delta}`."""
    return np.sqrt(radius * np.maximum(np.asarray(overlap, dtype=float), 0.0))


def hertz_contact_radius_from_force(force, radius, effective_modulus):
    r"""Contact radius (m) at force F (N): :math:`a = (3FR / (4E^*))^{1/3}`."""
    f = np.maximum(np.asarray(force, dtype=float), 0.0)
    return np.cbrt(3.0 * f * radius / (4.0 * effective_modulus))


def hertz_peak_pressure(force, radius, effective_modulus):
    r"""Hertz peak pressure (Pa), errata equation 17: :math:`p_0 = (6FE^{*2}/(\pi^3R^2))^{1/3} = 3F/(2\pi a^2)`."""
    f = np.maximum(np.asarray(force, dtype=float), 0.0)
    return np.cbrt(6.0 * f * effective_modulus**2 / (math.pi**3 * radius**2))


@dataclass(frozen=True)
class HertzImpact:
    """Closed-form elastic (Hertz) impact of a sphere on a flat, no damping.

    Attributes: ``max_overlap`` (m), ``max_force`` (N), ``contact_time`` (s),
    ``max_contact_radius`` (m), ``max_peak_pressure`` (Pa).
    """

    max_overlap: float
    max_force: float
    contact_time: float
    max_contact_radius: float
    max_peak_pressure: float


def hertz_impact(mass: float, radius: float, effective_modulus: float, normal_speed: float) -> HertzImpact:
    r"""Hertz impact of a ball of ``mass`` (kg) and ``radius`` (m) at ``normal_speed`` (m/s).

    .. math::
        \delta_{max} = \left(\frac{15 m v_n^2}{16 E^* \sqrt R}\right)^{2/5},\quad
        t_c = 2.9433\,\frac{\delta_{max}}{v_n} \quad\text{(errata Eqs. 10-11)}
    """
    v = abs(float(normal_speed))
    if v == 0.0:
        return HertzImpact(0.0, 0.0, math.inf, 0.0, 0.0)
    dmax = (15.0 * mass * v**2 / (16.0 * effective_modulus * math.sqrt(radius))) ** 0.4
    fmax = float(hertz_force(dmax, radius, effective_modulus))
    return HertzImpact(
        max_overlap=dmax,
        max_force=fmax,
        contact_time=HERTZ_CONTACT_TIME_FACTOR * dmax / v,
        max_contact_radius=math.sqrt(radius * dmax),
        max_peak_pressure=float(hertz_peak_pressure(fmax, radius, effective_modulus)),
    )


def _axis_von_mises(depth_ratio: float, nu: float) -> float:
    """von Mises stress / p₀ on the axis of a Hertz contact at depth z = depth_ratio · a.

    Johnson (1985), Contact Mechanics, Eq. 3.45: σ_r = σ_θ, σ_z principal, so σ_vm = |σ_z − σ_r|.
    """
    z = depth_ratio
    sigma_r = -((1.0 + nu) * (1.0 - z * math.atan(1.0 / z)) - 0.5 / (1.0 + z * z))
    sigma_z = -1.0 / (1.0 + z * z)
    return abs(sigma_z - sigma_r)


@lru_cache(maxsize=256)
def _axis_yield_point(nu: float) -> tuple[float, float]:
    res = minimize_scalar(
        lambda z: -_axis_von_mises(z, nu), bounds=(1e-3, 3.0), method="bounded", options={"xatol": 1e-12}
    )
    return float(1.0 / _axis_von_mises(res.x, nu)), float(res.x)


def yield_coefficient(nu: float) -> float:
    """Exact C(ν) = p₀/Y at first yield of a Hertz contact (dimensionless).

    Computed by maximising the von Mises stress of the Hertz field on the axis (where it is
    largest for ν ≥ ~0.1): C(0.3) = 1.6128. The paper uses C = 1.6 (Eq. 18).
    """
    return _axis_yield_point(float(nu))[0]


def yield_depth_ratio(nu: float) -> float:
    """Depth of first yield below the surface divided by the contact radius, z/a (0.481 at ν = 0.3)."""
    return _axis_yield_point(float(nu))[1]


def green_yield_coefficient(nu):
    """Green's (2005) fit C(ν) = 1.30075 + 0.87825ν + 0.54373ν² (within 0.1% of the exact C)."""
    nu = np.asarray(nu, dtype=float)
    return 1.30075 + 0.87825 * nu + 0.54373 * nu**2


@dataclass(frozen=True)
class FirstYield:
    """First yield of a Hertz contact: ``force`` (N), ``overlap`` (m), ``contact_radius`` (m),
    ``peak_pressure`` (Pa), ``depth`` (m below the surface, on the axis), ``coefficient`` C."""

    force: float
    overlap: float
    contact_radius: float
    peak_pressure: float
    depth: float
    coefficient: float


def first_yield(
    radius: float, effective_modulus: float, yield_strength: float, nu: float, coefficient: float | None = None
) -> FirstYield:
    r"""Onset of yield in a Hertz contact, errata equation 18:

    .. math:: F_y = \frac{\pi^3 (C Y)^3 R^2}{6 E^{*2}}

    ``coefficient`` C defaults to the exact C(ν) of :func:`yield_coefficient`; pass
    :data:`PAPER_YIELD_COEFFICIENT` (1.6) for the paper's value. ``nu`` is the Poisson's ratio of
    the yielding body.

    >>> fy = first_yield(radius=0.01, effective_modulus=230.8e9, yield_strength=210e6, nu=0.3)
    >>> round(fy.coefficient, 3), round(fy.depth / fy.contact_radius, 2)  # Johnson (1985): 1.61 and 0.48
    (1.613, 0.48)
    """
    c = yield_coefficient(nu) if coefficient is None else float(coefficient)
    p0 = c * yield_strength
    force = math.pi**3 * p0**3 * radius**2 / (6.0 * effective_modulus**2)
    a = float(hertz_contact_radius_from_force(force, radius, effective_modulus))
    return FirstYield(
        force=force,
        overlap=a * a / radius,
        contact_radius=a,
        peak_pressure=p0,
        depth=yield_depth_ratio(nu) * a,
        coefficient=c,
    )


def default_limiting_pressure(ball: Material, plate: Material) -> float:
    """Default limiting contact pressure p_y = C(ν)·Y (Pa) of the body that yields first.

    The yielding body is the one with the lower C(ν)·Y among those with a ``yield_strength``.
    Raises ``ValueError`` if neither has one.
    """
    candidates = [yield_coefficient(m.nu) * m.yield_strength for m in (ball, plate) if m.yield_strength]
    if not candidates:
        raise ValueError(
            "yield_strength=None for both ball and plate: give one a yield strength (Pa) or pass limiting_pressure (Pa)"
        )
    return min(candidates)


def yield_velocity(radius: float, ball: Material, plate: Material, limiting_pressure: float | None = None) -> float:
    r"""Thornton's (1997) normal impact speed V_y (m/s) at which yield starts:

    .. math:: V_y = \sqrt{\frac{\pi^5}{30}\,\frac{R^3}{m}\,\frac{p_y^5}{E^{*4}}}
              = 1.56 \sqrt{p_y^5 / (E^{*4}\rho)}

    for a ball of ``radius`` (m) and mass m = 4/3 π R³ ρ_ball. ``limiting_pressure`` p_y (Pa)
    defaults to C(ν)·Y of the body that yields first.

    Examples
    --------
    A 5 mm steel ball (E = 210 GPa, ν = 0.3, Y = 1 GPa) on a rigid plate: E* = E/(1 − ν²), p_y = C(ν)·Y with
    C(0.3) = 1.613 (Johnson 1985, §6.2); the closed form above, evaluated by hand:

    >>> import math
    >>> from contact import Material
    >>> steel = Material(E=210e9, nu=0.3, density=7800.0, yield_strength=1e9)
    >>> v_y = yield_velocity(5e-3, steel, Material.rigid())
    >>> p_y, e_star = yield_coefficient(0.3) * 1e9, 210e9 / (1 - 0.3**2)
    >>> bool(abs(v_y / (1.56 * math.sqrt(p_y**5 / (e_star**4 * 7800.0))) - 1) < 1e-3)
    True
    """
    radius = check_number("radius", radius, low=0.0, low_open=True, high=10.0, units="m", what="ball radius")
    if limiting_pressure is None:
        p_y = default_limiting_pressure(ball, plate)
    else:
        p_y = check_number(
            "limiting_pressure", limiting_pressure, low=1e3, high=1e12, units="Pa", what="limiting pressure"
        )
    mass = sphere_mass(radius, ball.density)
    e_star = effective_modulus(ball, plate)
    return math.sqrt(math.pi**5 / 30.0 * radius**3 / mass * p_y**5 / e_star**4)


def thornton_restitution(speed_ratio):
    r"""Thornton's (1997) normal restitution of an elastic-perfectly plastic impact, V_i/V_y ≥ 1.

    .. math::
        e = \sqrt{\tfrac{6\sqrt3}{5}}\sqrt{1 - \tfrac16\left(\tfrac{V_y}{V_i}\right)^2}
            \left[\frac{V_y/V_i}{V_y/V_i + 2\sqrt{\tfrac65 - \tfrac15 (V_y/V_i)^2}}\right]^{1/4}

    Returns 1 for ratios ≤ 1 (elastic impact).

    Examples
    --------
    Elastic up to V_y; at V_i = 10 V_y (V_y/V_i = 0.1) the formula above by hand gives 0.659, and for V_i ≫ V_y it
    tends to (6√3/5)^½ (V_y/(2√1.2 V_i))^¼ = 1.185 (V_y/V_i)^¼ (Thornton 1997):

    >>> [round(float(e), 3) for e in thornton_restitution([0.5, 1.0, 10.0])]
    [1.0, 1.0, 0.659]
    >>> round(float(thornton_restitution(1e6) / (1.185 * 1e-6**0.25)), 2)
    1.0
    """
    x = np.asarray(speed_ratio, dtype=float)
    y = 1.0 / np.maximum(x, 1.0)
    e = (
        math.sqrt(6.0 * math.sqrt(3.0) / 5.0)
        * np.sqrt(1.0 - y * y / 6.0)
        * (y / (y + 2.0 * np.sqrt(1.2 - 0.2 * y * y))) ** 0.25
    )
    return np.where(x <= 1.0, 1.0, e)


def hertz_pressure(r, contact_radius, peak_pressure):
    r"""Hertz pressure profile (Pa), errata equation 16: :math:`p(r) = p_0\sqrt{1 - r^2/a^2}`, 0 for r ≥ a."""
    r = np.asarray(r, dtype=float)
    if contact_radius <= 0.0:
        return np.zeros_like(r)
    s = 1.0 - (r / contact_radius) ** 2
    return peak_pressure * np.sqrt(np.maximum(s, 0.0))


def hertz_surface_displacement(r, force: float, contact_radius: float, effective_modulus: float) -> np.ndarray:
    r"""Normal surface displacement (m, into the body) of a Hertz pressure carrying ``force`` (N) over
    ``contact_radius`` a (m) on a half-space of modulus E* (Pa) (Johnson 1985, equations 3.41a-b):

    .. math:: u_z = \frac{\pi p_0}{4aE^*}(2a^2 - r^2),\ r \le a; \quad
              u_z = \frac{p_0}{2aE^*}\left[(2a^2 - r^2)\arcsin\frac{a}{r} + a\sqrt{r^2 - a^2}\right],\ r > a
    """
    r = np.abs(np.asarray(r, float))
    if force <= 0.0 or contact_radius <= 0.0:
        return np.zeros_like(r)
    a = contact_radius
    p0 = 3.0 * force / (2.0 * math.pi * a * a)
    inside = math.pi * p0 / (4.0 * a * effective_modulus) * (2.0 * a * a - r**2)
    rs = np.maximum(r, a)
    outside = (
        p0 / (2.0 * a * effective_modulus) * ((2.0 * a * a - rs**2) * np.arcsin(a / rs) + a * np.sqrt(rs**2 - a * a))
    )
    return np.where(r <= a, inside, outside)


def mesarovic_johnson_pressure(r, contact_radius, unloading_radius, unloading_pressure):
    r"""Pressure (Pa) during elastic unloading from a uniform pressure p* over radius a*
    (Mesarovic & Johnson 2000; errata equation 19):

    .. math:: p(r) = \frac{2p^*}{\pi}\arctan\sqrt{\frac{a^2 - r^2}{a^{*2} - a^2}}, \quad r \le a \le a^*

    ``contact_radius`` a (m) is the current radius, ``unloading_radius`` a* (m) and
    ``unloading_pressure`` p* (Pa) those at the start of unloading. At a = a* the profile is the
    uniform p*.
    """
    r = np.asarray(r, dtype=float)
    a, a_star = float(contact_radius), float(unloading_radius)
    inside = r < a
    num = np.maximum(a * a - r * r, 0.0)
    den = a_star * a_star - a * a
    if den <= 0.0:
        return np.where(inside, unloading_pressure, 0.0)
    return np.where(inside, 2.0 * unloading_pressure / math.pi * np.arctan(np.sqrt(num / den)), 0.0)


def mesarovic_johnson_force(contact_radius, unloading_radius, unloading_pressure):
    r"""Force (N) of the Mesarovic-Johnson unloading profile:
    :math:`F = F^*\,\tfrac{2}{\pi}[\arcsin x - x\sqrt{1-x^2}]`, x = a/a*, F* = π a*² p*."""
    x = np.clip(np.asarray(contact_radius, dtype=float) / unloading_radius, 0.0, 1.0)
    f_star = math.pi * unloading_radius**2 * unloading_pressure
    return f_star * 2.0 / math.pi * (np.arcsin(x) - x * np.sqrt(1.0 - x * x))


def mesarovic_johnson_overlap(contact_radius, unloading_radius, unloading_pressure, max_overlap, effective_modulus):
    r"""Overlap (m) during Mesarovic-Johnson unloading:
    :math:`\delta = \delta^* - \tfrac{2p^*a^*}{E^*}\sqrt{1-x^2}`, x = a/a*."""
    x = np.clip(np.asarray(contact_radius, dtype=float) / unloading_radius, 0.0, 1.0)
    return max_overlap - 2.0 * unloading_pressure * unloading_radius / effective_modulus * np.sqrt(1.0 - x * x)
