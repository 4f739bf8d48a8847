r"""Contact pressure p(r, t) along one impact: an input of the wear law (equation 15), with the sliding speed of
:mod:`wear.slip`.

Every pressure source produces the same small representation, :class:`PressureHistory`: at each time
t_i the pressure is axisymmetric about the contact centre ``contact_x[i]`` (m, along the impact
direction on the plate), zero for r ≥ extent_i, and tabulated on a uniform grid of
s = √(1 − r²/extent_i²) ∈ [0, 1] (s = 1 at the centre, 0 at the edge). In s the Hertz profile is the
straight line p₀s and the Mesarovic-Johnson profile is smooth, so linear interpolation resolves their
√-shaped edges exactly or nearly (a uniform grid in r would lose ~1-3% of p₀ in its edge cell); any smooth
axisymmetric field, a smooth function of r², stays smooth in s. Between two times the wear integrator
interpolates linearly in time at fixed absolute r.

Sources (``source=`` of :func:`pressure_history`):

``"hertz"``
    Errata Eq. 16, p = p₀√(1 − r²/a²), with the impact's contact radius a(t) and
    p₀ = 3F/(2πa²) from the impact's normal force F(t), so that ∫p dA = F at every instant (with the
    dashpot of errata Eq. 6 this includes the damping force; for an undamped Hertz impact p₀ is
    exactly the Hertz peak pressure, Eq. 17).
``"thornton"``
    Hertz truncated at the limiting pressure p_y: p = min(p₀√(1 − r²/a²), p_y), with p₀ chosen so that
    the truncated profile carries F(t). In closed form, with q = p_y/p₀: F/(πa²p_y) = 1 − q²/3 while
    truncated. For Thornton's (1997) plastic loading (a = √(Rδ), F = F_y + πp_yR(δ − δ_y)) this gives
    exactly his p₀ = 2E*a/(πR). If the mean pressure F/(πa²) reaches p_y (impossible on Thornton's
    loading branch) the pressure is taken uniform at F/(πa²), i.e. the force is kept and p_y exceeded.
``"paper"``
    The paper's recipe (its Eqs. 16-19). Ambiguities resolved as follows, see :func:`paper_pressure_history`:
    Eq. 16 (corrected Hertz, force-conserving as above) while the force has not exceeded the first-yield
    force F_y of Eq. 18 with the paper's C = 1.6; after F_y on the loading branch the flattened uniform
    pressure F/(πa²) (Eq. 19 at a = a*; option ``"hertz"`` keeps Eq. 16 instead); from the state of maximum
    overlap (a*, p* = F*/(πa*²)) on, Eq. 19 (Mesarovic & Johnson 2000 elastic unloading), with the current
    contact radius a found from the force, F/F* = (2/π)[arcsin x − x√(1−x²)], x = a/a*.
``"fe"``
    A tabulated p(r, t) from the finite-element plate (``fem.indent_impact``): surface node radii, the
    impact time of each FE step and the nodal pressures. Each step is resampled (linearly, as the FE
    field is piecewise linear on the surface) onto the table in s with extent = the first node
    beyond the last loaded one; negative nodal values (FE noise) are set to zero.

The sliding speed, the other input of the wear law, is :mod:`wear.slip`.

SI units throughout: time s, lengths m, forces N, pressures Pa, speeds m/s.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact.checks import check_array, check_choice, check_number
from contact.materials import effective_modulus
from contact.theory import PAPER_YIELD_COEFFICIENT, default_limiting_pressure, first_yield
from wear.pressure_profiles import mesarovic_johnson_radius_fraction, truncated_hertz_rows

__all__ = [
    "PRESSURE_SOURCES",
    "PressureHistory",
    "hertz_pressure_history",
    "paper_pressure_history",
    "fe_pressure_history",
    "pressure_history",
]

#: The pressure sources of :func:`pressure_history`.
PRESSURE_SOURCES = ("fe", "hertz", "paper", "thornton")
DEFAULT_POINTS = 257


@dataclass(frozen=True, eq=False)
class PressureHistory:
    """Axisymmetric contact pressure about a moving centre, sampled in time.

    Attributes
    ----------
    time : (n,) array, s
        Strictly increasing sample times (impact time, 0 at first contact).
    contact_x : (n,) array, m
        Contact centre on the plate along the impact direction.
    extent : (n,) array, m
        Radius beyond which the pressure is zero (the contact radius for the closed-form sources).
    pressure : (n, m) array, Pa
        ``pressure[i, k]`` is p at s_k = k/(m − 1), i.e. at r = extent[i] · √(1 − s_k²).
    source : str
        Name of the source that built it.
    """

    time: np.ndarray
    contact_x: np.ndarray
    extent: np.ndarray
    pressure: np.ndarray
    source: str = ""

    def __post_init__(self) -> None:
        t = check_array("time", self.time, units="s", min_size=2)
        if np.any(np.diff(t) <= 0.0):
            raise ValueError("time must be strictly increasing (s)")
        n = t.size
        x = check_array("contact_x", self.contact_x, units="m")
        a = check_array("extent", self.extent, low=0.0, units="m")
        p = check_array("pressure", self.pressure, low=0.0, units="Pa", ndim=2)
        if x.shape != (n,) or a.shape != (n,) or p.shape[0] != n or p.shape[1] < 3:
            raise ValueError(
                f"time, contact_x, extent, pressure have shapes {t.shape}, {x.shape}, {a.shape}, {p.shape}: "
                "need (n,), (n,), (n,), (n, m) with m >= 3"
            )
        for name, arr in (("time", t), ("contact_x", x), ("extent", a), ("pressure", p)):
            object.__setattr__(self, name, np.ascontiguousarray(arr))

    @property
    def s(self) -> np.ndarray:
        """Table abscissae s_k = √(1 − r²/extent²) (dimensionless), shape (m,)."""
        return np.linspace(0.0, 1.0, self.pressure.shape[1])

    def radii(self, step: int) -> np.ndarray:
        """Radii (m) of the table entries of sample ``step``, shape (m,)."""
        return self.extent[step] * np.sqrt(1.0 - self.s**2)

    @property
    def max_extent(self) -> float:
        """Largest loaded radius over the impact (m)."""
        return float(self.extent.max())

    def at(self, step: int, r) -> np.ndarray:
        """Pressure (Pa) at radii ``r`` (m) from the contact centre at sample ``step``."""
        r = np.abs(np.asarray(r, dtype=float))
        a = self.extent[step]
        if a <= 0.0:
            return np.zeros_like(r)
        s = np.sqrt(np.maximum(1.0 - (r / a) ** 2, 0.0))
        return np.where(r < a, np.interp(s, self.s, self.pressure[step]), 0.0)

    def force(self) -> np.ndarray:
        """Normal force ∫ p dA = 2πa² ∫₀¹ p s ds (N) at each sample, trapezoidal rule in s (shape (n,))."""
        s = self.s
        return 2.0 * math.pi * self.extent**2 * np.trapezoid(self.pressure * s, s, axis=1)


def _checked_impact_arrays(time, contact_x, contact_radius, normal_force):
    t = check_array("time", time, units="s", min_size=2)
    x = check_array("contact_x", contact_x, units="m")
    a = check_array("contact_radius", contact_radius, low=0.0, units="m")
    f = np.maximum(check_array("normal_force", normal_force, units="N"), 0.0)
    if not (t.shape == x.shape == a.shape == f.shape):
        raise ValueError(
            f"time, contact_x, contact_radius, normal_force have shapes {t.shape}, {x.shape}, {a.shape}, {f.shape}: "
            "must be equal"
        )
    return t, x, a, f


def hertz_pressure_history(
    time, contact_x, contact_radius, normal_force, *, limiting_pressure: float = math.inf, points: int = DEFAULT_POINTS
) -> PressureHistory:
    """Force-conserving Hertz pressure (equation 16), optionally truncated at ``limiting_pressure`` (Pa).

    ``time`` (s), ``contact_x`` (m), ``contact_radius`` (m) and ``normal_force`` (N) are the impact's
    histories; ``points`` is the size of the table in s (see :class:`PressureHistory`). With a finite
    ``limiting_pressure`` this is the ``"thornton"`` source (see the module docstring); with ``inf`` the
    ``"hertz"`` source.
    """
    t, x, a, f = _checked_impact_arrays(time, contact_x, contact_radius, normal_force)
    p_y = check_number("limiting_pressure", limiting_pressure, low=0.0, low_open=True, units="Pa", allow_inf=True)
    m = int(check_number("points", points, low=3, high=100_000))
    s = np.linspace(0.0, 1.0, m)
    rows = truncated_hertz_rows(s, a, f, p_y)
    rows[a <= 0.0] = 0.0
    return PressureHistory(t, x, a, rows, source="hertz" if math.isinf(p_y) else "thornton")


def paper_pressure_history(
    time,
    contact_x,
    contact_radius,
    normal_force,
    overlap,
    *,
    yield_force: float,
    loading_after_yield: str = "flat",
    points: int = DEFAULT_POINTS,
) -> PressureHistory:
    r"""The paper's pressure recipe: equation 16 up to first yield, then equation 19 (Mesarovic & Johnson) on unloading.

    Recipe, sample by sample (k* = sample of maximum ``overlap``, F* = F(k*), a* = a(k*), p* = F*/(πa*²)):

    1. Loading (k ≤ k*) while F has not yet exceeded ``yield_force`` F_y (N, the paper's Eq. 18 with C = 1.6):
       Hertz, Eq. 16, with p₀ = 3F/(2πa²).
    2. Loading after F first exceeded F_y: the paper gives no formula (its Fig. 8 shows the profile
       flattening). ``loading_after_yield="flat"`` (default) uses the uniform F/(πa²) — Eq. 19 at a = a*,
       continuous with step 3 at k*; ``"hertz"`` keeps Eq. 16 (then the shape jumps at k*).
    3. Unloading (k > k*) if F* > F_y: Eq. 19, p = (2p*/π) arctan√((a² − r²)/(a*² − a²)), with a = x a*
       from F/F* = (2/π)[arcsin x − x√(1−x²)] so that ∫p dA = F (the impact's own a(t) is not used: it
       follows the impact model, not Eq. 19). If F > F* (a dashpot can make it so) the pressure is
       uniform F/(πa*²) over a*.
    4. If F never exceeds F_y, all samples use Eq. 16: the ``"hertz"`` source.

    Inputs: ``time`` (s), ``contact_x`` (m), ``contact_radius`` (m), ``normal_force`` (N), ``overlap`` (m).
    """
    t, x, a, f = _checked_impact_arrays(time, contact_x, contact_radius, normal_force)
    d = check_array("overlap", overlap, units="m")
    if d.shape != t.shape:
        raise ValueError(f"overlap has shape {d.shape}: must equal time's {t.shape}")
    f_y = check_number("yield_force", yield_force, low=0.0, low_open=True, units="N", what="first-yield force")
    check_choice("loading_after_yield", loading_after_yield, ("flat", "hertz"))
    m = int(check_number("points", points, low=3, high=100_000))
    s = np.linspace(0.0, 1.0, m)
    rows = truncated_hertz_rows(s, a, f, math.inf)
    extent = a.copy()
    k_star = int(np.argmax(d))
    loading = np.arange(t.size) <= k_star
    yielded = np.cumsum(f > f_y) > 0
    if not np.any(yielded & loading):
        rows[a <= 0.0] = 0.0
        return PressureHistory(t, x, extent, rows, source="paper")
    if loading_after_yield == "flat":
        flat = yielded & loading & (a > 0.0)
        rows[flat] = (f[flat] / (math.pi * a[flat] ** 2))[:, None]
    a_star, f_star = a[k_star], f[k_star]
    p_star = f_star / (math.pi * a_star**2)
    unload = ~loading
    above = unload & (f >= f_star)
    rows[above] = (f[above] / (math.pi * a_star**2))[:, None]
    extent[above] = a_star
    mj = unload & ~above
    xfrac = mesarovic_johnson_radius_fraction(f[mj] / f_star)
    a_now = xfrac * a_star
    extent[mj] = a_now
    den = np.sqrt(np.maximum(a_star**2 - a_now**2, 1e-300 * a_star**2))
    num = a_now[:, None] * s[None, :]  # √(a² − r²) = a s
    rows[mj] = 2.0 * p_star / math.pi * np.arctan(num / den[:, None])
    rows[extent <= 0.0] = 0.0
    return PressureHistory(t, x, extent, rows, source="paper")


def fe_pressure_history(time, surface_r, pressure, contact_x, *, points: int | None = None) -> PressureHistory:
    """Pressure source ``"fe"``: a tabulated p(r, t) (e.g. from ``fem.indent_impact``).

    ``time`` (k,) s: impact time of each FE step; ``surface_r`` (m,) m: radii of the surface nodes;
    ``pressure`` (k, m) Pa: nodal contact pressure per step; ``contact_x`` (k,) m: contact centre at those
    times (interpolate the impact's ``contact_x`` to them). ``points`` defaults to max(513, 8 × nodes): the s
    grid is coarse in r near the centre (Δr ≈ a√(2/points)), so it must be fine enough for the nodal kinks.
    """
    t = check_array("time", time, units="s", min_size=2)
    r = check_array("surface_r", surface_r, low=0.0, units="m", min_size=2)
    p = np.maximum(check_array("pressure", pressure, units="Pa", ndim=2), 0.0)
    x = check_array("contact_x", contact_x, units="m")
    if p.shape != (t.size, r.size) or x.shape != t.shape:
        raise ValueError(
            f"time {t.shape}, surface_r {r.shape}, pressure {p.shape}, contact_x {x.shape}: "
            "need (k,), (m,), (k, m), (k,)"
        )
    order = np.argsort(r, kind="stable")
    r, p = r[order], p[:, order]
    if np.any(np.diff(r) <= 0.0):
        raise ValueError("surface_r has repeated radii: give each surface node once (m)")
    m = (
        max(2 * DEFAULT_POINTS - 1, 8 * r.size)
        if points is None
        else int(check_number("points", points, low=3, high=1e6))
    )
    s = np.linspace(0.0, 1.0, m)
    extent = np.zeros(t.size)
    rows = np.zeros((t.size, m))
    for i in range(t.size):
        loaded = np.flatnonzero(p[i] > 0.0)
        if loaded.size == 0:
            continue
        j = min(loaded[-1] + 1, r.size - 1)
        extent[i] = r[j]
        rows[i] = np.interp(r[j] * np.sqrt(1.0 - s**2), r, p[i])
    return PressureHistory(t, x, extent, rows, source="fe")


def _history_of(impact):
    return getattr(impact, "history", impact)


def pressure_history(
    impact,
    source: str = "fe",
    *,
    fe=None,
    limiting_pressure: float | None = None,
    yield_force: float | None = None,
    loading_after_yield: str = "flat",
    points: int | None = None,
) -> PressureHistory:
    """Pressure along the impact ``impact`` (a ``contact.ImpactResult``) from the named ``source``.

    ``source``: ``"fe"`` (needs ``fe``: an object with ``time`` (s), ``surface_r`` (m) and ``pressure``
    (Pa) such as ``fem.indent_impact``'s result, or a tuple of those three arrays), ``"hertz"``,
    ``"paper"`` (``yield_force`` (N) defaults to Eq. 18 with C = 1.6 from the plate's yield strength),
    ``"thornton"`` (``limiting_pressure`` (Pa) defaults to C(ν)·Y of the body that yields first).
    ``points``: size of the table in s (default 257; for ``"fe"`` max(513, 8 × surface nodes)).
    """
    check_choice("source", source, PRESSURE_SOURCES)
    h = _history_of(impact)
    if source != "fe" and points is None:
        points = DEFAULT_POINTS
    if source == "fe":
        if fe is None:
            raise ValueError("fe=None: source='fe' needs the FE pressure table (time s, surface_r m, pressure Pa)")
        if isinstance(fe, tuple):
            fe_time, fe_r, fe_p = fe
        else:
            fe_time, fe_r, fe_p = fe.time, fe.surface_r, fe.pressure
        fe_time = np.asarray(fe_time, dtype=float)
        return fe_pressure_history(fe_time, fe_r, fe_p, np.interp(fe_time, h.t, h.contact_x), points=points)
    if source == "hertz":
        return hertz_pressure_history(h.t, h.contact_x, h.contact_radius, h.normal_force, points=points)
    if source == "thornton":
        p_y = default_limiting_pressure(impact.ball, impact.plate) if limiting_pressure is None else limiting_pressure
        return hertz_pressure_history(
            h.t, h.contact_x, h.contact_radius, h.normal_force, limiting_pressure=p_y, points=points
        )
    if yield_force is None:
        plate = impact.plate
        if not plate.yield_strength:
            raise ValueError("plate.yield_strength=None: source='paper' needs the plate's yield strength (Pa)")
        e_star = effective_modulus(impact.ball, plate)
        yield_force = first_yield(
            impact.radius, e_star, plate.yield_strength, plate.nu, coefficient=PAPER_YIELD_COEFFICIENT
        ).force
    return paper_pressure_history(
        h.t,
        h.contact_x,
        h.contact_radius,
        h.normal_force,
        h.overlap,
        yield_force=yield_force,
        loading_after_yield=loading_after_yield,
        points=points,
    )
