"""wear: the wear law integrated over the moving contact patch, the worn and dented surface, the pipeline.

Wear of one impact (SI units; errata Eq. 15, w a depth)::

    from wear import WearLaw, pressure_history, sliding_speed, integrate_wear
    law = WearLaw(K=1e-12, alpha=1.0, beta=0.3)            # K in m^(0.7) s^(-0.7) Pa^(-1)
    p = pressure_history(impact, "hertz")                  # or "fe" (fe=...), "paper", "thornton"
    v = sliding_speed(impact, "sliding")                   # or "kinematic"
    wm = integrate_wear(p, v, law, density=impact.plate.density)
    wm.volume_m3, wm.mass_kg, wm.max_depth_m, wm.scar_length_m, wm.scar_width_m, wm.depth
    wm = wear_from_impact(impact, law, pressure="fe", fe=indentation)   # the same in one call
"""

from .integrate import (
    WearMap,
    axisymmetric_wear_depth,
    integrate_volume,
    integrate_wear,
    surface_grid,
    wear_from_impact,
)
from .law import WearLaw, wear_coefficient_units
from .pressure import (
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
    "PressureHistory",
    "SlidingSpeed",
    "WearLaw",
    "WearMap",
    "axisymmetric_wear_depth",
    "fe_pressure_history",
    "hertz_pressure_history",
    "integrate_volume",
    "integrate_wear",
    "paper_pressure_history",
    "pressure_history",
    "sliding_speed",
    "surface_grid",
    "wear_coefficient_units",
    "wear_from_impact",
]
