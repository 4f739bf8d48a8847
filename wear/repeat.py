r"""Repeated impacts of the same ball at the same spot, each on the plate the previous ones left (issue 6 §1).

``repeat(case, spec) -> RepeatResult``. One FE plate (:class:`fem.Plate`) lives through the whole sequence: it keeps
its plastic strain and residual stress, each impact's contact gap is measured to the dented (and worn) surface,
and the wear of each impact moves the FE mesh's surface nodes before the next one.

**One computed impact** (:func:`impact_on_plate`) is the two-way coupling of :mod:`wear.coupling` started from the
plate's current state: the FE plate is loaded once past the expected maximum overlap, the impact runs on that
loading branch, the plate is unloaded from the impact's maximum (``fem.Plate.unload``: its final, unloaded state is
the next impact's start), and the impact is re-run on the loading + unloading law until δ_max changes by less than
``fem.tolerance``. Overlaps: the FE measures δ from the original plane z = 0; on a dented plate the sphere first
touches the surface at δ₀ = :meth:`fem.Plate.first_contact_overlap` (≈ dent + wear depth at the centre). The
impact engine integrates from first contact, so its law is the FE law shifted by δ₀ (δ' = δ − δ₀); its F = 0
free flight from δ = 0 to δ₀ is not simulated. The ball travels d₀·V_t/V_n along x during that flight, so the
impact's wear map is shifted by that much (same ball, same trajectory, deeper first contact).

**Wear → FE surface.** The wear map is 2-D (x along the impact, y across) while the FE plate is axisymmetric
about the dent centre (the contact centre at the first impact's maximum overlap): the FE surface nodes move by
the azimuthal average of the wear depth at their radius (64 azimuths, rescaled so ∫2πr w̄ dr equals the map's
volume). For an oblique impact the scar is elongated, so the averaged depth is shallower than the map's maximum:
each record reports ``wear_peak_to_mean``, the map's max depth over the averaged profile's max (1 for a normal
impact).

**Shakedown.** An impact is *shaken down* when its largest pointwise increment of equivalent plastic strain
Δᾱ is below ``spec.shakedown_tolerance`` × the yield strain Y/E (default 1e-3 Y/E). From then on the impact
response is elastic and repeats itself while the surface is unchanged: the next computed impact is solved on the
plate's elastic response (:func:`elastic_impact_on_plate`, :func:`fem.elastic_reload`: no Newton iterations, the
plate's state unchanged) unless a return mapping of its elastic field yields beyond the tolerance; **cycle jump**:
the last computed impact's wear is applied ``n`` times at once (one block), with n such that the surface moves by at
most ``spec.surface_fraction`` × the approach δ_e of the last computed impact (its max overlap from first contact),
then the coupled impact is computed again on the new surface (which also checks that it is still shaken down: if
not, back to impact by impact). If no impact shakes down within ``spec.max_plastic_impacts`` computed one by one
(e.g. wear keeps changing the seat, so each impact yields a little), the run says so and goes on with blocks
anyway, one computed impact between blocks; the plastic strain increments of block impacts are then reported
(the last computed one's) but not added to the FE plate.

Why a fraction of the approach and not of a: the pressure is set by the gap profile between ball and surface
inside the contact, whose scale is the approach δ_e (a²/R on a flat, where the sphere's gap at the contact edge is
a²/2R; a²/R_eff on a conforming seat, 1/R_eff = 1/R − 1/R_seat, much less than a²/R). A surface change Δh = f·δ_e
changes that profile, hence the pressure, by a fraction of order f; the contact radius is 20–50 times longer than
δ_e, so a fraction of it would let the wear change the pressure by order one between re-solves (measured: a worn
depth of 0.12 δ_e lowers the max pressure of an elastic oblique impact by 21%, tests/test_repeat.py). Measuring
blocks by a²/R instead let them grow tenfold too large on the default case's conforming seat (after 10⁴ impacts
δ_e = 0.07 a²/R): a block of 962 impacts turned an elastic re-impact (e_n 0.9993) into a yielding one (0.972).
Without geometry update the surface never changes after shakedown and the remaining impacts are one block
(N impacts wear exactly N × one impact after shakedown). The cycle-jump error, measured on the default case over
2000 impacts against fraction 0.025: 0.3% on the surface depth at 0.1 (the default), 1.1% at 0.2, 7–13% at 0.4.

SI units throughout.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import replace
from types import SimpleNamespace
from typing import Any

import numpy as np

from contact import TabulatedLaw, effective_modulus
from contact.impact import ForceLawRangeError

from .coupling import UNLOAD_MARGIN, _first_yield_overlap, _inside_contact, _loading_path, _run_impact, fe_mesh
from .coupling import pressure_table as _pressure_table
from .integrate import WearMap
from .pipeline import impact_wear
from .repeat_records import ComputedImpact, ImpactRecord, RepeatResult, RepeatSpec, _yield_strain

__all__ = ["RepeatSpec", "ImpactRecord", "RepeatResult", "ComputedImpact", "impact_on_plate",
           "elastic_impact_on_plate", "repeat", "azimuthal_average", "smooth_profile"]  # fmt: skip

#: Azimuths of the azimuthal average of the wear map.
AZIMUTHS = 64
#: The FE mesh keeps its contact resolution out to this × the first impact's contact radius: the seat conforms and
#: the contact widens (2.35× over 10⁴ impacts of the default case; on fem's graded mesh the grown contact edge sat
#: in elements of ~a/4 and the FE peak pressure of a shaken-down impact fell 21% short of the half-space value).
CONTACT_GROWTH = 3.0


def azimuthal_average(wear: WearMap, centre_x: float, r: np.ndarray) -> np.ndarray:
    r"""Average of the wear map's depth (m) on circles of radius ``r`` (m) about (``centre_x``, 0), over
    :data:`AZIMUTHS` azimuths (bilinear interpolation; 0 outside the map)."""
    from scipy.interpolate import RegularGridInterpolator

    theta = (np.arange(AZIMUTHS) + 0.5) * 2.0 * math.pi / AZIMUTHS
    x = centre_x + r[:, None] * np.cos(theta)[None, :]
    y = r[:, None] * np.sin(theta)[None, :]
    f = RegularGridInterpolator((wear.y, wear.x), wear.depth, bounds_error=False, fill_value=0.0)
    return f(np.stack([y.ravel(), x.ravel()], axis=1)).reshape(x.shape).mean(axis=1)


def smooth_profile(r: np.ndarray, depth: np.ndarray, width: float) -> np.ndarray:
    r"""``depth`` (m) on the radii ``r`` (m, sorted, from the axis) smoothed by a Gaussian of standard deviation
    ``width`` (m) along r, even about the axis: resampled on a uniform grid of width/8, filtered, interpolated back.

    Why: the wear → geometry → pressure loop is an explicit update, and its gain at wavelength λ is about
    :math:`\Delta w/\Delta p \cdot \pi E^*/\lambda` per block (the elastic pressure of a surface ripple of
    wavelength λ is πE*/λ times its amplitude). At the FE node scale (λ ≈ 2 elements) a single impact of the default
    case is near the limit (gain ≈ 1; a block of n impacts multiplies it by n), so a node-to-node ripple of the FE
    pressure (P2 vertex vs mid-side) grows from impact to impact: measured on an elastic 30° case, 3% → 30% → 61%
    of the peak in three computed impacts. A filter of width 0.1a removes wavelengths below ~a/3 (factor
    exp(−(2πσ/λ)²/2) < 1e-2 for λ < 0.2a) and keeps the contact-scale shape the pressure follows (λ = a: 0.82)."""
    if width <= 0.0 or r.size < 3:
        return depth.copy()
    from scipy.ndimage import gaussian_filter1d

    step = width / 8.0
    grid = np.arange(0.0, r[-1] + step, step)
    values = np.interp(grid, r, depth)
    # 'mirror' reflects about the first sample (r = 0): the even extension of an axisymmetric profile
    smooth = gaussian_filter1d(values, sigma=8.0, mode="mirror", truncate=4.0)
    return np.interp(r, grid, smooth)


def _axisymmetric_volume(r: np.ndarray, depth: np.ndarray) -> float:
    return float(np.trapezoid(2.0 * math.pi * r * depth, r))


def _shifted_loading(res, d0: float):
    d = np.asarray(res.overlap, float) - d0
    f = np.maximum(np.asarray(res.force, float), 0.0)
    a = np.maximum(np.asarray(res.contact_radius, float), 0.0)
    k = int(np.argmax(d))
    d, f, a = d[: k + 1], f[: k + 1], a[: k + 1]
    keep = (d > 0.0) & np.concatenate([[True], np.diff(d) > 0])
    return np.r_[0.0, d[keep]], np.r_[0.0, f[keep]], np.r_[0.0, a[keep]]


def _law(loading, d0: float, unloading=None, e_star: float | None = None, points: int = 41) -> TabulatedLaw:
    """The FE law from first contact (δ' = δ − δ₀): the loading branch and the unloading curve from its top
    (``unloading``; or, without one, a provisional elastic Hertz-form curve with dF/dδ = 2E*a, which cannot change
    δ_max: see :func:`wear.coupling.provisional_law`)."""
    d, f, a = _shifted_loading(loading, d0)
    if unloading is None:
        d_star, f_star, a_star = d[-1], f[-1], a[-1]
        drop = min(3.0 * f_star / (4.0 * e_star * max(a_star, 1e-300)), d_star)
        s = np.linspace(1.0, 0.0, points)
        return TabulatedLaw(d, f, a, np.array([d_star]), (d_star - drop + s * drop)[None, :],
                            (f_star * s**1.5)[None, :], (a_star * np.sqrt(s))[None, :])  # fmt: skip
    top, grid, force, radius = unloading._unloading_curve(points)
    top -= d0
    grid = grid - d0
    end = max(float(grid[-1]), 0.0)
    # F^(2/3) is linear in δ near separation (Hertz-like); a residual overlap below first contact (numerical
    # noise of a shaken-down plate) closes the curve at δ' = 0
    g = np.interp(np.linspace(top, end, points)[::-1], grid[::-1], force[::-1] ** (2.0 / 3.0))[::-1] ** 1.5
    r = np.interp(np.linspace(top, end, points)[::-1], grid[::-1], radius[::-1])[::-1]
    g[-1], r[-1] = 0.0, 0.0
    return TabulatedLaw(d, f, a, np.array([top]), np.linspace(top, end, points)[None, :], g[None, :], r[None, :])


def _fe_cycle(loading, unloading, d0: float, d_star: float):
    """Loading steps below δ* and the unloading, overlaps from first contact, for :func:`wear.coupling
    .pressure_table`."""
    d = np.asarray(loading.overlap, float)
    k = int(np.searchsorted(d, d_star * (1.0 - 1e-12)))
    cat = lambda name: np.concatenate([np.asarray(getattr(loading, name), float)[:k],  # noqa: E731
                                       np.asarray(getattr(unloading, name), float)])  # fmt: skip
    return SimpleNamespace(
        overlap=cat("overlap") - d0,
        contact_radius=cat("contact_radius"),
        pressure=np.vstack([np.asarray(loading.pressure, float)[:k], np.asarray(unloading.pressure, float)]),
        surface_r=np.asarray(unloading.surface_r, float),
    )


def _loading_past_the_impact(case, ball, plate, d0: float, estimate: float, load, e_star: float):
    """(loading, law, impact): ``load(target)`` (an FE loading from first contact ``d0`` to ``d0`` + target, m) run
    (1 + ``fem.overshoot``) past ``estimate`` (m), further until the impact on its law stops short of the table's
    end; None after four tries."""
    target = (1.0 + case.fem.overshoot) * estimate
    for _ in range(4):
        loading = load(target)
        law = _law(loading, d0, e_star=e_star)
        try:
            impact = _run_impact(case, ball, plate, law)
        except ForceLawRangeError:
            # the engine stops where the overlap leaves the table: after a cycle-jump block the surface (hence the
            # depth an impact reaches) can change by more than the overshoot allows for
            target *= 1.5
            continue
        if impact.max_overlap * (1.0 + 2.0 * UNLOAD_MARGIN) < float(law.loading_overlap[-1]):
            return loading, law, impact
        target = 1.3 * impact.max_overlap
    return None


def impact_on_plate(case, fe_plate, estimate: float, axis_x: float = 0.0, unload_steps: int | None = None,
                    smoothing: float = 0.1):  # fmt: skip
    """One two-way coupled impact of ``case`` on the FE plate ``fe_plate`` (:class:`fem.Plate`) as it is now;
    commits the unloaded state to the plate. ``estimate`` (m): expected max overlap from first contact (the
    loading goes (1 + ``fem.overshoot``) past it; further if the impact goes deeper). ``axis_x`` (m): x of the
    FE axis (the dent centre) in the wear map's frame; ``smoothing``: width of the filter of the wear profile
    (× the contact radius, :func:`smooth_profile`). Returns a :class:`ComputedImpact`."""
    ball, plate = case.ball.material(), case.plate.material()
    e_star = effective_modulus(ball, plate)
    d0 = fe_plate.first_contact_overlap()
    first_yield = _first_yield_overlap(case, ball, plate) if d0 == 0.0 else None

    def load(target):
        return fe_plate.load(d0 + _loading_path(target, case.fem.load_steps, first_yield))

    solved = _loading_past_the_impact(case, ball, plate, d0, estimate, load, e_star)
    if solved is None:
        raise ValueError(f"the impact keeps going past the FE loading (four loadings from {estimate:.4g} m past "
                         "first contact, each deeper)")  # fmt: skip
    loading, law, impact = solved
    overlaps, change, iterations = [impact.max_overlap], math.inf, 1
    while iterations < case.fem.max_iterations:
        d_star = overlaps[-1] * (1.0 + UNLOAD_MARGIN)
        unloading = _unload(case, fe_plate, loading, d0 + d_star, unload_steps or case.fem.unload_steps)
        law = _law(loading, d0, unloading)
        impact = _run_impact(case, ball, plate, law)
        iterations += 1
        overlaps.append(impact.max_overlap)
        change = abs(overlaps[-1] - overlaps[-2]) / overlaps[-2]
        if change < case.fem.tolerance:
            break
    return _finish(case, fe_plate, impact, law, loading, unloading, d0, d_star, axis_x, smoothing, iterations,
                   change)  # fmt: skip


def elastic_impact_on_plate(case, fe_plate, estimate: float, tolerance: float, axis_x: float = 0.0,
                            smoothing: float = 0.1):  # fmt: skip
    """One impact of ``case`` on the FE plate's elastic response (:func:`fem.elastic_reload`: its state is not
    changed, the reloading and unloading retrace each other), or None when the elastic field yields: a return
    mapping of any loading step up to the impact's maximum gives Δᾱ > ``tolerance`` (then the plastic problem must
    be solved, :func:`impact_on_plate`). Arguments as :func:`impact_on_plate`. Exact, on the FE's own mesh, for a
    plate that does not yield (tests/test_repeat.py: every record equal to the elastic–plastic FE's within 1e-4)."""
    import fem

    ball, plate = case.ball.material(), case.plate.material()
    d0 = fe_plate.first_contact_overlap()
    reloads = []

    def load(target):
        reloads.append(fem.elastic_reload(fe_plate, d0 + _loading_path(target, case.fem.load_steps, None)))
        return reloads[-1].result

    solved = _loading_past_the_impact(case, ball, plate, d0, estimate, load, fe_plate.effective_modulus)
    if solved is None:
        return None
    loading, law, impact = solved
    reload = reloads[-1]
    d_star = impact.max_overlap * (1.0 + UNLOAD_MARGIN)
    # steps past the impact's maximum were never reached: their trial plastic strain does not count
    reached = np.asarray(loading.overlap) <= d0 + d_star
    trial = float(np.max(reload.trial_plastic_strain_increment[reached], initial=0.0))
    if trial > tolerance:
        return None
    steps = case.fem.unload_steps
    down = np.linspace(d0 + d_star, max(0.0, d0 - 0.05 * d_star), steps + 1)
    unloading = fem.elastic_reload(fe_plate, down, check_yield=False).result
    law = _law(loading, d0, unloading)
    first = impact.max_overlap
    impact = _run_impact(case, ball, plate, law)
    change = abs(impact.max_overlap - first) / first
    solved = _finish(case, fe_plate, impact, law, loading, unloading, d0, d_star, axis_x, smoothing, 2, change)
    return replace(solved, elastic=True, trial_increment=trial)


def _finish(case, fe_plate, impact, law, loading, unloading, d0, d_star, axis_x, smoothing, iterations,
            change) -> ComputedImpact:  # fmt: skip
    """The solved impact's pressure table, wear map (shifted to the first impact's frame) and the smoothed,
    azimuthally averaged wear profile on the FE surface nodes."""
    cycle = _fe_cycle(loading, unloading, d0, d0 + d_star)
    table = _pressure_table(cycle, impact)
    wm = impact_wear(case, impact, table)[1]
    # the ball flies d0·V_t/V_n along x before it touches the dented surface: same spot, shifted first contact
    v_n = case.impact.speed * math.cos(math.radians(case.impact.angle))
    v_t = case.impact.speed * math.sin(math.radians(case.impact.angle))
    shift = d0 * v_t / v_n
    wm = replace(wm, x=wm.x + shift)
    r = fe_plate.surface_r
    contact_radius = float(np.interp(d0 + d_star, loading.overlap, loading.contact_radius))
    profile = smooth_profile(r, azimuthal_average(wm, axis_x, r), smoothing * contact_radius)
    vol = _axisymmetric_volume(r, profile)
    if vol > 0.0:
        profile *= wm.volume_m3 / vol
    p_in = _inside_contact(cycle.pressure, cycle.surface_r, cycle.contact_radius)
    p_loading = _inside_contact(np.asarray(loading.pressure, float), cycle.surface_r, loading.contact_radius)
    return ComputedImpact(
        impact=impact,
        law=law,
        loading=loading,
        unloading=unloading,
        first_contact=d0,
        wear=wm,
        wear_profile=profile,
        max_pressure=float(p_in.max()),
        contact_radius=contact_radius,
        iterations=iterations,
        change=change,
        peak_pressure_curve=(np.asarray(loading.force, float), p_loading.max(axis=1)),
    )


def _unload(case, fe_plate, loading, max_overlap: float, steps: int):
    """``fe_plate.unload``; if fem does not converge near the loss of contact (a known weakness of its unloading
    from a plastic dent), once more with twice the steps before giving up (fem.ConvergenceError)."""
    import fem

    try:
        return fe_plate.unload(loading, max_overlap, steps=steps)
    except fem.ConvergenceError:
        return fe_plate.unload(loading, max_overlap, steps=2 * steps)


class _Accumulator:
    """Cumulative 2-D wear on a grid of the first impact's spacing, at first its grid padded by half its size on each
    side, extended (zeros) whenever a later impact's map reaches past it — the scar widens as the seat conforms
    (contact radius 0.18 → 0.43 mm over 10⁴ impacts of the default case), and wear outside the grid would be lost."""

    def __init__(self, first: WearMap):
        h = first.spacing
        pad_x = (first.x.size // 2) * h
        pad_y = (first.y.size // 2) * h
        self.x = np.arange(first.x[0] - pad_x, first.x[-1] + pad_x + 0.5 * h, h)
        ny = int(round((first.y[-1] + pad_y) / h))
        self.y = np.arange(-ny, ny + 1) * h
        self.depth = np.zeros((self.y.size, self.x.size))
        self.density = first.density

    def _cover(self, wm: WearMap) -> None:
        h = self.x[1] - self.x[0]
        left = max(0, math.ceil((self.x[0] - wm.x[0]) / h - 1e-9))
        right = max(0, math.ceil((wm.x[-1] - self.x[-1]) / h - 1e-9))
        half = (self.y.size - 1) // 2
        ny = max(half, math.ceil(max(abs(wm.y[0]), abs(wm.y[-1])) / h - 1e-9))
        if left or right or ny > half:
            self.x = self.x[0] + (np.arange(self.x.size + left + right) - left) * h
            self.y = np.arange(-ny, ny + 1) * h
            self.depth = np.pad(self.depth, ((ny - half, ny - half), (left, right)))

    def add(self, wm: WearMap, count: int) -> None:
        from scipy.interpolate import RegularGridInterpolator

        self._cover(wm)

        f = RegularGridInterpolator((wm.y, wm.x), wm.depth, bounds_error=False, fill_value=0.0)
        yy, xx = np.meshgrid(self.y, self.x, indexing="ij")
        self.depth += count * f(np.stack([yy.ravel(), xx.ravel()], axis=1)).reshape(yy.shape)

    def map(self) -> WearMap:
        from .integrate import _finish

        return _finish(self.x, self.y, self.depth.copy(), self.density, 0.01)


def repeat(case, spec: RepeatSpec, progress: Callable[[int, int], None] | None = None,
           on_computed: Callable[[int, Any], None] | None = None) -> RepeatResult:  # fmt: skip
    """Run ``spec.impacts`` impacts of ``case`` at one spot (see the module docstring). ``progress(done, total)``
    after each computed impact or block; ``on_computed(impact_number, fe_plate)`` after each computed impact
    (e.g. to write the FE mesh)."""
    import fem

    from .pipeline import Case, _impact

    if not isinstance(case, Case):
        raise ValueError(f"case={type(case).__name__} is not a wear.pipeline.Case")
    if not isinstance(spec, RepeatSpec):
        raise ValueError(f"spec={type(spec).__name__} is not a wear.repeat.RepeatSpec")
    ball, plate = case.ball.material(), case.plate.material()
    if plate.is_rigid:
        raise ValueError("plate.rigid=true: repeated impacts need a deformable FE plate (set plate.rigid = false)")
    t_start = time.perf_counter()
    estimate = _impact(case, ball, plate)
    mesh_overlap = (1.0 + case.fem.overshoot) * estimate.max_overlap
    mesh = fe_mesh(case, ball, plate, mesh_overlap, growth=CONTACT_GROWTH)
    ball_arg = None if ball.is_rigid else ball
    # the wear displacement fades over about one contact radius: the top element rows keep their shape for worn
    # depths up to a fraction of it (the run stops at half of it, see below)
    taper = fem.estimate_contact_radius(case.ball.radius, effective_modulus(ball, plate), plate, mesh_overlap)
    fe_plate = fem.Plate(case.ball.radius, plate, mesh_overlap, ball=ball_arg, mesh=mesh, taper_depth=taper)
    wear_limit = 0.5 * fe_plate.taper_depth
    h = estimate.history
    axis_x = float(h.contact_x[int(np.argmax(h.overlap))])
    tolerance = spec.shakedown_tolerance * _yield_strain(case)
    records: list[ImpactRecord] = []
    notes: list[str] = []
    acc = None
    done, computed, shakedown, plastic_run = 0, 0, None, 0
    last = None
    shaken = False
    gave_up = False  # no shakedown within max_plastic_impacts: blocks go on, one computed impact between them
    last_increment = 0.0
    d_est = estimate.max_overlap
    while done < spec.impacts:
        if last is None or not (shaken or gave_up) or records[-1].kind == "block":
            kind, count = "computed", 1
        else:
            kind = "block"
            count = spec.impacts - done
            change = float(last.wear_profile.max())
            if spec.geometry_update and change > 0.0:
                approach = last.impact.max_overlap  # from first contact: a²/R on a flat, less on a seat
                count = max(1, min(count, int(spec.surface_fraction * approach / change)))
        if kind == "computed":
            alpha_before = fe_plate.state.alpha
            met = (fe_plate.dent_depth.copy(), fe_plate.wear_depth.copy())
            # a shaken-down plate answers elastically: no plastic problem to solve unless the elastic field yields
            attempt = None
            if shaken and spec.elastic_after_shakedown:
                attempt = elastic_impact_on_plate(case, fe_plate, d_est, tolerance, axis_x, spec.wear_smoothing)
            last = attempt or impact_on_plate(case, fe_plate, d_est, axis_x, smoothing=spec.wear_smoothing)
            d_est = last.impact.max_overlap
            computed += 1
            increment = last.trial_increment if last.elastic else float(np.max(fe_plate.state.alpha - alpha_before))
            shaken = increment <= tolerance
            if shaken and shakedown is None:
                shakedown = done + 1
            plastic_run = 0 if shaken else plastic_run + 1
            last_increment = increment
            if not shaken and not gave_up and plastic_run >= spec.max_plastic_impacts:
                notes.append(
                    f"no shakedown after {plastic_run} impacts computed one by one (Δᾱ = {increment:.3g} > "
                    f"{tolerance:.3g}): from impact {done + 2} on, cycle-jump blocks extrapolate the last computed "
                    "impact's wear anyway (one computed impact between blocks; the plastic strain increments of "
                    "block impacts are not added to the FE plate)"
                )
                gave_up = True
        else:
            # shaken down: elastic response; after giving up: the last computed impact's increment, per impact
            increment = 0.0 if shaken else last_increment
        step_depth = float(last.wear_profile.max())
        if spec.geometry_update and step_depth > 0.0:
            room = wear_limit - float(fe_plate.wear_depth.max())
            if count * step_depth > room:
                count = int(room / step_depth)
                if count < 1:
                    notes.append(f"stopped after impact {done}: the worn depth would exceed {wear_limit:.3g} m, half "
                                 "the depth over which the FE mesh's nodes follow the wear (about the contact radius);"
                                 " beyond it the small-strain FE plate and its moved mesh are not valid")  # fmt: skip
                    break
        if acc is None:
            acc = _Accumulator(last.wear)
        acc.add(last.wear, count)
        if spec.geometry_update:
            fe_plate.move_surface(count * last.wear_profile)
        done += count
        total = acc.map()
        imp = last.impact
        profile_max = float(last.wear_profile.max())
        records.append(
            ImpactRecord(
                first=done - count + 1,
                last=done,
                count=count,
                kind=kind,
                normal_restitution=imp.normal_restitution,
                max_force=imp.max_force,
                max_pressure=last.max_pressure,
                contact_radius=last.contact_radius,
                max_overlap=imp.max_overlap,
                first_contact_overlap=last.first_contact,
                plastic_strain_increment=increment,
                wear_volume=last.wear.volume_m3,
                wear_max_depth=last.wear.max_depth_m,
                max_plastic_strain=float(fe_plate.state.alpha.max()),
                dent_depth=float(fe_plate.dent_depth.max()),
                total_wear_volume=total.volume_m3,
                total_wear_max_depth=total.max_depth_m,
                surface_depth=float(np.max(fe_plate.dent_depth + fe_plate.wear_depth)),
                wear_peak_to_mean=last.wear.max_depth_m / profile_max if profile_max > 0 else 1.0,
                shaken_down=bool(shaken),
                max_pressure_at_first_force=last.peak_pressure_at(records[0].max_force if records else imp.max_force),
                elastic_response=last.elastic,
            )
        )
        if kind == "computed" and on_computed is not None:
            on_computed(done, fe_plate)
        if progress is not None:
            progress(done, spec.impacts)
    if shakedown is None:
        notes.append(f"no impact without new plastic strain (tolerance Δᾱ <= {tolerance:.3g})")
    return RepeatResult(case, spec, records, fe_plate, acc.map(), shakedown, computed,
                        time.perf_counter() - t_start, notes, axis_x, met)  # fmt: skip
