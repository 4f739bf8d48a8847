"""contact: the impact of a ball on a flat plate (H-DD model) and closed-form contact mechanics.

Knows nothing of meshes or wear. SI units throughout; angles in degrees from the plate normal.
"""

from .halfspace import HalfspaceContact, halfspace_contact, sphere_on_axisymmetric_surface
from .impact import simulate_impact, simulate_impacts
from .materials import Material, effective_modulus, effective_shear_modulus
from .results import BatchResult, History, ImpactResult
from .tabulated import TabulatedLaw
from .theory import yield_velocity

__all__ = [
    "BatchResult",
    "HalfspaceContact",
    "History",
    "ImpactResult",
    "Material",
    "TabulatedLaw",
    "effective_modulus",
    "effective_shear_modulus",
    "halfspace_contact",
    "sphere_on_axisymmetric_surface",
    "simulate_impact",
    "simulate_impacts",
    "yield_velocity",
]
