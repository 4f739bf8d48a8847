r"""Integration of the wear law (errata equation 15) over one impact on a 2-D grid of the plate surface.

.. math:: w(x, y) = \int K\,p\big(\sqrt{(x - x_c(t))^2 + y^2},\,t\big)^{\alpha}\,v(t)^{\beta}\,dt

x runs along the impact direction on the plate, y across it; x_c(t) is the contact centre
(``PressureHistory.contact_x``). The time axis is the union of the pressure and speed samples, each
interval cut into sub-steps (:mod:`wear.substeps`) so that the patch moves less than a quarter cell per sub-step; the
integral is the trapezoidal rule over those sub-steps, with p interpolated linearly in time at fixed
(x, y) and v linearly in time. The grid spacing is 2 a_max / ``points_across`` (a_max the largest
loaded radius), ≥ 40 points across the largest contact diameter; the grid covers the whole scar.

Accuracy (measured in tests/test_wear_integrate.py, default 64 points across, 257-entry pressure tables):
the worn volume of an impact with α = 1, β = 0 equals K × normal impulse = K m V_n (1 + e) within 0.05%
(any source, any angle); a steady Hertz track matches its closed-form depth within 0.03% of the maximum
depth for α ≥ 1 and 0.1% for α = 0.5; h(r)/h(0) of a normal Hertz impact matches the quadrature within
3e-4. The kernel (:mod:`wear.accumulate`) interpolates p^α, not p, in s and in time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from contact.checks import check_number
from wear.accumulate import (
    accumulate_depth,
    accumulate_depth_numpy,
    accumulate_local_depth,
    local_speed,
    powered_table,
)
from wear.law import WearLaw
from wear.pressure import PressureHistory, pressure_history
from wear.slip import SlidingSpeed, sliding_speed
from wear.substeps import wear_substeps

__all__ = [
    "wear_map",
    "WearMap",
    "surface_grid",
    "integrate_wear",
    "integrate_wear_numpy",
    "wear_from_impact",
    "integrate_volume",
    "axisymmetric_wear_depth",
    "scar_extent",
    "MIN_POINTS_ACROSS",
    "implausible_wear",
]

#: Smallest accepted number of grid points across the largest contact diameter.
MIN_POINTS_ACROSS = 40
DEFAULT_POINTS_ACROSS = 64


@dataclass(frozen=True, eq=False)
class WearMap:
    """Wear depth over the plate surface after an impact (SI units).

    Attributes
    ----------
    x : (nx,) array, m
        Uniform grid along the impact direction (same frame as ``contact_x``).
    y : (ny,) array, m
        Uniform grid across the impact direction, symmetric about 0 (y = 0 is a grid line).
    depth : (ny, nx) array, m
        Worn depth, positive into the plate.
    volume_m3 : float
        Worn volume ∫ w dA (m³), see :func:`integrate_volume`.
    mass_kg : float
        Worn mass = plate density × volume (kg).
    max_depth_m : float
        Largest depth (m).
    scar_length_m, scar_width_m : float
        Extent of the scar along x and across (y) where the depth exceeds ``scar_threshold`` × max depth (m),
        see :func:`scar_extent`.
    density : float
        Plate density used for the mass (kg/m³).
    """

    x: np.ndarray
    y: np.ndarray
    depth: np.ndarray
    volume_m3: float
    mass_kg: float
    max_depth_m: float
    scar_length_m: float
    scar_width_m: float
    density: float

    @property
    def spacing(self) -> float:
        """Grid spacing (m), equal in x and y."""
        return float(self.x[1] - self.x[0])

    def centreline(self) -> np.ndarray:
        """Depth (m) along y = 0, shape (nx,)."""
        return self.depth[int(np.argmin(np.abs(self.y)))]

    def depth_at(self, x, y) -> np.ndarray:
        """Depth (m) at the points (``x``, ``y``) (m, arrays of one shape), bilinear on the grid, 0 off it."""
        x, y = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float))
        on = RegularGridInterpolator((self.y, self.x), self.depth, bounds_error=False, fill_value=0.0)
        return on(np.column_stack([y.ravel(), x.ravel()])).reshape(x.shape)


def implausible_wear(wm: WearMap, contact_radius: float, ball_mass: float) -> list[str]:
    """One line per way in which ``wm``, the wear of one impact, cannot be what one impact does: a depth beyond the
    largest contact radius ``contact_radius`` (m; the contact mechanics assume a surface that stays nearly flat over
    the contact), or a worn mass beyond the ball's ``ball_mass`` (kg; the ball's kinetic energy cannot remove more
    than itself in any published wear mechanism). Both point to a wear coefficient far too large for the case."""
    lines = []
    if wm.max_depth_m > contact_radius:
        lines.append(
            f"the wear depth of one impact, {wm.max_depth_m:.3g} m, exceeds the contact radius {contact_radius:.3g} m:"
            " the wear coefficient (wear.K or the law's constant) is far too large for this case"
        )
    if wm.mass_kg > ball_mass:
        lines.append(
            f"the worn mass of one impact, {wm.mass_kg:.3g} kg, exceeds the ball's mass {ball_mass:.3g} kg: the wear "
            "coefficient (wear.K or the law's constant) is far too large for this case"
        )
    return lines


def surface_grid(
    pressure: PressureHistory, points_across: int = DEFAULT_POINTS_ACROSS
) -> tuple[np.ndarray, np.ndarray]:
    """Grid (x, y) in m covering the whole scar of ``pressure``: spacing 2 a_max/``points_across``.

    x starts on the first contact centre (so a normal impact is centred on a node) and spans
    [min x_c − a_max, max x_c + a_max] plus two cells; y is symmetric about 0 with the same spacing.
    """
    n_across = int(check_number("points_across", points_across, low=MIN_POINTS_ACROSS, high=4096))
    a_max = pressure.max_extent
    if a_max <= 0.0:
        raise ValueError("pressure has no contact (all extents are 0 m): nothing to integrate")
    dx = 2.0 * a_max / n_across
    x0 = float(pressure.contact_x[0])
    lo = float(pressure.contact_x.min()) - a_max
    hi = float(pressure.contact_x.max()) + a_max
    i_lo = math.floor((lo - x0) / dx) - 2
    i_hi = math.ceil((hi - x0) / dx) + 2
    x = x0 + dx * np.arange(i_lo, i_hi + 1)
    half = math.ceil(a_max / dx) + 2
    y = dx * np.arange(-half, half + 1)
    return x, y


def integrate_volume(x, y, depth) -> float:
    """Volume (m³) under ``depth`` (m, shape (ny, nx)) on the uniform grid ``x``, ``y`` (m): the trapezoidal
    rule, which equals Σ w Δx Δy here because the depth vanishes on the grid border."""
    return float(np.trapezoid(np.trapezoid(depth, x, axis=1), y))


def scar_extent(coordinate, profile, threshold: float) -> float:
    """Length (m) of the region where ``profile`` exceeds ``threshold``, edges interpolated linearly."""
    above = np.flatnonzero(profile > threshold)
    if above.size == 0:
        return 0.0
    first, last = above[0], above[-1]
    c, p = coordinate, profile

    def crossing(i_out, i_in):
        if i_out < 0 or i_out >= p.size:
            return c[i_in]
        return c[i_out] + (threshold - p[i_out]) / (p[i_in] - p[i_out]) * (c[i_in] - c[i_out])

    return float(crossing(last + 1, last) - crossing(first - 1, first))


def wear_map(x: np.ndarray, y: np.ndarray, depth: np.ndarray, density: float, scar_threshold: float = 0.01) -> WearMap:
    """A :class:`WearMap` of the depth map ``depth`` (m, y × x) on the grid ``x``, ``y`` (m) of a plate of
    ``density`` (kg/m³): volume, mass, max depth, and the scar's extent where the depth exceeds ``scar_threshold`` ×
    its maximum."""
    max_depth = float(depth.max()) if depth.size else 0.0
    thr = scar_threshold * max_depth
    volume = integrate_volume(x, y, depth)
    return WearMap(
        x=x,
        y=y,
        depth=depth,
        volume_m3=volume,
        mass_kg=density * volume,
        max_depth_m=max_depth,
        scar_length_m=scar_extent(x, depth.max(axis=0), thr) if max_depth > 0.0 else 0.0,
        scar_width_m=scar_extent(y, depth.max(axis=1), thr) if max_depth > 0.0 else 0.0,
        density=density,
    )


def integrate_wear(
    pressure: PressureHistory,
    speed: SlidingSpeed,
    law: WearLaw,
    *,
    density: float,
    points_across: int = DEFAULT_POINTS_ACROSS,
    on: WearMap | None = None,
    scar_threshold: float = 0.01,
    engine: str = "numba",
) -> WearMap:
    """Wear depth map of one impact (equation 15 integrated over the moving contact patch).

    ``pressure``: p(r, t) about the contact centre (:func:`wear.pressure_history`); ``speed``: the sliding
    speed (:func:`wear.sliding_speed`); ``law``: :class:`WearLaw`; ``density``: plate density (kg/m³) for
    the worn mass; ``points_across``: grid points across the largest contact diameter (≥ 40).
    ``on``: a previous :class:`WearMap` to add this impact to, on its grid (no geometry update: the
    pressure is not changed by the wear). ``scar_threshold``: fraction of the max depth that bounds the
    scar for its length and width. ``engine``: ``"numba"`` (parallel kernel) or ``"numpy"`` (reference).

    Examples
    --------
    With α = 1 and β = 0 the worn volume is K ∫∫ p dA dt = K ∫ F dt, K times the normal impulse, 2 m v cos θ for
    an elastic rebound (momentum balance), whatever the pressure's shape:

    >>> import math
    >>> from contact import Material, simulate_impact
    >>> from wear import WearLaw, pressure_history, sliding_speed
    >>> ball = Material(E=380e9, nu=0.23, density=3900.0)
    >>> plate = Material(E=114e9, nu=0.34, density=4430.0)
    >>> impact = simulate_impact(5e-3, ball, plate, speed=3.0, angle=30.0, friction=0.3, history=True)
    >>> law = WearLaw(K=1e-12, alpha=1.0, beta=0.0)
    >>> wm = integrate_wear(pressure_history(impact, "hertz"), sliding_speed(impact), law, density=4430.0)
    >>> impulse = 2.0 * impact.mass * 3.0 * math.cos(math.radians(30.0))  # N s
    >>> bool(abs(wm.volume_m3 / (law.K * impulse) - 1) < 1e-3), bool(wm.mass_kg == 4430.0 * wm.volume_m3)
    (True, True)
    """
    density = check_number("density", density, low=0.0, low_open=True, high=1e5, units="kg/m^3", what="plate density")
    scar_threshold = check_number("scar_threshold", scar_threshold, low=0.0, high=1.0, low_open=True, high_open=True)
    if engine not in ("numba", "numpy"):
        raise ValueError(f"engine={engine!r} is not a valid choice: must be one of 'numba', 'numpy'")
    if on is None:
        x, y = surface_grid(pressure, points_across)
        depth = np.zeros((y.size, x.size))
    else:
        x, y, depth = on.x, on.y, on.depth.copy()
        reach = pressure.max_extent
        if pressure.contact_x.min() - reach < x[0] or pressure.contact_x.max() + reach > x[-1] or reach > y[-1]:
            raise ValueError(
                f"on= grid x in [{x[0]:.6g}, {x[-1]:.6g}] m, |y| <= {y[-1]:.6g} m does not cover this impact's "
                f"contact (centre in [{pressure.contact_x.min():.6g}, {pressure.contact_x.max():.6g}] m, "
                f"radius {reach:.6g} m)"
            )
    dx = float(x[1] - x[0])
    sub = wear_substeps(pressure, speed, law, dx)
    table = powered_table(pressure, law.alpha)
    if not sub.weight.size:
        return wear_map(x, y, depth, density, scar_threshold)
    x0, extent = float(x[0]), pressure.extent
    if speed.is_local:
        rates, dr = _rate_table(speed, pressure)
        if engine == "numba":
            accumulate_local_depth(
                depth,
                x0,
                dx,
                y,
                sub.contact_x,
                sub.step,
                sub.fraction,
                sub.weight,
                sub.slip,
                sub.row,
                extent,
                table,
                rates,
                dr,
                law.beta,
            )
        else:
            accumulate_depth_numpy(depth, x0, dx, y, sub, extent, table, rates, dr, law.beta)
    elif engine == "numba":
        accumulate_depth(depth, x0, dx, y, sub.contact_x, sub.step, sub.fraction, sub.weight, extent, table)
    else:
        accumulate_depth_numpy(depth, x0, dx, y, sub, extent, table)
    return wear_map(x, y, depth, density, scar_threshold)


def _rate_table(speed: SlidingSpeed, pressure: PressureHistory) -> tuple[np.ndarray, float]:
    """The surface's radial rates (m/s, (intervals, 513)) on radii 0 … the largest loaded radius of ``pressure`` (where
    the pressure wears), and their spacing (m)."""
    reach = pressure.max_extent
    rates = speed.radial.rate_table(reach)
    return np.ascontiguousarray(rates), reach / (rates.shape[1] - 1)


def integrate_wear_numpy(pressure: PressureHistory, speed: SlidingSpeed, law: WearLaw, **kwargs) -> WearMap:
    """:func:`integrate_wear` with the plain numpy engine (the benchmark's reference)."""
    return integrate_wear(pressure, speed, law, engine="numpy", **kwargs)


def axisymmetric_wear_depth(pressure: PressureHistory, speed: SlidingSpeed, law: WearLaw, r) -> np.ndarray:
    """Wear depth h(r) (m) of a normal impact at radii ``r`` (m) from the contact centre.

    The same time quadrature as :func:`integrate_wear` evaluated on a radial line (for moving the FE surface
    nodes). Raises ``ValueError`` if the contact centre moves by more than 1% of the largest contact radius.
    """
    r = np.abs(np.asarray(r, dtype=float))
    reach = pressure.max_extent
    travel = float(np.ptp(pressure.contact_x))
    if travel > 0.01 * reach:
        raise ValueError(
            f"contact_x moves by {travel:.6g} m (> 1% of the contact radius {reach:.6g} m): "
            "the axisymmetric wear profile needs a normal impact; use integrate_wear"
        )
    sub = wear_substeps(pressure, speed, law, max(reach, 1e-300))
    powered = PressureHistory(pressure.time, pressure.contact_x, pressure.extent, powered_table(pressure, law.alpha))
    h = np.zeros_like(r)
    if speed.is_local:
        # each radius's speed over the circle about the centre: |v_s e_x − u̇_r e_r|^β averaged over its angle
        rates, dr = _rate_table(speed, pressure)
        angle = np.linspace(0.0, 2.0 * np.pi, 64, endpoint=False)
        offsets = r[:, None] * np.cos(angle)[None, :], r[:, None] * np.sin(angle)[None, :]
    for k, (i0, w1, weight) in enumerate(zip(sub.step, sub.fraction, sub.weight, strict=True)):
        p = (1.0 - w1) * powered.at(i0, r) + w1 * powered.at(i0 + 1, r)
        if speed.is_local:
            rate = np.interp(r, dr * np.arange(rates.shape[1]), rates[sub.row[k]])
            p = p * np.mean(local_speed(sub.slip[k], rate[:, None], *offsets) ** law.beta, axis=1)
        h += weight * p
    return h


def wear_from_impact(
    impact,
    law: WearLaw,
    *,
    pressure: str = "fe",
    speed: str = "sliding",
    fe=None,
    points_across: int = DEFAULT_POINTS_ACROSS,
    scar_threshold: float = 0.01,
    **pressure_options,
) -> WearMap:
    """Wear map of one ``impact`` (a ``contact.ImpactResult`` with its history) in one call.

    ``pressure``: source name of :func:`wear.pressure_history` (``"fe"`` needs ``fe``: the FE pressure table,
    e.g. ``fem.indent_impact``'s result); ``speed``: ``"sliding"`` or ``"kinematic"``; ``pressure_options``
    (``limiting_pressure`` Pa, ``yield_force`` N, ``loading_after_yield``, ``points``) go to
    :func:`wear.pressure_history`. The worn mass uses the plate density ``impact.plate.density`` (kg/m³).

    Examples
    --------
    A normal elastic impact under Hertz's pressure with α = 1, β = 0: the worn volume is K times the normal
    impulse 2 m v (momentum balance), and the deepest wear is at the centre, below the first contact point:

    >>> from contact import Material, simulate_impact
    >>> from wear import WearLaw
    >>> ball = Material(E=380e9, nu=0.23, density=3900.0)
    >>> plate = Material(E=114e9, nu=0.34, density=4430.0)
    >>> impact = simulate_impact(5e-3, ball, plate, speed=3.0, angle=0.0, friction=0.3, history=True)
    >>> wm = wear_from_impact(impact, WearLaw(K=1e-12, alpha=1.0, beta=0.0), pressure="hertz")
    >>> bool(abs(wm.volume_m3 / (1e-12 * 2.0 * impact.mass * 3.0) - 1) < 1e-3)
    True
    >>> bool(float(wm.depth_at(0.0, 0.0)) > 0.99 * wm.max_depth_m)
    True
    """
    if getattr(impact, "history", None) is None:
        raise ValueError("impact.history=None: simulate the impact with history=True to integrate its wear")
    ph = pressure_history(impact, pressure, fe=fe, **pressure_options)
    return integrate_wear(
        ph,
        sliding_speed(impact, speed),
        law,
        density=impact.plate.density,
        points_across=points_across,
        scar_threshold=scar_threshold,
    )
