"""The FE surface fields p(r, t) and u_r(r, t) along a coupled impact (SI units).

:func:`pressure_table` places each step of a plate's cycle at the impact time where the impact reaches that
overlap (on the loading branch before t(δ_max), on the unloading branch after it); :func:`contact_pressure` keeps
the nodal pressure inside each step's contact radius. :func:`radial_table` places the surface's radial
displacement at the same times: its change is the surface's slip under the ball.
"""

from __future__ import annotations

import numpy as np

from contact import ImpactResult
from fem.plate_cycle import PlateCycle

__all__ = ["contact_pressure", "pressure_table", "radial_table"]


def contact_pressure(pressure, surface_r, contact_radius) -> np.ndarray:
    """Nodal pressure (Pa, steps × surface nodes) set to zero beyond each step's contact radius (m) and clipped at
    zero.

    The FE pressure is the L2 projection of the nodal reactions, which rings outside the contact (small positive
    values at nodes far from it, up to ~4% of the peak next to the edge). Left in, any positive node would stretch
    a wear grid sized from the largest loaded radius over the whole FE surface."""
    p = np.maximum(np.asarray(pressure, float), 0.0)
    r = np.asarray(surface_r, float)
    a = np.asarray(contact_radius, float)
    return np.where(r[None, :] <= a[:, None], p, 0.0)


def _placed_steps(cycle: PlateCycle, impact: ImpactResult) -> tuple[np.ndarray, np.ndarray]:
    """(the impact time of each step of ``cycle``, which steps are kept): plate step j at overlap δ_j (from first
    contact) gets the impact time where the impact has that overlap, on the loading branch for steps up to the
    cycle's maximum, on the unloading branch after it; steps below the residual overlap fall after separation and
    are dropped, as are steps no later than the kept step before them."""
    h = impact.history
    t, d = np.asarray(h.t, float), np.asarray(h.overlap, float)
    i_max = int(np.argmax(d))
    fe_d = np.asarray(cycle.overlap, float)
    j_max = int(np.argmax(fe_d))
    load_d = np.maximum.accumulate(d[: i_max + 1])
    times = np.empty(fe_d.size)
    times[: j_max + 1] = np.interp(fe_d[: j_max + 1], load_d, t[: i_max + 1])
    un_t, un_d = t[i_max:][::-1], d[i_max:][::-1]
    un_d = np.maximum.accumulate(un_d)
    times[j_max + 1 :] = np.interp(fe_d[j_max + 1 :], un_d, un_t, left=np.inf)
    keep = np.isfinite(times) & (times <= t[-1])
    previous = np.concatenate([[-np.inf], np.where(keep, times, -np.inf)[:-1]])
    keep &= np.where(keep, times, np.inf) > previous  # a step is kept if later than the kept step before it
    return times, keep


def _on_impact_times(
    impact: ImpactResult, times: np.ndarray, rows: np.ndarray, first: np.ndarray, last: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """``rows`` at ``times`` opened at the impact's first contact with the row ``first`` and closed at its
    separation with the row ``last`` (where the steps do not reach them)."""
    t = np.asarray(impact.history.t, float)
    if times[0] > t[0]:
        times, rows = np.concatenate([[t[0]], times]), np.vstack([first, rows])
    if times[-1] < t[-1]:
        times, rows = np.concatenate([times, [t[-1]]]), np.vstack([rows, last])
    return times, rows


def pressure_table(cycle: PlateCycle, impact: ImpactResult) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(time s, surface_r m, pressure Pa) of a plate cycle placed on the impact's time axis
    (:func:`_placed_steps`), zero pressure at first contact and at separation."""
    times, keep = _placed_steps(cycle, impact)
    rows = contact_pressure(cycle.pressure, cycle.surface_r, cycle.contact_radius)[keep]
    zero = np.zeros(rows.shape[1])
    times, rows = _on_impact_times(impact, times[keep], rows, zero, zero)
    return times, np.asarray(cycle.surface_r, float), rows


def radial_table(
    cycle: PlateCycle, impact: ImpactResult, before: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(time s, surface_r m, u_r m) of a plate cycle placed on the impact's time axis as :func:`pressure_table`:
    the radial displacement of the surface nodes, ``before`` (m, per surface node: the plate's before the impact,
    0 on a virgin plate) at first contact, the last step's at separation. Its change in time is the plate
    surface's radial slip under the ball (the ball, rigid in the FE, does not stretch)."""
    times, keep = _placed_steps(cycle, impact)
    rows = np.asarray(cycle.radial_displacement, float)[keep]
    times, rows = _on_impact_times(impact, times[keep], rows, np.asarray(before, float), rows[-1])
    return times, np.asarray(cycle.surface_r, float), rows
