"""The checked inputs of a batch of impacts (:func:`contact.impact.simulate_impacts`): the ball, plate and laws as the
engine's parameter vector (:class:`ImpactSetup`), the per-impact speed, angle and friction arrays, and their time
steps and Mindlin-Deresiewicz spring spacings. SI units; angles in degrees from the plate normal.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact import engine, laws, theory
from contact.checks import check_array, check_bool, check_choice, check_friction, check_number
from contact.materials import Material, effective_modulus, effective_shear_modulus
from contact.tabulated import TabulatedLaw
from contact.timestep import MAX_CONTACT_TIMES, STEPS_PER_CONTACT, check_time_step

__all__ = [
    "ImpactBatch",
    "ImpactSetup",
    "NORMAL_MODELS",
    "TANGENTIAL_MODELS",
    "SCHEMES",
    "SPEED_MAX",
    "broadcast_impacts",
    "check_histories",
    "check_impact_arrays",
    "impact_batch",
    "impact_setup",
    "spring_pitch",
    "time_steps",
]

#: Fastest impact the engine takes (m/s): the H-DD model is quasi-static (no stress waves, no hypervelocity
#: regime), far beyond its range above this.
SPEED_MAX = 1000.0

NORMAL_MODELS = {"hertz": laws.HERTZ, "thornton": laws.THORNTON, "tabulated": laws.TABULATED}
#: Tangential laws: (kernel code, spring factor f).
TANGENTIAL_MODELS = {
    "hdd": (laws.SPRING, 2.0 / 3.0),
    "mindlin": (laws.SPRING, 1.0),
    "mindlin_deresiewicz": (laws.MEMORY, 1.0),
}
SCHEMES = {"verlet": engine.VERLET, "paper": engine.PAPER}


@dataclass(frozen=True, eq=False)
class ImpactSetup:
    """The checked ball, plate and laws of a batch: ``radius`` (m), ``ball``, ``plate``, ``restitution``, the
    normal ``model`` name, E* ``e_star`` (Pa), the ball's ``mass`` (kg), Thornton's ``limiting_pressure`` p_y (Pa;
    None for the other laws), and the engine's parameter vector ``prm`` and tabulated-law arrays ``tab``."""

    radius: float
    ball: Material
    plate: Material
    restitution: float
    model: str
    e_star: float
    mass: float
    limiting_pressure: float | None
    prm: np.ndarray
    tab: tuple[np.ndarray, ...]


def _check_material(name: str, value) -> Material:
    if not isinstance(value, Material):
        raise ValueError(
            f"{name}={value!r} is not a contact.Material: build it with Material(E=..., nu=..., density=...)"
        )
    return value


def impact_setup(
    radius: float,
    ball: Material,
    plate: Material,
    restitution: float,
    normal_model: str,
    tangential_model: str,
    limiting_pressure: float | None,
    force_law: TabulatedLaw | None,
    scheme: str,
) -> ImpactSetup:
    """Validated scalar inputs and the kernel parameter vector (the arguments as
    :func:`contact.impact.simulate_impacts`')."""
    radius = check_number("radius", radius, low=0.0, low_open=True, high=10.0, units="m", what="ball radius")
    ball = _check_material("ball", ball)
    plate = _check_material("plate", plate)
    if math.isinf(ball.density):
        raise ValueError("ball.density=inf: the ball needs a finite density (kg/m^3); only the plate may be rigid")
    restitution = check_number(
        "restitution", restitution, low=0.0, low_open=True, high=1.0, what="normal restitution coefficient"
    )
    model = check_choice("normal_model", normal_model, NORMAL_MODELS)
    check_choice("tangential_model", tangential_model, TANGENTIAL_MODELS)
    check_choice("scheme", scheme, SCHEMES)
    if model != "hertz" and restitution != 1.0:
        raise ValueError(
            f"restitution={restitution:g} is not allowed with normal_model={model!r}: the dashpot is calibrated for "
            "the Hertz law only; that law dissipates through plasticity (use restitution=1.0)"
        )
    if model != "thornton" and limiting_pressure is not None:
        raise ValueError(f"limiting_pressure={limiting_pressure!r} is used only by normal_model='thornton'")
    if model == "tabulated":
        if not isinstance(force_law, TabulatedLaw):
            raise ValueError(
                f"force_law={force_law!r} is not a contact.TabulatedLaw: normal_model='tabulated' needs one"
            )
    elif force_law is not None:
        raise ValueError("force_law is used only by normal_model='tabulated'")
    e_star = effective_modulus(ball, plate)
    g_star = effective_shear_modulus(ball, plate)
    mass = theory.sphere_mass(radius, ball.density)
    prm = np.zeros(laws.N_PARAMS)
    prm[laws.P_RADIUS] = radius
    prm[laws.P_HERTZ_K] = 4.0 / 3.0 * e_star * math.sqrt(radius)
    prm[laws.P_ESTAR] = e_star
    prm[laws.P_GSTAR] = g_star
    prm[laws.P_MASS] = mass
    prm[laws.P_INERTIA] = 0.4 * mass * radius**2
    prm[laws.P_SHEAR] = force_law.shear_strength if model == "tabulated" else math.inf
    prm[laws.P_DAMP] = laws.dashpot_coefficient(restitution) * math.sqrt(2.0 * e_star * math.sqrt(radius) * mass)
    p_y = None
    if model == "thornton":
        if limiting_pressure is None:
            p_y = theory.default_limiting_pressure(ball, plate)
        else:
            p_y = check_number(
                "limiting_pressure", limiting_pressure, low=1e3, high=1e12, units="Pa", what="limiting pressure"
            )
        d_y = (math.pi * p_y / (2.0 * e_star)) ** 2 * radius
        prm[laws.P_PY] = p_y
        prm[laws.P_DY] = d_y
        prm[laws.P_FY] = prm[laws.P_HERTZ_K] * d_y**1.5
    tab = laws.tabulated_arrays(force_law if model == "tabulated" else None)
    return ImpactSetup(radius, ball, plate, restitution, model, e_star, mass, p_y, prm, tab)


@dataclass(frozen=True, eq=False)
class ImpactBatch:
    """The impacts of a batch as the engine takes them, one entry each: ``speed`` (m/s), ``angle`` (deg),
    ``friction``, the normal and tangential speeds ``vn0``, ``vt0`` (m/s), the time step ``dt`` (s), the step limit
    ``max_steps`` and the Mindlin-Deresiewicz spring spacing ``pitch`` (m; 0 for the other tangential laws); and the
    engine's codes of the integration ``scheme``, the ``normal`` and ``tangential`` laws and the spring ``factor``."""

    speed: np.ndarray
    angle: np.ndarray
    friction: np.ndarray
    vn0: np.ndarray
    vt0: np.ndarray
    dt: np.ndarray
    max_steps: np.ndarray
    pitch: np.ndarray
    scheme: int
    normal: int
    tangential: int
    factor: float


def impact_batch(
    setup: ImpactSetup,
    speed,
    angle,
    friction,
    tangential_model: str,
    scheme: str,
    force_law: TabulatedLaw | None,
    time_step: float | None,
    histories: bool,
    history_every: int,
) -> ImpactBatch:
    """The checked batch of impacts of ``speed``, ``angle`` and ``friction`` (broadcast together) with the ball,
    plate and laws of ``setup`` (the arguments as :func:`contact.impact.simulate_impacts`')."""
    speed, angle, friction = check_impact_arrays(speed, angle, friction)
    check_histories(histories, history_every)
    speed, angle, friction = broadcast_impacts(speed, angle, friction)
    vn0, vt0 = theory.speed_components(speed, angle)
    if np.any(vn0 < 1e-9 * speed):
        raise ValueError("angle is too close to 90 deg: the normal speed vanishes")
    dt, max_steps = time_steps(setup, vn0, time_step, histories, history_every)
    tangential, factor = TANGENTIAL_MODELS[tangential_model]
    pitch = np.zeros(vn0.shape)  # only the memory law has springs
    if tangential == laws.MEMORY:
        tabulated = force_law if setup.model == "tabulated" else None
        pitch = spring_pitch(setup.radius, setup.e_star, setup.mass, vn0, tabulated, setup.limiting_pressure)
    return ImpactBatch(
        speed,
        angle,
        friction,
        vn0,
        vt0,
        dt,
        max_steps,
        pitch,
        SCHEMES[scheme],
        NORMAL_MODELS[setup.model],
        tangential,
        factor,
    )


def check_impact_arrays(speed, angle, friction) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``speed`` (m/s) in (0, :data:`SPEED_MAX`], ``angle`` (deg from the normal) in [0, 90) and ``friction`` in
    [0, :data:`contact.checks.FRICTION_MAX`], each a scalar or an array, as checked arrays."""
    speed = check_array("speed", speed, low=0.0, low_open=True, units="m/s", what="impact speed", ndim=np.ndim(speed))
    if np.any(speed > SPEED_MAX):
        raise ValueError(
            f"speed={float(speed.max()):g} is out of range: impact speed must be in (0, {SPEED_MAX:g}] m/s"
        )
    angle = check_array("angle", angle, low=0.0, units="deg", what="impact angle from the normal", ndim=np.ndim(angle))
    if np.any(angle >= 90.0):
        bad = float(angle[angle >= 90.0].flat[0])
        raise ValueError(f"angle={bad:g} is out of range: impact angle from the normal must be in [0, 90) deg")
    friction = np.asarray(check_friction("friction", friction), float)
    return speed, angle, friction


def check_histories(histories: bool, history_every: int) -> None:
    """``histories`` a bool and ``history_every`` an integer ≥ 1 (steps)."""
    check_bool("histories", histories)
    if isinstance(history_every, bool) or not isinstance(history_every, (int, np.integer)) or history_every < 1:
        raise ValueError(f"history_every={history_every!r} is out of range: must be an integer >= 1 (steps)")


def broadcast_impacts(
    speed: np.ndarray, angle: np.ndarray, friction: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``speed``, ``angle`` and ``friction`` broadcast together and flattened to the batch (writable copies)."""
    try:
        # copies: a broadcast view (one row broadcast against a scalar) is flagged "warn on write", which numba
        # reads as a FutureWarning
        return tuple(np.array(np.ravel(a), dtype=float) for a in np.broadcast_arrays(speed, angle, friction))
    except ValueError:
        raise ValueError(
            f"speed, angle, friction have shapes {np.shape(speed)}, {np.shape(angle)}, {np.shape(friction)}: "
            "they must broadcast together"
        ) from None


def time_steps(
    setup: ImpactSetup, normal_speed: np.ndarray, time_step: float | None, histories: bool, history_every: int
) -> tuple[np.ndarray, np.ndarray]:
    """Per impact of normal speed ``normal_speed`` (m/s): the time step (s; default the Hertz contact time /
    :data:`contact.timestep.STEPS_PER_CONTACT`, else ``time_step`` checked against it) and the engine's step limit
    (:data:`contact.timestep.MAX_CONTACT_TIMES` Hertz contact times, plus a margin)."""
    contact_time = (
        theory.HERTZ_CONTACT_TIME_FACTOR
        * (15.0 * setup.mass / (16.0 * setup.e_star * math.sqrt(setup.radius))) ** 0.4
        * normal_speed**-0.2
    )
    if time_step is None:
        dt = contact_time / STEPS_PER_CONTACT
    else:
        dt = np.full(
            normal_speed.shape,
            check_time_step(time_step, contact_time, histories=histories, history_every=history_every),
        )
    max_steps = np.ceil(MAX_CONTACT_TIMES * contact_time / dt).astype(np.int64) + 1000
    return dt, max_steps


def spring_pitch(
    radius: float,
    e_star: float,
    mass: float,
    normal_speed: np.ndarray,
    force_law: TabulatedLaw | None,
    limiting_pressure: float | None,
) -> np.ndarray:
    """Spacing (m) of the Mindlin-Deresiewicz springs per impact: :data:`contact.laws.SPRINGS` of them over three
    times the larger of the Hertz contact radius at the impact's normal speed (:func:`contact.theory.hertz_impact`)
    and, with a ``limiting_pressure`` p_y (Pa), the radius √(Rδ) of a contact that takes the whole kinetic energy at
    p_y, ½mv² = πp_yRδ²/2; or over 1.5 times the largest contact radius of ``force_law``."""
    if force_law is not None:
        largest = max(
            float(np.max(force_law.loading_contact_radius)), float(np.max(force_law.unloading_contact_radius))
        )
        return np.full(normal_speed.shape, 1.5 * largest / laws.SPRINGS)
    largest = np.array([theory.hertz_impact(mass, radius, e_star, v).max_contact_radius for v in normal_speed])
    if limiting_pressure is not None:
        plastic_overlap = normal_speed * math.sqrt(mass / (math.pi * limiting_pressure * radius))
        largest = np.maximum(largest, np.sqrt(radius * plastic_overlap))
    return 3.0 * largest / laws.SPRINGS
