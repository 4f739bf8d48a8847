"""fem: an axisymmetric (r, z) elastic-plastic plate pressed by a sphere, in scikit-fem (SI units).

Entry points: :func:`indent` (overlap path → :class:`IndentationResult`), :func:`indent_impact`
(along an impact's overlap history), :class:`Plate` (a plate that keeps its state between indentations) and
:func:`elastic_reload` (its elastic response, condensed onto the surface), :func:`plate_mesh` and :mod:`fem.mesh`
(meshes).
"""

from .indent import estimate_contact_radius, indent, indent_impact, plate_mesh
from .mesh import generate_mesh, load_mesh
from .plate import Plate, surface_profile
from .reload import ElasticReload, elastic_reload
from .result import FirstYieldPoint, IndentationResult
from .solver import ConvergenceError

__all__ = [
    "ConvergenceError",
    "ElasticReload",
    "FirstYieldPoint",
    "IndentationResult",
    "Plate",
    "elastic_reload",
    "estimate_contact_radius",
    "generate_mesh",
    "indent",
    "indent_impact",
    "load_mesh",
    "plate_mesh",
    "surface_profile",
]
