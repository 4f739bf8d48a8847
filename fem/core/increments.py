"""The increment driver both plates share: guess → Newton attempt → cut in halves → :class:`ConvergenceError`.

A plate advances its state from one load level (a *target*: the overlap δ in m, or (δ, centre c, slide ξ) for the
3-D plate) to the next by a Newton attempt from a guess. An attempt that does not converge raises
:class:`NotConverged` with its last residual (N); the increment is then cut in halves, each half advanced in turn (the
first from the start, the second from the first half's state), at most ``max_cuts`` deep, before
:class:`ConvergenceError` names the target that failed.

>>> class Halving:
...     max_cuts = 3
...     def __init__(self):
...         self.stats = WorkCounters()
...     def attempt(self, state, previous, target):  # converges on steps of at most 0.25
...         if target - state > 0.25:
...             raise NotConverged(1.0)
...         return target
...     def midpoint(self, state, target):
...         return 0.5 * (state + target)
...     def describe(self, state, target):
...         return f"at {target}"
>>> plate = Halving()
>>> advance(plate, 0.0, None, 1.0)
1.0
>>> plate.stats.increments, plate.stats.cuts
(4, 3)
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import Generic, Protocol, TypeVar

__all__ = ["ConvergenceError", "NotConverged", "Stepper", "WorkCounters", "advance"]

State = TypeVar("State")
Target = TypeVar("Target")


class ConvergenceError(RuntimeError):
    """Newton did not converge even after cutting the increment."""


class NotConverged(Exception):
    """A Newton attempt failed; ``args[0]`` is its last residual (N), or why it failed (a sentence)."""


@dataclass
class WorkCounters:
    """The work of a plate's solver (for the benchmarks): converged ``increments``, ``cuts`` (halvings),
    Newton ``iterations``, ``factorisations`` (of which ``analyses`` analysed a new sparsity pattern: the others
    reused an analysis) and linear ``solves`` (factor applications), seconds spent
    factorising (``factor_time``) and assembling (``assembly_time``), ``cg_iterations`` (Krylov), ``relaxed``
    (iterations on a relaxed step), ``elastic_retries`` (attempts repeated with the elastic tangent), contact and
    stick ``set_updates``, line-search ``backtracks``; ``history`` a per-increment log."""

    increments: int = 0
    cuts: int = 0
    iterations: int = 0
    factorisations: int = 0
    analyses: int = 0
    solves: int = 0
    factor_time: float = 0.0
    assembly_time: float = 0.0
    cg_iterations: int = 0
    relaxed: int = 0
    elastic_retries: int = 0
    set_updates: int = 0
    backtracks: int = 0
    history: list = field(default_factory=list)

    def add(self, other: WorkCounters) -> None:
        """Add the counters of ``other`` (another run's work) to these."""
        for counter in fields(self):
            if counter.name != "history":
                setattr(self, counter.name, getattr(self, counter.name) + getattr(other, counter.name))
        self.history.extend(other.history)


class Stepper(Protocol, Generic[State, Target]):
    """What :func:`advance` needs of a plate's solver."""

    max_cuts: int
    stats: WorkCounters

    def attempt(self, state: State, previous: State | None, target: Target) -> State:
        """The converged state at ``target`` from ``state`` (``previous``: the state before it, for the guess), or
        :class:`NotConverged`."""
        ...

    def midpoint(self, state: State, target: Target) -> Target:
        """The target halfway from ``state`` to ``target``."""
        ...

    def describe(self, state: State, target: Target) -> str:
        """Where an increment failed, for the user: the target's load level (m) and the increment's start."""
        ...


def advance(stepper: Stepper, state: State, previous: State | None, target: Target, depth: int = 0) -> State:
    """The converged state at ``target`` from ``state``: ``stepper.attempt``, else the increment cut in halves (at
    most ``stepper.max_cuts`` deep); :class:`ConvergenceError` naming the target and the last residual (N), or why
    the attempt failed, if even that fails."""
    try:
        new = stepper.attempt(state, previous, target)
        stepper.stats.increments += 1
        return new
    except NotConverged as exc:
        if depth >= stepper.max_cuts:
            reason = exc.args[0]
            why = reason if isinstance(reason, str) else f"residual {float(reason):.3e} N"
            raise ConvergenceError(f"{stepper.describe(state, target)} (cut {depth} times): {why}") from None
    stepper.stats.cuts += 1
    middle = stepper.midpoint(state, target)
    half = advance(stepper, state, previous, middle, depth + 1)
    return advance(stepper, half, state, target, depth + 1)
