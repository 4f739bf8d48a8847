r"""Two-way coupling of the impact and the FE plate (issue 4 item 5; what it calls ``normal_model = "fe"``).

The impact runs on the FE plate's own normal law (contact's ``"tabulated"`` model: F(δ) and the contact
radius a(δ), so the tangential stiffness is k_t = 8G*a with the FE radius). The loading branch of an
elastic–plastic indentation is path-independent, so the FE plate is loaded **once**, past the expected
maximum overlap:

1. estimate δ_max with the impact's own normal model (Hertz or Thornton) and load the FE plate to
   (1 + ``overshoot``)·δ_est;
2. run the impact on that loading branch (the rebound uses a provisional elastic unloading curve of slope
   dF/dδ = 2E*a, which cannot change δ_max: the maximum is reached on the loading branch);
3. unload the FE plate from the impact's δ_max (one loading + unloading cycle) and run the impact again on
   the FE loading and the cycle's unloading curve (δ* = (1 + 1e-3) δ_max);
4. repeat 3 while the maximum overlap changes by more than ``tolerance`` (relative) between iterations.

Because δ_max depends only on the loading branch, step 3 normally converges at once (the change is the
interpolation difference between the two FE loading tables, ~1e-3 or less); the iterations and the final
change are reported. Cost: one FE loading to (1 + overshoot)·δ_est plus one FE cycle to δ_max.

The FE pressure p(r, t) along the impact is the cycle's nodal pressure with each FE step placed at the
impact time where the impact reaches that overlap (on the loading branch before t(δ_max), on the unloading
branch after it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from contact import ImpactResult, Material, TabulatedLaw, effective_modulus, simulate_impact
from contact.theory import hertz_impact, sphere_mass

__all__ = ["CouplingResult", "load_plate", "couple", "one_way", "pressure_table", "pressure_table_one_way",
           "fe_indent", "provisional_law", "cycle_law"]  # fmt: skip


#: Relative margin above the impact's δ_max at which the FE cycle starts unloading.
UNLOAD_MARGIN = 1e-3


def fe_indent(case, ball: Material, plate: Material, overlaps: np.ndarray):
    """Run ``fem.indent`` along the overlap path ``overlaps`` (m) with the case's FE options."""
    import fem

    kwargs: dict[str, Any] = {}
    ball_arg = None if ball.is_rigid else ball
    return fem.indent(radius=case.ball.radius, plate=plate, overlaps=np.asarray(overlaps, float), ball=ball_arg,
                      **kwargs)  # fmt: skip


@dataclass(frozen=True, eq=False)
class CouplingResult:
    """The converged two-way coupling: ``impact`` (final :class:`contact.ImpactResult`), ``fe`` (the FE cycle to
    δ_max), ``law`` (the :class:`contact.TabulatedLaw` used last), ``iterations`` (impact runs on FE laws),
    ``max_overlaps`` (m, per iteration), ``change`` (final relative change of δ_max), ``converged``,
    ``pressure_table`` ((time s, surface_r m, pressure Pa) for the ``"fe"`` pressure source), ``fe_load``
    (the single FE loading), ``estimate`` (the first impact, Hertz or Thornton)."""

    impact: ImpactResult
    fe: Any
    law: TabulatedLaw
    iterations: int
    max_overlaps: tuple
    change: float
    converged: bool
    pressure_table: tuple
    fe_load: Any
    estimate: ImpactResult

    def summary(self) -> dict:
        return {
            "iterations": self.iterations,
            "final_change": self.change,
            "converged": self.converged,
            "max_overlaps_m": list(self.max_overlaps),
            "estimate_model": self.estimate.normal_model,
            "estimate_max_overlap_m": self.estimate.max_overlap,
        }


def _loading_path(max_overlap: float, steps: int) -> np.ndarray:
    """Overlaps (m) from 0 (excluded) to ``max_overlap``, denser near the start where F(δ) curves most."""
    s = np.linspace(0.0, 1.0, steps + 1)[1:]
    return max_overlap * s**1.5


def load_plate(case, ball: Material, plate: Material, estimate: ImpactResult, indent=None):
    """Stage ``fem``: load the FE plate once to (1 + overshoot) × the estimated maximum overlap (m).

    ``indent(case, ball, plate, overlaps)`` runs the FE path (default :func:`fe_indent`)."""
    target = (1.0 + case.fem.overshoot) * estimate.max_overlap
    return (indent or fe_indent)(case, ball, plate, _loading_path(target, case.fem.load_steps))


def _loading_table(res) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Monotonic loading branch (δ, F, a) from 0 from an FE result (steps where δ still increases)."""
    d = np.asarray(res.overlap, float)
    f = np.maximum(np.asarray(res.force, float), 0.0)
    a = np.maximum(np.asarray(res.contact_radius, float), 0.0)
    k = int(np.argmax(d))
    d, f, a = d[: k + 1], f[: k + 1], a[: k + 1]
    keep = np.concatenate([[True], np.diff(d) > 0])
    d, f, a = d[keep], f[keep], a[keep]
    if d[0] > 0.0:
        d, f, a = np.concatenate([[0.0], d]), np.concatenate([[0.0], f]), np.concatenate([[0.0], a])
    return d, f, a


def provisional_law(res, e_star: float, points: int = 40) -> TabulatedLaw:
    r"""FE loading branch plus one elastic unloading curve from its top, of Hertz form
    :math:`F = F^*\left(\frac{\delta - \delta_p}{\delta^* - \delta_p}\right)^{3/2}`, with
    :math:`\delta^* - \delta_p = 3F^*/(4E^*a^*)` so that dF/dδ = 2E*a* at the start (exact for elastic
    unloading). Used only to find δ_max, which the unloading cannot change."""
    d, f, a = _loading_table(res)
    d_star, f_star, a_star = d[-1], f[-1], a[-1]
    drop = min(3.0 * f_star / (4.0 * e_star * max(a_star, 1e-300)), d_star)
    s = np.linspace(1.0, 0.0, points)
    ud = d_star - drop + s * drop
    return TabulatedLaw(d, f, a, np.array([d_star]), ud[None, :], (f_star * s**1.5)[None, :],
                        (a_star * np.sqrt(s))[None, :])  # fmt: skip


def _unloading_curve(res) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The FE unloading branch (δ, F, a) from its maximum overlap down to the residual overlap δ_p, where the
    force reaches zero (located by linear interpolation between the last loaded and first free steps)."""
    d = np.asarray(res.overlap, float)
    f = np.maximum(np.asarray(res.force, float), 0.0)
    a = np.maximum(np.asarray(res.contact_radius, float), 0.0)
    k = int(np.argmax(d))
    d, f, a = d[k:], f[k:], a[k:]
    free = np.flatnonzero(f <= 0.0)
    if free.size and free[0] > 0:
        j = int(free[0])
        w = f[j - 1] / (f[j - 1] - f[j])  # zero crossing between steps j-1 and j
        d_p = d[j - 1] + w * (d[j] - d[j - 1])
        d, f, a = np.append(d[:j], d_p), np.append(f[:j], 0.0), np.append(a[:j], 0.0)
    else:  # still loaded at the end of the path: close the curve at zero overlap
        d, f, a = np.append(d, 0.0), np.append(f, 0.0), np.append(a, 0.0)
    keep = np.concatenate([[True], np.diff(d) < 0])
    return d[keep], f[keep], a[keep]


def cycle_law(fe_load, fe_cycle) -> TabulatedLaw:
    """The FE law of the coupled impact: the single loading (``fe_load``, reaching past δ_max) and the
    unloading curve of the cycle (``fe_cycle``) that starts at δ* just above the impact's δ_max."""
    d, f, a = _loading_table(fe_load)
    ud, uf, ua = _unloading_curve(fe_cycle)
    return TabulatedLaw(d, f, a, np.array([ud[0]]), ud[None, :], uf[None, :], ua[None, :])


def _run_impact(case, ball, plate, law: TabulatedLaw) -> ImpactResult:
    spec = case.impact
    return simulate_impact(
        radius=case.ball.radius,
        ball=ball,
        plate=plate,
        speed=spec.speed,
        angle=spec.angle,
        friction=spec.friction,
        normal_model="tabulated",
        tangential_model=spec.tangential_model,
        force_law=law,
        scheme=spec.scheme,
        time_step=spec.time_step,
        history=True,
    )


def _cycle_path(max_overlap: float, load_steps: int, unload_steps: int) -> np.ndarray:
    load = _loading_path(max_overlap, load_steps)
    # unloading: dense near δ_max where the contact radius shrinks fastest, down to zero overlap
    s = np.linspace(0.0, 1.0, unload_steps + 1)[1:]
    return np.concatenate([load, max_overlap * (1.0 - s**1.3)])


def couple(case, ball: Material, plate: Material, fe_load, estimate: ImpactResult, indent=None) -> CouplingResult:
    """Stage ``coupling``: iterate impact ⇄ FE until δ_max changes by < ``case.fem.tolerance``.

    ``fe_load``: :func:`load_plate`'s result; ``estimate``: the first (Hertz or Thornton) impact."""
    indent = indent or fe_indent
    e_star = effective_modulus(ball, plate)
    law = provisional_law(fe_load, e_star)
    load_top = float(law.loading_overlap[-1])
    impact = _run_impact(case, ball, plate, law)
    overlaps = [impact.max_overlap]
    fe = None
    change = math.inf
    iterations = 1
    while iterations < case.fem.max_iterations:
        d_max = overlaps[-1]
        if d_max > load_top:
            raise ValueError(
                f"fem.overshoot={case.fem.overshoot:g} is too small: the impact reached {d_max:.4g} m, beyond the FE "
                f"loading to {load_top:.4g} m"
            )
        # unload from a hair above δ_max so that the impact's own maximum (on the same loading table) lies below
        # the tabulated δ*; the engine scales the curve down by that 1e-3, well inside the FE accuracy
        d_star = d_max * (1.0 + UNLOAD_MARGIN)
        fe = indent(case, ball, plate, _cycle_path(d_star, case.fem.load_steps, case.fem.unload_steps))
        law = cycle_law(fe_load, fe)
        impact = _run_impact(case, ball, plate, law)
        iterations += 1
        overlaps.append(impact.max_overlap)
        change = abs(overlaps[-1] - overlaps[-2]) / overlaps[-2]
        if change < case.fem.tolerance:
            break
    converged = change < case.fem.tolerance
    return CouplingResult(
        impact=impact,
        fe=fe,
        law=law,
        iterations=iterations,
        max_overlaps=tuple(overlaps),
        change=change,
        converged=converged,
        pressure_table=pressure_table(fe, impact),
        fe_load=fe_load,
        estimate=estimate,
    )


def pressure_table(fe, impact: ImpactResult) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(time s, surface_r m, pressure Pa) of an FE cycle placed on the impact's time axis.

    FE step j at overlap δ_j gets the impact time where the impact has that overlap: on the loading branch
    for steps up to the FE maximum, on the unloading branch after it (steps below the residual overlap fall
    after separation and are dropped, their pressure being zero)."""
    h = impact.history
    t, d = np.asarray(h.t, float), np.asarray(h.overlap, float)
    i_max = int(np.argmax(d))
    fe_d = np.asarray(fe.overlap, float)
    fe_p = np.asarray(fe.pressure, float)
    j_max = int(np.argmax(fe_d))
    load_d = np.maximum.accumulate(d[: i_max + 1])
    times = np.empty(fe_d.size)
    times[: j_max + 1] = np.interp(fe_d[: j_max + 1], load_d, t[: i_max + 1])
    un_t, un_d = t[i_max:][::-1], d[i_max:][::-1]
    un_d = np.maximum.accumulate(un_d)
    times[j_max + 1 :] = np.interp(fe_d[j_max + 1 :], un_d, un_t, left=np.inf)
    keep = np.isfinite(times) & (times <= t[-1])
    keep &= np.concatenate([[True], np.diff(np.where(keep, times, -np.inf)) > 0])
    times, rows = times[keep], fe_p[keep]
    # close the table at separation with zero pressure, and open it at first contact
    if times[0] > t[0]:
        times, rows = np.concatenate([[t[0]], times]), np.vstack([np.zeros(rows.shape[1]), rows])
    if times[-1] < t[-1]:
        times, rows = np.concatenate([times, [t[-1]]]), np.vstack([rows, np.zeros(rows.shape[1])])
    return times, np.asarray(fe.surface_r, float), rows


def one_way(case, ball: Material, plate: Material, impact: ImpactResult):
    """Stage ``fem`` of a one-way run: ``fem.indent_impact`` along the impact's overlap history."""
    import fem

    ball_arg = None if ball.is_rigid else ball
    return fem.indent_impact(impact, plate, ball=ball_arg)


def pressure_table_one_way(fe) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(time s, surface_r m, pressure Pa) of an ``fem.indent_impact`` result."""
    return np.asarray(fe.time, float), np.asarray(fe.surface_r, float), np.asarray(fe.pressure, float)


def hertz_reference(case, ball: Material, plate: Material):
    """Closed-form Hertz impact of the case's normal speed (errata Eqs. 10–11), for checks."""
    v_n = case.impact.speed * math.cos(math.radians(case.impact.angle))
    mass = sphere_mass(case.ball.radius, ball.density)
    return hertz_impact(mass, case.ball.radius, effective_modulus(ball, plate), v_n)
