"""What a wear law predicts for erosion, in the three numbers measurements are compared by: the velocity exponent, the
angle of maximum erosion and the erosion at normal incidence over the maximum (SI units; angles: from the plate
normal in, from the surface out, as erosion data are quoted).

Measured on ductile metals: erosion ∝ V^2.3–2.9 (Finnie; Oka et al. 2005: k₂ = 2.3 H_v^0.038; DNV-RP-O501:
n = 2.6), a maximum at 20–30° from the surface, and at normal incidence about a third of the maximum (Hutchings
1981; Oka's correlation gives 0.5–0.7 for hard steels).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from wear.case import Case
from wear.chain.calibration_data import CalibrationData
from wear.chain.forward_model import ForwardModel

__all__ = ["LawTrends", "law_trends", "erosion_curve"]


@dataclass(frozen=True)
class LawTrends:
    """``law``; ``velocity_exponent`` d ln E / d ln V between ``speeds`` at the angle of maximum; ``peak_angle``
    (deg from the surface) of the maximum erosion at ``speed``; ``normal_to_max`` E(normal incidence)/E_max."""

    law: str
    velocity_exponent: float
    peak_angle: float
    normal_to_max: float


def erosion_curve(case: Case, speeds, angles, values: dict[str, float] | None = None) -> np.ndarray:
    """The erosion ratio (kg/kg) of the case's wear law at every (speed m/s, angle deg from the normal) pair
    (arrays of equal size), with ``values`` replacing some of its constants."""
    speeds, angles = np.asarray(speeds, float), np.asarray(angles, float)
    data = CalibrationData(angles, speeds, "erosion_kg_per_kg", np.full(angles.size, math.nan), {})
    return ForwardModel(case, data).predict(values or {})


def law_trends(case: Case, speed: float = 50.0, speeds: tuple[float, float] = (25.0, 75.0)) -> LawTrends:
    """The trends of the case's wear law (see the module docstring), angles every 0.5° from 0 to 89° from the
    normal; the angle of maximum is the vertex of the parabola through the largest value and its two neighbours
    (DNV-RP-O501's 34.71° from the surface, not the grid's 34.5°)."""
    step = 0.5
    angles = np.arange(0.0, 89.01, step)
    e = erosion_curve(case, np.full(angles.size, speed), angles)
    k = int(np.argmax(e))
    peak = float(angles[k])
    if 0 < k < angles.size - 1:
        curvature = e[k - 1] - 2.0 * e[k] + e[k + 1]
        if curvature < 0.0:  # the largest sample is at least its neighbours: the vertex is within half a step
            peak += 0.5 * step * float(e[k - 1] - e[k + 1]) / float(curvature)
    pair = erosion_curve(case, np.array(speeds), np.full(2, peak))
    exponent = math.log(pair[1] / pair[0]) / math.log(speeds[1] / speeds[0]) if pair.min() > 0 else math.nan
    return LawTrends(case.wear.law, exponent, 90.0 - peak, float(e[0] / e[k]) if e[k] > 0 else math.nan)
