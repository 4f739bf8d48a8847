"""Results of impact simulations: :class:`History`, :class:`ImpactResult`, :class:`BatchResult`.

SI units: s, m, N, Pa, m/s, rad/s, J; angles in degrees from the plate normal.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

from contact.materials import Material

__all__ = ["History", "ImpactResult", "BatchResult"]


@dataclass(frozen=True, eq=False)
class History:
    """Time histories of one impact, sampled at every ``every``-th engine step from first contact (t = 0) to
    separation (always the last sample, where forces, ξ, contact radius and pressure are 0 and the overlap is the
    one at separation: the residual dent's depth for a plastic contact, 0 for an elastic one up to one step).
    Read-only numpy arrays:

    ``t`` (s); ``overlap`` δ (m); ``normal_force`` F_n (N); ``tangential_force`` F_t (N, on the ball along the
    impact direction); ``tangential_displacement`` ξ (m, the H-DD spring's; with ``mindlin_deresiewicz`` the ball
    surface's slide ∫(v_t − Rω) dt); ``contact_radius`` a (m);
    ``peak_pressure`` (Pa: 3F_n/(2πa²) for ``tabulated``; for ``thornton`` p_y while loading plastically and
    the Hertz p₀ of the unloading bounded by p_y; for ``hertz`` the Hertz p₀ of the spring's force, the
    dashpot's left out: :func:`contact.laws.normal_law`);
    ``slip_velocity`` v_t − Rω (m/s, contact point relative to the plate); ``sliding`` (bool, gross sliding);
    ``center_x`` ball centre position along the impact direction measured from the first-contact point (m);
    ``contact_x`` contact-point position on the plate (m, = ``center_x``: the contact point is under the centre);
    ``omega`` spin (rad/s, positive = rolling forward);
    ``normal_velocity`` dδ/dt (m/s, positive towards the plate); ``tangential_velocity`` v_t of the centre (m/s).
    """

    t: np.ndarray
    overlap: np.ndarray
    normal_force: np.ndarray
    tangential_force: np.ndarray
    tangential_displacement: np.ndarray
    contact_radius: np.ndarray
    peak_pressure: np.ndarray
    slip_velocity: np.ndarray
    sliding: np.ndarray
    center_x: np.ndarray
    contact_x: np.ndarray
    omega: np.ndarray
    normal_velocity: np.ndarray
    tangential_velocity: np.ndarray

    def __post_init__(self) -> None:
        for f in fields(self):
            getattr(self, f.name).setflags(write=False)

    def __len__(self) -> int:
        return int(self.t.size)


#: Scalar outputs shared by ImpactResult and BatchResult (arrays there), with units.
OUTPUT_UNITS = {
    "normal_restitution": "",
    "tangential_restitution": "",
    "rebound_angle": "deg",
    "contact_point_rebound_angle": "deg",
    "spin": "rad/s",
    "rebound_normal_velocity": "m/s",
    "rebound_tangential_velocity": "m/s",
    "contact_time": "s",
    "sliding_time": "s",
    "max_force": "N",
    "max_overlap": "m",
    "max_contact_radius": "m",
    "max_peak_pressure": "Pa",
    "max_tangential_force": "N",
    "energy_in": "J",
    "energy_out": "J",
    "normal_work": "J",
    "friction_work": "J",
    "time_step": "s",
    "steps": "",
}


def _json_float(x: float) -> float | str | None:
    """JSON has no inf/NaN: +inf (rigid body) -> "inf", NaN (undefined, e.g. e_t at angle 0) -> None."""
    if math.isnan(x):
        return None
    return x if math.isfinite(x) else ("inf" if x > 0 else "-inf")


@dataclass(frozen=True, eq=False)
class ImpactResult:
    """One impact. Inputs are repeated (``radius`` m, ``ball``, ``plate``, ``speed`` m/s, ``angle`` deg,
    ``friction``, ``restitution``, model names, ``mass`` kg, ``limiting_pressure`` Pa or None).

    Outputs: ``normal_restitution`` −v_n'/v_n; ``tangential_restitution`` v_t'/v_t of the centre (NaN at
    angle 0); ``rebound_angle`` atan(v_t'/v_n') and ``contact_point_rebound_angle`` atan((v_t' − Rω')/v_n')
    (deg from the normal, may be < 0); ``spin`` ω' (rad/s, positive = rolling forward);
    ``rebound_normal_velocity`` (m/s, away from the plate, > 0), ``rebound_tangential_velocity`` (m/s);
    ``contact_time``, ``sliding_time`` (s); ``max_force``, ``max_tangential_force`` (N); ``max_overlap``,
    ``max_contact_radius`` (m); ``max_peak_pressure`` (Pa, the largest ``History.peak_pressure``). Energy balance (J):
    ``energy_in − energy_out = normal_work + friction_work`` to integration accuracy, with ``normal_work``
    = ∫F_n dδ (dashpot or plastic loss) and ``friction_work`` = −∫F_t (v_t − Rω) dt (work taken from the
    ball by the tangential force). ``time_step`` (s), ``steps`` engine steps in contact, ``history``.
    """

    radius: float
    ball: Material
    plate: Material
    speed: float
    angle: float
    friction: float
    restitution: float
    normal_model: str
    tangential_model: str
    scheme: str
    mass: float
    limiting_pressure: float | None
    normal_restitution: float
    tangential_restitution: float
    rebound_angle: float
    contact_point_rebound_angle: float
    spin: float
    rebound_normal_velocity: float
    rebound_tangential_velocity: float
    contact_time: float
    sliding_time: float
    max_force: float
    max_overlap: float
    max_contact_radius: float
    max_peak_pressure: float
    max_tangential_force: float
    energy_in: float
    energy_out: float
    normal_work: float
    friction_work: float
    time_step: float
    steps: int
    history: History | None = None

    def to_dict(self) -> dict:
        """Plain-JSON dict of inputs and outputs (NaN → None, inf → "inf"; materials as dicts; no history)."""
        d: dict = {}
        for f in fields(self):
            v = getattr(self, f.name)
            if f.name == "history":
                continue
            if isinstance(v, Material):
                v = {"E": v.E, "nu": v.nu, "density": v.density, "yield_strength": v.yield_strength, "name": v.name}
                v = {k: _json_float(x) if isinstance(x, float) else x for k, x in v.items()}
            elif isinstance(v, (float, np.floating)):
                v = _json_float(float(v))
            elif isinstance(v, np.integer):
                v = int(v)
            d[f.name] = v
        return d


@dataclass(frozen=True, eq=False)
class BatchResult:
    """Many impacts: the fields of :class:`ImpactResult` as numpy arrays over the batch (``speed``, ``angle``,
    ``friction`` and every output), the shared inputs as scalars, and ``histories`` (a tuple of
    :class:`History`, or None unless requested). ``batch[i]`` is the :class:`ImpactResult` of impact i."""

    radius: float
    ball: Material
    plate: Material
    speed: np.ndarray
    angle: np.ndarray
    friction: np.ndarray
    restitution: float
    normal_model: str
    tangential_model: str
    scheme: str
    mass: float
    limiting_pressure: float | None
    normal_restitution: np.ndarray
    tangential_restitution: np.ndarray
    rebound_angle: np.ndarray
    contact_point_rebound_angle: np.ndarray
    spin: np.ndarray
    rebound_normal_velocity: np.ndarray
    rebound_tangential_velocity: np.ndarray
    contact_time: np.ndarray
    sliding_time: np.ndarray
    max_force: np.ndarray
    max_overlap: np.ndarray
    max_contact_radius: np.ndarray
    max_peak_pressure: np.ndarray
    max_tangential_force: np.ndarray
    energy_in: np.ndarray
    energy_out: np.ndarray
    normal_work: np.ndarray
    friction_work: np.ndarray
    time_step: np.ndarray
    steps: np.ndarray
    histories: tuple[History, ...] | None = None

    def __len__(self) -> int:
        return int(self.speed.size)

    def __getitem__(self, i: int) -> ImpactResult:
        n = len(self)
        if not -n <= i < n:
            raise IndexError(f"impact index {i} out of range for a batch of {n}")
        kw = {}
        for f in fields(ImpactResult):
            if f.name == "history":
                continue
            v = getattr(self, f.name)
            if isinstance(v, np.ndarray):
                v = v[i].item()
            kw[f.name] = v
        kw["history"] = None if self.histories is None else self.histories[i]
        return ImpactResult(**kw)
