r"""The impact ⇄ plate fixed point, for any plate (SI units).

An impact and the plate it hits answer each other: the plate's force law depends on the path the impact drives it
along, and the impact on the force law it runs on. The coupling iterates the two from a starting impact:

1. the plate runs its cycle along the last impact (:meth:`CyclingPlate.cycle`: its path from the plate's kept
   state, and the force law that cycle gives: overlaps from first contact, contact's ``"tabulated"`` model);
2. the impact runs again on that law;
3. repeat while the two last impacts differ (:meth:`CyclingPlate.change`) by ``tolerance`` or more, at most
   ``max_cycles`` plate cycles.

What a cycle is and what a change measures is the plate's own: the axisymmetric frictionless plate's loading branch
is path independent, so its cycle is the unloading from the impact's δ_max and only δ_max counts
(:mod:`fem.axisymmetric_coupling`); the 3-D plate with friction runs the whole path (overlap, moving centre, slide),
so δ_max and the tangential restitution e_t count (:mod:`fem.solid_coupling`). Each gives :func:`fixed_point` its
starting impact and wraps the :class:`FixedPoint` in its coupled-impact type.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Generic, Protocol, TypeVar

from contact import ImpactResult, TabulatedLaw

__all__ = ["Cycle", "CyclingPlate", "FixedPoint", "ImpactOnLaw", "fixed_point"]

#: An impact run on a force law (overlaps from first contact): the case's impact with ``normal_model="tabulated"``.
ImpactOnLaw = Callable[[TabulatedLaw], ImpactResult]

#: What a plate's cycle along an impact records (its steps, states, meshes): the plate's own type.
Cycle = TypeVar("Cycle")


class CyclingPlate(Protocol[Cycle]):
    """What the coupling asks of a plate."""

    def cycle(self, impact: ImpactResult) -> tuple[Cycle, TabulatedLaw]:
        """The plate's cycle along ``impact`` (from the plate's kept state, which it does not change) and the force
        law (overlaps from first contact) that cycle gives."""
        ...

    def change(self, before: ImpactResult, after: ImpactResult) -> float:
        """How much two successive impacts differ in what the plate's cycle depends on (dimensionless)."""
        ...


@dataclass(frozen=True, eq=False)
class FixedPoint(Generic[Cycle]):
    """The coupling's end: ``impact`` (the last impact run), ``law`` (the force law it ran on), ``cycle`` (the
    plate's cycle that law came from, run along ``impacts[-2]``), ``impacts`` (every impact run, the starting one
    first), ``change`` (the last :meth:`CyclingPlate.change`, inf before any cycle) and ``converged`` (it fell below
    the tolerance)."""

    impact: ImpactResult
    law: TabulatedLaw
    cycle: Cycle
    impacts: tuple[ImpactResult, ...]
    change: float
    converged: bool

    @property
    def max_overlaps(self) -> tuple[float, ...]:
        """δ_max (m, from first contact) of each impact run, the starting one first."""
        return tuple(impact.max_overlap for impact in self.impacts)

    @property
    def tangential_restitutions(self) -> tuple[float, ...]:
        """e_t of each impact run, the starting one first."""
        return tuple(impact.tangential_restitution for impact in self.impacts)


def fixed_point(
    plate: CyclingPlate[Cycle],
    impact_on: ImpactOnLaw,
    first: ImpactResult,
    tolerance: float,
    max_cycles: int,
    progress: Callable[[int], None] | None = None,
) -> FixedPoint[Cycle]:
    """Iterate ``plate``'s cycles and ``impact_on`` its laws from the impact ``first`` (module docstring) until two
    successive impacts change by less than ``tolerance``, at most ``max_cycles`` (≥ 1) cycles; ``progress(k)`` is
    called as cycle k (from 0) starts."""
    if max_cycles < 1:
        raise ValueError(f"max_cycles={max_cycles} is out of range: the coupling runs at least 1 plate cycle")
    impacts = [first]
    change = math.inf
    for k in range(max_cycles):
        if progress is not None:
            progress(k)
        cycle, law = plate.cycle(impacts[-1])
        impacts.append(impact_on(law))
        change = plate.change(impacts[-2], impacts[-1])
        if change < tolerance:
            break
    return FixedPoint(impacts[-1], law, cycle, tuple(impacts), change, change < tolerance)
