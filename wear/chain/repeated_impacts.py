"""Repeated impacts of the same ball at the same spot, each on the plate the previous ones left: the entry point over
the plate models (``fem.model``). The axisymmetric plate's repetition (dent, wear moving the FE surface, shakedown,
cycle jump) is :mod:`wear.chain.axisymmetric_repeat`; the 3-D plate's (oblique impacts with friction, every impact
computed) is :mod:`wear.chain.solid_repeat`. SI units; the repetition's settings are ``case.repeat``
(:class:`wear.case.RepeatSpec`).
"""

from __future__ import annotations

from collections.abc import Callable

import fem
from wear.case import Case, check_job_case
from wear.chain.axisymmetric_repeat import axisymmetric_repeat
from wear.chain.records import RepeatResult
from wear.chain.solid_repeat import solid_repeat

__all__ = ["REPEATS", "repeat"]

#: The repetition on each plate model of ``fem.model``.
REPEATS: dict[str, Callable[..., RepeatResult]] = {"axisymmetric": axisymmetric_repeat, "3d": solid_repeat}


def repeat(
    case: Case,
    progress: Callable[[int, int], None] | None = None,
    on_computed: Callable[[int, fem.Plate], None] | None = None,
) -> RepeatResult:
    """Run ``case.repeat.impacts`` impacts of ``case`` at one spot on the plate of ``case.fem.model``.
    ``progress(done, total)`` after each computed impact or block; ``on_computed(impact_number, fe_plate)`` after
    each computed impact (e.g. to write the FE mesh)."""
    if not isinstance(case, Case):
        raise ValueError(f"case={type(case).__name__} is not a wear.Case")
    check_job_case(case, "repeat")
    return REPEATS[case.fem.model](case, progress, on_computed)
