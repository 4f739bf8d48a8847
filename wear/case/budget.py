r"""Work bounds: a case whose estimated memory or wall time would not fit is refused before any work, in one line
naming the key the user gave, its value, the estimate and the largest (or smallest) value of that key that fits.

Memory: at most :func:`memory_budget`, the lesser of :data:`MAX_MEMORY` and half this machine's physical memory (read
with ``os.sysconf``), so that no case it accepts makes this machine swap. Time: at most :data:`MAX_SECONDS` of
estimated work, a fixed bound (a long run is a choice of the user's case, not of the machine).

The estimates (each with the measurement behind it where it is defined) are upper bounds of the peak memory or
wall time; :func:`check_budget` takes one as a function of the key's value and finds the value that fits by
bisection, so that an estimate is written once and its refusal follows from it.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable

__all__ = ["MAX_MEMORY", "MAX_SECONDS", "memory_budget", "fitting_value", "check_budget"]

#: Largest estimated peak memory of a case (B) on a machine with at least twice as much: 2 GB.
MAX_MEMORY = 2e9
#: Largest estimated wall time of a case's work (s): one hour.
MAX_SECONDS = 3600.0


def memory_budget() -> float:
    """The memory (B) a case may need: :data:`MAX_MEMORY`, or half this machine's physical memory if that is less
    (``os.sysconf``; where the machine does not say, :data:`MAX_MEMORY`)."""
    try:
        physical = os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    except (AttributeError, OSError, ValueError):
        return MAX_MEMORY
    return min(MAX_MEMORY, 0.5 * physical) if physical > 0 else MAX_MEMORY


def fitting_value(
    need: Callable[[float], float], limit: float, cheap: float, value: float, *, integer: bool = True
) -> float | None:
    """The value between ``cheap`` (the end of a key's range that needs least) and ``value`` (which needs more than
    ``limit``) nearest ``value`` with ``need(x) <= limit``, for a ``need`` monotone between them (bisection: to
    an integer with ``integer``, else to 1e-3 relative), or None if even ``cheap`` needs more."""
    if need(cheap) > limit:
        return None
    good, bad = cheap, value
    while True:
        if integer:
            if abs(bad - good) <= 1:
                return good
            mid = good + (bad - good) // 2
        else:
            if abs(bad - good) <= 1e-3 * max(abs(good), abs(bad)):
                return good
            mid = 0.5 * (good + bad)
        if need(mid) <= limit:
            good = mid
        else:
            bad = mid


def check_budget(
    name: str,
    value: float,
    need: Callable[[float], float],
    *,
    what: str,
    valid: tuple[float, float],
    memory: bool = True,
    increasing: bool = True,
    integer: bool = True,
    context: str = "",
) -> None:
    """A one-line ``ValueError`` if ``need(value)`` (B with ``memory``, else s) exceeds :func:`memory_budget` (or
    :data:`MAX_SECONDS`): after ``context`` (e.g. the file the value is of) it names ``name``, ``value``, the
    estimate (``what`` says of what) and the value of ``name`` nearest ``value`` that fits (:func:`fitting_value`),
    in the key's ``valid`` range (low, high); the need grows with the value (``increasing``) or falls with it (e.g.
    a mesh size)."""
    limit = memory_budget() if memory else MAX_SECONDS
    estimate = need(value)
    if estimate <= limit:
        return
    cheap = valid[0] if increasing else valid[1]
    best = fitting_value(need, limit, cheap, value, integer=integer)
    amount = f"{estimate / 1e9:.3g} GB" if memory else _duration(estimate)
    bound = f"at most {limit / 1e9:.3g} GB on this machine" if memory else f"at most {_duration(limit)}"
    if best is None:
        fix = f"no {name} in [{valid[0]:g}, {valid[1]:g}] fits with the case's other keys"
    else:
        fix = f"give {name} {'<=' if increasing else '>='} {_shown(best, integer, up=not increasing)}"
    raise ValueError(f"{context}{name}={value:g} needs ~{amount} ({what}): {bound}; {fix}")


def _shown(value: float, integer: bool, up: bool) -> str:
    """``value`` as text: an integer as it is, else to 4 significant digits rounded ``up`` or down (toward the cheap
    end, so that the value shown fits too)."""
    if integer or value == 0.0:
        return f"{value:g}"
    quantum = 10.0 ** (math.floor(math.log10(abs(value))) - 3)
    return f"{(math.ceil if up else math.floor)(value / quantum) * quantum:.4g}"


def _duration(seconds: float) -> str:
    if seconds < 120.0:
        return f"{seconds:.3g} s"
    if seconds < 7200.0:
        return f"{seconds / 60.0:.3g} min"
    return f"{seconds / 3600.0:.3g} h"
