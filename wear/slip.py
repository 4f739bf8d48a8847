r"""The slip of the contacting surfaces along one impact: the sliding speed v of the wear law (errata equation 15),
the relative tangential velocity of the ball's and the plate's surface points in contact (SI units: m, s, m/s).

Three models (``model=`` of :func:`sliding_speed`, the case's ``wear.speed``), the same on every plate:

``"local"``
    The FE plate surface's own slip where the plate resolves it. On the axisymmetric plate a surface point at
    distance r from the contact centre, in the direction e_r, slips at

    .. math:: \mathbf{v}(r, t) = v_s(t)\,\mathbf{e}_x - \dot u_r(r, t)\,\mathbf{e}_r,

    v_s the impact's contact-point slip velocity along the impact direction x while the contact slides (0 while it
    sticks: the axisymmetric plate is frictionless and carries no stick zone of its own) and u_r the plate
    surface's radial displacement (:func:`fem.pressure_table.radial_table`; the ball, rigid in the FE, does not
    stretch): at normal incidence the surface still slips radially under the ball, the micro-slip through which
    Engel's impact-wear specimens wear. On the 3-D plate each surface vertex slips by its own FE slip, zero where
    it sticks (:mod:`wear.solid_wear`).
``"sliding"``
    The paper's contact-point slip: ``|v_t − Rω|`` while the contact is in gross sliding, 0 while it sticks, the
    same at every point of the contact.
``"kinematic"``
    ``|v_t − Rω|`` throughout, stuck or not (while stuck it is the small micro-slip speed of the tangential spring).

>>> import numpy as np
>>> motion = RadialSlip(np.array([0.0, 1e-6]), np.array([0.0, 1e-4]), np.array([[0.0, 0.0], [0.0, -2e-8]]))
>>> motion.rates()[0, 1]  # m/s: the surface at r = 0.1 mm moved 20 nm inwards in 1 µs
np.float64(-0.02)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact.checks import check_array, check_choice

__all__ = ["SPEED_MODELS", "RadialSlip", "SlidingSpeed", "sliding_speed"]

#: The sliding-speed models of :func:`sliding_speed`.
SPEED_MODELS = ("local", "sliding", "kinematic")


@dataclass(frozen=True, eq=False)
class RadialSlip:
    """The plate surface's radial displacement ``displacement`` u_r (m, (n, m): positive away from the contact
    centre) at reference radii ``r`` (m, (m,), from the contact centre) at ``time`` (s, (n,), increasing); between
    two times it moves at a constant rate."""

    time: np.ndarray
    r: np.ndarray
    displacement: np.ndarray

    def __post_init__(self) -> None:
        t = check_array("time", self.time, units="s", min_size=2)
        r = check_array("r", self.r, low=0.0, units="m", min_size=2)
        u = check_array("displacement", self.displacement, units="m", ndim=2)
        if np.any(np.diff(t) <= 0.0) or u.shape != (t.size, r.size):
            raise ValueError(
                f"time {t.shape} must increase strictly and displacement {u.shape} be (time, r) = ({t.size}, {r.size})"
            )
        order = np.argsort(r)
        object.__setattr__(self, "time", np.ascontiguousarray(t))
        object.__setattr__(self, "r", np.ascontiguousarray(r[order]))
        object.__setattr__(self, "displacement", np.ascontiguousarray(u[:, order]))

    def rates(self) -> np.ndarray:
        """u̇_r (m/s, (n − 1, m)) over each interval between two times, at :attr:`r`."""
        return np.diff(self.displacement, axis=0) / np.diff(self.time)[:, None]

    def rate_table(self, reach: float, points: int = 513) -> np.ndarray:
        """:meth:`rates` resampled on ``points`` radii 0 … ``reach`` (m), equally spaced (linear between the plate's
        radii)."""
        grid = np.linspace(0.0, reach, points)
        return np.array([np.interp(grid, self.r, row) for row in self.rates()])


@dataclass(frozen=True, eq=False)
class SlidingSpeed:
    """Sliding speed of the contact points (m/s, ≥ 0) at ``time`` (s); ``model`` names how it was built. The local
    slip (``model="local"``) also holds the contact-point slip velocity ``slip_velocity`` (m/s, signed, along the
    impact direction x; 0 while the contact sticks) and the plate surface's ``radial`` motion; ``speed`` is then
    ``|slip_velocity|``."""

    time: np.ndarray
    speed: np.ndarray
    model: str = ""
    slip_velocity: np.ndarray | None = None
    radial: RadialSlip | None = None

    def __post_init__(self) -> None:
        t = check_array("time", self.time, units="s", min_size=2)
        v = check_array("speed", self.speed, low=0.0, units="m/s")
        if v.shape != t.shape or np.any(np.diff(t) <= 0.0):
            raise ValueError(f"time {t.shape} and speed {v.shape} must have equal shapes; time strictly increasing")
        object.__setattr__(self, "time", np.ascontiguousarray(t))
        object.__setattr__(self, "speed", np.ascontiguousarray(v))
        if (self.slip_velocity is None) != (self.radial is None):
            raise ValueError("slip_velocity and radial: give both (the local slip) or neither")
        if self.slip_velocity is not None:
            s = check_array("slip_velocity", self.slip_velocity, units="m/s")
            if s.shape != t.shape:
                raise ValueError(f"slip_velocity {s.shape} must have time's shape {t.shape}")
            object.__setattr__(self, "slip_velocity", np.ascontiguousarray(s))

    @property
    def is_local(self) -> bool:
        """Whether the speed varies over the contact (the local slip with the surface's radial motion)."""
        return self.radial is not None


def sliding_speed(impact, model: str = "sliding", radial: RadialSlip | None = None) -> SlidingSpeed:
    """Sliding speed of the contact points along ``impact`` (an ImpactResult or its History), m/s, by ``model``
    (module docstring): ``"local"`` needs the plate surface's ``radial`` motion (:class:`RadialSlip`, the FE
    plate's); ``"sliding"`` and ``"kinematic"`` are the impact's contact-point slip."""
    check_choice("model", model, SPEED_MODELS)
    h = getattr(impact, "history", impact)
    velocity = np.asarray(h.slip_velocity, dtype=float)
    if model == "kinematic":
        return SlidingSpeed(np.asarray(h.t, dtype=float), np.abs(velocity), model=model)
    velocity = np.where(np.asarray(h.sliding, dtype=bool), velocity, 0.0)
    if model == "sliding":
        return SlidingSpeed(np.asarray(h.t, dtype=float), np.abs(velocity), model=model)
    if radial is None:
        raise ValueError(
            "model='local' is the FE plate surface's slip: it needs the plate's radial surface motion (radial=, "
            "fem's radial_table); without an FE plate use 'sliding' (the contact-point slip) or 'kinematic'"
        )
    return SlidingSpeed(np.asarray(h.t, dtype=float), np.abs(velocity), model, velocity, radial)
