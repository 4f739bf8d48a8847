r"""The impact ⇄ axisymmetric plate coupling: an impact on the plate's own force law, for a virgin or a used plate
(SI units); the fixed point is :func:`fem.coupling.fixed_point`, the plate's cycles :class:`UnloadingCycles`.

The impact runs on the FE plate's normal law (contact's ``"tabulated"`` model: F(δ) and the contact radius a(δ), so
the tangential stiffness is k_t = 8G*a with the FE radius). The loading branch of an elastic–plastic indentation is
path independent, so the plate is loaded **once**, past the expected maximum overlap:

1. load the plate from its current state to (1 + ``overshoot``) × the estimated approach (further if the impact
   goes deeper than the table);
2. run the impact on that loading branch (the rebound uses a provisional elastic unloading curve of slope
   dF/dδ = 2E*a, which cannot change δ_max: the maximum is reached on the loading branch);
3. unload the plate from just above the impact's δ_max (restarting from the kept loading state below it:
   :meth:`fem.Plate.unload`, which commits the unloaded state) and run the impact again on the loading + unloading
   law;
4. repeat 3 while δ_max changes by more than ``tolerance`` (relative) between impact runs.

Because δ_max depends only on the loading branch, step 3 normally converges at once (the impact loads on the same
table; only the unloading changes): about one FE cycle in all. Overlaps: the plate measures δ from its original
plane z = 0; on a dented or worn plate the sphere first touches the surface at δ₀ =
:meth:`fem.Plate.first_contact_overlap`, and the impact engine integrates from first contact, so its law is the FE
law shifted by δ₀ (δ' = δ − δ₀). :func:`couple_elastic` solves the same impact on the plate's elastic response
(:func:`fem.elastic_reload`, the plate's state unchanged) while that response yields nowhere.

The force law is :func:`fem.force_law.force_law`, the plate's cycle :class:`fem.plate_cycle.PlateCycle`, and the FE
pressure p(r, t) along the impact :func:`fem.pressure_table.pressure_table`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Protocol

import numpy as np

from contact import ImpactResult, TabulatedLaw
from contact.impact import ForceLawRangeError
from fem.axisymmetric.reload import elastic_reload
from fem.axisymmetric.result import IndentationResult
from fem.axisymmetric.solver import PlateState
from fem.core.increments import ConvergenceError
from fem.coupling import FixedPoint, ImpactOnLaw, fixed_point
from fem.force_law import force_law
from fem.plate_cycle import PlateCycle
from fem.pressure_table import contact_pressure, pressure_table, radial_table

__all__ = [
    "UNLOAD_MARGIN",
    "CouplingSettings",
    "CoupledImpact",
    "UnloadingCycles",
    "couple",
    "couple_elastic",
    "loading_path",
]

#: Relative margin above the impact's δ_max at which the plate starts unloading: the impact's own maximum (on the
#: same loading table) then lies below the tabulated δ*, and the engine scales the curve down by that 1e-3, well
#: inside the FE accuracy.
UNLOAD_MARGIN = 1e-3
#: Loadings tried when the impact goes past the table's end before giving up.
LOADING_TRIES = 4


class CoupledPlate(Protocol):
    """What the coupling needs of a plate (:class:`fem.Plate` is one)."""

    effective_modulus: float
    state: PlateState

    def first_contact_overlap(self) -> float: ...

    def plastic_work(self, since: PlateState) -> float: ...

    def surface_radial_displacement(self) -> np.ndarray: ...

    def first_yield_overlap(self) -> float | None: ...

    def load(self, overlaps: np.ndarray) -> IndentationResult: ...

    def unload(self, loading: IndentationResult, max_overlap: float, steps: int = 8) -> IndentationResult: ...


@dataclass(frozen=True)
class CouplingSettings:
    """The coupling's numbers: ``tolerance`` on the relative change of δ_max between impact runs, ``max_iterations``
    (impact runs), the FE increments ``load_steps`` and ``unload_steps``, the ``overshoot`` of the single loading
    past the estimated approach (relative)."""

    tolerance: float
    max_iterations: int
    load_steps: int
    unload_steps: int
    overshoot: float


def loading_path(max_overlap: float, steps: int, first_yield_overlap: float | None = None) -> np.ndarray:
    """Overlaps (m) from 0 (excluded) to ``max_overlap``, denser near the start where F(δ) curves most; with
    ``first_yield_overlap`` (m) the path starts with an elastic step at half of it (the plate locates first yield
    between an elastic and a plastic step)."""
    s = np.linspace(0.0, 1.0, steps + 1)[1:]
    path = max_overlap * s**1.5
    if first_yield_overlap is not None and 0.5 * first_yield_overlap < path[0]:
        path = np.r_[0.5 * first_yield_overlap, path]
    return path


@dataclass(frozen=True, eq=False)
class CoupledImpact:
    """An impact coupled to the plate: ``impact`` (the last :class:`contact.ImpactResult`), ``law`` (the force law
    it ran on, overlaps from first contact), ``cycle`` (:class:`PlateCycle`), ``first_contact`` δ₀ (m, from the
    original plane), ``max_overlaps`` (m, δ_max of each impact run, from first contact), ``change`` (final relative
    change of δ_max), ``converged``, ``unload_overlap`` δ* (m, from first contact: where the unloading starts, a hair
    above the impact's δ_max), ``elastic`` (solved on the plate's elastic response, the plate's state
    unchanged) and ``trial_increment`` (the largest Δᾱ a return mapping of that elastic response gives; 0 for a
    plastic solve), ``plastic_work`` (J, the plate's plastic dissipation over the cycle: 0 on the elastic
    response), ``pressure_table`` ((time s, surface_r m, pressure Pa) of :func:`pressure_table`), ``radial_table``
    ((time s, surface_r m, u_r m) of :func:`radial_table`: the surface's radial slip)."""

    impact: ImpactResult
    law: TabulatedLaw
    cycle: PlateCycle
    first_contact: float
    max_overlaps: tuple[float, ...]
    change: float
    converged: bool
    pressure_table: tuple[np.ndarray, np.ndarray, np.ndarray]
    radial_table: tuple[np.ndarray, np.ndarray, np.ndarray]
    unload_overlap: float
    elastic: bool = False
    trial_increment: float = 0.0
    plastic_work: float = 0.0

    @property
    def iterations(self) -> int:
        """Impact runs on the plate's laws."""
        return len(self.max_overlaps)

    @property
    def loading(self) -> IndentationResult:
        """The plate's loading (overlaps from the original plane)."""
        return self.cycle.loading

    @property
    def unloading(self) -> IndentationResult:
        """The plate's unloading from δ* (overlaps from the original plane)."""
        return self.cycle.unloading

    @property
    def contact_radius(self) -> float:
        """The plate's contact radius (m) at δ*."""
        loading = self.cycle.loading
        return float(np.interp(self.first_contact + self.unload_overlap, loading.overlap, loading.contact_radius))

    @property
    def max_pressure(self) -> float:
        """The largest pressure (Pa) of the cycle inside the contact."""
        c = self.cycle
        return float(contact_pressure(c.pressure, c.surface_r, c.contact_radius).max())

    def peak_pressure_at(self, force: float) -> float:
        """The plate's peak pressure (Pa) when the loading passes ``force`` (N), interpolated between the loading
        steps; NaN beyond its largest force."""
        loading = self.cycle.loading
        f = np.asarray(loading.force, float)
        if f.size == 0 or force > f.max():
            return float("nan")
        p = contact_pressure(loading.pressure, loading.surface_r, loading.contact_radius).max(axis=1)
        return float(np.interp(force, np.maximum.accumulate(f), p))


def _loading_past_the_impact(
    load: Callable[[float], IndentationResult],
    impact_on: ImpactOnLaw,
    first_contact: float,
    estimate: float,
    settings: CouplingSettings,
    effective_modulus: float,
):
    """(loading, law, impact): ``load(target)`` (a loading from first contact to first contact + target, m) run
    (1 + overshoot) past ``estimate`` (m), further until the impact on its law stops short of the table's end;
    None after :data:`LOADING_TRIES` loadings."""
    target = (1.0 + settings.overshoot) * estimate
    for _ in range(LOADING_TRIES):
        loading = load(target)
        law = force_law(loading, None, first_contact, effective_modulus)
        try:
            impact = impact_on(law)
        except ForceLawRangeError:
            # the engine stops where the overlap leaves the table: the surface (hence the depth an impact reaches)
            # can have changed by more than the overshoot allows for
            target *= 1.5
            continue
        if impact.max_overlap * (1.0 + 2.0 * UNLOAD_MARGIN) < float(law.loading_overlap[-1]):
            return loading, law, impact
        target = 1.3 * impact.max_overlap
    return None


@dataclass(frozen=True)
class UnloadingCycles:
    """The axisymmetric plate's cycles for :func:`fem.coupling.fixed_point`: the kept ``loading`` (overlaps from the
    original plane) and an unloading ``unload(δ*)`` from δ* = δ₀ + δ_max (1 + :data:`UNLOAD_MARGIN`) of the impact
    (δ₀ = ``first_contact``, m). The loading branch is path independent: only δ_max counts."""

    loading: IndentationResult
    unload: Callable[[float], IndentationResult]
    first_contact: float

    def cycle(self, impact: ImpactResult) -> tuple[PlateCycle, TabulatedLaw]:
        """The loading below δ* joined to the unloading from δ*, and their force law."""
        d_star = self.first_contact + impact.max_overlap * (1.0 + UNLOAD_MARGIN)
        unloading = self.unload(d_star)
        law = force_law(self.loading, unloading, self.first_contact)
        return PlateCycle.join(self.loading, unloading, self.first_contact, d_star), law

    def change(self, before: ImpactResult, after: ImpactResult) -> float:
        """The relative change of δ_max."""
        return abs(after.max_overlap - before.max_overlap) / before.max_overlap


def _coupled(point: FixedPoint[PlateCycle], first_contact: float, radial_before: np.ndarray) -> CoupledImpact:
    """The coupled impact of the axisymmetric plate's fixed point; ``radial_before`` (m) the surface nodes' u_r before
    the impact."""
    return CoupledImpact(
        point.impact,
        point.law,
        point.cycle,
        first_contact,
        point.max_overlaps,
        point.change,
        point.converged,
        pressure_table(point.cycle, point.impact),
        radial_table(point.cycle, point.impact, radial_before),
        point.impacts[-2].max_overlap * (1.0 + UNLOAD_MARGIN),
    )


def couple(plate: CoupledPlate, impact_on: ImpactOnLaw, estimate: float, settings: CouplingSettings) -> CoupledImpact:
    """The impact ``impact_on`` coupled to ``plate`` as it is now (see the module docstring); commits the unloaded
    state to the plate. ``estimate`` (m): the expected approach (max overlap from first contact)."""
    if settings.max_iterations < 2:
        raise ValueError(
            f"max_iterations={settings.max_iterations} is out of range: the coupling needs >= 2 "
            "impact runs (the first finds δ_max on the loading branch, the next runs on the "
            "unloading)"
        )
    first_contact = plate.first_contact_overlap()
    first_yield = plate.first_yield_overlap()
    before, radial_before = plate.state, plate.surface_radial_displacement()

    def load(target: float) -> IndentationResult:
        return plate.load(first_contact + loading_path(target, settings.load_steps, first_yield))

    solved = _loading_past_the_impact(load, impact_on, first_contact, estimate, settings, plate.effective_modulus)
    if solved is None:
        raise ValueError(
            f"the impact keeps going past the FE loading ({LOADING_TRIES} loadings from {estimate:.4g} m "
            "past first contact, each deeper): raise fem.overshoot"
        )
    loading, _, impact = solved

    def unload(d_star: float) -> IndentationResult:
        try:
            return plate.unload(loading, d_star, steps=settings.unload_steps)
        except ConvergenceError:
            # the unloading from a plastic dent can fail near the loss of contact in coarse steps: once more in finer
            return plate.unload(loading, d_star, steps=2 * settings.unload_steps)

    cycles = UnloadingCycles(loading, unload, first_contact)
    point = fixed_point(cycles, impact_on, impact, settings.tolerance, settings.max_iterations - 1)
    return replace(_coupled(point, first_contact, radial_before), plastic_work=plate.plastic_work(before))


def couple_elastic(
    plate, impact_on: ImpactOnLaw, estimate: float, settings: CouplingSettings, yield_tolerance: float
) -> CoupledImpact | None:
    """The impact ``impact_on`` on ``plate``'s elastic response (:func:`fem.elastic_reload`: the plate's state is
    not changed, the reloading and unloading retrace each other), or None when that response yields: a return
    mapping of any loading step up to the impact's maximum gives Δᾱ > ``yield_tolerance`` (then the plastic
    problem must be solved, :func:`couple`). Exact, on the FE's own mesh, for a plate that does not yield. One
    unloading: the elastic loading branch is the plate's, so δ_max cannot change."""
    first_contact = plate.first_contact_overlap()
    reloads = []

    def load(target: float) -> IndentationResult:
        reloads.append(elastic_reload(plate, first_contact + loading_path(target, settings.load_steps, None)))
        return reloads[-1].result

    solved = _loading_past_the_impact(load, impact_on, first_contact, estimate, settings, plate.effective_modulus)
    if solved is None:
        return None
    loading, _, impact = solved
    unload_at = impact.max_overlap * (1.0 + UNLOAD_MARGIN)
    # steps past the impact's maximum were never reached: their trial plastic strain does not count
    reached = np.asarray(loading.overlap) <= first_contact + unload_at
    trial = float(np.max(reloads[-1].trial_plastic_strain_increment[reached], initial=0.0))
    if trial > yield_tolerance:
        return None

    def unload(d_star: float) -> IndentationResult:
        down = np.linspace(d_star, max(0.0, first_contact - 0.05 * (d_star - first_contact)), settings.unload_steps + 1)
        return elastic_reload(plate, down, check_yield=False).result

    point = fixed_point(UnloadingCycles(loading, unload, first_contact), impact_on, impact, settings.tolerance, 1)
    return replace(
        _coupled(point, first_contact, plate.surface_radial_displacement()), elastic=True, trial_increment=trial
    )
