"""The first estimate of a case's impact: the impact on the case's own normal model, which a run couples to its
plate and a repeat starts from (SI units)."""

from __future__ import annotations

from contact import ImpactResult, simulate_impact
from wear.case import Case

__all__ = ["estimate_arguments", "estimate_impact"]


def estimate_arguments(case: Case, **overrides) -> dict:
    """:func:`contact.simulate_impact`'s arguments for the case's impact on its own normal model
    (``impact.normal_model``; Thornton's law is Hertz's when nothing yields), ``overrides`` replacing some."""
    args = case.impact_arguments(**overrides)  # checks the time step for the histories, if asked for
    thornton = args["normal_model"] == "thornton" and "normal_model" not in overrides
    if thornton and not args["plate"].yield_strength and not args["ball"].yield_strength:
        args["normal_model"] = "hertz"  # nothing yields: Thornton's law is Hertz
    return args


def estimate_impact(case: Case, **overrides) -> ImpactResult:
    """The impact of ``case`` on its own normal model, with its histories (:func:`estimate_arguments`): the impact
    of an uncoupled run and the first estimate of a coupled one."""
    return simulate_impact(**estimate_arguments(case, history=True, **overrides))
