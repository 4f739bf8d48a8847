r"""Repeated impacts of the same ball at the same spot on the axisymmetric plate, each on the plate the previous
ones left (``fem.model = "axisymmetric"`` of :func:`wear.chain.repeated_impacts.repeat`).

``axisymmetric_repeat(case) -> RepeatResult`` (the repetition's settings are ``case.repeat``,
:class:`wear.case.RepeatSpec`). One FE plate (:class:`fem.Plate`) lives through the whole sequence: it keeps
its plastic strain and residual stress, each impact's contact gap is measured to the dented (and worn) surface,
and the wear of each impact moves the FE mesh's surface nodes before the next one.

**One computed impact** (:func:`impact_on_plate`) is the two-way coupling of :func:`fem.couple` started from the
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
Δᾱ is below ``repeat.shakedown_tolerance`` × the yield strain Y/E (default 1e-3 Y/E). From then on the impact
response is elastic and repeats itself while the surface is unchanged: the next computed impact is solved on the
plate's elastic response (:func:`fem.couple_elastic`, :func:`fem.elastic_reload`: no Newton iterations, the
plate's state unchanged) unless a return mapping of its elastic field yields beyond the tolerance; **cycle jump**:
the last computed impact's wear is applied ``n`` times at once (one block), with n such that the surface moves by at
most ``repeat.surface_fraction`` × the approach δ_e of the last computed impact (its max overlap from first contact),
then the coupled impact is computed again on the new surface (which also checks that it is still shaken down: if
not, back to impact by impact). If no impact shakes down within ``repeat.max_plastic_impacts`` computed one by one
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

import numpy as np
from scipy.interpolate import RegularGridInterpolator
from scipy.ndimage import gaussian_filter1d

import fem
from contact import effective_modulus
from contact.theory import speed_components, sphere_mass
from wear.case import Case
from wear.chain.axisymmetric_run import impact_wear
from wear.chain.check import halfspace_check
from wear.chain.estimate import estimate_impact
from wear.chain.plate import case_plate, coupling_settings, impact_on_law
from wear.chain.records import ComputedImpact, ImpactRecord, RepeatResult, yield_strain
from wear.chain.repeat_loop import SiteImpact, repeat_at_site
from wear.integrate import WearMap, implausible_wear

__all__ = [
    "AZIMUTHS",
    "CONTACT_GROWTH",
    "AxisymmetricSite",
    "ComputedImpact",
    "ImpactRecord",
    "RepeatResult",
    "axisymmetric_repeat",
    "azimuthal_average",
    "impact_on_plate",
    "smooth_profile",
]

#: Azimuths of the azimuthal average of the wear map.
AZIMUTHS = 64
#: The FE mesh keeps its contact resolution out to this × the first impact's contact radius: the seat conforms and
#: the contact widens (2.35× over 10⁴ impacts of the default case; on fem's graded mesh the grown contact edge sat
#: in elements of ~a/4 and the FE peak pressure of a shaken-down impact fell 21% short of the half-space value).
CONTACT_GROWTH = 3.0


def azimuthal_average(wear: WearMap, centre_x: float, r: np.ndarray) -> np.ndarray:
    r"""Average of the wear map's depth (m) on circles of radius ``r`` (m) about (``centre_x``, 0), over
    :data:`AZIMUTHS` azimuths (bilinear interpolation; 0 outside the map)."""
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
    step = width / 8.0
    grid = np.arange(0.0, r[-1] + step, step)
    values = np.interp(grid, r, depth)
    # 'mirror' reflects about the first sample (r = 0): the even extension of an axisymmetric profile
    smooth = gaussian_filter1d(values, sigma=8.0, mode="mirror", truncate=4.0)
    return np.interp(r, grid, smooth)


def _axisymmetric_volume(r: np.ndarray, depth: np.ndarray) -> float:
    return float(np.trapezoid(2.0 * math.pi * r * depth, r))


def impact_on_plate(
    case: Case, fe_plate: fem.Plate, estimate: float, axis_x: float = 0.0, yield_tolerance: float | None = None
) -> ComputedImpact | None:
    """One impact of ``case`` coupled to the FE plate ``fe_plate`` as it is now (:func:`fem.couple`, which commits
    the unloaded state to the plate), and its wear. ``estimate`` (m): the expected approach (max overlap from first
    contact); ``axis_x`` (m): x of the FE axis (the dent centre) in the wear map's frame. With ``yield_tolerance``
    the impact is solved on the plate's elastic response instead (:func:`fem.couple_elastic`, the plate's state
    unchanged), or None when that response yields more than the tolerance (Δᾱ)."""
    args = (fe_plate, impact_on_law(case), estimate, coupling_settings(case))
    if yield_tolerance is None:
        coupled = fem.couple(*args)
    else:
        coupled = fem.couple_elastic(*args, yield_tolerance)
        if coupled is None:
            return None
    wm = impact_wear(case, coupled.impact, coupled.pressure_table, coupled.plastic_work, coupled.radial_table)[1]
    # the ball flies d0·V_t/V_n along x before it touches the dented surface: same spot, shifted first contact
    v_n, v_t = speed_components(case.impact.speed, case.impact.angle)
    wm = replace(wm, x=wm.x + coupled.first_contact * v_t / v_n)
    r = fe_plate.surface_r
    profile = smooth_profile(r, azimuthal_average(wm, axis_x, r), case.repeat.wear_smoothing * coupled.contact_radius)
    vol = _axisymmetric_volume(r, profile)
    if vol > 0.0:
        profile *= wm.volume_m3 / vol
    return ComputedImpact(coupled, wm, profile)


class AxisymmetricSite:
    """The axisymmetric FE plate at the site of a repetition (:class:`wear.chain.repeat_loop.RepeatSite`; module
    docstring): one :class:`fem.Plate` meshed for the case's first impact, its axis at the contact centre of the
    first impact's maximum overlap, moved by the azimuthally averaged wear of each computed impact."""

    cycle_jump = True
    about: tuple[str, ...] = ()

    def __init__(self, case: Case):
        ball, plate = case.ball.material(), case.plate.material()
        if plate.is_rigid:
            raise ValueError("plate.rigid=true: repeated impacts need a deformable FE plate (set plate.rigid = false)")
        self.case = case
        estimate = estimate_impact(case)
        mesh_overlap = (1.0 + case.fem.overshoot) * estimate.max_overlap
        # the wear displacement fades over about one contact radius: the top element rows keep their shape for worn
        # depths up to a fraction of it (the run stops at half of it, see room)
        taper = fem.estimate_contact_radius(case.ball.radius, effective_modulus(ball, plate), plate, mesh_overlap)
        self.plate = case_plate(case, mesh_overlap, growth=CONTACT_GROWTH, taper_depth=taper)
        self.wear_limit = 0.5 * self.plate.taper_depth
        h = estimate.history
        self.axis_x = float(h.contact_x[int(np.argmax(h.overlap))])
        self.tolerance = case.repeat.shakedown_tolerance * yield_strain(case)
        self.expected = estimate.max_overlap
        self.last: ComputedImpact | None = None
        self.met: tuple[np.ndarray, np.ndarray] = ()

    def compute(self, shaken: bool, done: int) -> SiteImpact:
        fe_plate, case = self.plate, self.case
        alpha_before = fe_plate.state.alpha
        self.met = (fe_plate.dent_depth.copy(), fe_plate.wear_depth.copy())
        # a shaken-down plate answers elastically: no plastic problem to solve unless the elastic field yields
        attempt = None
        if shaken and case.repeat.elastic_after_shakedown:
            attempt = impact_on_plate(case, fe_plate, self.expected, self.axis_x, yield_tolerance=self.tolerance)
        last = attempt or impact_on_plate(case, fe_plate, self.expected, self.axis_x)
        self.last, self.expected = last, last.impact.max_overlap
        coupled = last.coupled
        increment = coupled.trial_increment if coupled.elastic else float(np.max(fe_plate.state.alpha - alpha_before))
        profile_max = float(last.wear_profile.max())
        return SiteImpact(
            impact=last.impact,
            wear=last.wear,
            increment=increment,
            max_pressure=coupled.max_pressure,
            contact_radius=coupled.contact_radius,
            first_contact=coupled.first_contact,
            plastic_work=coupled.plastic_work,
            elastic=coupled.elastic,
            surface_change=profile_max,
            peak_to_mean=last.wear.max_depth_m / profile_max if profile_max > 0 else 1.0,
            pressure_at=coupled.peak_pressure_at,
        )

    def first_notes(self, first: SiteImpact) -> list[str]:
        ball_mass = sphere_mass(self.case.ball.radius, self.case.ball.material().density)
        return implausible_wear(first.wear, first.contact_radius, ball_mass)

    def room(self) -> tuple[float, str]:
        why = (
            f"the worn depth would exceed {self.wear_limit:.3g} m, half the depth over which the FE mesh's nodes "
            "follow the wear (about the contact radius); beyond it the small-strain FE plate and its moved mesh are "
            "not valid"
        )
        return self.wear_limit - float(self.plate.wear_depth.max()), why

    def move_surface(self, count: int) -> None:
        self.plate.move_surface(count * self.last.wear_profile)

    def state_fields(self, total: WearMap) -> dict[str, float]:
        fe_plate = self.plate
        return {
            "max_plastic_strain": float(fe_plate.state.alpha.max()),
            "dent_depth": float(fe_plate.dent_depth.max()),
            "surface_depth": float(np.max(fe_plate.dent_depth + fe_plate.wear_depth)),
            "pile_up_height": max(float(np.max(-fe_plate.dent_depth)), 0.0),
        }

    def finish(self, result: RepeatResult) -> RepeatResult:
        result = replace(result, axis_x=self.axis_x, met_surface=self.met)
        return replace(
            result,
            halfspace_check=halfspace_check(result),
            wear_depth_over_taper=float(self.plate.wear_depth.max() / self.plate.taper_depth),
        )


def axisymmetric_repeat(
    case: Case,
    progress: Callable[[int, int], None] | None = None,
    on_computed: Callable[[int, fem.Plate], None] | None = None,
) -> RepeatResult:
    """Run ``case.repeat.impacts`` impacts of ``case`` at one spot on the axisymmetric plate (see the module
    docstring; :func:`wear.chain.repeat_loop.repeat_at_site`); ``progress`` and ``on_computed`` as
    :func:`wear.chain.repeated_impacts.repeat`."""
    t_start = time.perf_counter()
    return repeat_at_site(AxisymmetricSite(case), case, t_start, progress, on_computed)
