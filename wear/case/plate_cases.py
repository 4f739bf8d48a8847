"""The plate models as the case schema reads them: each model's :class:`PlateCase` (its ``fem.model`` name, the
``[fem]`` keys only it reads, its work check) and :data:`PLATE_CASES`, the one list of them, so that the schema's
checks of a case on a plate (:mod:`wear.case.check`) ask the plate's declaration and never which plate it is.

Why here and not beside each plate's chain (:mod:`wear.chain.plates`): the case schema sits below the chains
(imports go one way: the chains read the case, never the reverse), so what the case reads of a plate is declared
in the case's layer, and each chain's :class:`wear.chain.plate_model.PlateModel` takes its declaration from here
(its ``name`` is its declaration's), so a plate's name, keys and work are written once. Not in the plates' FE
folders of :mod:`fem` either: a work check takes a :class:`wear.case.Case` (its budget names the case's keys), which
``fem`` may not import. The declarations take the case's work estimates (:mod:`wear.case.work`), which read the
schema, so this list sits above the schema's tables: the choices of ``fem.model`` the tables need while they are
built are its names again (:data:`wear.case.choices.FEM_MODELS`), held equal to this list by the test suite.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from wear.case.case import Case
from wear.case.work import check_axisymmetric_work, check_solid_work

__all__ = ["AXISYMMETRIC_CASE", "PLATE_CASES", "PlateCase", "SOLID_CASE"]


@dataclass(frozen=True)
class PlateCase:
    """What the case schema reads of a plate model: ``name`` (its ``fem.model``), ``fem_keys`` (the ``[fem]`` keys
    only it reads, besides those of its coupling; a job refuses them on another plate) and ``check_work(case, job)``
    (a one-line ``ValueError`` for a ``run``, ``repeat`` or ``indent`` of ``case`` on this plate past the memory or
    time budget of :mod:`wear.case.budget`; None if it fits)."""

    name: str
    fem_keys: tuple[str, ...]
    check_work: Callable[[Case, str], None]


#: The axisymmetric (r, z) frictionless plate: no ``[fem]`` key of its own.
AXISYMMETRIC_CASE = PlateCase("axisymmetric", (), check_axisymmetric_work)
#: The 3-D half plate with Coulomb friction: its own cycles and increments, besides those of the axisymmetric
#: coupling it starts from.
SOLID_CASE = PlateCase("3d", ("solid_iterations", "solid_load_steps", "solid_unload_steps"), check_solid_work)

#: The plate models by ``fem.model``, in the order of its choices.
PLATE_CASES: dict[str, PlateCase] = {plate.name: plate for plate in (AXISYMMETRIC_CASE, SOLID_CASE)}
