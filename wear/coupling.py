r"""Two-way coupling of the impact and the FE plate (issue 4 item 5; what it calls ``normal_model = "fe"``).

The impact runs on the FE plate's own normal law (contact's ``"tabulated"`` model: F(δ) and the contact
radius a(δ), so the tangential stiffness is k_t = 8G*a with the FE radius). The loading branch of an
elastic–plastic indentation is path-independent, so the FE plate is loaded **once**, past the expected
maximum overlap:

1. estimate δ_max with the impact's own normal model (Hertz or Thornton) and load the FE plate to
   (1 + ``overshoot``)·δ_est;
2. run the impact on that loading branch (the rebound uses a provisional elastic unloading curve of slope
   dF/dδ = 2E*a, which cannot change δ_max: the maximum is reached on the loading branch);
3. unload the FE plate from the impact's δ_max (restarting from the kept loading state just below it:
   ``IndentationResult.unload_from``) and run the impact again on the FE law (``res.force_law()``: the
   loading and the unloading from δ* = (1 + 1e-3) δ_max);
4. repeat 3 while the maximum overlap changes by more than ``tolerance`` (relative) between iterations.

Because δ_max depends only on the loading branch, step 3 normally converges at once (the impact loads on
the same table; only the unloading changes); the iterations and the final change are reported. Cost: one
FE loading to (1 + overshoot)·δ_est plus one unloading per iteration (normally one): about one FE cycle.

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

__all__ = [
    "CouplingResult",
    "hertz_surface_displacement",
    "FeCycle",
    "RestitutionSweep",
    "couple",
    "fe_indent",
    "fe_mesh",
    "fe_unload",
    "load_plate",
    "one_way",
    "pressure_table",
    "pressure_table_one_way",
    "provisional_law",
    "restitution_sweep",
]


#: Relative margin above the impact's δ_max at which the FE cycle starts unloading.
UNLOAD_MARGIN = 1e-3


def fe_mesh(case, ball: Material, plate: Material, max_overlap: float, growth: float = 1.0):
    """The FE mesh for a path reaching ``max_overlap`` (m): fem's default mesh scaled to it, or with
    ``fem.mesh_scale`` ≠ 1 a generated mesh with fem's default element counts across the contact and first-yield
    radii divided by ``mesh_scale``; ``growth``: the contact will widen to that × its first radius
    (:func:`fem.mesh.generate_mesh`)."""
    import fem
    from fem.mesh import DEFAULT_PARAMETERS

    ball_arg = None if ball.is_rigid else ball
    if case.fem.mesh_scale == 1.0:
        return fem.plate_mesh(case.ball.radius, plate, max_overlap, ball_arg, growth=growth)
    scale = case.fem.mesh_scale
    return fem.plate_mesh(
        case.ball.radius,
        plate,
        max_overlap,
        ball_arg,
        contact_elements=max(6, round(DEFAULT_PARAMETERS["contact_elements"] / scale)),
        yield_elements=max(4, round(DEFAULT_PARAMETERS["yield_elements"] / scale)),
        growth=growth,
    )


def fe_indent(case, ball: Material, plate: Material, overlaps: np.ndarray, keep_states: bool = False,
              mesh_overlap: float | None = None):  # fmt: skip
    """``fem.indent`` along the overlap path ``overlaps`` (m) on :func:`fe_mesh` sized for ``mesh_overlap`` (m;
    default the path's maximum: give the same value to run several paths on the same mesh)."""
    import fem

    overlaps = np.asarray(overlaps, float)
    ball_arg = None if ball.is_rigid else ball
    mesh = fe_mesh(case, ball, plate, float(overlaps.max()) if mesh_overlap is None else mesh_overlap)
    return fem.indent(case.ball.radius, plate, overlaps, ball=ball_arg, mesh=mesh, keep_states=keep_states)


def fe_unload(case, fe_load, max_overlap: float):
    """Unload the kept loading run ``fe_load`` from ``max_overlap`` (m) to separation
    (``IndentationResult.unload_from``, ``fem.unload_steps`` steps).

    Since fem's contact set converges through the loss of contact (any step size), this is used for yielding
    plates too. It replaced a workaround that stopped ~3% of F* before separation and extrapolated δ_p; on the
    default case the two agreed on the dent to 0.2% (3.660 vs 3.653 µm) and on e_n to 4e-4 (0.8097 vs 0.8100)."""
    return fe_load.unload_from(max_overlap, steps=case.fem.unload_steps)


def hertz_surface_displacement(r, force: float, contact_radius: float, effective_modulus: float) -> np.ndarray:
    r"""Normal surface displacement (m, into the body) of a Hertz pressure carrying ``force`` (N) over
    ``contact_radius`` a (m) on a half-space of modulus E* (Pa) (Johnson 1985, Eqs. 3.41a-b):

    .. math:: u_z = \frac{\pi p_0}{4aE^*}(2a^2 - r^2),\ r \le a; \quad
              u_z = \frac{p_0}{2aE^*}\left[(2a^2 - r^2)\arcsin\frac{a}{r} + a\sqrt{r^2 - a^2}\right],\ r > a
    """
    r = np.abs(np.asarray(r, float))
    if force <= 0.0 or contact_radius <= 0.0:
        return np.zeros_like(r)
    a = contact_radius
    p0 = 3.0 * force / (2.0 * math.pi * a * a)
    inside = math.pi * p0 / (4.0 * a * effective_modulus) * (2.0 * a * a - r**2)
    rs = np.maximum(r, a)
    outside = (
        p0 / (2.0 * a * effective_modulus) * ((2.0 * a * a - rs**2) * np.arcsin(a / rs) + a * np.sqrt(rs**2 - a * a))
    )
    return np.where(r <= a, inside, outside)


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


def _loading_path(max_overlap: float, steps: int, first_yield_overlap: float | None = None) -> np.ndarray:
    """Overlaps (m) from 0 (excluded) to ``max_overlap``, denser near the start where F(δ) curves most; with
    ``first_yield_overlap`` (m) the path starts with an elastic step at half of it (fem locates first yield
    between an elastic and a plastic step)."""
    s = np.linspace(0.0, 1.0, steps + 1)[1:]
    path = max_overlap * s**1.5
    if first_yield_overlap is not None and 0.5 * first_yield_overlap < path[0]:
        path = np.r_[0.5 * first_yield_overlap, path]
    return path


def _first_yield_overlap(case, ball: Material, plate: Material) -> float | None:
    """Hertz first-yield overlap (m) with the exact C(ν) (errata Eq. 18), None for a plate that never yields."""
    if not plate.yield_strength:
        return None
    from contact.theory import first_yield

    return first_yield(case.ball.radius, effective_modulus(ball, plate), plate.yield_strength, plate.nu).overlap


def load_plate(case, ball: Material, plate: Material, estimate: ImpactResult, indent=None):
    """Stage ``fem``: load the FE plate once to (1 + overshoot) × the estimated maximum overlap (m).

    ``indent(case, ball, plate, overlaps)`` runs the FE path (default :func:`fe_indent`)."""
    target = (1.0 + case.fem.overshoot) * estimate.max_overlap
    path = _loading_path(target, case.fem.load_steps, _first_yield_overlap(case, ball, plate))
    return (indent or fe_indent)(case, ball, plate, path, keep_states=True)


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


@dataclass(frozen=True, eq=False)
class FeCycle:
    """The FE plate's cycle of a coupled impact: the kept loading steps up to δ* followed by the unloading from δ*
    (arrays per step as in ``fem.IndentationResult``: ``overlap`` m, ``force`` N, ``contact_radius`` m,
    ``pressure`` Pa (steps, surface nodes), ``regime``, ``max_equivalent_plastic_strain``), ``surface_r`` (m),
    ``residual_depth`` (m, after unloading), ``first_yield`` (or None), ``loading`` and ``unloading`` results."""

    overlap: np.ndarray
    force: np.ndarray
    contact_radius: np.ndarray
    pressure: np.ndarray
    regime: list
    max_equivalent_plastic_strain: np.ndarray
    surface_r: np.ndarray
    residual_depth: np.ndarray
    first_yield: Any
    loading: Any
    unloading: Any

    @classmethod
    def join(cls, loading, unloading, max_overlap: float) -> FeCycle:
        d = np.asarray(loading.overlap, float)
        # leading loading steps strictly below δ* (the loading may be a whole cycle: stop at its peak)
        below = (d < max_overlap * (1.0 - 1e-12)) & np.concatenate([[True], np.diff(d) > 0])
        k = int(np.argmin(below)) if not below.all() else d.size
        fy = loading.first_yield
        if fy is not None and fy.overlap > max_overlap:
            fy = None

        def cat(name):
            return np.concatenate([np.asarray(getattr(loading, name), float)[:k],
                                   np.asarray(getattr(unloading, name), float)])  # fmt: skip

        return cls(
            overlap=cat("overlap"),
            force=cat("force"),
            contact_radius=cat("contact_radius"),
            pressure=np.vstack([np.asarray(loading.pressure, float)[:k], np.asarray(unloading.pressure, float)]),
            regime=list(loading.regime[:k]) + list(unloading.regime),
            max_equivalent_plastic_strain=cat("max_equivalent_plastic_strain"),
            surface_r=np.asarray(unloading.surface_r, float),
            residual_depth=np.asarray(unloading.residual_depth, float),
            first_yield=fy,
            loading=loading,
            unloading=unloading,
        )

    def write(self, path):
        """The deformed FE mesh after the unloading (``IndentationResult.write``)."""
        return self.unloading.write(path)


def couple(case, ball: Material, plate: Material, fe_load, estimate: ImpactResult, unload=None) -> CouplingResult:
    """Stage ``coupling``: iterate impact ⇄ FE until δ_max changes by < ``case.fem.tolerance``.

    ``fe_load``: :func:`load_plate`'s result (kept states); ``estimate``: the first (Hertz or Thornton) impact;
    ``unload(case, fe_load, max_overlap)`` unloads the plate from ``max_overlap`` (default :func:`fe_unload`)."""
    unload = unload or fe_unload
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
        # unload from a hair above δ_max so that the impact's own maximum (on the same loading table) lies below
        # the tabulated δ*; the engine scales the curve down by that 1e-3, well inside the FE accuracy
        d_star = d_max * (1.0 + UNLOAD_MARGIN)
        if d_star > load_top:
            raise ValueError(
                f"fem.overshoot={case.fem.overshoot:g} is too small: the impact reached {d_max:.4g} m, beyond the FE "
                f"loading to {load_top:.4g} m"
            )
        unloading = unload(case, fe_load, d_star)
        fe = FeCycle.join(fe_load, unloading, d_star)
        law = fe_load.force_law()  # the loading plus every unloading computed so far
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
    times, rows = times[keep], _inside_contact(fe_p, fe.surface_r, fe.contact_radius)[keep]
    # close the table at separation with zero pressure, and open it at first contact
    if times[0] > t[0]:
        times, rows = np.concatenate([[t[0]], times]), np.vstack([np.zeros(rows.shape[1]), rows])
    if times[-1] < t[-1]:
        times, rows = np.concatenate([times, [t[-1]]]), np.vstack([rows, np.zeros(rows.shape[1])])
    return times, np.asarray(fe.surface_r, float), rows


def one_way(case, ball: Material, plate: Material, impact: ImpactResult):
    """Stage ``fem`` of a one-way run: ``fem.indent_impact`` along the impact's overlap history."""
    import fem

    mesh = fe_mesh(case, ball, plate, impact.max_overlap)
    return fem.indent_impact(impact, plate, steps=case.fem.load_steps + case.fem.unload_steps, mesh=mesh)


def pressure_table_one_way(fe) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(time s, surface_r m, pressure Pa) of an ``fem.indent_impact`` result."""
    rows = _inside_contact(fe.pressure, fe.surface_r, fe.contact_radius)
    return np.asarray(fe.time, float), np.asarray(fe.surface_r, float), rows


def _inside_contact(pressure, surface_r, contact_radius) -> np.ndarray:
    """Nodal pressure (Pa) set to zero beyond each step's FE contact radius (m), and clipped at zero.

    The FE pressure is the L2 projection of the nodal reactions, which rings outside the contact (small
    positive values at nodes far from it, up to ~4% of the peak next to the edge). Left in, any positive
    node would stretch the wear grid (sized from the largest loaded radius) over the whole FE surface."""
    p = np.maximum(np.asarray(pressure, float), 0.0)
    r = np.asarray(surface_r, float)
    a = np.asarray(contact_radius, float)
    return np.where(r[None, :] <= a[:, None], p, 0.0)


def hertz_reference(case, ball: Material, plate: Material):
    """Closed-form Hertz impact of the case's normal speed (errata Eqs. 10–11), for checks."""
    v_n = case.impact.speed * math.cos(math.radians(case.impact.angle))
    mass = sphere_mass(case.ball.radius, ball.density)
    return hertz_impact(mass, case.ball.radius, effective_modulus(ball, plate), v_n)


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


def restitution_sweep(case, speed_ratios) -> RestitutionSweep:
    """Run the two-way coupled normal impact of ``case`` (angle set to 0) at each V_n/V_y in ``speed_ratios``."""
    from contact.theory import thornton_restitution, yield_velocity

    from .pipeline import _impact

    ball, plate = case.ball.material(), case.plate.material()
    if not plate.yield_strength:
        raise ValueError("plate.yield_strength=None: the restitution sweep needs a plate that yields (Pa)")
    v_y = yield_velocity(case.ball.radius, ball, plate)
    ratios = np.asarray(speed_ratios, float)
    e, its, changes = [], [], []
    for ratio in ratios:
        c = case.with_(impact={"speed": float(ratio * v_y), "angle": 0.0})
        estimate = _impact(c, ball, plate)
        res = couple(c, ball, plate, load_plate(c, ball, plate, estimate), estimate)
        e.append(res.impact.normal_restitution)
        its.append(res.iterations)
        changes.append(res.change)
    e = np.asarray(e)
    ref = np.asarray(thornton_restitution(ratios), float)
    return RestitutionSweep(ratios, e, ref, (e - ref) / ref, np.asarray(its), np.asarray(changes), v_y)
