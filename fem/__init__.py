"""fem: an axisymmetric (r, z) elastic-plastic plate pressed by a sphere, in scikit-fem (SI units).

Entry points: :func:`indent` (overlap path → :class:`IndentationResult`), :func:`indent_impact`
(along an impact's overlap history), :func:`plate_mesh` and :mod:`fem.mesh` (meshes).
"""

from .indent import estimate_contact_radius, indent, indent_impact, plate_mesh
from .mesh import generate_mesh, load_mesh
from .plate import Plate
from .result import FirstYieldPoint, IndentationResult
from .solver import ConvergenceError

__all__ = [
    "ConvergenceError",
    "FirstYieldPoint",
    "IndentationResult",
    "Plate",
    "estimate_contact_radius",
    "generate_mesh",
    "indent",
    "indent_impact",
    "load_mesh",
    "plate_mesh",
]
