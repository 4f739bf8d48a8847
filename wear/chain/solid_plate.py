"""The 3-D plate model (``fem.model = "3d"``): the half plate with Coulomb friction of :mod:`fem.solid`, its run
(:mod:`wear.chain.solid_run`, started from the axisymmetric coupled impact) and its repetition
(:mod:`wear.chain.solid_repeat`)."""

from __future__ import annotations

from wear.case.plate_cases import SOLID_CASE
from wear.chain.plate_model import PlateModel
from wear.chain.solid_repeat import solid_repeat
from wear.chain.solid_run import on_solid_plate, prepare_solid_case

__all__ = ["SOLID"]

#: The 3-D plate model.
SOLID = PlateModel(SOLID_CASE, prepare_solid_case, on_solid_plate, solid_repeat)
