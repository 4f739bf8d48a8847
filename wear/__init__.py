"""wear: the wear law over the moving contact patch, the worn and dented surface, erosion, and the chains.

Rooms, imported one way (each only from those before it): the wear law (:mod:`wear.law`, :mod:`wear.pressure`,
:mod:`wear.integrate`, :mod:`wear.surface`: imports ``contact``, never ``fem``) ← the case (:mod:`wear.case`) ←
erosion (:mod:`wear.erosion`) ← the chains (:mod:`wear.chain`) ← the command line (:mod:`wear.app`). The main entry
points are importable from here, each loaded on first use (PEP 562), so that ``import wear.law`` does not load the
FE plate (``fem``, scikit-fem) that the chains need. SI units; angles in degrees from the plate normal.

Wear of one impact (errata Eq. 15, w a depth)::

    from wear import WearLaw, pressure_history, sliding_speed, integrate_wear
    law = WearLaw(K=1e-12, alpha=1.0, beta=0.3)            # K in m^(0.7) s^(-0.7) Pa^(-1)
    p = pressure_history(impact, "hertz")                  # or "fe" (fe=...), "paper", "thornton"
    v = sliding_speed(impact, "sliding")                   # or "kinematic"; "local" with an FE plate's radial=
    wm = integrate_wear(p, v, law, density=impact.plate.density)
    wm = wear_from_impact(impact, law, pressure="hertz")   # the same in one call

The whole chain, repeated impacts and erosion of a case::

    from wear import Case, calibrate, default_case, erode_case, read_data, repeat, run
    result = run(Case())                                    # impactwear run's default case
    many = repeat(Case().with_(repeat={"impacts": 10}))
    stream = erode_case(default_case("erode"))
    fitted = calibrate(Case(), read_data("DATA.csv"))      # the wear law's constants fitted to measurements
"""

from __future__ import annotations

import importlib
from typing import Any

#: name → the module that defines it; ``wear.<name>`` imports that module on first access.
_EXPORTS = {
    "__version__": "contact",  # the installed impactwear's version, read in one place
    "Case": "wear.case",
    "default_case": "wear.case",
    "dump_case": "wear.case",
    "load_case": "wear.case",
    "parse_case": "wear.case",
    "IndentRun": "wear.chain",
    "RepeatResult": "wear.chain",
    "RestitutionSweep": "wear.chain",
    "RunResult": "wear.chain",
    "indent_case": "wear.chain",
    "repeat": "wear.chain",
    "restitution_sweep": "wear.chain",
    "run": "wear.chain",
    "CalibrationResult": "wear.chain.calibrate",
    "calibrate": "wear.chain.calibrate",
    "CalibrationData": "wear.chain.calibration_data",
    "read_data": "wear.chain.calibration_data",
    "ErosionRun": "wear.erosion",
    "erode_angles": "wear.erosion",
    "erode_case": "wear.erosion",
    "WearMap": "wear.integrate",
    "axisymmetric_wear_depth": "wear.integrate",
    "integrate_volume": "wear.integrate",
    "integrate_wear": "wear.integrate",
    "surface_grid": "wear.integrate",
    "wear_from_impact": "wear.integrate",
    "WearLaw": "wear.law",
    "wear_coefficient_units": "wear.law",
    "PRESSURE_SOURCES": "wear.pressure",
    "SPEED_MODELS": "wear.slip",
    "PressureHistory": "wear.pressure",
    "RadialSlip": "wear.slip",
    "SlidingSpeed": "wear.slip",
    "fe_pressure_history": "wear.pressure",
    "hertz_pressure_history": "wear.pressure",
    "paper_pressure_history": "wear.pressure",
    "pressure_history": "wear.pressure",
    "sliding_speed": "wear.slip",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str) -> Any:
    """``wear.<name>`` for a name of :data:`__all__`: imported from its module on first access, then cached."""
    if name not in _EXPORTS:
        raise AttributeError(f"module 'wear' has no attribute {name!r}")
    value = getattr(importlib.import_module(_EXPORTS[name]), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *__all__})
