"""contact: the impact of a ball on a flat plate (H-DD model) and closed-form contact mechanics.

Knows nothing of meshes or wear. SI units throughout; angles in degrees from the plate normal.

Importing any ``contact.x`` runs this file first, so what it imports every user of ``contact`` pays for. It imports
the numpy-only modules; the names whose modules load heavier libraries are exported on first access (PEP 562, as
the package ``wear`` does for its chains): the impact (:func:`simulate_impact`, :func:`simulate_impacts`: the numba
engine, :mod:`contact.engine`, and scipy's ODE solver) and :func:`yield_velocity` (:mod:`contact.theory`:
scipy.optimize and scipy.special). So the input checks (:mod:`contact.checks`, which the wear law imports) load
neither numba nor scipy, and ``from contact import simulate_impact`` works as before. The alternative, numba's
kernels compiled on the first impact rather than decorated at the top of :mod:`contact.engine`, would hide the
kernels behind a factory and still leave scipy on every import.
"""

from importlib.metadata import PackageNotFoundError, version
from typing import TYPE_CHECKING, Any

from contact.halfspace import HalfspaceContact, halfspace_contact, sphere_on_axisymmetric_surface
from contact.materials import Material, effective_modulus, effective_shear_modulus
from contact.results import BatchResult, History, ImpactResult
from contact.tabulated import TabulatedLaw

if TYPE_CHECKING:  # what the names exported on first access are, for type checkers and editors
    from contact.impact import simulate_impact, simulate_impacts
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


def __getattr__(name: str) -> Any:
    """``contact.simulate_impact``, ``contact.simulate_impacts`` and ``contact.yield_velocity``: imported from their
    module on first access, then kept."""
    # here, not at the top: the impact loads numba's engine and the closed forms scipy, which the checks do not need
    if name in ("simulate_impact", "simulate_impacts"):
        from contact import impact as module  # numba's kernels, scipy's ODE solver
    elif name == "yield_velocity":
        from contact import theory as module  # scipy.optimize, scipy.special
    else:
        raise AttributeError(f"module 'contact' has no attribute {name!r}")
    value = getattr(module, name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
