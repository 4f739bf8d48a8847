"""Repeated impacts of the same ball at the same spot, each on the plate the previous ones left: the entry point over
the plate models (``fem.model``, :data:`wear.chain.plates.PLATES`), each repeating on its own plate
(:attr:`wear.chain.plate_model.PlateModel.repeat`; the FE plates through the one loop of
:func:`wear.chain.repeat_loop.repeat_at_site`). SI units; the repetition's settings are ``case.repeat``
(:class:`wear.case.RepeatSpec`).
"""

from __future__ import annotations

from collections.abc import Callable

from wear.case import Case, check_job_case
from wear.chain.plates import plate_model
from wear.chain.records import PlateState, RepeatResult

__all__ = ["repeat"]


def repeat(
    case: Case,
    progress: Callable[[int, int], None] | None = None,
    on_computed: Callable[[int, PlateState], None] | None = None,
) -> RepeatResult:
    """Run ``case.repeat.impacts`` impacts of ``case`` at one spot on the plate of ``case.fem.model``.
    ``progress(done, total)`` after each computed impact or block; ``on_computed(impact_number, fe_plate)`` after
    each computed impact (e.g. to write the FE mesh)."""
    if not isinstance(case, Case):
        raise ValueError(f"case={type(case).__name__} is not a wear.Case")
    check_job_case(case, "repeat")
    return plate_model(case).repeat(case, progress, on_computed)
