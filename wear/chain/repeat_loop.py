"""The one loop of repeated impacts at one site, for any plate (SI units; the repetition's settings are
``case.repeat``): :func:`repeat_at_site` asks the plate's :class:`RepeatSite` for each impact on the plate as it is
now, accumulates the wear, moves the plate's surface by it (``repeat.geometry_update``), records each row and
reports the progress, never asking which plate it is.

Each row is one computed impact or, on a plate that jumps cycles (:attr:`RepeatSite.cycle_jump`, the axisymmetric
plate: :mod:`wear.chain.axisymmetric_repeat`), a block of impacts extrapolated from the last computed one once it is
shaken down (its increment of equivalent plastic strain Δᾱ at most ``repeat.shakedown_tolerance`` × Y/E) or after
``repeat.max_plastic_impacts`` impacts computed one by one without shakedown; a block moves the surface by at most
``repeat.surface_fraction`` × the approach, and a computed impact follows each block. On a plate that does not jump
cycles (the 3-D plate: :mod:`wear.chain.solid_repeat`) every impact is computed. The run stops where the plate says
its surface may wear no deeper (:meth:`RepeatSite.room`).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from contact import ImpactResult
from wear.case import Case
from wear.chain.records import ImpactRecord, PlateState, RepeatResult, yield_strain
from wear.chain.wear_accumulator import WearAccumulator
from wear.integrate import WearMap

__all__ = ["RepeatSite", "SiteImpact", "repeat_at_site"]


@dataclass(frozen=True, eq=False)
class SiteImpact:
    """One impact computed at the site on the plate as it is now: ``impact``, its ``wear`` (x in the first impact's
    frame), ``increment`` (largest increment of equivalent plastic strain Δᾱ it left), ``max_pressure`` (Pa),
    ``contact_radius`` (m), ``first_contact`` (overlap m at which the ball first touched the plate's surface),
    ``plastic_work`` (J), ``elastic`` (solved on the plate's elastic response), ``surface_change`` (largest depth,
    m, its wear moves the plate's surface by), ``peak_to_mean`` (the wear map's largest depth over
    ``surface_change``: 1 where the surface takes the map as it is) and ``pressure_at(force)`` (the peak pressure,
    Pa, when its loading passes ``force`` N; NaN beyond its largest force)."""

    impact: ImpactResult
    wear: WearMap
    increment: float
    max_pressure: float
    contact_radius: float
    first_contact: float
    plastic_work: float
    elastic: bool
    surface_change: float
    peak_to_mean: float
    pressure_at: Callable[[float], float]


class RepeatSite(Protocol):
    """A plate at the site of a repetition, as :func:`repeat_at_site` asks it."""

    #: The plate as it is now (passed to ``on_computed``, kept in the result).
    plate: PlateState
    #: Whether blocks of impacts extrapolate a computed one (else every impact is computed).
    cycle_jump: bool
    #: What the summary says first of how this plate repeats.
    about: tuple[str, ...]

    def compute(self, shaken: bool, done: int) -> SiteImpact:
        """The next impact on the plate as it is now (its state committed), after ``done`` impacts; ``shaken``:
        the last computed impact was shaken down."""
        ...

    def first_notes(self, first: SiteImpact) -> list[str]:
        """What the summary says of the first impact (e.g. an implausible wear)."""
        ...

    def room(self) -> tuple[float, str]:
        """(the depth, m, the surface may still wear before the plate is no longer valid, inf for no limit; why)."""
        ...

    def move_surface(self, count: int) -> None:
        """Lower the plate's surface by ``count`` times the last computed impact's wear."""
        ...

    def state_fields(self, total: WearMap) -> dict[str, float]:
        """The record's fields of the plate as it is now, with the accumulated wear ``total``:
        ``max_plastic_strain``, ``dent_depth`` (m), ``surface_depth`` (m, dent + wear) and ``pile_up_height``
        (m)."""
        ...

    def finish(self, result: RepeatResult) -> RepeatResult:
        """``result`` with what the plate adds to it (its axis, the surface its last impact met, its checks)."""
        ...


@dataclass
class _Loop:
    """Where the loop is: impacts done and computed, the first shaken-down impact, the impacts computed one by one
    since the last shaken-down one, and whether it gave up waiting for shakedown."""

    done: int = 0
    computed: int = 0
    shakedown: int | None = None
    plastic_run: int = 0
    shaken: bool = False
    gave_up: bool = False
    increment: float = 0.0


def _block_size(case: Case, last: SiteImpact, done: int) -> int:
    """Impacts of a block after ``last``: the rest, or with the geometry update as many as move the surface by
    ``repeat.surface_fraction`` × the approach (module docstring)."""
    spec = case.repeat
    count = spec.impacts - done
    change = last.surface_change
    if spec.geometry_update and change > 0.0:
        approach = last.impact.max_overlap  # from first contact: a²/R on a flat, less on a seat
        count = max(1, min(count, int(spec.surface_fraction * approach / change)))
    return count


def _computed(site: RepeatSite, case: Case, loop: _Loop, tolerance: float, notes: list[str]) -> SiteImpact:
    """The next computed impact, with the loop's shakedown bookkeeping."""
    spec = case.repeat
    last = site.compute(loop.shaken, loop.done)
    loop.computed += 1
    increment = last.increment
    loop.shaken = increment <= tolerance
    if loop.shaken and loop.shakedown is None:
        loop.shakedown = loop.done + 1
    loop.plastic_run = 0 if loop.shaken else loop.plastic_run + 1
    loop.increment = increment
    if site.cycle_jump and not loop.shaken and not loop.gave_up and loop.plastic_run >= spec.max_plastic_impacts:
        notes.append(
            f"no shakedown after {loop.plastic_run} impacts computed one by one (Δᾱ = {increment:.3g} > "
            f"{tolerance:.3g}): from impact {loop.done + 2} on, cycle-jump blocks extrapolate the last computed "
            "impact's wear anyway (one computed impact between blocks; the plastic strain increments of "
            "block impacts are not added to the FE plate)"
        )
        loop.gave_up = True
    return last


def _record(
    site: RepeatSite,
    last: SiteImpact,
    kind: str,
    count: int,
    loop: _Loop,
    increment: float,
    total: WearMap,
    first: ImpactRecord | None,
    t_row: float,
) -> ImpactRecord:
    """The row of ``count`` impacts (``kind``: computed or block) ending at ``loop.done``, ``total`` the wear so far;
    ``first``: the first row (None: this is it); ``t_row``: when the row started (s, :func:`time.perf_counter`)."""
    imp = last.impact
    return ImpactRecord(
        first=loop.done - count + 1,
        last=loop.done,
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
        total_wear_volume=total.volume_m3,
        total_wear_max_depth=total.max_depth_m,
        wear_peak_to_mean=last.peak_to_mean,
        shaken_down=bool(loop.shaken),
        max_pressure_at_first_force=last.pressure_at(imp.max_force if first is None else first.max_force),
        elastic_response=last.elastic,
        plastic_work=last.plastic_work if kind == "computed" or not loop.shaken else 0.0,
        tangential_restitution=imp.tangential_restitution,
        **site.state_fields(total),
        wall_time=time.perf_counter() - t_row,
    )


def repeat_at_site(
    site: RepeatSite,
    case: Case,
    t_start: float,
    progress: Callable[[int, int], None] | None = None,
    on_computed: Callable[[int, PlateState], None] | None = None,
) -> RepeatResult:
    """Run ``case.repeat.impacts`` impacts of ``case`` on the plate ``site`` (module docstring), started at
    ``t_start`` (s, :func:`time.perf_counter`); ``progress`` and ``on_computed`` as
    :func:`wear.chain.repeated_impacts.repeat`."""
    spec = case.repeat
    tolerance = spec.shakedown_tolerance * yield_strain(case)
    records: list[ImpactRecord] = []
    notes = list(site.about)
    loop, acc, last = _Loop(), None, None
    stop = False  # the first impact alone wears deeper than the plate allows
    while loop.done < spec.impacts:
        t_row = time.perf_counter()
        if last is None or not (loop.shaken or loop.gave_up) or records[-1].kind == "block" or not site.cycle_jump:
            kind, count = "computed", 1
            last = _computed(site, case, loop, tolerance, notes)
            increment = last.increment
        else:
            kind, count = "block", _block_size(case, last, loop.done)
            # shaken down: elastic response; after giving up: the last computed impact's increment, per impact
            increment = 0.0 if loop.shaken else loop.increment
        step_depth = last.surface_change
        if spec.geometry_update and step_depth > 0.0:
            room, why = site.room()
            if count * step_depth > room:
                count = int(room / step_depth)
                if count < 1:
                    notes.append(f"stopped after impact {max(loop.done, 1)}: {why}")
                    if records:
                        break
                    # the first impact alone wears deeper: it is reported, on the surface it met, and the run ends
                    count, stop = 1, True
        if acc is None:
            notes.extend(site.first_notes(last))
            acc = WearAccumulator(last.wear)
        acc.add(last.wear, count)
        if spec.geometry_update and not stop:
            site.move_surface(count)
        loop.done += count
        first = records[0] if records else None
        records.append(_record(site, last, kind, count, loop, increment, acc.map(), first, t_row))
        if kind == "computed" and on_computed is not None:
            on_computed(loop.done, site.plate)
        if progress is not None:
            progress(loop.done, spec.impacts)
        if stop:
            break
    if loop.shakedown is None:
        notes.append(f"no impact without new plastic strain (tolerance Δᾱ <= {tolerance:.3g})")
    wall = time.perf_counter() - t_start
    return site.finish(RepeatResult(case, records, site.plate, acc.map(), loop.shakedown, loop.computed, wall, notes))
