"""The axisymmetric plate model (``fem.model = "axisymmetric"``): the (r, z) frictionless FE plate of
:mod:`fem.axisymmetric`, its run (:mod:`wear.chain.axisymmetric_run`) and its repetition
(:mod:`wear.chain.axisymmetric_repeat`)."""

from __future__ import annotations

from wear.case import Case
from wear.case.plate_cases import AXISYMMETRIC_CASE
from wear.chain.axisymmetric_repeat import axisymmetric_repeat
from wear.chain.axisymmetric_run import on_axisymmetric_plate
from wear.chain.plate_model import PlateModel

__all__ = ["AXISYMMETRIC"]


def _as_given(case: Case) -> Case:
    """The axisymmetric plate runs every case as given (its checks are the case schema's)."""
    return case


#: The axisymmetric plate model.
AXISYMMETRIC = PlateModel(AXISYMMETRIC_CASE, _as_given, on_axisymmetric_plate, axisymmetric_repeat)
