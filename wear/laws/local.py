r"""The local law dw/dt = K p^α v^β over the moving contact patch (errata Equation 15, :class:`wear.law.WearLaw`;
Archard's law is α = β = 1). Its volume over a whole impact is :func:`local_volume`; its map on the surface grid is
:func:`wear.integrate_wear`'s. SI units.
"""

from __future__ import annotations

import math

import numpy as np

from contact import ImpactResult
from wear.law import WearLaw
from wear.laws.declaration import Constants, Law
from wear.pressure import PressureHistory
from wear.slip import SlidingSpeed

__all__ = ["LAW", "local_volume", "pressed_area"]


def pressed_area(pressure: PressureHistory, alpha: float) -> np.ndarray:
    """∫ p^α dA = 2πa² ∫₀¹ p(s)^α s ds (Pa^α m²) at each sample of the pressure table (trapezoidal rule in s)."""
    s = pressure.s
    return 2.0 * math.pi * pressure.extent**2 * np.trapezoid(pressure.pressure**alpha * s, s, axis=1)


def local_volume(pressure: PressureHistory, speed: SlidingSpeed, law: WearLaw, area: np.ndarray | None = None) -> float:
    r"""Worn volume (m³) of equation 15 over a whole impact, without the surface grid:
    :math:`V = K \int v^\beta \int p^\alpha\,dA\,dt` (:func:`pressed_area`, given as ``area`` if already known for
    this α), the time integral by the trapezoidal rule (the sliding speed interpolated to the pressure's times). It is
    the volume of :func:`wear.integrate_wear`'s map without its spatial discretisation."""
    if area is None:
        area = pressed_area(pressure, law.alpha)
    v = np.interp(pressure.time, speed.time, speed.speed)
    rate = v**law.beta * area if law.beta > 0.0 else area
    return float(law.K * np.trapezoid(rate, pressure.time))


def _volumes(
    constants: Constants, impact: ImpactResult, *, local: float | None, plate_work: float | None
) -> dict[str, float]:
    """The cutting of one impact: its Eq. 15 volume ``local`` (m³, :func:`local_volume`)."""
    if local is None:
        raise ValueError("the local law needs the impact's Eq. 15 volume (wear.local_volume)")
    return {"cutting": local}


LAW = Law(
    name="local",
    description="Eq. 15, dw/dt = K p^alpha v^beta over the moving patch",
    volumes=_volumes,
    constants=("K", "alpha", "beta"),
    inputs=("pressure", "speed", "points_across"),
    scale="K",
    log_constants=("K",),
    uses_local=True,
)
