"""The time quadrature of the wear law (errata equation 15) over one impact, for a surface grid of a given spacing.

The time axis is the union of the pressure and speed samples (and, with the local slip, of the surface's radial
motion), each interval cut into sub-steps so that the contact patch moves less than ``cell_fraction`` of a grid cell
per sub-step (:data:`MAX_CELL_FRACTION`, a quarter). Each sub-step carries the contact centre, the pressure sample
and time weight between which p is interpolated linearly, and its weight: the trapezoidal rule's Δt × K v^β, or, with
the local slip, the midpoint rule's Δt × K (each node's own speed is taken in the kernel, :mod:`wear.accumulate`).
Sub-steps that cannot wear (no contact, no weight) are dropped. SI units.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact.checks import check_number
from wear.law import WearLaw
from wear.pressure import PressureHistory
from wear.slip import SlidingSpeed

__all__ = ["SubSteps", "wear_substeps", "MAX_CELL_FRACTION"]

#: Largest patch motion per sub-step, in grid cells.
MAX_CELL_FRACTION = 0.25


@dataclass(frozen=True, eq=False)
class SubSteps:
    """The time quadrature of one impact: per sub-step the contact centre ``contact_x`` (m), the pressure
    sample ``step`` and time weight ``fraction`` (p = (1−f)·p[step] + f·p[step+1]), and ``weight`` = trapezoid
    Δt × K v^β (units of K × s × (m/s)^β, so that weight × p^α is a depth in m). With the local slip
    (:attr:`wear.slip.SlidingSpeed.is_local`) the sub-steps are the midpoints of the intervals, ``weight`` = Δt × K,
    ``slip`` the contact-point slip velocity (m/s) and ``row`` the interval of the surface's radial motion
    (:meth:`wear.slip.RadialSlip.rates`) at each; each node's own speed is then taken in the kernel."""

    contact_x: np.ndarray
    step: np.ndarray
    fraction: np.ndarray
    weight: np.ndarray
    slip: np.ndarray | None = None
    row: np.ndarray | None = None


def wear_substeps(
    pressure: PressureHistory,
    speed: SlidingSpeed,
    law: WearLaw,
    spacing: float,
    cell_fraction: float = MAX_CELL_FRACTION,
) -> SubSteps:
    """Sub-steps of the time integral for a grid of ``spacing`` (m); drops sub-steps that cannot wear."""
    spacing = check_number("spacing", spacing, low=0.0, low_open=True, units="m")
    tp = pressure.time
    nodes = np.union1d(tp, speed.time[(speed.time > tp[0]) & (speed.time < tp[-1])])
    if speed.is_local:
        tr = speed.radial.time
        nodes = np.union1d(nodes, tr[(tr > tp[0]) & (tr < tp[-1])])
    xc = np.interp(nodes, tp, pressure.contact_x)
    pieces = np.maximum(np.ceil(np.abs(np.diff(xc)) / (cell_fraction * spacing)), 1).astype(np.int64)
    # sub-step times: each interval [t_k, t_k+1] cut into pieces[k] equal parts
    starts = np.repeat(nodes[:-1], pieces)
    widths = np.repeat(np.diff(nodes) / pieces, pieces)
    offsets = np.arange(starts.size) - np.repeat(np.cumsum(pieces) - pieces, pieces)
    tau = np.append(starts + offsets * widths, nodes[-1])
    dt = np.diff(tau)
    slip = row = None
    if speed.is_local:
        # the surface's radial rate is constant between its times: the midpoint rule on each sub-interval (one of
        # them, not the two a trapezoid node between them would straddle)
        tau = tau[:-1] + 0.5 * dt
        weight = dt * law.K
        slip = np.interp(tau, speed.time, speed.slip_velocity, left=0.0, right=0.0)
        times = speed.radial.time
        row = np.clip(np.searchsorted(times, tau, side="right") - 1, 0, times.size - 2)
    else:
        trap = np.zeros_like(tau)
        trap[:-1] += 0.5 * dt
        trap[1:] += 0.5 * dt
        v = np.interp(tau, speed.time, speed.speed, left=0.0, right=0.0)
        weight = trap * law.K * v**law.beta
    step = np.clip(np.searchsorted(tp, tau, side="right") - 1, 0, tp.size - 2)
    fraction = np.clip((tau - tp[step]) / (tp[step + 1] - tp[step]), 0.0, 1.0)
    loaded = (pressure.extent[step] > 0.0) | (pressure.extent[step + 1] > 0.0)
    keep = (weight > 0.0) & loaded

    def kept(values: np.ndarray | None) -> np.ndarray | None:
        return None if values is None else np.ascontiguousarray(values[keep])

    return SubSteps(
        contact_x=kept(np.interp(tau, tp, pressure.contact_x)),
        step=kept(step),
        fraction=kept(fraction),
        weight=kept(weight),
        slip=kept(slip),
        row=kept(row),
    )
