"""contact: the impact of a ball on a flat plate (H-DD model) and closed-form contact mechanics.

Knows nothing of meshes or wear. SI units throughout; angles in degrees from the plate normal.
"""

from importlib.metadata import PackageNotFoundError, version

from contact.halfspace import HalfspaceContact, halfspace_contact, sphere_on_axisymmetric_surface
from contact.impact import simulate_impact, simulate_impacts
from contact.materials import Material, effective_modulus, effective_shear_modulus
from contact.results import BatchResult, History, ImpactResult
from contact.tabulated import TabulatedLaw
from contact.theory import yield_velocity

try:
    #: The installed impactwear's version (stated once, in pyproject.toml); ``fem`` and ``wear`` give the same.
    __version__ = version("impactwear")
except PackageNotFoundError:  # a source tree used without being installed
    __version__ = "0+unknown"

__all__ = [
    "__version__",
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
