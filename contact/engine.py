r"""Batched numba time integration of ball-on-plate impacts (the engine behind :func:`contact.simulate_impact`).

Each impact starts at first contact (δ = 0, dδ/dt = v_n > 0, ω = 0, ξ = 0) and is integrated with a fixed
step until the contact ends: the first step end at which the normal force is zero while the ball moves
away (dδ/dt < 0). The end of contact is therefore located to within one step.

Equations of motion (ball of mass m, I = 2/5 m R²; errata conventions):

.. math:: m\ddot\delta = -F_n,\qquad m\dot v_t = F_t,\qquad I\dot\omega = -R F_t,\qquad
          \dot\xi = v_t - R\omega \ \text{(while sticking)}

Schemes: ``VERLET`` (default): velocity Verlet with ξ treated as a position whose velocity is the slip
velocity; the Hertz dashpot uses the predicted velocity v + a Δt, which keeps the scheme second order.
``PAPER``: the paper's explicit constant-acceleration steps (Eqs. 12–13), first order in Δt.

The batch kernel runs impacts in parallel (``prange``); one impact's state lives in registers. Results
of one impact do not depend on the batch it runs in (same floating-point operations, no fastmath).
SI units throughout.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

from .laws import ERR_MAX_STEPS, OK, P_GSTAR, P_INERTIA, P_MASS, P_RADIUS, normal_law, tangential_law

__all__ = ["VERLET", "PAPER", "OUT_FIELDS", "run_batch", "run_history", "HISTORY_FIELDS"]

VERLET, PAPER = 0, 1

#: Columns of the batch output array.
OUT_FIELDS = (
    "normal_velocity",
    "tangential_velocity",
    "spin",
    "contact_time",
    "sliding_time",
    "max_force",
    "max_overlap",
    "max_contact_radius",
    "max_peak_pressure",
    "max_tangential_force",
    "normal_work",
    "friction_work",
    "steps",
    "error",
)
_N_OUT = len(OUT_FIELDS)

#: Rows of the history array (``sliding`` stored as 0/1).
HISTORY_FIELDS = (
    "t",
    "overlap",
    "normal_force",
    "tangential_force",
    "tangential_displacement",
    "contact_radius",
    "peak_pressure",
    "slip_velocity",
    "sliding",
    "center_x",
    "normal_velocity",
    "tangential_velocity",
    "omega",
)


@njit(cache=True)
def _step(scheme, model, factor, friction, dt, delta, vn, x, vt, om, xi, fn, ft, dmax, prm, tab):
    """Advance one impact by one step; returns the new state and (a, p, sliding, error)."""
    mass, inertia, radius = prm[P_MASS], prm[P_INERTIA], prm[P_RADIUS]
    an = -fn / mass
    at = ft / mass
    aw = -radius * ft / inertia
    if scheme == VERLET:
        vn_half = vn + 0.5 * dt * an
        vt_half = vt + 0.5 * dt * at
        om_half = om + 0.5 * dt * aw
        delta_new = delta + dt * vn_half
        x_new = x + dt * vt_half
        xi_trial = xi + dt * (vt_half - radius * om_half)
        rate = vn + dt * an
    else:
        delta_new = delta + dt * vn + 0.5 * dt * dt * an
        x_new = x + dt * vt + 0.5 * dt * dt * at
        xi_trial = xi + dt * (vt - radius * om) + 0.5 * dt * dt * (at - radius * aw)
        vn_half = vn + dt * an
        vt_half = vt + dt * at
        om_half = om + dt * aw
        rate = vn_half
    dmax_new = max(dmax, delta_new)
    fn_new, a, p, err = normal_law(
        model, delta_new, rate, dmax_new, prm, tab[0], tab[1], tab[2], tab[3], tab[4], tab[5]
    )
    ft_new, xi_new, sliding = tangential_law(xi_trial, a, fn_new, friction, factor, prm[P_GSTAR])
    if scheme == VERLET:
        vn_new = vn_half - 0.5 * dt * fn_new / mass
        vt_new = vt_half + 0.5 * dt * ft_new / mass
        om_new = om_half - 0.5 * dt * radius * ft_new / inertia
    else:
        vn_new, vt_new, om_new = vn_half, vt_half, om_half
    return delta_new, vn_new, x_new, vt_new, om_new, xi_new, fn_new, ft_new, dmax_new, a, p, sliding, err


@njit(cache=True)
def _impact(scheme, model, factor, friction, dt, vn0, vt0, max_steps, prm, tab, out, hist, every):
    """Integrate one impact; fill ``out`` (see OUT_FIELDS) and, if ``every`` > 0, rows of ``hist``."""
    radius = prm[P_RADIUS]
    delta, vn, x, vt, om, xi, fn, ft, dmax = 0.0, vn0, 0.0, vt0, 0.0, 0.0, 0.0, 0.0, 0.0
    t, t_slide = 0.0, 0.0
    fmax, amax, pmax, ftmax, wn, wt = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    err = OK
    row = 0
    if every > 0:
        hist[:, 0] = 0.0
        hist[7, 0] = vt0
        hist[10, 0] = vn0
        hist[11, 0] = vt0
        row = 1
    steps = 0
    while True:
        vs = vt - radius * om
        pn, pt = fn * vn, ft * vs
        delta, vn, x, vt, om, xi, fn, ft, dmax, a, p, sliding, e = _step(
            scheme, model, factor, friction, dt, delta, vn, x, vt, om, xi, fn, ft, dmax, prm, tab
        )
        steps += 1
        t = steps * dt
        vs = vt - radius * om
        wn += 0.5 * dt * (pn + fn * vn)
        wt -= 0.5 * dt * (pt + ft * vs)
        done = fn <= 0.0 and vn < 0.0
        if done:
            sliding = False
        if sliding:
            t_slide += dt
        fmax = max(fmax, fn)
        amax = max(amax, a)
        pmax = max(pmax, p)
        ftmax = max(ftmax, abs(ft))
        if e != OK:
            err = e
            done = True
        elif steps >= max_steps:
            err = ERR_MAX_STEPS
            done = True
        if every > 0 and (done or steps % every == 0):
            hist[0, row] = t
            hist[1, row] = max(delta, 0.0) if not done else 0.0
            hist[2, row] = fn
            hist[3, row] = ft
            hist[4, row] = xi if not done else 0.0
            hist[5, row] = a
            hist[6, row] = p
            hist[7, row] = vs
            hist[8, row] = 1.0 if sliding else 0.0
            hist[9, row] = x
            hist[10, row] = vn
            hist[11, row] = vt
            hist[12, row] = om
            row += 1
        if done:
            break
    out[0] = vn
    out[1] = vt
    out[2] = om
    out[3] = t
    out[4] = t_slide
    out[5] = fmax
    out[6] = dmax
    out[7] = amax
    out[8] = pmax
    out[9] = ftmax
    out[10] = wn
    out[11] = wt
    out[12] = steps
    out[13] = err
    return row


@njit(cache=True, parallel=True)
def run_batch(scheme, model, factor, friction, dt, vn0, vt0, max_steps, prm, tab):
    """Integrate every impact i (arrays of length n); returns the (n, len(OUT_FIELDS)) output array."""
    n = vn0.shape[0]
    out = np.empty((n, _N_OUT))
    dummy = np.empty((1, 1))
    for i in prange(n):
        _impact(scheme, model, factor, friction[i], dt[i], vn0[i], vt0[i], max_steps[i], prm, tab, out[i], dummy, 0)
    return out


@njit(cache=True)
def run_history(scheme, model, factor, friction, dt, vn0, vt0, max_steps, prm, tab, capacity, every):
    """Integrate one impact recording every ``every``-th step (and the last) into a (13, rows) array."""
    out = np.empty(_N_OUT)
    hist = np.empty((len(HISTORY_FIELDS), capacity))
    rows = _impact(scheme, model, factor, friction, dt, vn0, vt0, max_steps, prm, tab, out, hist, every)
    return out, hist[:, :rows]
