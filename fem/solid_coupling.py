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
   absolute for e_t) between impact runs.

Unlike the axisymmetric frictionless plate, the loading branch of the 3-D plate depends on the path (friction and
the moving centre), so every iteration runs the whole path. Started from the axisymmetric coupled impact (whose
normal law is the 3-D one's within about 1 %), one or two iterations normally suffice.

The impact's tangential law is the one ``impact_on_law`` runs: in the chain the plate's own, Mindlin–Deresiewicz
partial slip with memory (``wear.chain.solid.solid_case``), fed by the 3-D plate's normal force and contact radius
and limited, like the plate's slip traction, by the plate surface's shear strength (Orowan's τ = min(μp, k),
:mod:`fem.solid.friction`; the law carries it as ``TabulatedLaw.shear_strength``). The 3-D plate's tangential force
along the path (``solid.tangential_force``) is compared with the impact's
(:attr:`SolidCoupledImpact.tangential_mismatch`), the measure of what the law misses.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from scipy.integrate import cumulative_trapezoid

from contact import ImpactResult, Material, TabulatedLaw
from contact.fields import SurfaceField
from fem.core.increments import WorkCounters
from fem.force_law import force_law
from fem.solid.indentation import MAX_FRICTION, SolidIndentation, SolidRecorder, solid_solver

__all__ = ["ImpactPath", "SolidCouplingSettings", "SolidCoupledImpact", "couple_solid", "impact_path",
           "place_steps"]  # fmt: skip


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
    change), ``converged``, ``work`` the 3-D solver's work over all cycles."""

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
    its force law (overlaps from the plate's original plane, a virgin plate)."""
    top = float(path.overlap[path.peak])
    probe_overlap = (1.0 + settings.overshoot) * top
    solver = solid_solver(radius, plate, probe_overlap, path.centre, friction, ball, hardening,
                          settings.contact_elements, settings.box_depth)  # fmt: skip
    recorder = SolidRecorder(solver)
    state, previous = solver.initial_state(), None
    for k in range(path.overlap.size):
        if k == path.peak + 1:
            top_state, top_previous = state, previous
            probe = recorder.measure(solver.advance(
                top_state, top_previous, (probe_overlap, float(path.centre[path.peak]), float(path.slide[path.peak]))
            ))  # fmt: skip
            state, previous = top_state, top_previous
        target = (float(path.overlap[k]), float(path.centre[k]), float(path.slide[k]))
        previous, state = state, solver.advance(state, previous, target)
        recorder.add(state)
    solid = recorder.result()
    upto = path.peak + 1
    loading = _Branch(np.r_[solid.overlap[:upto], probe_overlap], np.r_[solid.normal_force[:upto], probe["P"]],
                      np.r_[solid.contact_radius[:upto], probe["a"]])  # fmt: skip
    unloading = _Branch(solid.overlap[path.peak :], solid.normal_force[path.peak :],
                        solid.contact_radius[path.peak :])  # fmt: skip
    law = force_law(loading, unloading, shear_strength=solver.surface.shear_strength)
    return solid, _with_probe_unloading(law, probe_overlap, probe["P"], probe["a"])


def _with_probe_unloading(law: TabulatedLaw, overlap: float, force: float, radius: float) -> TabulatedLaw:
    """``law`` with a second unloading curve from the probe's ``overlap`` (m): the computed curve moved up by the
    probe's extra overlap and scaled to its ``force`` (N) and ``radius`` (m). An impact that goes past the path's
    δ_max (by less than the coupling's tolerance once converged) unloads between the two, where the engine
    interpolates; the next cycle computes its own."""
    top = float(law.unloading_max_overlap[-1])
    grid, f, a = law.unloading_overlap[-1], law.unloading_force[-1], law.unloading_contact_radius[-1]
    return TabulatedLaw(
        law.loading_overlap, law.loading_force, law.loading_contact_radius,
        np.r_[law.unloading_max_overlap, overlap], np.vstack([law.unloading_overlap, grid + (overlap - top)]),
        np.vstack([law.unloading_force, f * (force / f[0])]),
        np.vstack([law.unloading_contact_radius, a * (radius / max(a[0], 1e-300))]), law.shear_strength,
    )  # fmt: skip


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
    """Couple an impact to the 3-D plate (module docstring): ``impact_on_law(law)`` runs the case's impact (with
    histories) on a force law, ``first`` is the starting impact (e.g. the axisymmetric coupled one), ``radius`` (m)
    the ball's, ``plate`` and ``ball`` (None = rigid) the materials, ``friction`` μ (the impact's, ≤
    :data:`fem.solid.indentation.MAX_FRICTION`), ``hardening`` H (Pa). ``progress(iteration)`` is called as each 3-D
    cycle starts."""
    settings = settings or SolidCouplingSettings()
    if not 0.0 <= friction <= MAX_FRICTION:
        raise ValueError(f"friction={friction!r}: the 3-D plate takes a Coulomb coefficient in [0, {MAX_FRICTION}]")
    impact = first
    overlaps, restitutions = [first.max_overlap], [first.tangential_restitution]
    change, converged = math.inf, False
    work = WorkCounters()
    for iteration in range(settings.max_iterations):
        if progress is not None:
            progress(iteration)
        path = impact_path(impact, settings.load_steps, settings.unload_steps)
        solid, law = solid_cycle(path, radius, plate, friction, ball, hardening, settings)
        work.add(solid.stats)
        impact = impact_on_law(law)
        overlaps.append(impact.max_overlap)
        restitutions.append(impact.tangential_restitution)
        tangential = abs(restitutions[-1] - restitutions[-2])
        change = max(abs(overlaps[-1] - overlaps[-2]) / overlaps[-2], tangential if math.isfinite(tangential) else 0.0)
        if change < settings.tolerance:
            converged = True
            break
    return SolidCoupledImpact(impact=impact, law=law, solid=solid, path=path, times=place_steps(impact, path),
                              max_overlaps=tuple(overlaps), tangential_restitutions=tuple(restitutions),
                              change=change, converged=converged, work=work)  # fmt: skip
