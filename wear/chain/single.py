r"""The whole chain for one impact case: impact → FE plate → coupling → wear → deformed surface.

``run(case) -> RunResult`` for a :class:`wear.Case` (its ``[ball]``, ``[plate]``, ``[impact]``, ``[wear]``,
``[fem]`` tables; SI units, angles in degrees from the plate normal)::

    from wear import Case, run
    result = run(Case())
    result.summary()["wear"]["volume_m3"]

Stages (their wall times are in ``RunResult.stage_times``):

1. ``impact``: the H-DD impact (:func:`contact.simulate_impact`) with ``case.impact``'s normal model.
2. ``fem`` + ``coupling``: with ``fem.coupling = "two-way"``
   the impact is re-run on the FE plate's own force–overlap law and contact radius until the maximum
   overlap changes by < ``fem.tolerance`` (:func:`fem.couple`); ``"one-way"`` drives the FE plate with
   the impact's overlap history (``fem.indent_impact``); ``"none"`` skips the FE (no dent; the pressure
   source must then not be ``"fe"``).
3. ``plate3d`` (``fem.model = "3d"``): the impact coupled to the 3-D half plate with friction, started from the
   axisymmetric coupled impact; the whole chain then runs on the plate's tangential law, Mindlin–Deresiewicz
   (:mod:`wear.chain.solid`).
4. ``wear``: Eq. 15 integrated over the moving contact patch (:func:`wear.integrate_wear`; on the 3-D plate with its
   pressure and stick/slip fields, :mod:`wear.solid_wear`).
5. ``surface``: the residual FE dent placed at the contact centre of maximum overlap plus the wear map
   (:class:`wear.surface.DeformedSurface`; the 3-D plate's residual surface itself on the 3-D plate).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

import fem
from contact import ImpactResult, Material, effective_modulus, simulate_impact
from contact.theory import PAPER_YIELD_COEFFICIENT, first_yield, speed_components, yield_velocity
from fem import CoupledImpact, IndentationResult, PlateCycle, worst_regime
from fem.solid_coupling import SolidCoupledImpact
from wear.case import JOBS, Case
from wear.chain.plate import case_mesh, case_plate, coupling_settings, impact_on_law, wear_constants
from wear.chain.solid import check_solid_case, solid_case, solid_impact, solid_surface, solid_wear
from wear.integrate import WearMap
from wear.laws import LAWS, ImpactWear, wear_of_impact
from wear.pressure import PressureHistory, pressure_history, sliding_speed
from wear.surface import DeformedSurface

__all__ = [
    "RunResult",
    "run",
    "estimate_arguments",
    "estimate_impact",
    "impact_wear",
    "speed_ratio",
    "STAGES",
]

#: Stages of :func:`run`, in order (the output writer adds "meshes" and "figures").
STAGES = ("impact", "fem", "coupling", "plate3d", "wear", "surface")


@dataclass(frozen=True, eq=False)
class RunResult:
    """Everything one :func:`run` produced (SI units).

    ``estimate`` (the impact on the case's own normal model), ``impact`` (:class:`contact.ImpactResult`, the final
    impact: coupled if two-way), ``fe`` (the plate's :class:`fem.PlateCycle` (two-way), its
    :class:`fem.IndentationResult` (one-way) or None), ``coupling`` (:class:`fem.CoupledImpact` or None),
    ``pressure`` (:class:`wear.PressureHistory`), ``wear`` (:class:`wear.WearMap`), ``worn`` (the wear law's volumes
    by mechanism, :class:`wear.laws.ImpactWear`), ``surface``
    (:class:`wear.surface.DeformedSurface`), ``yield_info`` (dict: ``F_y_paper`` Eq. 18 with C = 1.6, ``F_c_exact``
    with C(ν), ``fe_first_yield_force`` of the plate the impact ran on and that plate, ``fe_first_yield_plate``,
    ``V_y`` Thornton's yield speed, N and m/s), ``regime`` (str, of the plate the impact ran on), ``stage_times``
    (dict stage → s), ``solid`` (:class:`fem.solid_coupling.SolidCoupledImpact` with ``fem.model = "3d"``, else
    None; ``fe`` and ``coupling`` are then the axisymmetric plate it started from).
    """

    case: Case
    estimate: ImpactResult
    impact: ImpactResult
    fe: PlateCycle | IndentationResult | None
    coupling: CoupledImpact | None
    pressure: PressureHistory
    wear: WearMap
    worn: ImpactWear
    surface: DeformedSurface
    yield_info: dict[str, float | None]
    regime: str
    stage_times: dict[str, float]
    solid: SolidCoupledImpact | None = None

    @property
    def fem_model(self) -> str | None:
        """The FE plate the impact ran on (``fem.model``: "axisymmetric" or "3d"; None without an FE plate)."""
        if self.solid is not None:
            return "3d"
        return None if self.fe is None else "axisymmetric"

    def summary(self) -> dict:
        """The numbers of summary.json (without versions; the writer adds them)."""
        imp = self.impact
        names = ("normal_restitution", "tangential_restitution", "rebound_angle", "contact_point_rebound_angle",
                 "spin", "rebound_normal_velocity", "rebound_tangential_velocity", "contact_time", "sliding_time",
                 "max_force", "max_tangential_force", "max_overlap", "max_contact_radius", "max_peak_pressure",
                 "normal_model")  # fmt: skip
        impact = {k: getattr(imp, k) for k in names}
        # the pressure of the plate the impact acted on: the FE's where there is one (its contact pressure field),
        # else the normal law's (the Hertz-type 3F/(2πa²) would overstate a plastic contact's by up to 1.5x)
        if self.solid is not None:
            impact["max_peak_pressure"] = float(np.max(self.solid.solid.max_pressure))
            impact["max_peak_pressure_source"] = "3-D FE plate"
        elif self.fe is not None:
            impact["max_peak_pressure"] = float(np.max(self.fe.pressure))
            impact["max_peak_pressure_source"] = "FE plate"
        else:
            impact["max_peak_pressure_source"] = f"normal law {imp.normal_model!r}"
        impact["units"] = "s, N, m, Pa, m/s, rad/s, deg"
        w, c = self.wear, self.coupling
        dent = self.surface.dent_dimensions()
        coupling = None
        if c is not None:
            coupling = {
                "plate": "axisymmetric",
                "iterations": c.iterations,
                "final_change": c.change,
                "converged": c.converged,
                "max_overlaps_m": list(c.max_overlaps),
                "estimate_model": self.estimate.normal_model,
                "estimate_max_overlap_m": self.estimate.max_overlap,
            }
        if self.solid is not None:
            # the coupling of the plate the impact ran on; the axisymmetric one it started from is kept inside
            s = self.solid
            coupling = {
                "plate": "3d",
                "iterations": s.iterations,
                "final_change": s.change,
                "converged": s.converged,
                "max_overlaps_m": list(s.max_overlaps),
                "start": "the axisymmetric coupled impact",
                "start_max_overlap_m": s.max_overlaps[0],
                "axisymmetric_start": coupling,
            }
        return {
            "case": self.case.to_dict(JOBS["run"].tables),
            "fem_model": self.fem_model,
            "impact": impact,
            "yield": dict(self.yield_info),
            "regime": self.regime,
            "regime_plate": self.fem_model,
            **({} if self.solid is None else {"axisymmetric_start_regime": worst_regime(self.fe.regime)}),
            "wear": {
                "volume_m3": w.volume_m3,
                "mass_kg": w.mass_kg,
                "max_depth_m": w.max_depth_m,
                "scar_length_m": w.scar_length_m,
                "scar_width_m": w.scar_width_m,
                "law": str(self.case.wear.wear_law())
                if self.worn.law == "local"
                else f"{self.worn.law}: {LAWS[self.worn.law]}",
                "pressure_source": self.pressure.source,
                "parts_m3": dict(self.worn.parts),
            },
            "dent": {
                "max_depth_m": self.surface.max_dent_depth,
                "centre_x_m": self.surface.dent_centre[0],
                "length_m": dent.length,
                "width_m": dent.width,
                "pile_up_m": dent.pile_up,
                "model": "3d" if self.solid is not None else "axisymmetric",
            },
            "coupling": coupling,
            "plate_3d": None if self.solid is None else solid_summary(self.solid),
            "stage_times_s": dict(self.stage_times),
        }


def solid_summary(coupled: SolidCoupledImpact) -> dict:
    """The 3-D plate's block of summary.json (SI units)."""
    solid, stats = coupled.solid, coupled.work
    shear_strength = solid.solver.surface.shear_strength
    yielded = np.flatnonzero(solid.max_equivalent_plastic_strain > 0.0)
    return {
        "iterations": coupled.iterations,
        "converged": coupled.converged,
        "final_change": coupled.change,
        "max_overlaps_m": list(coupled.max_overlaps),
        "tangential_restitutions": list(coupled.tangential_restitutions),
        "max_normal_force_N": float(np.max(solid.normal_force)),
        "max_tangential_force_N": float(np.max(np.abs(solid.tangential_force))),
        "tangential_model": coupled.impact.tangential_model,
        "tangential_mismatch": coupled.tangential_mismatch,
        "surface_shear_strength_Pa": None if math.isinf(shear_strength) else shear_strength,
        "max_contact_radius_m": float(np.max(solid.contact_radius)),
        "max_stick_radius_m": float(np.max(solid.stick_radius)),
        "first_yield_force_N": float(solid.normal_force[yielded[0]]) if yielded.size else None,
        "max_equivalent_plastic_strain": float(np.max(solid.max_equivalent_plastic_strain)),
        "increments": stats.increments,
        "factorisations": stats.factorisations,
        "linear_solves": stats.solves,
        "dofs": int(solid.final.u.size),
    }


def _yield_info(
    case: Case,
    ball: Material,
    plate: Material,
    fe: PlateCycle | IndentationResult | None,
    solid: SolidCoupledImpact | None = None,
) -> dict:
    """First yield: the closed forms (N, m/s) and the FE plate's that the impact ran on (``fe_first_yield_plate``):
    the axisymmetric plate's found within 1 % in force (:mod:`fem.axisymmetric.indent`), or on the 3-D plate the normal
    force of its first step along the impact's path with plastic strain (an upper bound at the path's resolution,
    ``fem.solid_load_steps``); the axisymmetric plate it started from is then ``axisymmetric_first_yield_force``."""
    info: dict[str, float | str | None] = {
        "F_y_paper": None,
        "F_c_exact": None,
        "fe_first_yield_force": None,
        "fe_first_yield_plate": None,
        "V_y": None,
    }
    if plate.yield_strength and not plate.is_rigid:
        e_star = effective_modulus(ball, plate)
        R, Y = case.ball.radius, plate.yield_strength
        info["F_y_paper"] = first_yield(R, e_star, Y, plate.nu, coefficient=PAPER_YIELD_COEFFICIENT).force
        info["F_c_exact"] = first_yield(R, e_star, Y, plate.nu).force
        info["V_y"] = yield_velocity(R, ball, plate)
    if fe is not None:
        info["fe_first_yield_plate"] = "axisymmetric"
        info["fe_first_yield_force"] = None if fe.first_yield is None else float(fe.first_yield.force)
    if solid is not None:
        info["axisymmetric_first_yield_force"] = info["fe_first_yield_force"]
        info["fe_first_yield_plate"] = "3d"
        info["fe_first_yield_force"] = solid_summary(solid)["first_yield_force_N"]
    return info


#: The regime of a 3-D plate that yielded: its plastic strain says that it yielded, not where (the regimes of
#: :data:`fem.REGIMES` are classified on the axisymmetric plate's surface layer).
SOLID_PLASTIC_REGIME = "plastic (3-D plate: extent not classified)"


def _regime(
    impact: ImpactResult, info: dict, fe: PlateCycle | IndentationResult | None, solid: SolidCoupledImpact | None = None
) -> str:
    if solid is not None:
        return "elastic" if np.max(solid.solid.max_equivalent_plastic_strain) == 0.0 else SOLID_PLASTIC_REGIME
    if fe is not None and len(fe.regime):
        return worst_regime(fe.regime)
    if info["F_c_exact"] is None:
        return "elastic"
    return "elastic" if impact.max_force < info["F_c_exact"] else "plastic (no FE: regime not resolved)"


def estimate_arguments(case: Case, **overrides) -> dict:
    """:func:`contact.simulate_impact`'s arguments for the case's impact on its own normal model
    (``impact.normal_model``; Thornton's law is Hertz's when nothing yields), ``overrides`` replacing some."""
    args = case.impact_arguments(**overrides)  # checks the time step for the histories, if asked for
    thornton = args["normal_model"] == "thornton" and "normal_model" not in overrides
    if thornton and not args["plate"].yield_strength and not args["ball"].yield_strength:
        args["normal_model"] = "hertz"  # nothing yields: Thornton's law is Hertz
    return args


def estimate_impact(case: Case, **overrides) -> ImpactResult:
    """The impact of ``case`` on its own normal model, with its histories (:func:`estimate_arguments`): the impact
    of an uncoupled run and the first estimate of a coupled one."""
    return simulate_impact(**estimate_arguments(case, history=True, **overrides))


def impact_wear(case: Case, impact: ImpactResult, fe_table=None,
                plate_work: float | None = None) -> tuple[PressureHistory, WearMap, ImpactWear]:  # fmt: skip
    """Stage ``wear``: the pressure history p(r, t) of ``impact`` (``case.wear.pressure``; ``fe_table`` the FE
    (time s, r m, pressure Pa) table where it is "fe"), the wear map (m) and the worn volumes of the case's wear law
    (:func:`wear.laws.wear_of_impact`; ``plate_work`` the FE plate's plastic dissipation, J)."""
    w = case.wear
    ph = pressure_history(impact, w.pressure, fe=fe_table, limiting_pressure=case.impact.limiting_pressure)
    wm, worn = wear_of_impact(w.law, wear_constants(case), w.wear_law(), impact, ph, sliding_speed(impact, w.speed),
                              density=case.plate.material().density, points_across=w.points_across,
                              plate_work=plate_work)  # fmt: skip
    return ph, wm, worn


def one_way(case: Case, impact: ImpactResult) -> IndentationResult:
    """The FE plate along the impact's overlap history (``fem.indent_impact``, ``fem.load_steps + unload_steps``
    increments, the mesh of ``fem.mesh_scale``): the FE stage of a one-way run."""
    mesh = case_mesh(case, impact.max_overlap)
    steps = case.fem.load_steps + case.fem.unload_steps
    return fem.indent_impact(impact, case.plate.material(), steps=steps, mesh=mesh)


def run(case: Case, progress: Callable[[str], None] | None = None) -> RunResult:
    """Run the whole chain for ``case`` (see the module docstring). ``progress(stage)`` is called as each stage
    starts ("impact", "fem", "coupling", "wear", "surface")."""
    if not isinstance(case, Case):
        raise ValueError(f"case={type(case).__name__} is not a wear.Case")
    notify = progress or (lambda stage: None)
    ball, plate = case.ball.material(), case.plate.material()
    coupling_mode = case.fem.coupling
    if coupling_mode != "none" and plate.is_rigid:
        raise ValueError(f"fem.coupling={coupling_mode!r} needs a deformable plate: set fem.coupling='none'")
    if coupling_mode == "none" and case.wear.pressure == "fe":
        raise ValueError("wear.pressure='fe' needs the FE plate: set fem.coupling to 'two-way' or 'one-way'")
    if case.fem.model == "3d":
        check_solid_case(case)
        case = solid_case(case)
    times: dict[str, float] = {}

    def timed(stage, fn, *args, **kwargs):
        notify(stage)
        t0 = time.perf_counter()
        out = fn(*args, **kwargs)
        times[stage] = time.perf_counter() - t0
        return out

    estimate = impact = timed("impact", estimate_impact, case)
    fe: PlateCycle | IndentationResult | None = None
    coupled = fe_table = None
    if coupling_mode == "two-way":
        plate_fe = timed("fem", case_plate, case, (1.0 + case.fem.overshoot) * estimate.max_overlap)
        coupled = timed("coupling", fem.couple, plate_fe, impact_on_law(case), estimate.max_overlap,
                        coupling_settings(case))  # fmt: skip
        impact, fe, fe_table = coupled.impact, coupled.cycle, coupled.pressure_table
    elif coupling_mode == "one-way":
        fe = timed("fem", one_way, case, impact)
        times["coupling"] = 0.0
        rows = fem.contact_pressure(fe.pressure, fe.surface_r, fe.contact_radius)
        fe_table = (np.asarray(fe.time, float), np.asarray(fe.surface_r, float), rows)

    solid = None
    if case.fem.model == "3d":
        solid = timed("plate3d", solid_impact, case, impact)
        impact = solid.impact
        ph, wm, worn = timed("wear", solid_wear, case, solid)
    else:
        plate_work = None if coupled is None else coupled.plastic_work
        ph, wm, worn = timed("wear", impact_wear, case, impact, fe_table, plate_work)

    def surface_stage() -> DeformedSurface:
        if solid is not None:
            return solid_surface(solid, wm)
        h = impact.history
        i_max = int(np.argmax(h.overlap))
        centre = (float(h.contact_x[i_max]), 0.0)
        if fe is None:
            return DeformedSurface(wm.x, wm.y, wm.depth.T, np.array([0.0, 1.0]), np.zeros(2), centre)
        r = np.asarray(fe.surface_r, dtype=float)
        order = np.argsort(r)
        return DeformedSurface(wm.x, wm.y, wm.depth.T, r[order], np.asarray(fe.residual_depth, float)[order], centre)

    surface = timed("surface", surface_stage)
    info = _yield_info(case, ball, plate, fe, solid)
    return RunResult(case=case, estimate=estimate, impact=impact, fe=fe, coupling=coupled, pressure=ph, wear=wm,
                     worn=worn, surface=surface, yield_info=info, regime=_regime(impact, info, fe, solid),
                     stage_times=times, solid=solid)  # fmt: skip


def speed_ratio(case: Case) -> float:
    """Normal impact speed over Thornton's yield speed V_y (dimensionless; inf if the plate never yields)."""
    ball, plate = case.ball.material(), case.plate.material()
    if not plate.yield_strength:
        return math.inf
    v_n, _ = speed_components(case.impact.speed, case.impact.angle)
    return v_n / yield_velocity(case.ball.radius, ball, plate)
