r"""The whole chain for one impact case: impact → FE plate → coupling → wear → deformed surface.

``run(case) -> RunResult`` for a :class:`wear.Case` (its ``[ball]``, ``[plate]``, ``[impact]``, ``[wear]``,
``[fem]`` tables; SI units, angles in degrees from the plate normal)::

    from wear import Case, run
    result = run(Case())
    result.summary()["wear"]["volume_m3"]

Steps (their wall times are in ``RunResult.stage_times``, the summary's ``stage_times_s``: names users read, kept;
a sweep's stage is another thing, :mod:`wear.app.sweep.stages`):

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
import warnings
from collections.abc import Callable
from dataclasses import dataclass

from contact import ImpactResult, Material, effective_modulus
from contact.theory import PAPER_YIELD_COEFFICIENT, first_yield, speed_components, sphere_mass, yield_velocity
from fem import CoupledImpact, PlateCycle
from fem.axisymmetric.result import IndentationResult
from fem.solid_coupling import SolidCoupledImpact
from wear.case import JOBS, Case
from wear.case.check import check_work
from wear.chain.estimate import estimate_impact
from wear.chain.plate_model import PlateRun
from wear.chain.plates import couple_plate, prepare_case
from wear.integrate import WearMap, implausible_wear
from wear.laws import local
from wear.laws.impact import ImpactWear
from wear.laws.registry import law_named
from wear.pressure import PressureHistory
from wear.surface import DeformedSurface

__all__ = [
    "RunResult",
    "run",
    "speed_ratio",
    "STEPS",
]

#: Steps of :func:`run`, in order, as its progress reports them (the output writer adds "meshes" and "figures").
STEPS = ("impact", "fem", "coupling", "plate3d", "wear", "surface")
#: The plate's blocks of summary.json that it always holds, null where the plate has none
#: (:meth:`wear.chain.plate_model.PlateRun.summary_blocks`); the plate's other blocks are there only where it has them.
SUMMARY_PLATE_BLOCKS = ("coupling", "plate_3d")


@dataclass(frozen=True, eq=False)
class RunResult:
    """Everything one :func:`run` produced (SI units).

    ``estimate`` (the impact on the case's own normal model), ``impact`` (:class:`contact.ImpactResult`, the final
    impact: coupled if two-way), ``plate`` (the plate the impact acted on, :class:`wear.chain.plate_model.PlateRun`:
    what the outputs and figures ask for), ``pressure`` (:class:`wear.PressureHistory`), ``wear``
    (:class:`wear.WearMap`), ``worn`` (the wear law's volumes by mechanism, :class:`wear.laws.impact.ImpactWear`),
    ``surface`` (:class:`wear.surface.DeformedSurface`), ``yield_info`` (dict: ``F_y_paper`` Eq. 18 with C = 1.6,
    ``F_c_exact`` with C(ν), ``fe_first_yield_force`` of the plate the impact ran on, ``V_y`` Thornton's yield
    speed, N and m/s), ``regime`` (str), ``stage_times`` (dict stage → s). ``fe``, ``coupling`` and ``solid`` are
    the plate's parts: the axisymmetric plate's cycle and coupled impact (on the 3-D plate, those it started
    from) and the 3-D coupled impact (None on another plate).
    """

    case: Case
    estimate: ImpactResult
    impact: ImpactResult
    plate: PlateRun
    pressure: PressureHistory
    wear: WearMap
    worn: ImpactWear
    surface: DeformedSurface
    yield_info: dict[str, float | None]
    regime: str
    stage_times: dict[str, float]

    @property
    def fem_model(self) -> str | None:
        """The FE plate the impact ran on (``fem.model``: "axisymmetric" or "3d"; None without an FE plate)."""
        return self.plate.model

    @property
    def fe(self) -> PlateCycle | IndentationResult | None:
        """The axisymmetric plate's cycle (two-way) or indentation (one-way), None without one."""
        return self.plate.fields.get("fe")

    @property
    def coupling(self) -> CoupledImpact | None:
        """The impact coupled to the axisymmetric plate (two-way), None otherwise."""
        return self.plate.fields.get("coupling")

    @property
    def solid(self) -> SolidCoupledImpact | None:
        """The impact coupled to the 3-D plate, None on another plate."""
        return self.plate.fields.get("solid")

    def summary(self) -> dict:
        """The numbers of summary.json (without versions; the writer adds them)."""
        imp = self.impact
        names = (
            "normal_restitution",
            "tangential_restitution",
            "rebound_angle",
            "contact_point_rebound_angle",
            "spin",
            "rebound_normal_velocity",
            "rebound_tangential_velocity",
            "contact_time",
            "sliding_time",
            "max_force",
            "max_tangential_force",
            "max_overlap",
            "max_contact_radius",
            "max_peak_pressure",
            "normal_model",
        )
        impact = {k: getattr(imp, k) for k in names}
        # the pressure of the plate the impact acted on: the FE's where there is one (its contact pressure field),
        # else the normal law's (the Hertz-type 3F/(2πa²) would overstate a plastic contact's by up to 1.5x)
        impact["max_peak_pressure"], impact["max_peak_pressure_source"] = self.plate.peak_pressure()
        impact["units"] = "s, N, m, Pa, m/s, rad/s, deg"
        w = self.wear
        dent = self.surface.dent_dimensions()
        blocks = self.plate.summary_blocks(self.estimate)
        return {
            "case": self.case.to_dict(JOBS["run"].tables),
            "fem_model": self.fem_model,
            "impact": impact,
            "yield": dict(self.yield_info),
            "regime": self.regime,
            "regime_plate": self.fem_model,
            **{k: v for k, v in blocks.items() if k not in SUMMARY_PLATE_BLOCKS},
            "wear": {
                "volume_m3": w.volume_m3,
                "mass_kg": w.mass_kg,
                "max_depth_m": w.max_depth_m,
                "scar_length_m": w.scar_length_m,
                "scar_width_m": w.scar_width_m,
                "law": str(self.case.wear.wear_law())
                if self.worn.law == local.LAW.name
                else f"{self.worn.law}: {law_named(self.worn.law).description}",
                "pressure_source": self.pressure.source,
                "parts_m3": dict(self.worn.parts),
            },
            "dent": {
                "max_depth_m": self.surface.max_dent_depth,
                "centre_x_m": self.surface.dent_centre[0],
                "length_m": dent.length,
                "width_m": dent.width,
                "pile_up_m": dent.pile_up,
                "model": self.fem_model or "axisymmetric",
            },
            **{k: blocks.get(k) for k in SUMMARY_PLATE_BLOCKS},
            "stage_times_s": dict(self.stage_times),
        }


def _yield_info(case: Case, ball: Material, plate: Material) -> dict:
    """First yield by the closed forms (N, m/s); the plate the impact ran on adds its own
    (:meth:`wear.chain.plate_model.PlateRun.yield_info`)."""
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
    return info


def run(case: Case, progress: Callable[[str], None] | None = None) -> RunResult:
    """Run the whole chain for ``case`` (see the module docstring). ``progress(step)`` is called as each step
    starts ("impact", "fem", "coupling", "plate3d", "wear", "surface").

    Examples
    --------
    The default case (an alumina ball at 3 m/s, 30° from the normal, on Ti-6Al-4V) on a coarse FE plate (element
    sizes × 4, 8 + 4 load steps: a few seconds), worn with α = 1, β = 0 under Thornton's pressure along the coupled
    impact: the worn volume is K ∫∫ p dA dt = K ∫ F dt, K times the normal impulse m v_n (1 + e) (momentum balance),
    and the plate yields, so the rebound keeps less than all of the normal speed:

    >>> import math
    >>> from wear.case import Case
    >>> from contact.theory import sphere_mass
    >>> case = Case().with_(
    ...     fem={"mesh_scale": 4.0, "load_steps": 8, "unload_steps": 4},
    ...     wear={"alpha": 1.0, "beta": 0.0, "pressure": "thornton", "speed": "sliding"},
    ... )
    >>> result = run(case)
    >>> e = result.impact.normal_restitution
    >>> impulse = sphere_mass(case.ball.radius, case.ball.density) * 3.0 * math.cos(math.radians(30.0)) * (1 + e)
    >>> bool(abs(result.wear.volume_m3 / (case.wear.K * impulse) - 1) < 1e-3), bool(e < 1.0)
    (True, True)
    """
    if not isinstance(case, Case):
        raise ValueError(f"case={type(case).__name__} is not a wear.Case")
    check_work(case, "run")  # a runaway is refused before any work
    notify = progress or (lambda step: None)
    ball, plate = case.ball.material(), case.plate.material()
    coupling_mode = case.fem.coupling
    if coupling_mode != "none" and plate.is_rigid:
        raise ValueError(f"fem.coupling={coupling_mode!r} needs a deformable plate: set fem.coupling='none'")
    if coupling_mode == "none" and case.wear.pressure == "fe":
        raise ValueError("wear.pressure='fe' needs the FE plate: set fem.coupling to 'two-way' or 'one-way'")
    case = prepare_case(case)
    times: dict[str, float] = {}

    def timed(step, fn, *args, **kwargs):
        notify(step)
        t0 = time.perf_counter()
        out = fn(*args, **kwargs)
        times[step] = time.perf_counter() - t0
        return out

    estimate = timed("impact", estimate_impact, case)
    on_plate = couple_plate(case, estimate, timed)
    ph, wm, worn = timed("wear", on_plate.wear, case)
    for line in implausible_wear(wm, on_plate.impact.max_contact_radius, sphere_mass(case.ball.radius, ball.density)):
        warnings.warn(line, stacklevel=2)
    surface = timed("surface", on_plate.surface, wm)
    info = on_plate.yield_info(_yield_info(case, ball, plate))
    return RunResult(
        case=case,
        estimate=estimate,
        impact=on_plate.impact,
        plate=on_plate,
        pressure=ph,
        wear=wm,
        worn=worn,
        surface=surface,
        yield_info=info,
        regime=on_plate.regime(info),
        stage_times=times,
    )


def speed_ratio(case: Case) -> float:
    """Normal impact speed over Thornton's yield speed V_y (dimensionless; inf if the plate never yields)."""
    ball, plate = case.ball.material(), case.plate.material()
    if not plate.yield_strength:
        return math.inf
    v_n, _ = speed_components(case.impact.speed, case.impact.angle)
    return v_n / yield_velocity(case.ball.radius, ball, plate)
