"""wear: the wear law over the moving contact patch, the worn and dented surface, erosion, and the chains.

Rooms, imported one way (each only from those before it): the wear law (:mod:`wear.law`, :mod:`wear.pressure`,
:mod:`wear.integrate`, :mod:`wear.surface`: imports ``contact``, never ``fem``) ← the case (:mod:`wear.case`) ←
erosion (:mod:`wear.erosion`) ← the chains (:mod:`wear.chain`) ← the command line (:mod:`wear.app`). The main entry
points are importable from here. SI units; angles in degrees from the plate normal.

Wear of one impact (errata Eq. 15, w a depth)::

    from wear import WearLaw, pressure_history, sliding_speed, integrate_wear
    law = WearLaw(K=1e-12, alpha=1.0, beta=0.3)            # K in m^(0.7) s^(-0.7) Pa^(-1)
    p = pressure_history(impact, "hertz")                  # or "fe" (fe=...), "paper", "thornton"
    v = sliding_speed(impact, "sliding")                   # or "kinematic"
    wm = integrate_wear(p, v, law, density=impact.plate.density)
    wm = wear_from_impact(impact, law, pressure="hertz")   # the same in one call

The whole chain, repeated impacts and erosion of a case::

    from wear import Case, default_case, run, repeat, erode_case
    result = run(Case())                                    # impactwear run's default case
    many = repeat(Case().with_(repeat={"impacts": 10}))
    stream = erode_case(default_case("erode"))
"""

from wear.case import Case, default_case, dump_case, load_case, parse_case
from wear.chain import (
    IndentRun,
    RepeatResult,
    RestitutionSweep,
    RunResult,
    indent_case,
    repeat,
    restitution_sweep,
    run,
)
from wear.erosion import ErosionRun, erode_angles, erode_case
from wear.integrate import (
    WearMap,
    axisymmetric_wear_depth,
    integrate_volume,
    integrate_wear,
    surface_grid,
    wear_from_impact,
)
from wear.law import WearLaw, wear_coefficient_units
from wear.pressure import (
    PRESSURE_SOURCES,
    SPEED_MODELS,
    PressureHistory,
    SlidingSpeed,
    fe_pressure_history,
    hertz_pressure_history,
    paper_pressure_history,
    pressure_history,
    sliding_speed,
)

__all__ = [
    "PRESSURE_SOURCES",
    "SPEED_MODELS",
    "Case",
    "ErosionRun",
    "IndentRun",
    "PressureHistory",
    "RepeatResult",
    "RestitutionSweep",
    "RunResult",
    "SlidingSpeed",
    "WearLaw",
    "WearMap",
    "axisymmetric_wear_depth",
    "default_case",
    "dump_case",
    "erode_angles",
    "erode_case",
    "fe_pressure_history",
    "hertz_pressure_history",
    "indent_case",
    "integrate_volume",
    "integrate_wear",
    "load_case",
    "paper_pressure_history",
    "parse_case",
    "pressure_history",
    "repeat",
    "restitution_sweep",
    "run",
    "sliding_speed",
    "surface_grid",
    "wear_coefficient_units",
    "wear_from_impact",
]
