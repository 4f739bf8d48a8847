r"""Oblique impact of an elastic ball on a flat plate: :func:`simulate_impact` and :func:`simulate_impacts`.

The H-DD model (errata Eqs. 3–9): Hertz normal force with an optional restitution dashpot (Eq. 6), or
Thornton's (1997) elastic–perfectly plastic law, or a tabulated law from a finite-element plate; Di Renzo &
Di Maio's integral tangential spring with Coulomb truncation; ball rotation with I = 2/5 m R². The plate is
fixed and flat. SI units; angles in degrees from the plate normal. The inputs are checked in
:mod:`contact.impact_inputs`.
"""

from __future__ import annotations

import numpy as np

from contact import engine, laws
from contact.checks import check_bool, check_number
from contact.impact_inputs import (
    NORMAL_MODELS,
    SCHEMES,
    SPEED_MAX,
    TANGENTIAL_MODELS,
    ImpactBatch,
    ImpactSetup,
    impact_batch,
    impact_setup,
)
from contact.materials import Material
from contact.results import BatchResult, History, ImpactResult
from contact.tabulated import TabulatedLaw

__all__ = [
    "simulate_impact",
    "simulate_impacts",
    "ForceLawRangeError",
    "NORMAL_MODELS",
    "TANGENTIAL_MODELS",
    "SCHEMES",
    "SPEED_MAX",
]


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
        Coulomb friction coefficient μ, in [0, 1] (:data:`contact.checks.FRICTION_MAX`); scalar or array.
        ``speed``, ``angle`` and ``friction`` are broadcast together to the batch shape (flattened).
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

    Examples
    --------
    Three speeds in one batch, elastic: each keeps its normal speed, and Hertz's contact time falls as the normal
    speed to the power −1/5 (Johnson 1985, §11.4), so 1 and 4 m/s differ by 4^(1/5):

    >>> from contact import Material, simulate_impacts
    >>> ball = Material(E=380e9, nu=0.23, density=3900.0)
    >>> plate = Material(E=114e9, nu=0.34, density=4430.0)
    >>> batch = simulate_impacts(radius=5e-3, ball=ball, plate=plate, speed=[1.0, 2.0, 4.0], angle=0.0, friction=0.3)
    >>> len(batch), [round(float(e), 4) for e in batch.normal_restitution]
    (3, [1.0, 1.0, 1.0])
    >>> bool(abs(batch.contact_time[0] / batch.contact_time[2] / 4 ** 0.2 - 1) < 1e-3)
    True
    """
    setup = impact_setup(
        radius, ball, plate, restitution, normal_model, tangential_model, limiting_pressure, force_law, scheme
    )
    batch = impact_batch(
        setup, speed, angle, friction, tangential_model, scheme, force_law, time_step, histories, history_every
    )
    out = _run_batch(setup, batch)
    _raise_first_error(out, setup.tab, batch)
    hist = _histories(setup, batch, out, history_every) if histories else None
    return _batch_result(setup, tangential_model, scheme, batch, out, hist)


def _run_batch(setup: ImpactSetup, batch: ImpactBatch) -> np.ndarray:
    """The engine's (numba, parallel) run of every impact of ``batch``: one row of
    :data:`contact.engine.OUT_FIELDS` per impact, its error code last."""
    return engine.run_batch(
        batch.scheme,
        batch.normal,
        batch.tangential,
        batch.factor,
        batch.friction,
        batch.dt,
        batch.vn0,
        batch.vt0,
        batch.max_steps,
        setup.prm,
        setup.tab,
        batch.pitch,
    )


def _raise_first_error(out: np.ndarray, tab: tuple[np.ndarray, ...], batch: ImpactBatch) -> None:
    """Raise for the first impact the engine flagged in the last column of ``out``: :class:`ForceLawRangeError`
    where it left the tabulated law ``tab``, else a ValueError naming ``time_step`` or ``tangential_model``."""
    errors = out[:, -1].astype(int)
    if np.any(errors):
        i = int(np.flatnonzero(errors)[0])
        why = _ERRORS[errors[i]].format(load=tab[0][0, -1], unload=tab[1][-1], steps=int(batch.max_steps[i]))
        name = {laws.ERR_MAX_STEPS: "time_step", laws.ERR_SPRINGS: "tangential_model"}.get(errors[i], "force_law")
        error = ForceLawRangeError if name == "force_law" else ValueError
        raise error(f"{name}: impact {i} (speed={batch.speed[i]:g} m/s, angle={batch.angle[i]:g} deg): {why}")


def _histories(setup: ImpactSetup, batch: ImpactBatch, out: np.ndarray, every: int) -> tuple[History, ...]:
    """The time history of each impact of ``batch``, run once more recording every ``every``-th step (and the
    last) into a buffer sized by the step count of the batch run ``out``."""
    hist = []
    for i in range(batch.speed.size):
        capacity = int(out[i, engine.OUT_FIELDS.index("steps")]) // every + 3
        _, h = engine.run_history(
            batch.scheme,
            batch.normal,
            batch.tangential,
            batch.factor,
            batch.friction[i],
            batch.dt[i],
            batch.vn0[i],
            batch.vt0[i],
            batch.max_steps[i],
            setup.prm,
            setup.tab,
            batch.pitch[i],
            capacity,
            every,
        )
        hist.append(_history(h))
    return tuple(hist)


def _batch_result(
    setup: ImpactSetup,
    tangential_model: str,
    scheme: str,
    batch: ImpactBatch,
    out: np.ndarray,
    hist: tuple[History, ...] | None,
) -> BatchResult:
    """The :class:`BatchResult` of the engine's output ``out`` (one row of :data:`contact.engine.OUT_FIELDS` per
    impact): rebound velocities (m/s), restitutions, angles (deg), energies (J) and the engine's maxima."""
    col = {name: out[:, k] for k, name in enumerate(engine.OUT_FIELDS)}
    vn, vt, spin = col["normal_velocity"], col["tangential_velocity"], col["spin"]
    radius, mass, vn0, vt0 = setup.radius, setup.mass, batch.vn0, batch.vt0
    inertia = 0.4 * mass * radius**2
    with np.errstate(invalid="ignore", divide="ignore"):
        tangential_restitution = np.where(vt0 > 0.0, vt / np.where(vt0 > 0.0, vt0, 1.0), np.nan)
    return BatchResult(
        radius=radius,
        ball=setup.ball,
        plate=setup.plate,
        speed=batch.speed,
        angle=batch.angle,
        friction=batch.friction,
        restitution=setup.restitution,
        normal_model=setup.model,
        tangential_model=tangential_model,
        scheme=scheme,
        mass=mass,
        limiting_pressure=setup.limiting_pressure,
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
        energy_in=0.5 * mass * batch.speed**2,
        energy_out=0.5 * mass * (vn**2 + vt**2) + 0.5 * inertia * spin**2,
        normal_work=col["normal_work"],
        friction_work=col["friction_work"],
        time_step=batch.dt,
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
    r"""Simulate one impact of a ball on a plate: the H-DD model (errata equations 1–13), the batch of one of
    :func:`simulate_impacts`.

    Parameters
    ----------
    radius
        Ball radius R (m), in (0, 10].
    ball, plate
        :class:`contact.Material` (the plate may be ``Material.rigid()``).
    speed
        Impact speed \|v\| (m/s), in (0, 1000].
    angle
        Impact angle θ from the plate normal (deg), in [0, 90).
    friction
        Coulomb friction coefficient μ, in [0, 1] (:data:`contact.checks.FRICTION_MAX`).
    restitution
        Normal restitution e in (0, 1] that sets the Hertz dashpot (errata Eq. 6); 1 = no damping.
    normal_model
        ``"hertz"``, ``"thornton"`` (with ``limiting_pressure`` p_y in Pa) or ``"tabulated"`` (with ``force_law``,
        a :class:`contact.TabulatedLaw`, e.g. an FE plate's).
    tangential_model
        ``"hdd"``, ``"mindlin"`` or ``"mindlin_deresiewicz"``.
    scheme
        ``"verlet"`` (second order, default) or ``"paper"`` (the paper's Eqs. 12–13, first order).
    time_step
        Δt (s); default: the Hertz contact time of the normal speed / 2000.
    history
        Record a :class:`History` (every ``history_every``-th step and the last, at separation).

    The models, the limits of ``time_step`` and the tabulated law's rules: :func:`simulate_impacts`.

    Examples
    --------
    An alumina ball on an elastic Ti-6Al-4V plate lasts Hertz's contact time and rebounds with all its normal speed
    (Johnson 1985, §11.4):

    >>> import math
    >>> from contact import Material, effective_modulus, simulate_impact
    >>> from contact.theory import hertz_impact, sphere_mass
    >>> ball = Material(E=380e9, nu=0.23, density=3900.0)
    >>> plate = Material(E=114e9, nu=0.34, density=4430.0)
    >>> impact = simulate_impact(radius=5e-3, ball=ball, plate=plate, speed=3.0, angle=30.0, friction=0.3)
    >>> round(impact.normal_restitution, 4)
    1.0
    >>> normal_speed = 3.0 * math.cos(math.radians(30.0))
    >>> hertz = hertz_impact(sphere_mass(5e-3, 3900.0), 5e-3, effective_modulus(ball, plate), normal_speed)
    >>> print(f"{impact.contact_time:.3e} s against Hertz's {hertz.contact_time:.3e} s")
    2.308e-05 s against Hertz's 2.308e-05 s
    """
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
