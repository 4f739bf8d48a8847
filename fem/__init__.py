"""fem: an axisymmetric (r, z) elastic-plastic plate pressed by a sphere, in scikit-fem (SI units).

Entry points: :func:`indent` (overlap path → :class:`IndentationResult`), :func:`indent_impact`
(along an impact's overlap history), :class:`Plate` (a plate that keeps its state between indentations),
:func:`elastic_reload` (its elastic response, condensed onto the surface), :func:`couple` (an impact on the plate's
own force law, :mod:`fem.coupling`), :func:`plate_mesh` and :mod:`fem.mesh` (meshes).

The 3-D plate (half block about the plane of incidence, quadratic tetrahedra, Coulomb friction): :func:`indent_solid`
(:mod:`fem.solid`, :mod:`fem.solid_solver`, :mod:`fem.forms3d`, :mod:`fem.mesh3d`, sparse solves in
:mod:`fem.linear`, the stress on its surface in :mod:`fem.surface_stress`) and :func:`couple_solid` (an oblique
impact on it, :mod:`fem.solid_coupling`).
"""

from fem.coupling import CoupledImpact, CouplingSettings, PlateCycle, contact_pressure, couple, couple_elastic
from fem.indent import estimate_contact_radius, indent, indent_impact, plate_mesh
from fem.mesh import generate_mesh, load_mesh
from fem.plate import Plate, surface_profile
from fem.reload import ElasticReload, elastic_reload
from fem.result import REGIMES, FirstYieldPoint, IndentationResult, worst_regime
from fem.solid import SolidIndentation, indent_solid
from fem.solid_coupling import SolidCoupledImpact, couple_solid
from fem.solver import ConvergenceError

__all__ = [
    "REGIMES",
    "ConvergenceError",
    "CoupledImpact",
    "CouplingSettings",
    "PlateCycle",
    "contact_pressure",
    "couple",
    "couple_elastic",
    "ElasticReload",
    "FirstYieldPoint",
    "IndentationResult",
    "Plate",
    "SolidIndentation",
    "SolidCoupledImpact",
    "couple_solid",
    "elastic_reload",
    "estimate_contact_radius",
    "generate_mesh",
    "indent",
    "indent_impact",
    "indent_solid",
    "load_mesh",
    "plate_mesh",
    "surface_profile",
    "worst_regime",
]
