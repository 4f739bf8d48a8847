"""fem: an axisymmetric (r, z) elastic-plastic plate pressed by a sphere, in scikit-fem (SI units).

Entry points: :func:`indent` (overlap path → :class:`IndentationResult`), :func:`indent_impact`
(along an impact's overlap history), :class:`Plate` (a plate that keeps its state between indentations),
:func:`elastic_reload` (its elastic response, condensed onto the surface), :func:`couple` (an impact on the plate's
own force law, :mod:`fem.axisymmetric_coupling`; the force law :mod:`fem.force_law`, the plate's cycle
:mod:`fem.plate_cycle`, its pressure along the impact :mod:`fem.pressure_table`), :func:`plate_mesh` and
:mod:`fem.axisymmetric.mesh` (meshes). Both plates' couplings are the one fixed point of :mod:`fem.coupling`.

The 3-D plate (half block about the plane of incidence, quadratic tetrahedra, Coulomb friction): :func:`indent_solid`
(:mod:`fem.solid.indentation`, :mod:`fem.solid.solver`, :mod:`fem.solid.forms`, :mod:`fem.solid.mesh`, sparse solves in
:mod:`fem.core.linear`, the stress on its surface in :mod:`fem.solid.surface_stress`) and :func:`couple_solid` (an
oblique impact on it, :mod:`fem.solid_coupling`).
"""

from contact import __version__
from fem.axisymmetric.indent import indent, indent_impact, plate_mesh
from fem.axisymmetric.mesh import generate_mesh, load_mesh
from fem.axisymmetric.plate import Plate, surface_profile
from fem.axisymmetric.reload import ElasticReload, elastic_reload
from fem.axisymmetric.result import REGIMES, FirstYieldPoint, IndentationResult, worst_regime
from fem.axisymmetric_coupling import CoupledImpact, CouplingSettings, couple, couple_elastic
from fem.core.increments import ConvergenceError
from fem.core.material import estimate_contact_radius
from fem.plate_cycle import PlateCycle
from fem.pressure_table import contact_pressure
from fem.solid.indentation import SolidIndentation, indent_solid
from fem.solid_coupling import SolidCoupledImpact, couple_solid

__all__ = [
    "__version__",
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
