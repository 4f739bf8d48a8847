"""The time step of an impact: its default and the bounds a given one must keep, :func:`check_time_step`.

The engine (:mod:`contact.engine`) integrates with a fixed step Δt; by default Δt = t_c/:data:`STEPS_PER_CONTACT`
of the Hertz contact time t_c of each impact's normal speed. A given Δt must resolve the contact (at most t_c/10)
and must not ask for so many steps that the run takes hours or its time histories fill the memory. SI units.
"""

from __future__ import annotations

import numpy as np

from contact.checks import check_number

__all__ = ["check_time_step", "STEPS_PER_CONTACT", "MAX_CONTACT_TIMES", "MAX_STEPS", "MAX_HISTORY_STEPS"]

#: Default number of steps per Hertz contact time t_c (time step t_c/2000).
STEPS_PER_CONTACT = 2000
#: Safety stop: an impact may take at most this many default Hertz contact times (plastic contacts last longer).
MAX_CONTACT_TIMES = 200.0
#: Most engine steps per Hertz contact time (t_c/Δt) a given time step may ask for: 10⁴ × the default 2000. Measured
#: (2 cores): 2e7 steps take 1.2 s of engine time for a Hertz impact and 7.6 s for a Thornton one; the smallest
#: time steps of the tests, the validation and the benchmarks ask for at most ~1e7 (bench_sweep's fallback; the
#: tests ≤ 5e4). A time step that asks for more is a typo (1e-15 s: ~1e10 steps, hours) and is refused up front.
MAX_STEPS = 2e7
#: The same with time histories (``histories``/``history``): a history keeps 13 floats (104 B) per step, and the
#: coupled run built on it ~330 B per step in all (measured: 2e6 steps 32 s and 1 GB, 2e7 steps 5 min and 6.6 GB).
MAX_HISTORY_STEPS = 2e6


def _short(x: float) -> str:
    """2e7, 1.3e15: a count in short scientific notation."""
    mantissa, exponent = f"{x:.1e}".split("e")
    return f"{mantissa.rstrip('0').rstrip('.')}e{int(exponent)}"


def check_time_step(
    time_step, contact_time, *, histories: bool = False, history_every: int = 1, name: str = "time_step"
) -> float:
    """``time_step`` Δt (s) checked against the Hertz ``contact_time`` t_c (s; scalar or the batch's array): at most
    t_c/10 (a contact needs steps to be resolved), and at least t_c/:data:`MAX_STEPS`, or with ``histories`` (every
    ``history_every``-th step kept) t_c/(:data:`MAX_HISTORY_STEPS` × ``history_every``), so a time step that would
    run for hours or fill the memory is refused before any step. Errors are one line naming ``name`` (e.g.
    ``impact.time_step`` for a case key). Returns Δt (s) as a float."""
    step = check_number(name, time_step, low=0.0, low_open=True, high=1.0, units="s", what="time step")
    longest, shortest = float(np.max(contact_time)), float(np.min(contact_time))
    if shortest / step < 10.0:
        raise ValueError(
            f"{name}={step:g} is out of range: must be at most 1/10 of the Hertz contact time ({shortest:.3g} s here)"
        )
    bound, why = MAX_STEPS, ""
    if histories and MAX_HISTORY_STEPS * history_every < MAX_STEPS:
        bound, why = MAX_HISTORY_STEPS * history_every, " with time histories (104 B per kept step)"
    if longest / step > bound:
        raise ValueError(
            f"{name}={step:g} s gives ~{_short(longest / step)} steps over the Hertz contact time {longest:.3g} s: "
            f"at most {_short(bound)}{why}; give {name} >= {longest / bound:.3g} s"
        )
    return step
