r"""The oblique impact ⇄ 3-D plate coupling (SI units).

The impact engine integrates the ball; the 3-D plate (:mod:`fem.solid.indentation`) answers with its normal force and
contact radius along the impact's own path. One coupling iteration:

1. take the path of the impact (:func:`impact_path`): the normal overlap δ(t), the contact centre c(t) (the point
   under the ball's centre, ``contact_x``) and the slide ξ(t) = ∫ (v_t − Rω) dt of the ball's surface in contact
   (the slip velocity's time integral), sampled at ``load_steps`` overlaps up to δ_max (denser near the start) and
   ``unload_steps`` normal-force levels down to separation, then the ball lifted off;
2. press and drag the sphere over the 3-D plate along it with the impact's friction μ (stick and slip; the same μ
   as the impact's Coulomb limit), plus one probe step past δ_max (``overshoot``) so that the next impact may go a
   little deeper on the plate's loading branch;
3. run the impact again on the 3-D plate's law (contact's ``"tabulated"`` model: F(δ) and a(δ) on loading, the
   unloading curve from the top; the tangential law then has the 3-D contact radius and normal force);
4. repeat while δ_max or the tangential restitution e_t change by more than ``tolerance`` (relative for δ_max,
   absolute for e_t) between impact runs: the fixed point of :func:`fem.coupling.fixed_point` on the plate's
   :class:`PathCycles`.

Unlike the axisymmetric frictionless plate, the loading branch of the 3-D plate depends on the path (friction and
the moving centre), so every iteration runs the whole path. Started from the axisymmetric coupled impact (whose
normal law is the 3-D one's within about 1 %), one or two iterations normally suffice.

The impact's tangential law is the one ``impact_on_law`` runs: in the chain the plate's own, Mindlin–Deresiewicz
partial slip with memory (``wear.chain.solid.solid_case``), fed by the 3-D plate's normal force and contact radius
and limited, like the plate's slip traction, by the plate surface's shear strength (Orowan's τ = min(μp, k),
:mod:`fem.solid.friction`; the law carries it as ``TabulatedLaw.shear_strength``). The 3-D plate's tangential force
along the path (``solid.tangential_force``) is compared with the impact's
(:attr:`SolidCoupledImpact.tangential_mismatch`), the measure of what the law misses.

**On a used plate** (:func:`couple_solid_plate`, repeated impacts at one site): the same loop on a
:class:`fem.solid.plate.SolidPlate` that keeps its state. Every cycle starts from the plate's kept state (the previous
impacts' dent, pile-up, plastic strain and residual stress) and only the converged impact's final, lifted-off state
is committed. Overlaps: the plate measures δ from its original plane; on a dented plate the sphere first touches
the surface at δ₀ = :meth:`fem.solid.plate.SolidPlate.first_contact_overlap`, and the impact engine integrates from
first contact, so the path is pressed at δ₀ + δ' and the law is the plate's shifted by δ₀ (as the axisymmetric
coupling, :mod:`fem.coupling`). The slide ξ of the new impact counts from its first contact, with no stick history
(:meth:`fem.solid.plate.SolidPlate.start_state`); its contact centres are placed at the site's point of first
contact (``centre_offset`` in the plate's frame).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace

import numpy as np
from scipy.integrate import cumulative_trapezoid

from contact import ImpactResult, Material, TabulatedLaw
from contact.checks import check_friction
from contact.fields import SurfaceField
from fem.core.increments import WorkCounters
from fem.coupling import fixed_point
from fem.force_law import force_law, with_unloading_from
from fem.solid.indentation import SolidIndentation, solid_solver
from fem.solid.plate import SolidPlate, press_path, solid_plastic_work
from fem.solid.solver import SolidSolver
from fem.solid.state import SolidState

__all__ = [
    "ImpactPath",
    "PathCycles",
    "SolidCouplingSettings",
    "SolidCoupledImpact",
    "couple_solid",
    "couple_solid_plate",
    "impact_path",
    "place_steps",
    "plate_cycle",
    "solid_cycle",
]


@dataclass(frozen=True)
class SolidCouplingSettings:
    """The 3-D coupling's numbers: ``tolerance`` (relative change of δ_max and absolute change of e_t between
    impact runs), ``max_iterations`` (3-D plate cycles), the increments ``load_steps`` and ``unload_steps``, the
    probe step's ``overshoot`` past δ_max (relative), ``contact_elements`` across the largest contact radius and the
    refined box's ``box_depth`` (in contact radii, :func:`fem.solid.mesh.generate_block`)."""

    tolerance: float = 0.005
    max_iterations: int = 3
    load_steps: int = 10
    unload_steps: int = 6
    overshoot: float = 0.1
    contact_elements: int = 4
    box_depth: float = 1.0


@dataclass(frozen=True)
class ImpactPath:
    """The path of an impact sampled for the plate: per step the impact ``time`` (s), ``overlap`` δ, contact
    ``centre`` c and ``slide`` ξ (m); ``peak`` the index of δ_max."""

    time: np.ndarray
    overlap: np.ndarray
    centre: np.ndarray
    slide: np.ndarray
    peak: int


def impact_path(impact: ImpactResult, load_steps: int, unload_steps: int) -> ImpactPath:
    r"""The path of ``impact`` (with histories) for the 3-D plate: ``load_steps`` overlaps
    δ_max (k/n)^{3/2} on the loading branch (F ∝ δ^{3/2} curves most at the start), ``unload_steps`` normal forces
    F_max (1 − k/n) on the unloading branch (the force falls steeply just after the top of a plastic contact), then
    the ball lifted off (δ = 0) at the separation's centre and slide."""
    h = impact.history
    t, d, f = (np.asarray(a, float) for a in (h.t, h.overlap, h.normal_force))
    peak = int(np.argmax(d))
    if peak == 0 or d[peak] <= 0.0:
        raise ValueError("impact: its overlap history never rises above 0 m; there is no path to press")
    s = np.arange(1, load_steps + 1) / load_steps
    loading = d[peak] * s**1.5
    t_load = np.interp(loading, np.maximum.accumulate(d[: peak + 1]), t[: peak + 1])
    levels = f[peak] * (1.0 - np.arange(1, unload_steps + 1) / unload_steps)
    branch = np.minimum.accumulate(f[peak:])
    t_unload = np.interp(-levels, -branch, t[peak:])
    t_load[-1] = t[peak]
    times = np.r_[t_load, t_unload, t[-1]]  # the last: lift-off at separation
    slide = cumulative_trapezoid(np.asarray(h.slip_velocity, float), t, initial=0.0)
    overlap = np.r_[np.interp(times[:-1], t, d), 0.0]
    centre = np.interp(times, t, np.asarray(h.contact_x, float))
    return ImpactPath(times, overlap, centre, np.interp(times, t, slide), load_steps - 1)


def place_steps(impact: ImpactResult, path: ImpactPath) -> np.ndarray:
    """Times (s) in ``impact`` of the plate steps of ``path`` (run along a neighbouring impact): each loading step at
    the time the impact reaches its overlap (clipped to δ_max), each unloading step where the impact falls back to
    it, the lift-off at separation."""
    h = impact.history
    t, d = np.asarray(h.t, float), np.asarray(h.overlap, float)
    peak = int(np.argmax(d))
    rise = np.interp(path.overlap[: path.peak + 1], np.maximum.accumulate(d[: peak + 1]), t[: peak + 1])
    fall = np.interp(-path.overlap[path.peak + 1 : -1], -np.minimum.accumulate(d[peak:]), t[peak:])
    times = np.r_[rise, np.maximum(fall, t[peak]), t[-1]]
    # steps the impact does not separate in time (beyond its δ_max) are spread by a hair: times stay increasing
    gap = 1e-9 * float(t[-1])
    for k in range(1, times.size):
        times[k] = max(times[k], times[k - 1] + gap)
    return times


@dataclass(frozen=True)
class _Branch:
    overlap: np.ndarray
    force: np.ndarray
    contact_radius: np.ndarray


@dataclass(frozen=True, eq=False)
class SolidCoupledImpact:
    """An oblique impact coupled to the 3-D plate: ``impact`` (the last impact run), ``law`` (the 3-D plate's force
    law it ran on), ``solid`` (the 3-D plate along the path that law came from), ``path`` (that path),
    ``times`` (s: the solid's steps placed in ``impact``, :func:`place_steps`), ``max_overlaps`` (m) and
    ``tangential_restitutions`` of each impact run (the first is the starting impact's), ``change`` (the last
    change), ``converged``, ``work`` the 3-D solver's work over all cycles, ``first_contact`` δ₀ (m: the overlap
    from the plate's original plane at which the impact's law starts, 0 on a virgin plate; the overlaps of
    ``solid`` count from that plane, those of ``path`` and ``law`` from first contact), ``plastic_work`` (J, the
    whole plate's plastic dissipation over the impact's cycle)."""

    impact: ImpactResult
    law: TabulatedLaw
    solid: SolidIndentation
    path: ImpactPath
    times: np.ndarray
    max_overlaps: tuple[float, ...]
    tangential_restitutions: tuple[float, ...]
    change: float
    converged: bool
    work: WorkCounters = field(default_factory=WorkCounters)
    first_contact: float = 0.0
    plastic_work: float = 0.0

    @property
    def iterations(self) -> int:
        """3-D plate cycles run."""
        return len(self.max_overlaps) - 1

    @property
    def field(self) -> SurfaceField:
        """The 3-D plate's surface fields along the impact, its steps at their impact ``times``
        (:meth:`fem.solid.indentation.SolidIndentation.surface_field`)."""
        return self.solid.surface_field(self.times)

    @property
    def tangential_mismatch(self) -> float:
        """Largest absolute difference of the 3-D plate's tangential force Q and the impact's F_t over the plate's
        steps, relative to the impact's largest absolute F_t (the 3-D plate against the impact's tangential law at the
        same instants)."""
        h = self.impact.history
        ft = np.interp(self.times, h.t, h.tangential_force)
        scale = float(np.max(np.abs(h.tangential_force)))
        # the impact's F_t acts on the ball; the plate carries the opposite
        gap = float(np.max(np.abs(self.solid.tangential_force + ft)))
        return gap / scale if scale > 0.0 else 0.0


def solid_cycle(
    path: ImpactPath,
    radius: float,
    plate: Material,
    friction: float,
    ball: Material | None,
    hardening: float,
    settings: SolidCouplingSettings,
) -> tuple[SolidIndentation, TabulatedLaw]:
    """The 3-D plate along ``path`` (its steps recorded; one probe step ``overshoot`` past δ_max, not recorded) and
    its force law, on a virgin plate meshed for this path."""
    probe_overlap = (1.0 + settings.overshoot) * float(path.overlap[path.peak])
    solver = solid_solver(
        radius,
        plate,
        probe_overlap,
        path.centre,
        friction,
        ball,
        hardening,
        settings.contact_elements,
        settings.box_depth,
    )
    return plate_cycle(path, solver, solver.initial_state(), settings.overshoot)


def plate_cycle(
    path: ImpactPath,
    solver: SolidSolver,
    start: SolidState,
    overshoot: float,
    first_contact: float = 0.0,
    centre_offset: float = 0.0,
) -> tuple[SolidIndentation, TabulatedLaw]:
    """The plate of ``solver`` along ``path`` from ``start`` (:func:`fem.solid.plate.press_path`) and its force law.
    The path's overlaps count from first contact and its centres from the impact's first contact point; the plate's
    from its original plane and its own origin: δ = ``first_contact`` + δ' (m; the lift-off at the original plane)
    and c = ``centre_offset`` + c' (m). The law's overlaps are the impact's, from first contact (the plate's shifted
    by δ₀, as :func:`fem.coupling.force_law` does for the axisymmetric plate)."""
    top = float(path.overlap[path.peak])
    probe_overlap = (1.0 + overshoot) * top
    overlaps = np.r_[first_contact + path.overlap[:-1], 0.0]  # the last step lifts the ball off
    centres = centre_offset + path.centre
    probe = (first_contact + probe_overlap, float(centres[path.peak]), float(path.slide[path.peak]))
    solid, measured = press_path(solver, start, overlaps, centres, path.slide, path.peak, probe)
    upto = path.peak + 1
    loading = _Branch(
        np.r_[solid.overlap[:upto], probe[0]],
        np.r_[solid.normal_force[:upto], measured["P"]],
        np.r_[solid.contact_radius[:upto], measured["a"]],
    )
    unloading = _Branch(solid.overlap[path.peak :], solid.normal_force[path.peak :], solid.contact_radius[path.peak :])
    law = force_law(loading, unloading, first_contact, shear_strength=solver.surface.shear_strength)
    # an impact a little past the path's δ_max (by less than the coupling's tolerance once converged) unloads
    # between the computed curve and the probe's; the next cycle computes its own
    return solid, with_unloading_from(law, probe_overlap, measured["P"], measured["a"])


def couple_solid(
    impact_on_law: Callable[[TabulatedLaw], ImpactResult],
    first: ImpactResult,
    radius: float,
    plate: Material,
    friction: float,
    ball: Material | None = None,
    hardening: float = 0.0,
    settings: SolidCouplingSettings | None = None,
    progress: Callable[[int], None] | None = None,
) -> SolidCoupledImpact:
    """Couple an impact to a virgin 3-D plate (module docstring; each cycle meshes a new plate for its path):
    ``impact_on_law(law)`` runs the case's impact (with histories) on a force law, ``first`` is the starting impact
    (e.g. the axisymmetric coupled one), ``radius`` (m) the ball's, ``plate`` and ``ball`` (None = rigid) the
    materials, ``friction`` μ (the impact's, ≤ :data:`contact.checks.FRICTION_MAX`), ``hardening`` H (Pa).
    ``progress(iteration)`` is called as each 3-D cycle starts."""
    settings = settings or SolidCouplingSettings()
    friction = check_friction("friction", friction)

    def cycle(path: ImpactPath) -> tuple[SolidIndentation, TabulatedLaw]:
        return solid_cycle(path, radius, plate, friction, ball, hardening, settings)

    coupled = _couple(impact_on_law, first, cycle, settings, progress)
    solid = coupled.solid
    return replace(coupled, plastic_work=solid_plastic_work(solid.solver, solid.solver.initial_state(), solid.final))


def couple_solid_plate(
    impact_on_law: Callable[[TabulatedLaw], ImpactResult],
    first: ImpactResult,
    plate: SolidPlate,
    settings: SolidCouplingSettings | None = None,
    centre_offset: float = 0.0,
    progress: Callable[[int], None] | None = None,
) -> SolidCoupledImpact:
    """Couple an impact to the stateful 3-D ``plate`` as it is now (:class:`fem.solid.plate.SolidPlate`: its mesh,
    friction and materials), the loop of :func:`couple_solid`; every cycle starts from the plate's kept state, and
    the converged impact's final, lifted-off state is committed to the plate. The impact's first contact is at
    x = ``centre_offset`` (m) in the plate's frame and at δ₀ = :meth:`~fem.solid.plate.SolidPlate.first_contact_overlap`
    there (the impact runs on the plate's law shifted by δ₀, :func:`plate_cycle`). ``first``: the starting impact
    (e.g. the impact on the dented plate's reloading law, :func:`fem.force_law.reloading_law`)."""
    settings = settings or SolidCouplingSettings()
    first_contact = plate.first_contact_overlap(centre_offset)
    start = plate.start_state(first_contact, centre_offset)
    before = plate.state

    def cycle(path: ImpactPath) -> tuple[SolidIndentation, TabulatedLaw]:
        return plate_cycle(path, plate.solver, start, settings.overshoot, first_contact, centre_offset)

    coupled = _couple(impact_on_law, first, cycle, settings, progress)
    plate.commit(coupled.solid)
    return replace(coupled, first_contact=first_contact, plastic_work=plate.plastic_work(before))


@dataclass(frozen=True)
class PathCycles:
    """The 3-D plate's cycles for :func:`fem.coupling.fixed_point`: ``run(path)`` presses and drags the plate along
    the impact's path (:func:`impact_path` with the ``settings``' steps) from the plate's kept state; the loading
    branch depends on the path, so δ_max and e_t count. ``work`` adds up the 3-D solver's work over the cycles."""

    run: Callable[[ImpactPath], tuple[SolidIndentation, TabulatedLaw]]
    settings: SolidCouplingSettings
    work: WorkCounters = field(default_factory=WorkCounters)

    def cycle(self, impact: ImpactResult) -> tuple[tuple[ImpactPath, SolidIndentation], TabulatedLaw]:
        """((the path of ``impact``, the plate along it), its force law)."""
        path = impact_path(impact, self.settings.load_steps, self.settings.unload_steps)
        solid, law = self.run(path)
        self.work.add(solid.stats)
        return (path, solid), law

    def change(self, before: ImpactResult, after: ImpactResult) -> float:
        """The larger of the relative change of δ_max and the absolute change of e_t (0 where e_t is undefined)."""
        tangential = abs(after.tangential_restitution - before.tangential_restitution)
        overlap = abs(after.max_overlap - before.max_overlap) / before.max_overlap
        return max(overlap, tangential if math.isfinite(tangential) else 0.0)


def _couple(
    impact_on_law: Callable[[TabulatedLaw], ImpactResult],
    first: ImpactResult,
    run: Callable[[ImpactPath], tuple[SolidIndentation, TabulatedLaw]],
    settings: SolidCouplingSettings,
    progress: Callable[[int], None] | None,
) -> SolidCoupledImpact:
    """The coupled impact of the fixed point (:func:`fem.coupling.fixed_point`) of the plate's ``run(path)``."""
    cycles = PathCycles(run, settings)
    point = fixed_point(cycles, impact_on_law, first, settings.tolerance, settings.max_iterations, progress)
    path, solid = point.cycle
    return SolidCoupledImpact(
        impact=point.impact,
        law=point.law,
        solid=solid,
        path=path,
        times=place_steps(point.impact, path),
        max_overlaps=point.max_overlaps,
        tangential_restitutions=point.tangential_restitutions,
        change=point.change,
        converged=point.converged,
        work=cycles.work,
    )
