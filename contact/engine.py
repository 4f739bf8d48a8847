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

One concept longer than ~400 lines (~100 of them the kernels' arguments, one a line): the step, the single-impact
loop, the SIMD lane block and the batch driver stay in one file because numba inlines ``inline="always"`` kernels
and checks its cache only against the file that defines a kernel, so a kernel split from its callers would leave
their caches stale after an edit, silently (the force laws of :mod:`contact.laws` already cost that, and the
development notes say to delete the caches; a second file of kernels would double the trap).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from contact.laws import (
    ERR_MAX_STEPS,
    HERTZ,
    MEMORY,
    OK,
    P_DAMP,
    P_GSTAR,
    P_HERTZ_K,
    P_INERTIA,
    P_MASS,
    P_RADIUS,
    P_SHEAR,
    SPRING,
    SPRINGS,
    memory_tangential_law,
    normal_law,
    tangential_law,
)

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


@njit(cache=True, inline="always", error_model="numpy")
def _hertz_verlet_step(
    factor, friction, dt, delta, vn, x, vt, om, xi, fn, ft, dmax, radius, mass, inertia, stiff, damp, gstar
):
    """The Hertz + dashpot, velocity-Verlet step written without branches (selects only) so that a loop over
    impacts vectorises; same equations as the general path (:func:`contact.laws.normal_law`, ``tangential_law``)."""
    vn_half = vn - 0.5 * dt * fn / mass
    vt_half = vt + 0.5 * dt * ft / mass
    om_half = om - 0.5 * dt * radius * ft / inertia
    delta_new = delta + dt * vn_half
    x_new = x + dt * vt_half
    xi_trial = xi + dt * (vt_half - radius * om_half)
    rate = vn - dt * fn / mass
    dc = delta_new if delta_new > 0.0 else 0.0
    root = math.sqrt(dc)
    fn_raw = stiff * dc * root + damp * math.sqrt(root) * rate
    fn_new = fn_raw if fn_raw > 0.0 else 0.0
    a = math.sqrt(radius * dc)
    p = 1.5 * stiff * root / (math.pi * radius)  # Hertz p0 of the spring's force (see contact.laws.normal_law)
    k_t = factor * 8.0 * gstar * a
    force = -k_t * xi_trial
    limit = friction * fn_new
    sliding = math.fabs(force) > limit
    sign = 1.0 if xi_trial > 0.0 else -1.0
    xi_slide = sign * limit / k_t if k_t > 0.0 else 0.0
    xi_new = xi_slide if sliding else xi_trial
    ft_new = -sign * limit if sliding else force
    vn_new = vn_half - 0.5 * dt * fn_new / mass
    vt_new = vt_half + 0.5 * dt * ft_new / mass
    om_new = om_half - 0.5 * dt * radius * ft_new / inertia
    dmax_new = delta_new if delta_new > dmax else dmax
    return delta_new, vn_new, x_new, vt_new, om_new, xi_new, fn_new, ft_new, dmax_new, a, p, sliding, OK


@njit(cache=True, inline="always", error_model="numpy")
def _step(
    scheme, model, tangential, factor, friction, dt, delta, vn, x, vt, om, xi, fn, ft, dmax, prm, tab, springs, pitch
):
    """Advance one impact by one step; returns the new state and (a, p, sliding, error). With the ``MEMORY``
    tangential law ξ is the ball surface's slide ∫(v_t − Rω) dt and ``springs`` (spaced ``pitch`` m) its state."""
    mass, inertia, radius = prm[P_MASS], prm[P_INERTIA], prm[P_RADIUS]
    if model == HERTZ and scheme == VERLET and tangential == SPRING:
        return _hertz_verlet_step(
            factor,
            friction,
            dt,
            delta,
            vn,
            x,
            vt,
            om,
            xi,
            fn,
            ft,
            dmax,
            radius,
            mass,
            inertia,
            prm[P_HERTZ_K],
            prm[P_DAMP],
            prm[P_GSTAR],
        )
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
    if tangential == MEMORY:
        ft_new, sliding, e = memory_tangential_law(
            springs, pitch, xi_trial - xi, a, fn_new, friction, prm[P_GSTAR], prm[P_SHEAR]
        )
        xi_new = xi_trial
        err = err if err != OK else e
    else:
        ft_new, xi_new, sliding = tangential_law(xi_trial, a, fn_new, friction, factor, prm[P_GSTAR])
    if scheme == VERLET:
        vn_new = vn_half - 0.5 * dt * fn_new / mass
        vt_new = vt_half + 0.5 * dt * ft_new / mass
        om_new = om_half - 0.5 * dt * radius * ft_new / inertia
    else:
        vn_new, vt_new, om_new = vn_half, vt_half, om_half
    return delta_new, vn_new, x_new, vt_new, om_new, xi_new, fn_new, ft_new, dmax_new, a, p, sliding, err


@njit(cache=True, error_model="numpy")
def _impact(scheme, model, tangential, factor, friction, dt, vn0, vt0, max_steps, prm, tab, pitch, out, hist, every):
    """Integrate one impact; fill ``out`` (see OUT_FIELDS) and, if ``every`` > 0, rows of ``hist``."""
    radius = prm[P_RADIUS]
    springs = np.zeros(SPRINGS if tangential == MEMORY else 1)
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
            scheme,
            model,
            tangential,
            factor,
            friction,
            dt,
            delta,
            vn,
            x,
            vt,
            om,
            xi,
            fn,
            ft,
            dmax,
            prm,
            tab,
            springs,
            pitch,
        )
        steps += 1
        t = steps * dt
        vs = vt - radius * om
        wn += 0.5 * dt * (pn + fn * vn)
        wt -= 0.5 * dt * (pt + ft * vs)
        ended = fn <= 0.0 and vn < 0.0
        done = ended or e != OK or steps >= max_steps
        err = e if e != OK else (OK if ended or not done else ERR_MAX_STEPS)
        sliding = sliding and not done
        if sliding:
            t_slide += dt
        fmax = max(fmax, fn)
        amax = max(amax, a)
        pmax = max(pmax, p)
        ftmax = max(ftmax, abs(ft))
        if every > 0 and (done or steps % every == 0):
            hist[0, row] = t
            hist[1, row] = max(delta, 0.0)
            hist[2, row] = fn
            hist[3, row] = ft
            hist[4, row] = xi if not done else 0.0
            hist[5, row] = a if not done else 0.0
            hist[6, row] = p if not done else 0.0
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


#: Impacts integrated side by side in one block (SIMD lanes): the state of a block lives in short arrays that
#: the compiler can keep in vector registers; lanes that have finished are frozen by selects, not branches.
LANES = 8


# Rows of a block's state array (one column per lane); integers are stored as floats (exact below 2**53).
_D, _VN, _X, _VT, _OM, _XI, _FN, _FT, _DMAX, _GO, _STEPS = range(11)
_SLIDE, _FMAX, _AMAX, _PMAX, _FTMAX, _WN, _WT, _ERR, _MU, _DT, _LIMIT = range(11, 22)
_ROWS = 22


@njit(cache=True, inline="always", error_model="numpy")
def _lane_update(st, k, radius, new):
    """Book-keeping of lane k after a step, with selects only (so that the lane loop vectorises):
    frozen once its impact has ended. Returns 1.0 while the lane is still active."""
    d1, vn1, x1, vt1, om1, xi1, fn1, ft1, dm1, a, p, sliding, e = new
    go = st[_GO, k] > 0.0
    h = st[_DT, k]
    vs0 = st[_VT, k] - radius * st[_OM, k]
    vs1 = vt1 - radius * om1
    ended = fn1 <= 0.0 and vn1 < 0.0
    too_long = st[_STEPS, k] + 1.0 >= st[_LIMIT, k]
    done = ended or e != OK or too_long
    code = e if e != OK else (OK if ended else ERR_MAX_STEPS)
    st[_SLIDE, k] += h if (sliding and go and not done) else 0.0
    st[_FMAX, k] = fn1 if (go and fn1 > st[_FMAX, k]) else st[_FMAX, k]
    st[_AMAX, k] = a if (go and a > st[_AMAX, k]) else st[_AMAX, k]
    st[_PMAX, k] = p if (go and p > st[_PMAX, k]) else st[_PMAX, k]
    st[_FTMAX, k] = math.fabs(ft1) if (go and math.fabs(ft1) > st[_FTMAX, k]) else st[_FTMAX, k]
    st[_WN, k] += 0.5 * h * (st[_FN, k] * st[_VN, k] + fn1 * vn1) if go else 0.0
    st[_WT, k] -= 0.5 * h * (st[_FT, k] * vs0 + ft1 * vs1) if go else 0.0
    st[_ERR, k] = code if (go and done) else st[_ERR, k]
    st[_D, k] = d1 if go else st[_D, k]
    st[_VN, k] = vn1 if go else st[_VN, k]
    st[_X, k] = x1 if go else st[_X, k]
    st[_VT, k] = vt1 if go else st[_VT, k]
    st[_OM, k] = om1 if go else st[_OM, k]
    st[_XI, k] = xi1 if go else st[_XI, k]
    st[_FN, k] = fn1 if go else st[_FN, k]
    st[_FT, k] = ft1 if go else st[_FT, k]
    st[_DMAX, k] = dm1 if go else st[_DMAX, k]
    st[_STEPS, k] += 1.0 if go else 0.0
    st[_GO, k] = 0.0 if done else st[_GO, k]


@njit(cache=True, error_model="numpy")
def _block(scheme, model, factor, friction, dt, vn0, vt0, max_steps, prm, tab, out):
    """Integrate up to LANES impacts side by side (the same arithmetic per impact as :func:`_impact`)."""
    n = vn0.shape[0]
    radius, mass, inertia = prm[P_RADIUS], prm[P_MASS], prm[P_INERTIA]
    st = np.zeros((_ROWS, LANES))
    for k in range(LANES):
        i = min(k, n - 1)  # padding lanes repeat the last impact and are discarded
        st[_VN, k], st[_VT, k], st[_GO, k] = vn0[i], vt0[i], 1.0
        st[_MU, k], st[_DT, k], st[_LIMIT, k] = friction[i], dt[i], max_steps[i]
    fast = model == HERTZ and scheme == VERLET
    stiff, damp, gstar = prm[P_HERTZ_K], prm[P_DAMP], prm[P_GSTAR]
    no_springs = np.zeros(1)
    n_active = LANES
    while n_active > 0:
        if fast:
            for k in range(LANES):
                new = _hertz_verlet_step(
                    factor,
                    st[_MU, k],
                    st[_DT, k],
                    st[_D, k],
                    st[_VN, k],
                    st[_X, k],
                    st[_VT, k],
                    st[_OM, k],
                    st[_XI, k],
                    st[_FN, k],
                    st[_FT, k],
                    st[_DMAX, k],
                    radius,
                    mass,
                    inertia,
                    stiff,
                    damp,
                    gstar,
                )
                _lane_update(st, k, radius, new)
        else:
            for k in range(LANES):
                new = _step(
                    scheme,
                    model,
                    SPRING,
                    factor,
                    st[_MU, k],
                    st[_DT, k],
                    st[_D, k],
                    st[_VN, k],
                    st[_X, k],
                    st[_VT, k],
                    st[_OM, k],
                    st[_XI, k],
                    st[_FN, k],
                    st[_FT, k],
                    st[_DMAX, k],
                    prm,
                    tab,
                    no_springs,
                    0.0,
                )
                _lane_update(st, k, radius, new)
        n_active = 0
        for k in range(LANES):
            n_active += 1 if st[_GO, k] > 0.0 else 0
    for k in range(min(n, LANES)):
        out[k, 0] = st[_VN, k]
        out[k, 1] = st[_VT, k]
        out[k, 2] = st[_OM, k]
        out[k, 3] = st[_STEPS, k] * st[_DT, k]
        out[k, 4] = st[_SLIDE, k]
        out[k, 5] = st[_FMAX, k]
        out[k, 6] = st[_DMAX, k]
        out[k, 7] = st[_AMAX, k]
        out[k, 8] = st[_PMAX, k]
        out[k, 9] = st[_FTMAX, k]
        out[k, 10] = st[_WN, k]
        out[k, 11] = st[_WT, k]
        out[k, 12] = st[_STEPS, k]
        out[k, 13] = st[_ERR, k]


@njit(cache=True, parallel=True, error_model="numpy")
def run_batch(scheme, model, tangential, factor, friction, dt, vn0, vt0, max_steps, prm, tab, pitch):
    """Integrate every impact i (arrays of length n) in blocks of LANES (one by one with the ``MEMORY`` tangential
    law, whose springs ``pitch`` m apart are no register state); returns the (n, len(OUT_FIELDS)) array."""
    n = vn0.shape[0]
    out = np.empty((n, _N_OUT))
    if tangential == MEMORY:
        no_history = np.empty((len(HISTORY_FIELDS), 1))
        for i in prange(n):
            _impact(
                scheme,
                model,
                tangential,
                factor,
                friction[i],
                dt[i],
                vn0[i],
                vt0[i],
                max_steps[i],
                prm,
                tab,
                pitch[i],
                out[i],
                no_history,
                0,
            )
        return out
    n_blocks = (n + LANES - 1) // LANES
    for b in prange(n_blocks):
        lo, hi = b * LANES, min(n, b * LANES + LANES)
        _block(
            scheme,
            model,
            factor,
            friction[lo:hi],
            dt[lo:hi],
            vn0[lo:hi],
            vt0[lo:hi],
            max_steps[lo:hi],
            prm,
            tab,
            out[lo:hi],
        )
    return out


@njit(cache=True, error_model="numpy")
def run_history(scheme, model, tangential, factor, friction, dt, vn0, vt0, max_steps, prm, tab, pitch, capacity, every):
    """Integrate one impact recording every ``every``-th step (and the last) into a (13, rows) array."""
    out = np.empty(_N_OUT)
    hist = np.empty((len(HISTORY_FIELDS), capacity))
    rows = _impact(
        scheme, model, tangential, factor, friction, dt, vn0, vt0, max_steps, prm, tab, pitch, out, hist, every
    )
    return out, hist[:, :rows]
