"""Normal restitution of the coupled FE impact against Thornton (1997) over V_n/V_y (SI units)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

import fem
from contact.theory import thornton_restitution, yield_velocity
from wear.case import Case
from wear.chain.estimate import estimate_impact
from wear.chain.plate import case_plate, coupling_settings, impact_on_law

__all__ = ["RestitutionSweep", "restitution_sweep"]


@dataclass(frozen=True, eq=False)
class RestitutionSweep:
    """Normal restitution of coupled FE impacts against Thornton (1997) over V_n/V_y.

    ``speed_ratio`` V_n/V_y; ``restitution`` e_n of the two-way coupled impacts; ``thornton`` Thornton's closed
    form at the same ratios; ``difference`` (e_n − e_Thornton)/e_Thornton; ``iterations`` and ``change`` of each
    coupling; ``yield_speed`` V_y (m/s)."""

    speed_ratio: np.ndarray
    restitution: np.ndarray
    thornton: np.ndarray
    difference: np.ndarray
    iterations: np.ndarray
    change: np.ndarray
    yield_speed: float


def restitution_sweep(case: Case, speed_ratios) -> RestitutionSweep:
    """The two-way coupled normal impact of ``case`` (angle set to 0) at each V_n/V_y in ``speed_ratios``, each on
    a virgin plate (:func:`fem.couple`)."""
    ball, plate = case.ball.material(), case.plate.material()
    if not plate.yield_strength:
        raise ValueError("plate.yield_strength=None: the restitution sweep needs a plate that yields (Pa)")
    v_y = yield_velocity(case.ball.radius, ball, plate)
    ratios = np.asarray(speed_ratios, float)
    e, its, changes = [], [], []
    for ratio in ratios:
        c = case.with_(impact={"speed": float(ratio * v_y), "angle": 0.0})
        estimate = estimate_impact(c)
        fe_plate = case_plate(c, (1.0 + c.fem.overshoot) * estimate.max_overlap)
        res = fem.couple(fe_plate, impact_on_law(c), estimate.max_overlap, coupling_settings(c))
        e.append(res.impact.normal_restitution)
        its.append(res.iterations)
        changes.append(res.change)
    e = np.asarray(e)
    ref = np.asarray(thornton_restitution(ratios), float)
    return RestitutionSweep(ratios, e, ref, (e - ref) / ref, np.asarray(its), np.asarray(changes), v_y)
