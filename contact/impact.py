r"""Oblique impact of an elastic ball on a flat plate: :func:`simulate_impact` and :func:`simulate_impacts`.

The H-DD model (errata Eqs. 3–9): Hertz normal force with an optional restitution dashpot (Eq. 6), or
Thornton's (1997) elastic–perfectly plastic law, or a tabulated law from a finite-element plate; Di Renzo &
Di Maio's integral tangential spring with Coulomb truncation; ball rotation with I = 2/5 m R². The plate is
fixed and flat. SI units; angles in degrees from the plate normal.
"""

from __future__ import annotations

import math

import numpy as np

from contact import engine, laws, theory
from contact.checks import check_array, check_bool, check_choice, check_number
from contact.materials import Material, effective_modulus, effective_shear_modulus
from contact.results import BatchResult, History, ImpactResult
from contact.tabulated import TabulatedLaw
from contact.timestep import MAX_CONTACT_TIMES, STEPS_PER_CONTACT, check_time_step

__all__ = [
    "simulate_impact",
    "simulate_impacts",
    "ForceLawRangeError",
    "NORMAL_MODELS",
    "TANGENTIAL_MODELS",
    "SCHEMES",
    "SPEED_MAX",
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


def _check_material(name: str, value) -> Material:
    if not isinstance(value, Material):
        raise ValueError(
            f"{name}={value!r} is not a contact.Material: build it with Material(E=..., nu=..., density=...)"
        )
    return value


def _setup(radius, ball, plate, restitution, normal_model, tangential_model, limiting_pressure, force_law, scheme):
    """Validated scalar inputs and the kernel parameter vector."""
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
    return radius, ball, plate, restitution, model, e_star, mass, p_y, prm, tab


class ForceLawRangeError(ValueError):
    """The overlap left the range a tabulated ``force_law`` covers (beyond its loading curve, or unloading from
    beyond its last unloading curve): a caller that builds the table can extend it and run again."""


_ERRORS = {
    laws.ERR_LOADING_TABLE: "the overlap went beyond the loading curve of force_law (loading_overlap[-1]={load:.4g} m)",
    laws.ERR_UNLOADING_TABLE: "unloading started beyond the last unloading curve of force_law "
    "(unloading_max_overlap[-1]={unload:.4g} m)",
    laws.ERR_MAX_STEPS: "the contact did not end within {steps} steps",
    laws.ERR_SPRINGS: "the contact radius outgrew the row of Mindlin-Deresiewicz springs (3 times the Hertz or the "
    "plastic energy bound, or 1.5 times force_law's largest)",
}


def _spring_pitch(
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


def simulate_impacts(
    radius: float,
    ball: Material,
    plate: Material,
    speed,
    angle,
    friction,
    restitution: float = 1.0,
    normal_model: str = "hertz",
    tangential_model: str = "hdd",
    limiting_pressure: float | None = None,
    force_law: TabulatedLaw | None = None,
    scheme: str = "verlet",
    time_step: float | None = None,
    histories: bool = False,
    history_every: int = 1,
) -> BatchResult:
    r"""Simulate many impacts of the same ball on the same plate in one batched (numba, parallel) run.

    Parameters
    ----------
    radius
        Ball radius R (m), in (0, 10].
    ball, plate
        :class:`contact.Material` (the plate may be ``Material.rigid()``).
    speed
        Impact speed \|v\| (m/s), in (0, 1000]; scalar or array.
    angle
        Impact angle θ from the plate normal (deg), in [0, 90); scalar or array.
    friction
        Coulomb friction coefficient μ, in [0, 10]; scalar or array. ``speed``, ``angle`` and ``friction`` are
        broadcast together to the batch shape (flattened).
    restitution
        Normal restitution e in (0, 1] that sets the Hertz dashpot (errata Eq. 6); 1 = no damping.
    normal_model
        ``"hertz"``, ``"thornton"`` (with ``limiting_pressure`` p_y in Pa, default C(ν)·Y of the body that yields
        first) or ``"tabulated"`` (with ``force_law``, a :class:`contact.TabulatedLaw`).
    tangential_model
        ``"hdd"`` (F_t = −(2/3)·8G*a·ξ), ``"mindlin"`` (without the 2/3) or ``"mindlin_deresiewicz"`` (partial
        slip with memory of the loading history, :func:`contact.laws.memory_tangential_law`).
    scheme
        ``"verlet"`` (second order, default) or ``"paper"`` (the paper's Eqs. 12–13, first order).
    time_step
        Δt (s); default: the Hertz contact time of each impact's normal speed / 2000. A given Δt must give 10 to
        :data:`contact.timestep.MAX_STEPS` steps over the Hertz contact time
        (:data:`contact.timestep.MAX_HISTORY_STEPS` with ``histories``): :func:`contact.timestep.check_time_step`.
    histories
        Record a :class:`History` per impact; ``history_every`` k keeps every k-th step (and the last).

    Notes
    -----
    Tabulated law: loading follows F(δ), a(δ) of the table; once δ decreases, unloading (and any reloading up to
    δ*) follows the unloading curve of the reached δ*, interpolated linearly in δ* between the tabulated curves in
    the normalised coordinate s = (δ − δ_p)/(δ* − δ_p), with F and a normalised by their values at δ* (so unloading
    starts exactly on the loading branch); δ_p is interpolated linearly in δ*. Below the smallest tabulated δ*
    the first curve's normalised shape is used with δ_p scaled in proportion to δ*. The table is not
    extrapolated: if an impact loads beyond ``force_law.loading_overlap[-1]`` or starts unloading beyond
    ``force_law.unloading_max_overlap[-1]``, a ValueError names ``force_law``. The default time step then still
    uses the Hertz contact time of ``ball`` and ``plate``, and k_t = 8G*a uses the tabulated a.

    Hertz contact time: see :func:`contact.theory.hertz_impact`. Contact ends at the first step end where F_n = 0
    while the ball moves away (located within one step). Only ``normal_model="hertz"`` takes ``restitution`` < 1.
    """
    radius, ball, plate, restitution, model, e_star, mass, p_y, prm, tab = _setup(
        radius, ball, plate, restitution, normal_model, tangential_model, limiting_pressure, force_law, scheme
    )
    speed = check_array("speed", speed, low=0.0, low_open=True, units="m/s", what="impact speed", ndim=np.ndim(speed))
    if np.any(speed > SPEED_MAX):
        raise ValueError(
            f"speed={float(speed.max()):g} is out of range: impact speed must be in (0, {SPEED_MAX:g}] m/s"
        )
    angle = check_array("angle", angle, low=0.0, units="deg", what="impact angle from the normal", ndim=np.ndim(angle))
    if np.any(angle >= 90.0):
        bad = float(angle[angle >= 90.0].flat[0])
        raise ValueError(f"angle={bad:g} is out of range: impact angle from the normal must be in [0, 90) deg")
    friction = check_array("friction", friction, low=0.0, what="friction coefficient", ndim=np.ndim(friction))
    if np.any(friction > 10.0):
        raise ValueError(f"friction={float(friction.max()):g} is out of range: friction coefficient must be in [0, 10]")
    check_bool("histories", histories)
    if isinstance(history_every, bool) or not isinstance(history_every, (int, np.integer)) or history_every < 1:
        raise ValueError(f"history_every={history_every!r} is out of range: must be an integer >= 1 (steps)")
    try:
        # copies: a broadcast view (one row broadcast against a scalar) is flagged "warn on write", which numba
        # reads as a FutureWarning
        speed, angle, friction = (
            np.array(np.ravel(a), dtype=float) for a in np.broadcast_arrays(speed, angle, friction)
        )
    except ValueError:
        raise ValueError(
            f"speed, angle, friction have shapes {np.shape(speed)}, {np.shape(angle)}, {np.shape(friction)}: "
            "they must broadcast together"
        ) from None
    vn0, vt0 = theory.speed_components(speed, angle)
    if np.any(vn0 < 1e-9 * speed):
        raise ValueError("angle is too close to 90 deg: the normal speed vanishes")
    contact_time = (
        theory.HERTZ_CONTACT_TIME_FACTOR * (15.0 * mass / (16.0 * e_star * math.sqrt(radius))) ** 0.4 * vn0**-0.2
    )
    if time_step is None:
        dt = contact_time / STEPS_PER_CONTACT
    else:
        dt = np.full(
            speed.shape, check_time_step(time_step, contact_time, histories=histories, history_every=history_every)
        )
    max_steps = np.ceil(MAX_CONTACT_TIMES * contact_time / dt).astype(np.int64) + 1000
    code, scheme_code = NORMAL_MODELS[model], SCHEMES[scheme]
    tangential, factor = TANGENTIAL_MODELS[tangential_model]
    pitch = np.zeros(vn0.shape)  # only the memory law has springs
    if tangential == laws.MEMORY:
        pitch = _spring_pitch(radius, e_star, mass, vn0, force_law if model == "tabulated" else None, p_y)
    out = engine.run_batch(scheme_code, code, tangential, factor, friction, dt, vn0, vt0, max_steps, prm, tab, pitch)
    errors = out[:, -1].astype(int)
    if np.any(errors):
        i = int(np.flatnonzero(errors)[0])
        why = _ERRORS[errors[i]].format(load=tab[0][0, -1], unload=tab[1][-1], steps=int(max_steps[i]))
        name = {laws.ERR_MAX_STEPS: "time_step", laws.ERR_SPRINGS: "tangential_model"}.get(errors[i], "force_law")
        error = ForceLawRangeError if name == "force_law" else ValueError
        raise error(f"{name}: impact {i} (speed={speed[i]:g} m/s, angle={angle[i]:g} deg): {why}")
    hist = None
    if histories:
        hist = []
        for i in range(speed.size):
            capacity = int(out[i, engine.OUT_FIELDS.index("steps")]) // history_every + 3
            _, h = engine.run_history(
                scheme_code,
                code,
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
                capacity,
                history_every,
            )
            hist.append(_history(h))
        hist = tuple(hist)
    col = {name: out[:, k] for k, name in enumerate(engine.OUT_FIELDS)}
    vn, vt, spin = col["normal_velocity"], col["tangential_velocity"], col["spin"]
    inertia = 0.4 * mass * radius**2
    with np.errstate(invalid="ignore", divide="ignore"):
        tangential_restitution = np.where(vt0 > 0.0, vt / np.where(vt0 > 0.0, vt0, 1.0), np.nan)
    return BatchResult(
        radius=radius,
        ball=ball,
        plate=plate,
        speed=speed,
        angle=angle,
        friction=friction,
        restitution=restitution,
        normal_model=model,
        tangential_model=tangential_model,
        scheme=scheme,
        mass=mass,
        limiting_pressure=p_y,
        normal_restitution=-vn / vn0,
        tangential_restitution=tangential_restitution,
        rebound_angle=np.degrees(np.arctan2(vt, -vn)),
        contact_point_rebound_angle=np.degrees(np.arctan2(vt - radius * spin, -vn)),
        spin=spin,
        rebound_normal_velocity=-vn,
        rebound_tangential_velocity=vt,
        contact_time=col["contact_time"],
        sliding_time=col["sliding_time"],
        max_force=col["max_force"],
        max_overlap=col["max_overlap"],
        max_contact_radius=col["max_contact_radius"],
        max_peak_pressure=col["max_peak_pressure"],
        max_tangential_force=col["max_tangential_force"],
        energy_in=0.5 * mass * speed**2,
        energy_out=0.5 * mass * (vn**2 + vt**2) + 0.5 * inertia * spin**2,
        normal_work=col["normal_work"],
        friction_work=col["friction_work"],
        time_step=dt,
        steps=col["steps"].astype(np.int64),
        histories=hist,
    )


def _history(h: np.ndarray) -> History:
    row = {name: np.ascontiguousarray(h[k]) for k, name in enumerate(engine.HISTORY_FIELDS)}
    row["sliding"] = row["sliding"] > 0.5
    row["contact_x"] = row["center_x"].copy()
    return History(**row)


def simulate_impact(
    radius: float,
    ball: Material,
    plate: Material,
    speed: float,
    angle: float,
    friction: float,
    restitution: float = 1.0,
    normal_model: str = "hertz",
    tangential_model: str = "hdd",
    limiting_pressure: float | None = None,
    force_law: TabulatedLaw | None = None,
    scheme: str = "verlet",
    time_step: float | None = None,
    history: bool = True,
    history_every: int = 1,
) -> ImpactResult:
    """Simulate one impact (the batch of one of :func:`simulate_impacts`; same parameters, SI units, angles
    in degrees from the plate normal). ``history`` records a :class:`History` (every ``history_every``-th
    step and the last, at separation)."""
    for name, value, units in (("speed", speed, "m/s"), ("angle", angle, "deg"), ("friction", friction, "")):
        check_number(name, value, units=units)
    check_bool("history", history)
    batch = simulate_impacts(
        radius,
        ball,
        plate,
        speed,
        angle,
        friction,
        restitution=restitution,
        normal_model=normal_model,
        tangential_model=tangential_model,
        limiting_pressure=limiting_pressure,
        force_law=force_law,
        scheme=scheme,
        time_step=time_step,
        histories=history,
        history_every=history_every,
    )
    return batch[0]
