r"""The whole chain for one impact case: impact → FE plate → coupling → wear → deformed surface.

``run(case) -> RunResult``. A :class:`Case` is a set of frozen dataclasses (SI units, angles in degrees
from the plate normal)::

    from wear.pipeline import Case, run
    result = run(Case.default())
    result.summary()["wear"]["volume_m3"]

Stages (their wall times are in ``RunResult.stage_times``):

1. ``impact``: the H-DD impact (:func:`contact.simulate_impact`) with ``case.impact``'s normal model.
2. ``fem`` + ``coupling``: with ``fem.coupling = "two-way"`` (what issue 4 calls ``normal_model = "fe"``)
   the impact is re-run on the FE plate's own force–overlap law and contact radius until the maximum
   overlap changes by < ``fem.tolerance`` (:mod:`wear.coupling`); ``"one-way"`` drives the FE plate with
   the impact's overlap history (``fem.indent_impact``); ``"none"`` skips the FE (no dent; the pressure
   source must then not be ``"fe"``).
3. ``wear``: Eq. 15 integrated over the moving contact patch (:func:`wear.integrate_wear`).
4. ``surface``: the residual FE dent placed at the contact centre of maximum overlap plus the wear map
   (:class:`wear.surface.DeformedSurface`).
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field, fields, replace
from typing import Any

import numpy as np

from contact import ImpactResult, Material, effective_modulus, simulate_impact
from contact.theory import PAPER_YIELD_COEFFICIENT, first_yield, yield_velocity
from contact.validation import check_bool, check_choice, check_number

from .integrate import WearMap, integrate_wear
from .law import WearLaw
from .pressure import PRESSURE_SOURCES, SPEED_MODELS, PressureHistory, pressure_history, sliding_speed
from .surface import DeformedSurface

__all__ = [
    "BallSpec",
    "PlateSpec",
    "ImpactSpec",
    "WearSpec",
    "FemSpec",
    "OutputSpec",
    "Case",
    "RunResult",
    "run",
    "STAGES",
    "COUPLINGS",
]

#: Stages of :func:`run`, in order (the output writer adds "meshes" and "figures").
STAGES = ("impact", "fem", "coupling", "wear", "surface")
COUPLINGS = ("two-way", "one-way", "none")


@dataclass(frozen=True)
class BallSpec:
    """The ball: ``radius`` (m), ``E`` (Pa, inf = rigid), ``nu``, ``density`` (kg/m³),
    ``yield_strength`` (Pa or None)."""

    radius: float = 2.5e-3
    E: float = 380e9
    nu: float = 0.23
    density: float = 3950.0
    yield_strength: float | None = None
    name: str = "alumina"

    def __post_init__(self) -> None:
        check_number("ball.radius", self.radius, low=0.0, low_open=True, high=10.0, units="m", what="ball radius")
        self.material()

    def material(self) -> Material:
        try:
            return Material(self.E, self.nu, self.density, self.yield_strength, self.name)
        except ValueError as exc:
            raise ValueError(f"ball.{exc}") from None


@dataclass(frozen=True)
class PlateSpec:
    """The plate: ``E`` (Pa), ``nu``, ``density`` (kg/m³), ``yield_strength`` (Pa; None = elastic); ``rigid``
    (E, nu, density ignored)."""

    rigid: bool = False
    E: float = 114e9
    nu: float = 0.34
    density: float = 4430.0
    yield_strength: float | None = 880e6
    name: str = "Ti-6Al-4V"

    def __post_init__(self) -> None:
        check_bool("plate.rigid", self.rigid)
        self.material()

    def material(self) -> Material:
        if self.rigid:
            return Material.rigid(name=self.name)
        try:
            return Material(self.E, self.nu, self.density, self.yield_strength, self.name)
        except ValueError as exc:
            raise ValueError(f"plate.{exc}") from None


@dataclass(frozen=True)
class ImpactSpec:
    """The impact: ``speed`` (m/s), ``angle`` (deg from the normal), ``friction`` μ, ``restitution`` (Hertz dashpot),
    ``normal_model`` ("hertz" or "thornton": the impact model of a one-way run, and the first estimate of a two-way
    run), ``tangential_model``, ``limiting_pressure`` (Pa or None), ``scheme``, ``time_step`` (s or None)."""

    speed: float = 3.0
    angle: float = 30.0
    friction: float = 0.3
    restitution: float = 1.0
    normal_model: str = "thornton"
    tangential_model: str = "hdd"
    limiting_pressure: float | None = None
    scheme: str = "verlet"
    time_step: float | None = None

    def __post_init__(self) -> None:
        check_number("impact.speed", self.speed, low=0.0, low_open=True, high=1000.0, units="m/s")
        check_number("impact.angle", self.angle, low=0.0, high=90.0, high_open=True, units="deg")
        check_number("impact.friction", self.friction, low=0.0, high=10.0)
        check_number("impact.restitution", self.restitution, low=0.0, low_open=True, high=1.0)
        check_choice("impact.normal_model", self.normal_model, ("hertz", "thornton"))
        check_choice("impact.tangential_model", self.tangential_model, ("hdd", "mindlin"))
        check_choice("impact.scheme", self.scheme, ("verlet", "paper"))


@dataclass(frozen=True)
class WearSpec:
    """Wear law Eq. 15 ``K`` (m^(1−β) s^(β−1) Pa^(−α)), ``alpha``, ``beta``; ``pressure`` source
    ("fe", "hertz", "paper", "thornton"); sliding ``speed`` model ("sliding", "kinematic");
    ``points_across`` grid points across the largest contact diameter (≥ 40)."""

    K: float = 1e-11
    alpha: float = 1.0
    beta: float = 0.3
    pressure: str = "fe"
    speed: str = "sliding"
    points_across: int = 64

    def __post_init__(self) -> None:
        self.law()
        check_choice("wear.pressure", self.pressure, PRESSURE_SOURCES)
        check_choice("wear.speed", self.speed, SPEED_MODELS)
        check_number("wear.points_across", self.points_across, low=40, high=2000)

    def law(self) -> WearLaw:
        try:
            return WearLaw(K=self.K, alpha=self.alpha, beta=self.beta)
        except ValueError as exc:
            raise ValueError(f"wear.{exc}") from None


@dataclass(frozen=True)
class FemSpec:
    """FE plate: ``coupling`` ("two-way", "one-way", "none"); ``tolerance`` on the change of the maximum overlap
    between coupling iterations (relative); ``max_iterations``; ``load_steps`` FE increments up to the maximum
    overlap, ``unload_steps`` after it; ``overshoot`` how far past the estimated maximum overlap the single FE
    loading goes (relative); ``mesh_scale`` multiplies the FE element sizes (> 1: coarser, for quick runs)."""

    coupling: str = "two-way"
    tolerance: float = 0.005
    max_iterations: int = 8
    load_steps: int = 16
    unload_steps: int = 8
    overshoot: float = 0.1
    mesh_scale: float = 2.0

    def __post_init__(self) -> None:
        check_choice("fem.coupling", self.coupling, COUPLINGS)
        check_number("fem.tolerance", self.tolerance, low=1e-6, high=0.2)
        check_number("fem.max_iterations", self.max_iterations, low=2, high=50)
        check_number("fem.load_steps", self.load_steps, low=4, high=1000)
        check_number("fem.unload_steps", self.unload_steps, low=2, high=1000)
        check_number("fem.overshoot", self.overshoot, low=0.02, high=2.0)
        check_number("fem.mesh_scale", self.mesh_scale, low=0.25, high=8.0)


@dataclass(frozen=True)
class OutputSpec:
    """Outputs: ``figures`` (PNG), ``render`` (3-D view), ``plate_mesh`` (path of a user's meshio plate block to
    deform instead of the generated one; "" = generate), ``block_thickness`` (m) of the generated block."""

    figures: bool = True
    render: bool = True
    plate_mesh: str = ""
    block_thickness: float = 2e-3

    def __post_init__(self) -> None:
        check_bool("output.figures", self.figures)
        check_bool("output.render", self.render)
        if not isinstance(self.plate_mesh, str):
            raise ValueError(f"output.plate_mesh={self.plate_mesh!r} is not a string: give a mesh file path")
        if self.plate_mesh and not os.path.isfile(self.plate_mesh):
            raise ValueError(f"output.plate_mesh={self.plate_mesh!r} is not a file: give a meshio-readable plate mesh")
        check_number("output.block_thickness", self.block_thickness, low=0.0, low_open=True, high=1.0, units="m")


_SPECS = {"ball": BallSpec, "plate": PlateSpec, "impact": ImpactSpec, "wear": WearSpec, "fem": FemSpec,
          "output": OutputSpec}  # fmt: skip


@dataclass(frozen=True)
class Case:
    """A whole run case: ball, plate, impact, wear, fem and output specs (see each class for keys and units).

    :meth:`default` is the embedded default case (also ``impactwear run`` with no case file): a hard alumina
    ball (R = 2.5 mm) hitting a Ti-6Al-4V plate at 3 m/s, 30° from the normal, μ = 0.3 — about 11 times
    Thornton's yield speed in the normal direction, so first yield is far exceeded and the plastic zone
    reaches the surface — with the paper's wear law α = 1, β = 0.3, K = 1e-11 m^0.7 s^-0.7 Pa^-1.
    """

    ball: BallSpec = field(default_factory=BallSpec)
    plate: PlateSpec = field(default_factory=PlateSpec)
    impact: ImpactSpec = field(default_factory=ImpactSpec)
    wear: WearSpec = field(default_factory=WearSpec)
    fem: FemSpec = field(default_factory=FemSpec)
    output: OutputSpec = field(default_factory=OutputSpec)

    @classmethod
    def default(cls) -> Case:
        return cls()

    @classmethod
    def from_dict(cls, tables: dict[str, dict[str, Any]]) -> Case:
        """A case from a dict of tables (e.g. a checked TOML case); absent keys take the defaults above."""
        unknown = set(tables) - set(_SPECS)
        if unknown:
            raise ValueError(f"[{sorted(unknown)[0]}] is not a known case table: known tables are {', '.join(_SPECS)}")
        parts = {}
        for table, spec in _SPECS.items():
            values = dict(tables.get(table) or {})
            names = {f.name for f in fields(spec)}
            for key in values:
                if key not in names:
                    raise ValueError(f"{table}.{key} is not a known key: keys of [{table}] are {', '.join(names)}")
            parts[table] = spec(**values)
        return cls(**parts)

    def to_dict(self) -> dict[str, dict[str, Any]]:
        return asdict(self)

    def with_(self, **tables: dict[str, Any]) -> Case:
        """A copy with some keys replaced, e.g. ``case.with_(impact={"speed": 2.0})``."""
        return replace(self, **{t: replace(getattr(self, t), **v) for t, v in tables.items()})


@dataclass(frozen=True, eq=False)
class RunResult:
    """Everything one :func:`run` produced (SI units).

    ``impact`` (:class:`contact.ImpactResult`, the final impact: coupled if two-way), ``fe`` (the FE result or
    None), ``coupling`` (:class:`wear.coupling.CouplingResult` or None), ``pressure``
    (:class:`wear.PressureHistory`), ``wear`` (:class:`wear.WearMap`), ``surface``
    (:class:`wear.surface.DeformedSurface`), ``yield_info`` (dict: ``F_y_paper`` Eq. 18 with C = 1.6,
    ``F_c_exact`` with C(ν), ``fe_first_yield_force``, ``V_y`` Thornton's yield speed, N and m/s), ``regime``
    (str), ``stage_times`` (dict stage → s).
    """

    case: Case
    impact: ImpactResult
    fe: Any
    coupling: Any
    pressure: PressureHistory
    wear: WearMap
    surface: DeformedSurface
    yield_info: dict
    regime: str
    stage_times: dict

    def summary(self) -> dict:
        """The numbers of summary.json (without versions; the writer adds them)."""
        imp = self.impact
        impact = {
            k: getattr(imp, k)
            for k in (
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
        }
        impact["units"] = "s, N, m, Pa, m/s, rad/s, deg"
        w = self.wear
        coupling = None if self.coupling is None else self.coupling.summary()
        return {
            "case": self.case.to_dict(),
            "impact": impact,
            "yield": dict(self.yield_info),
            "regime": self.regime,
            "wear": {
                "volume_m3": w.volume_m3,
                "mass_kg": w.mass_kg,
                "max_depth_m": w.max_depth_m,
                "scar_length_m": w.scar_length_m,
                "scar_width_m": w.scar_width_m,
                "law": str(self.case.wear.law()),
                "pressure_source": self.pressure.source,
            },
            "dent": {
                "max_depth_m": self.surface.max_dent_depth,
                "centre_x_m": self.surface.dent_centre[0],
            },
            "coupling": coupling,
            "stage_times_s": dict(self.stage_times),
        }


def _yield_info(case: Case, ball: Material, plate: Material, fe) -> dict:
    info: dict[str, Any] = {"F_y_paper": None, "F_c_exact": None, "fe_first_yield_force": None, "V_y": None}
    if plate.yield_strength and not plate.is_rigid:
        e_star = effective_modulus(ball, plate)
        R, Y = case.ball.radius, plate.yield_strength
        info["F_y_paper"] = first_yield(R, e_star, Y, plate.nu, coefficient=PAPER_YIELD_COEFFICIENT).force
        info["F_c_exact"] = first_yield(R, e_star, Y, plate.nu).force
        info["V_y"] = yield_velocity(R, ball, plate)
    fy = getattr(fe, "first_yield", None) if fe is not None else None
    if fy is not None:
        info["fe_first_yield_force"] = float(fy.force)
    return info


def _regime(impact: ImpactResult, info: dict, fe) -> str:
    regimes = getattr(fe, "regime", None) if fe is not None else None
    if regimes is not None and len(regimes):
        order = ("elastic", "contained", "surface-plastic", "fully-plastic")
        worst = max((r for r in regimes if r in order), key=order.index, default="elastic")
        return str(worst)
    if info["F_c_exact"] is None:
        return "elastic"
    return "elastic" if impact.max_force < info["F_c_exact"] else "plastic (no FE: regime not resolved)"


def _impact(case: Case, ball: Material, plate: Material, **overrides) -> ImpactResult:
    spec = case.impact
    kwargs = dict(
        radius=case.ball.radius,
        ball=ball,
        plate=plate,
        speed=spec.speed,
        angle=spec.angle,
        friction=spec.friction,
        restitution=spec.restitution,
        normal_model=spec.normal_model,
        tangential_model=spec.tangential_model,
        limiting_pressure=spec.limiting_pressure,
        scheme=spec.scheme,
        time_step=spec.time_step,
        history=True,
    )
    if kwargs["normal_model"] == "thornton" and not plate.yield_strength and not ball.yield_strength:
        kwargs["normal_model"] = "hertz"  # nothing yields: Thornton's law is Hertz
    kwargs.update(overrides)
    return simulate_impact(**kwargs)


def impact_wear(case: Case, impact: ImpactResult, fe_table=None):
    """Stage ``wear``: the pressure history p(r, t) of ``impact`` (``case.wear.pressure``; ``fe_table`` the FE
    (time s, r m, pressure Pa) table where it is "fe") and the wear map of Eq. 15 integrated over the moving
    patch (m). Returns (:class:`wear.pressure.PressureHistory`, :class:`wear.WearMap`)."""
    ph = pressure_history(impact, case.wear.pressure, fe=fe_table, limiting_pressure=case.impact.limiting_pressure)
    wm = integrate_wear(ph, sliding_speed(impact, case.wear.speed), case.wear.law(),
                        density=case.plate.material().density, points_across=case.wear.points_across)  # fmt: skip
    return ph, wm


def run(case: Case, progress: Callable[[str], None] | None = None) -> RunResult:
    """Run the whole chain for ``case`` (see the module docstring). ``progress(stage)`` is called as each stage
    starts ("impact", "fem", "coupling", "wear", "surface")."""
    if not isinstance(case, Case):
        raise ValueError(f"case={type(case).__name__} is not a wear.pipeline.Case")
    notify = progress or (lambda stage: None)
    ball, plate = case.ball.material(), case.plate.material()
    coupling_mode = case.fem.coupling
    if coupling_mode != "none" and plate.is_rigid:
        raise ValueError(f"fem.coupling={coupling_mode!r} needs a deformable plate: set fem.coupling='none'")
    if coupling_mode == "none" and case.wear.pressure == "fe":
        raise ValueError("wear.pressure='fe' needs the FE plate: set fem.coupling to 'two-way' or 'one-way'")
    times: dict[str, float] = {}

    def timed(stage, fn, *args, **kwargs):
        notify(stage)
        t0 = time.perf_counter()
        out = fn(*args, **kwargs)
        times[stage] = time.perf_counter() - t0
        return out

    impact = timed("impact", _impact, case, ball, plate)
    fe = coupled = fe_table = None
    if coupling_mode != "none":
        from . import coupling as coupling_module

        if coupling_mode == "two-way":
            fe_load = timed("fem", coupling_module.load_plate, case, ball, plate, impact)
            coupled = timed("coupling", coupling_module.couple, case, ball, plate, fe_load, impact)
            impact, fe, fe_table = coupled.impact, coupled.fe, coupled.pressure_table
        else:
            fe = timed("fem", coupling_module.one_way, case, ball, plate, impact)
            times["coupling"] = 0.0
            fe_table = coupling_module.pressure_table_one_way(fe)

    ph, wm = timed("wear", impact_wear, case, impact, fe_table)

    def surface_stage():
        h = impact.history
        i_max = int(np.argmax(h.overlap))
        centre = (float(h.contact_x[i_max]), 0.0)
        if fe is None:
            return DeformedSurface(wm.x, wm.y, wm.depth.T, np.array([0.0, 1.0]), np.zeros(2), centre)
        r = np.asarray(fe.surface_r, dtype=float)
        order = np.argsort(r)
        return DeformedSurface(wm.x, wm.y, wm.depth.T, r[order], np.asarray(fe.residual_depth, float)[order], centre)

    surface = timed("surface", surface_stage)
    info = _yield_info(case, ball, plate, fe)
    return RunResult(
        case=case,
        impact=impact,
        fe=fe,
        coupling=coupled,
        pressure=ph,
        wear=wm,
        surface=surface,
        yield_info=info,
        regime=_regime(impact, info, fe),
        stage_times=times,
    )


def speed_ratio(case: Case) -> float:
    """Normal impact speed over Thornton's yield speed V_y (dimensionless; inf if the plate never yields)."""
    ball, plate = case.ball.material(), case.plate.material()
    if not plate.yield_strength:
        return math.inf
    v_n = case.impact.speed * math.cos(math.radians(case.impact.angle))
    return v_n / yield_velocity(case.ball.radius, ball, plate)
