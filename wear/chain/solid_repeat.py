r"""Repeated oblique impacts with friction at one site on the 3-D plate (``fem.model = "3d"``; SI units).

One :class:`fem.solid.plate.SolidPlate` lives through the sequence: it keeps its plastic strain, residual stress,
dent and pile-up, and each impact is coupled to it as it is now (:func:`fem.solid_coupling.couple_solid_plate`):
the sphere first touches the dented surface at δ₀ (overlaps from the original plane), the impact runs on the plate's
law from first contact, each coupling cycle restarts from the kept state and the converged impact's lifted-off state
is committed. The slide ξ of each impact starts at 0 at its first contact, with no stick history.

**Where the ball lands.** Every impact is the same ball on the same trajectory: it crosses the original plane where
the first one touched (x = 0 of the plate's frame) and flies d₀·V_t/V_n further along x before it meets the dent
(as the axisymmetric repeat's wear map shift, :mod:`wear.chain.axisymmetric_repeat`), where d₀ is the first-contact
overlap at the site; the impact's contact centres are placed from there.

**The mesh** is built once, from the first impact (the axisymmetric coupled impact of the case, the 3-D coupling's
start, as in :func:`wear.run`), as the single chain's first 3-D cycle meshes it: for its probe overlap over its
contact centres' track (:func:`fem.solid_coupling.solid_cycle`). The contact of a later impact on the conforming
dent reaches a little wider, into the box's graded margin; a mesh sized for 1.2 × the probe overlap (3.7 instead of
4 elements across the contact) met a NaN residual of the 3-D solver's frictional Newton at the second loading step
of the default case (30°, μ = 0.3), where this one converges.

**Where each coupling starts.** The first impact's coupling starts from the axisymmetric coupled impact (as the
single chain's); each later one from the impact run on the dented plate's reloading law, built from the previous
impact's converged law (:func:`fem.force_law.reloading_law`: the last unloading curve reloaded, then the loading
branch beyond it). The previous impact itself, run on the virgin plate, is a poorer start: its path is far from the
dented plate's, and the default case's second impact needed a third plate cycle from it (docs/repeat.md).

**Every impact is computed.** No cycle jump, no elastic shortcut after shakedown: neither is measured for the 3-D
plate, so ``repeat.surface_fraction``, ``max_plastic_impacts``, ``elastic_after_shakedown`` and ``wear_smoothing``
are refused at other than their defaults (:func:`check_solid_repeat`); shakedown (Δᾱ below
``repeat.shakedown_tolerance`` × Y/E) is reported, not used.

**Wear moves the 3-D surface** (``repeat.geometry_update``, as on the axisymmetric plate): the wear of each impact
(:func:`wear.chain.solid.solid_wear`, the 3-D pressure and slip fields, on a 2-D map) lowers the plate's surface at
its surface nodes (:meth:`fem.solid.plate.SolidPlate.move_surface`, the map read bilinearly at the nodes) before the
next impact, whose contact gap is measured to the dented and worn surface; ``surface_depth`` reports the dent plus
the accumulated wear. With ``repeat.geometry_update = false`` the wear is accumulated beside the plate only.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import replace

import numpy as np

from contact import ImpactResult, TabulatedLaw
from fem.force_law import reloading_law
from fem.solid.plate import SolidPlate
from fem.solid_coupling import SolidCoupledImpact, couple_solid_plate, impact_path
from wear.case import Case, RepeatSpec
from wear.chain.axisymmetric_run import on_axisymmetric_plate
from wear.chain.estimate import estimate_impact
from wear.chain.plate import impact_on_law
from wear.chain.plate_model import untimed
from wear.chain.records import RepeatResult
from wear.chain.repeat_loop import SiteImpact, repeat_at_site
from wear.chain.solid import check_solid_case, solid_case, solid_settings, solid_wear
from wear.integrate import WearMap
from wear.solid_wear import solid_dent_depth

__all__ = ["MAX_SOLID_IMPACTS", "SolidSite", "check_solid_repeat", "solid_repeat"]

#: ``repeat`` keys that only steer the cycle jump, the elastic shortcut or the moved surface of the axisymmetric plate.
_AXISYMMETRIC_ONLY = ("surface_fraction", "max_plastic_impacts", "elastic_after_shakedown", "wear_smoothing")


#: Most impacts a 3-D repeat computes: each is a 3-D coupling of 3-10 min on 2 cores on the default mesh
#: (docs/repeat.md), so 20 impacts are already hours; more are refused up front.
MAX_SOLID_IMPACTS = 20


def check_solid_repeat(case: Case) -> None:
    """One-line ``ValueError`` for a repeat the 3-D plate cannot run: the 3-D plate's checks
    (:func:`wear.chain.solid.check_solid_case`), too many impacts, or a cycle-jump key at other than its default
    (module docstring)."""
    check_solid_case(case)
    spec, default = case.repeat, RepeatSpec()
    if spec.impacts > MAX_SOLID_IMPACTS:
        raise ValueError(
            f"repeat.impacts={spec.impacts}: with fem.model='3d' every impact is a 3-D coupling of minutes on 2 cores "
            f"(docs/repeat.md); at most {MAX_SOLID_IMPACTS} impacts"
        )
    for key in _AXISYMMETRIC_ONLY:
        value, kept = getattr(spec, key), getattr(default, key)
        if value != kept:
            raise ValueError(
                f"repeat.{key}={value!r}: with fem.model='3d' every impact is computed (no cycle jump, "
                f"no elastic shortcut, no moved surface); leave it at its default {kept!r}"
            )


def _first_impact(case: Case):
    """The 3-D coupling's start: the case's impact coupled to a virgin axisymmetric plate (as :func:`wear.run`)."""
    return on_axisymmetric_plate(case, estimate_impact(case), untimed).impact


def _next_start(on_law: Callable[[TabulatedLaw], ImpactResult], coupled: SolidCoupledImpact) -> ImpactResult:
    """The start of the next impact's coupling at this site: the impact run on the plate's reloading law after
    ``coupled`` (module docstring)."""
    return on_law(reloading_law(coupled.law))


def _pressure_at_force(coupled: SolidCoupledImpact, force: float) -> float:
    """The 3-D plate's peak pressure (Pa) when its loading passes ``force`` (N); NaN beyond its largest force."""
    solid, upto = coupled.solid, coupled.path.peak + 1
    f = np.maximum.accumulate(solid.normal_force[:upto])
    if force > f[-1]:
        return float("nan")
    return float(np.interp(force, f, solid.max_pressure[:upto]))


class SolidSite:
    """The 3-D plate at the site of a repetition (:class:`wear.chain.repeat_loop.RepeatSite`; module docstring):
    one :class:`fem.solid.plate.SolidPlate` meshed as the single chain's first 3-D cycle, every impact computed."""

    cycle_jump = False

    def __init__(self, case: Case):
        self.case = case
        ball, material = case.ball.material(), case.plate.material()
        self.settings = settings = solid_settings(case)
        self.start = start = _first_impact(case)
        # the mesh of the single chain's first 3-D cycle (module docstring)
        path = impact_path(start, settings.load_steps, settings.unload_steps)
        probe = (1.0 + settings.overshoot) * float(path.overlap[path.peak])
        track = (float(np.min(path.centre)), float(np.max(path.centre)))
        self.plate = SolidPlate(
            case.ball.radius,
            material,
            probe,
            track,
            case.impact.friction,
            None if ball.is_rigid else ball,
            0.0,
            settings.contact_elements,
            settings.box_depth,
        )
        self.flight = math.tan(math.radians(case.impact.angle))  # V_t/V_n of the incoming ball
        self.on_law = impact_on_law(case)
        self.axis_x: float | None = None
        self.coupled: SolidCoupledImpact | None = None
        self.wear: WearMap | None = None
        moved = "moves the plate's surface" if case.repeat.geometry_update else "is accumulated beside the plate"
        self.about = (f"fem.model='3d': every impact computed on the 3-D plate (no cycle jump); the wear {moved}",)

    def compute(self, shaken: bool, done: int) -> SiteImpact:
        plate, case = self.plate, self.case
        alpha_before = plate.state.alpha
        offset = plate.first_contact_overlap(0.0) * self.flight
        coupled = couple_solid_plate(self.on_law, self.start, plate, self.settings, offset)
        if done + 1 < case.repeat.impacts:
            self.start = _next_start(self.on_law, coupled)
        wm = solid_wear(case, coupled)[1]
        if self.axis_x is None:
            self.axis_x = float(coupled.solid.centre[coupled.path.peak])
        self.coupled, self.wear = coupled, wm
        solid = coupled.solid
        return SiteImpact(
            impact=coupled.impact,
            wear=wm,
            increment=float(np.max(plate.state.alpha - alpha_before, initial=0.0)),
            max_pressure=float(np.max(solid.max_pressure)),
            contact_radius=float(np.max(solid.contact_radius)),
            first_contact=coupled.first_contact,
            plastic_work=coupled.plastic_work,
            elastic=False,
            surface_change=wm.max_depth_m,
            peak_to_mean=1.0,
            pressure_at=lambda force: _pressure_at_force(coupled, force),
        )

    def first_notes(self, first: SiteImpact) -> list[str]:
        return []

    def room(self) -> tuple[float, str]:
        return math.inf, "the 3-D plate's surface follows any wear"

    def move_surface(self, count: int) -> None:
        xy = self.plate.surface_xy
        self.plate.move_surface(count * self.wear.depth_at(xy[:, 0], xy[:, 1]))

    def state_fields(self, total: WearMap) -> dict[str, float]:
        plate = self.plate
        dent = solid_dent_depth(self.coupled.field, total.x, total.y)
        return {
            "max_plastic_strain": float(np.max(plate.state.alpha)),
            "dent_depth": plate.dent_depth,
            "surface_depth": float(np.max(dent.T + total.depth)),
            "pile_up_height": plate.pile_up_height,
        }

    def finish(self, result: RepeatResult) -> RepeatResult:
        return replace(result, axis_x=self.axis_x)


def solid_repeat(
    case: Case,
    progress: Callable[[int, int], None] | None = None,
    on_computed: Callable[[int, SolidPlate], None] | None = None,
) -> RepeatResult:
    """Run ``case.repeat.impacts`` impacts of ``case`` at one site on the 3-D plate (module docstring;
    :func:`wear.chain.repeat_loop.repeat_at_site`). ``progress(done, total)`` and ``on_computed(impact_number,
    plate)`` after each impact."""
    check_solid_repeat(case)
    case = solid_case(case)
    t_start = time.perf_counter()
    return repeat_at_site(SolidSite(case), case, t_start, progress, on_computed)
