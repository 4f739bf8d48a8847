"""The choices of the case's string keys that name a model: the impact–plate couplings (``fem.coupling``), the FE
plate models (``fem.model``), the impact's normal and tangential force laws (``impact.normal_model``,
``impact.tangential_model``) and its time integration schemes (``impact.scheme``).
"""

from __future__ import annotations

from contact.impact import NORMAL_MODELS as ENGINE_NORMAL_MODELS
from contact.impact import TANGENTIAL_MODELS as ENGINE_TANGENTIAL_MODELS

__all__ = ["COUPLINGS", "FEM_MODELS", "NORMAL_MODELS", "TANGENTIAL_MODELS", "SCHEMES"]

#: The impact–plate couplings: the impact on the FE plate's own force law, the FE plate along the closed-form
#: impact, or no FE plate.
COUPLINGS = ("two-way", "one-way", "none")
#: The FE plate models' names (``fem.model``'s choices): the axisymmetric (r, z) frictionless plate and the 3-D half
#: plate with Coulomb friction. What the case reads of each (its own ``[fem]`` keys, its work check) is its
#: declaration in :data:`wear.case.plate_cases.PLATE_CASES`, which sits above the tables these choices build.
FEM_MODELS = ("axisymmetric", "3d")
#: The impact engine's normal laws (:data:`contact.impact.NORMAL_MODELS`) but its "tabulated" one, which runs on a
#: force law given as data (:class:`contact.TabulatedLaw`): a case holds no such key; its FE plate's tabulated law
#: is what ``fem.coupling = "two-way"`` gives the impact.
NORMAL_MODELS = tuple(model for model in ENGINE_NORMAL_MODELS if model != "tabulated")
#: The impact engine's tangential laws (:data:`contact.impact.TANGENTIAL_MODELS`).
TANGENTIAL_MODELS = tuple(ENGINE_TANGENTIAL_MODELS)
SCHEMES = ("verlet", "paper")
