r"""Contact force laws of the impact engine: normal (Hertz + dashpot, Thornton, tabulated) and tangential (H-DD).

The numba kernels here evaluate one contact state; :mod:`contact.engine` integrates them. SI units:
overlaps and radii in m, forces in N, pressures in Pa, velocities in m/s.

Normal laws (errata Eqs. 4, 6; Thornton 1997):

* ``hertz``: :math:`F_n = \tfrac43 E^*\sqrt R\,\delta^{3/2} + c\sqrt{S_n m}\,\dot\delta`,
  :math:`S_n = 2E^*\sqrt{R\delta}`, clipped at :math:`F_n \ge 0`; :math:`a = \sqrt{R\delta}`. The dimensionless
  dashpot coefficient :math:`c(e)` is found once per restitution e by solving the dimensionless impact
  (:func:`dashpot_coefficient`).
* ``thornton``: Hertz until the peak pressure reaches :math:`p_y` (overlap :math:`\delta_y = (\pi p_y/2E^*)^2R`),
  then :math:`F = F_y + \pi p_y R(\delta - \delta_y)`, :math:`a = \sqrt{R\delta}`. Unloading from
  :math:`(\delta^*, F^*)` is Hertzian with the enlarged radius :math:`R_p = 4E^*a_p^3/(3F^*)`,
  :math:`a_p^2 = (2F^* + F_y)/(2\pi p_y)`, residual overlap :math:`\delta_p = \delta^* - a_p^2/R_p`.
* ``tabulated``: a :class:`contact.TabulatedLaw` (see :func:`tabulated_arrays`).

Tangential laws (errata Eqs. 3, 8): :math:`F_t = -f k_t \xi`, :math:`k_t = 8G^*a`, f = 2/3 (``hdd``) or 1
(``mindlin``); Coulomb truncation :math:`|F_t| \le \mu F_n` with :math:`\xi` cut back to :math:`\mu F_n/(f k_t)`.
``mindlin_deresiewicz``: partial slip with memory (:func:`memory_tangential_law`), whose slip traction is
limited by the plate surface's shear strength k where the tabulated law carries one (Orowan's friction,
:math:`\tau = \min(\mu p, k)`: :func:`slip_line_load`).
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np
from numba import njit
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from contact.tabulated import TabulatedLaw

__all__ = [
    "HERTZ",
    "THORNTON",
    "TABULATED",
    "dashpot_coefficient",
    "dimensionless_restitution",
    "tabulated_arrays",
    "normal_law",
    "tangential_law",
    "memory_tangential_law",
    "slip_line_load",
    "SPRING",
    "MEMORY",
    "SPRINGS",
]

HERTZ, THORNTON, TABULATED = 0, 1, 2

# Indices into the parameter vector ``prm`` shared by the kernels.
P_RADIUS, P_HERTZ_K, P_ESTAR, P_DAMP, P_PY, P_DY, P_FY, P_GSTAR, P_MASS, P_INERTIA, P_SHEAR = range(11)
N_PARAMS = 11

# Error codes a kernel can report per impact.
OK, ERR_LOADING_TABLE, ERR_UNLOADING_TABLE, ERR_MAX_STEPS, ERR_SPRINGS = 0, 1, 2, 3, 4

# Tangential laws: one spring (H-DD, Mindlin) or Mindlin-Deresiewicz with memory (a row of 1-D springs).
SPRING, MEMORY = 0, 1
#: Springs of the Mindlin-Deresiewicz law per impact, over [0, 3 a_Hertz] (about 130 across a Hertz contact).
SPRINGS = 400


# ---------------------------------------------------------------------------------------------------------
# Restitution dashpot: c(e) from the dimensionless Hertz impact
# ---------------------------------------------------------------------------------------------------------


def dimensionless_restitution(c: float) -> float:
    r"""Normal restitution of the Hertz impact with the dashpot coefficient ``c`` (dimensionless).

    With :math:`\delta = \delta_0 x`, :math:`t = (\delta_0/v)\tau`, :math:`\delta_0 = (m v^2/K)^{2/5}`,
    :math:`K = \tfrac43E^*\sqrt R`, the impact is :math:`x'' = -\max(0, x^{3/2} + c\sqrt{3/2}\,x^{1/4}x')`,
    x(0) = 0, x'(0) = 1, independent of v, m, R, E*: e depends on c alone. Contact ends when the force
    vanishes with the ball moving away (the engine's rule); then e = −x'.
    """
    ch = c * math.sqrt(1.5)

    def rhs(_t, y):
        x, v = y
        xp = max(x, 0.0)
        return [v, -max(0.0, xp**1.5 + ch * xp**0.25 * v)]

    def end(_t, y):
        x, v = y
        return math.copysign(abs(x) ** 1.25, x) + ch * v

    end.terminal = True
    end.direction = -1.0
    sol = solve_ivp(rhs, (0.0, 20.0), [0.0, 1.0], method="DOP853", rtol=1e-12, atol=1e-14, events=end)
    if sol.status != 1:
        raise RuntimeError(f"dimensionless impact with c={c} did not end")
    return float(-sol.y_events[0][0][1])


@lru_cache(maxsize=64)
def dashpot_coefficient(restitution: float) -> float:
    r"""Dashpot coefficient c (dimensionless) of errata equation 6 that gives the normal ``restitution`` e.

    Solved once per e by root finding on :func:`dimensionless_restitution` (cached); e = 1 gives c = 0.
    The linear-spring shortcut :math:`c = -2\sqrt{5/6}\ln e/\sqrt{\ln^2 e + \pi^2}` is not used (it is off by
    5% at e = 0.6 for a Hertz spring).
    """
    e = float(restitution)
    if e >= 1.0 - 1e-12:  # closer to 1 than the root finder can resolve: no damping
        return 0.0
    hi = 1.0
    while dimensionless_restitution(hi) > e:
        hi *= 2.0
        if hi > 1e4:
            raise ValueError(f"restitution={e:g} is too small to reach with the Hertz dashpot")
    return float(brentq(lambda c: dimensionless_restitution(c) - e, 0.0, hi, xtol=1e-13, rtol=1e-12))


# ---------------------------------------------------------------------------------------------------------
# Tabulated law: normalised arrays for the kernel
# ---------------------------------------------------------------------------------------------------------


def tabulated_arrays(law: TabulatedLaw | None) -> tuple[np.ndarray, ...]:
    r"""Arrays the kernel uses to evaluate a :class:`TabulatedLaw` (dummy arrays for ``None``).

    Returns ``(load, unload_max, unload_residual, s, force_ratio, radius_ratio)``: ``load`` is (3, n) with
    rows δ, F, a of the loading branch; per unloading curve j, ``s[j]`` is the increasing coordinate
    :math:`s = (\delta - \delta_{p,j})/(\delta^*_j - \delta_{p,j})` and ``force_ratio[j]``, ``radius_ratio[j]``
    are F/F(δ*_j) and a/a(δ*_j) along it. Normalising lets the kernel interpolate between curves and still
    start every unloading exactly on the loading branch.
    """
    if law is None:
        z = np.zeros((1, 2))
        return np.zeros((3, 2)), np.ones(1), np.zeros(1), z, z, z
    load = np.vstack([law.loading_overlap, law.loading_force, law.loading_contact_radius]).astype(float)
    uo, uf, ua = law.unloading_overlap, law.unloading_force, law.unloading_contact_radius
    dmax = law.unloading_max_overlap.astype(float)
    dres = uo[:, -1].astype(float)
    if np.any(uf[:, 0] <= 0.0) or np.any(ua[:, 0] <= 0.0):
        raise ValueError("force_law: every unloading curve must start with a positive force (N) and contact radius (m)")
    s = ((uo - dres[:, None]) / (dmax - dres)[:, None])[:, ::-1]
    force_ratio = (uf / uf[:, :1])[:, ::-1]
    radius_ratio = (ua / ua[:, :1])[:, ::-1]
    return (
        np.ascontiguousarray(load),
        np.ascontiguousarray(dmax),
        np.ascontiguousarray(dres),
        np.ascontiguousarray(s),
        np.ascontiguousarray(force_ratio),
        np.ascontiguousarray(radius_ratio),
    )


@njit(cache=True, error_model="numpy")
def _bracket(x, xs):
    """(lo, w): the interval [xs[lo], xs[lo + 1]] of increasing ``xs`` holding ``x`` and the weight of its upper end
    (clamped: (0, 0) below the first value, (n − 2, 1) above the last)."""
    n = xs.shape[0]
    if x <= xs[0]:
        return 0, 0.0
    if x >= xs[n - 1]:
        return n - 2, 1.0
    lo, hi = 0, n - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if xs[mid] <= x:
            lo = mid
        else:
            hi = mid
    return lo, (x - xs[lo]) / (xs[hi] - xs[lo])


@njit(cache=True, error_model="numpy")
def _interp(x, xs, ys):
    """Linear interpolation in increasing ``xs`` (clamped to the end values)."""
    lo, w = _bracket(x, xs)
    return ys[lo] + w * (ys[lo + 1] - ys[lo])


@njit(cache=True, error_model="numpy")
def _interp_from_zero(x, xs, ys, power):
    """:func:`_interp`, but in an interval whose lower end has y = 0 (first contact of the loading branch,
    separation at the end of an unloading curve) as y_hi·w^power: Hertz-like, F ∝ w^1.5 and a ∝ w^0.5. Linear in
    both, 3F/(2πa²) ∝ 1/w there: a spurious peak pressure up to 10× the real one at the first and last steps."""
    lo, w = _bracket(x, xs)
    if ys[lo] == 0.0:
        return ys[lo + 1] * w**power
    return ys[lo] + w * (ys[lo + 1] - ys[lo])


@njit(cache=True, error_model="numpy")
def _tabulated(delta, dmax, load, umax, ures, s_tab, f_tab, a_tab):
    """(force N, contact radius m, error code) of the tabulated law at overlap ``delta``, max overlap ``dmax``."""
    if dmax > load[0, load.shape[1] - 1]:
        return 0.0, 0.0, ERR_LOADING_TABLE
    if delta >= dmax:
        return _interp_from_zero(delta, load[0], load[1], 1.5), _interp_from_zero(delta, load[0], load[2], 0.5), OK
    k = umax.shape[0]
    if dmax > umax[k - 1]:
        return 0.0, 0.0, ERR_UNLOADING_TABLE
    # bracketing curves j, j+1 and weight w; below the first curve its shape is used with δ_p ∝ δ*
    if dmax <= umax[0]:
        j, w = 0, 0.0
        dres = ures[0] * dmax / umax[0]
    else:
        j = 0
        while umax[j + 1] < dmax:
            j += 1
        w = (dmax - umax[j]) / (umax[j + 1] - umax[j])
        dres = ures[j] + w * (ures[j + 1] - ures[j])
    if delta <= dres:
        return 0.0, 0.0, OK
    s = (delta - dres) / (dmax - dres)
    f = _interp_from_zero(s, s_tab[j], f_tab[j], 1.5)
    r = _interp_from_zero(s, s_tab[j], a_tab[j], 0.5)
    if w > 0.0:
        f = (1.0 - w) * f + w * _interp_from_zero(s, s_tab[j + 1], f_tab[j + 1], 1.5)
        r = (1.0 - w) * r + w * _interp_from_zero(s, s_tab[j + 1], a_tab[j + 1], 0.5)
    return f * _interp(dmax, load[0], load[1]), r * _interp(dmax, load[0], load[2]), OK


@njit(cache=True, inline="always", error_model="numpy")
def normal_law(model, delta, rate, dmax, prm, load, umax, ures, s_tab, f_tab, a_tab):
    """Normal force (N, ≥ 0), contact radius a (m), peak pressure (Pa), error code.

    ``delta`` overlap (m), ``rate`` dδ/dt (m/s, used by the Hertz dashpot), ``dmax`` the largest overlap
    reached so far including this one (m). Peak pressure: 3F/(2πa²) (tabulated); for Thornton min(Hertz p₀, p_y):
    p_y while it loads plastically, and after it the Hertz p₀ of the unloading curvature R_p bounded by p_y (at
    the start of the unloading 3F_p/(2πa_p²) ≈ 1.5 p_y: Thornton's flat-topped loading distribution and his
    Hertzian unloading one do not join, and the limiting pressure is the bound his model rests on); for Hertz that
    of the spring's force alone,
    p₀ = 3F_el/(2πa²) = (2E*/π)·√(δ/R): the dashpot's force has no pressure distribution of its own, and counted in
    it would give 3F/(2πa²) → ∞ as a → 0 at first contact (the dashpot acts at once, the area grows from zero).
    """
    if delta <= 0.0:
        return 0.0, 0.0, 0.0, OK
    radius = prm[P_RADIUS]
    if model == HERTZ:
        root = math.sqrt(delta)
        force = prm[P_HERTZ_K] * delta * root + prm[P_DAMP] * math.sqrt(root) * rate
        force = max(force, 0.0)
        a = math.sqrt(radius * delta)
        return force, a, 1.5 * prm[P_HERTZ_K] * root / (math.pi * radius), OK
    if model == THORNTON:
        py, dy, fy, estar = prm[P_PY], prm[P_DY], prm[P_FY], prm[P_ESTAR]
        if dmax <= dy:
            a = math.sqrt(radius * delta)
            force = prm[P_HERTZ_K] * delta * math.sqrt(delta)
            return force, a, 1.5 * force / (math.pi * a * a), OK
        if delta >= dmax:
            return fy + math.pi * py * radius * (delta - dy), math.sqrt(radius * delta), py, OK
        fp = fy + math.pi * py * radius * (dmax - dy)
        ap = math.sqrt((2.0 * fp + fy) / (2.0 * math.pi * py))
        rp = 4.0 * estar * ap**3 / (3.0 * fp)
        d = delta - (dmax - ap * ap / rp)
        if d <= 0.0:
            return 0.0, 0.0, 0.0, OK
        a = math.sqrt(rp * d)
        force = 4.0 / 3.0 * estar * math.sqrt(rp) * d * math.sqrt(d)
        return force, a, min(1.5 * force / (math.pi * a * a), py), OK
    force, a, err = _tabulated(delta, dmax, load, umax, ures, s_tab, f_tab, a_tab)
    if a > 0.0:
        return force, a, 1.5 * force / (math.pi * a * a), err
    return force, a, 0.0, err


@njit(cache=True, error_model="numpy")
def slip_line_load(x, contact_radius, peak_pressure, friction, shear_strength):
    r"""The slip traction's line load (N/m) at x (m) of a Hertzian contact of radius a (m) and peak pressure
    p₀ (Pa) whose slip traction is Orowan's, τ = min(μp, k) (k = ``shear_strength`` in Pa; ∞ for Coulomb's
    μp): the method of dimensionality reduction's transform of the traction (Popov & Heß 2015, ch. 3),

    .. math:: q_t(x) = 2\int_0^{b} \min\bigl(\mu p_0\sqrt{b^2 - s^2}/a,\ k\bigr)\,ds,\qquad
              b^2 = a^2 - x^2,

    in closed form: with h = ka/(μp₀), q_t = μp₀πb²/(2a) where b ≤ h (Coulomb's μq(x)), else
    2ks₁ + (μp₀/a)(πb²/2 − s₁h − b² asin(s₁/b)), s₁ = √(b² − h²). Its integral over the contact is the tangential
    force of gross sliding, ∫min(μp, k) dA."""
    b2 = contact_radius * contact_radius - x * x
    if b2 <= 0.0 or friction <= 0.0:
        return 0.0
    coulomb = friction * peak_pressure / contact_radius
    if not shear_strength < coulomb * math.sqrt(b2):
        return 0.5 * math.pi * coulomb * b2
    h = shear_strength / coulomb
    b = math.sqrt(b2)
    s1 = math.sqrt(b2 - h * h)
    return 2.0 * shear_strength * s1 + coulomb * (0.5 * math.pi * b2 - s1 * h - b2 * math.asin(s1 / b))


@njit(cache=True, error_model="numpy")
def memory_tangential_law(
    springs, pitch, slide_increment, contact_radius, normal_force, friction, gstar, shear_strength=math.inf
):
    r"""Mindlin–Deresiewicz tangential force with memory, for any history of the normal force and the slide.

    The method of dimensionality reduction (Popov & Heß 2015, ch. 5: exact, in the Cattaneo–Mindlin approximation,
    for any history of the normal and the tangential loading): the contact is a row of independent 1-D springs at
    x_i = (i + ½)·``pitch`` (m) on each side of the centre, each with the tangential stiffness 4G*·Δx and the normal
    line load of the Hertz shape carrying the normal force F,

    .. math:: q(x) = \frac{3F}{4a}\Bigl(1 - \frac{x^2}{a^2}\Bigr),\qquad
              |u_i| \le \frac{\mu\, q(x_i)}{4G^*} = \frac{3\mu F}{16 G^* a}\Bigl(1 - \frac{x_i^2}{a^2}\Bigr).

    (the line load's sum over the springs is made F exactly, so gross sliding is at μF). With a finite
    ``shear_strength`` k (Pa) the limits are the line load of Orowan's slip traction min(μp, k) on the Hertz
    pressure of F and a, :func:`slip_line_load` (scaled by the same discrete normalisation), and gross sliding is
    at ∫min(μp, k) dA. Each spring in contact
    (x_i < a) takes the ball surface's ``slide_increment`` dξ (m) and slips at its Coulomb
    limit; a spring outside the contact is unloaded (it enters the contact at zero). The force on the ball is
    F_t = −8G*·Δx·Σ u_i (N): at constant F this is Cattaneo–Mindlin's F_t = −μF[1 − (1 − ξ/ξ_max)^{3/2}],
    ξ_max = 3μF/(16G*a) (Johnson 1985, Eq. 7.42), with the unloading and reloading of Mindlin & Deresiewicz
    (1953; Johnson §7.3).
    ``springs`` (m) is the state, updated in place. Returns (F_t N, sliding flag: every spring in contact slips,
    error code: ERR_SPRINGS if a outgrows the row).
    """
    n = springs.shape[0]
    if contact_radius > n * pitch:
        return 0.0, False, ERR_SPRINGS
    if contact_radius <= 0.0 or normal_force <= 0.0:
        springs[:] = 0.0
        return 0.0, False, OK
    # the line load's discrete shape, normalised so that the springs' limits add up to exactly μF
    inside = min(n, int(contact_radius / pitch + 0.5))  # springs with x_i < a
    shape = 0.0
    for i in range(inside):
        x = (i + 0.5) * pitch
        shape += 1.0 - (x / contact_radius) ** 2
    peak = friction * normal_force / (8.0 * gstar * pitch * shape) if shape > 0.0 else 0.0
    scale = normal_force / (8.0 * gstar * pitch * shape) if shape > 0.0 else 0.0
    peak_pressure = 1.5 * normal_force / (math.pi * contact_radius * contact_radius)
    line_load = 0.75 * normal_force / contact_radius  # q(0) of the Hertz line load, N/m
    total = 0.0
    sliding = True
    for i in range(n):
        if i >= inside:
            # springs leave the contact from the outside in, each unloaded as it leaves: past the first unloaded
            # one all are
            if springs[i] == 0.0:
                break
            springs[i] = 0.0
            continue
        u = springs[i] + slide_increment
        x = (i + 0.5) * pitch
        if shear_strength < math.inf:
            limit = scale * slip_line_load(x, contact_radius, peak_pressure, friction, shear_strength) / line_load
        else:
            limit = peak * (1.0 - (x / contact_radius) ** 2)
        if u > limit:
            u = limit
        elif u < -limit:
            u = -limit
        else:
            sliding = False
        springs[i] = u
        total += u
    return -8.0 * gstar * pitch * total, sliding, OK


@njit(cache=True, inline="always", error_model="numpy")
def tangential_law(xi_trial, contact_radius, normal_force, friction, factor, gstar):
    """H-DD / Mindlin tangential force with Coulomb truncation.

    Returns (F_t N, ξ m after truncation, sliding flag). ``factor`` f = 2/3 (H-DD) or 1 (Mindlin).
    """
    stiffness = factor * 8.0 * gstar * contact_radius
    force = -stiffness * xi_trial
    limit = friction * normal_force
    if abs(force) > limit:
        sign = 1.0 if xi_trial > 0.0 else -1.0
        xi = sign * limit / stiffness if stiffness > 0.0 else 0.0
        return -sign * limit, xi, True
    return force, xi_trial, False
