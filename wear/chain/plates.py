"""The plate models by ``fem.model``: each plate declares its :class:`wear.chain.plate_model.PlateModel` in its own
module, and :data:`PLATES` lists them, so a new plate model is its module and one line here. A run and a repeat
take the case's plate from here and never ask which plate it is."""

from __future__ import annotations

from contact import ImpactResult
from wear.case import Case
from wear.chain.axisymmetric_plate import AXISYMMETRIC
from wear.chain.plate_model import PlateModel, PlateRun, Timed, untimed
from wear.chain.solid_plate import SOLID

__all__ = ["PLATES", "couple_plate", "plate_model", "prepare_case"]

#: The plate models by ``fem.model``.
PLATES: dict[str, PlateModel] = {model.name: model for model in (AXISYMMETRIC, SOLID)}


def plate_model(case: Case) -> PlateModel:
    """The plate model of ``case.fem.model``."""
    return PLATES[case.fem.model]


def prepare_case(case: Case) -> Case:
    """``case`` as the plate of its ``fem.model`` runs it, checked before any work (:attr:`PlateModel.prepare`)."""
    return plate_model(case).prepare(case)


def couple_plate(case: Case, estimate: ImpactResult, timed: Timed | None = None) -> PlateRun:
    """The case's impact coupled to the plate of ``fem.model`` (:data:`PLATES`), starting from ``estimate`` (the
    impact on the case's own normal law); ``timed(stage, function, *args)`` runs each stage (default: untimed)."""
    return plate_model(case).couple(case, estimate, timed or untimed)
