r"""Finnie's (1960) micro-cutting volume of a rigid particle of mass m at speed V (Wear 3: 87–103),

.. math:: W = \frac{c\,m V^2}{p\,\psi K}\left(\sin 2\alpha - \frac{6}{K}\sin^2\alpha\right), \ \tan\alpha \le
          \frac{K}{6}; \qquad W = \frac{c\,m V^2}{p\,\psi K}\,\frac{K\cos^2\alpha}{6}, \ \tan\alpha > \frac{K}{6}

(p the plastic flow pressure ≈ the hardness, K the ratio of vertical to horizontal force on the particle ≈ 2, ψ the
ratio of the depth of contact to the depth of cut ≈ 2, c the fraction of particles cutting ideally; α from the
surface); its maximum is at tan 2α = K/3 (16.8° from the surface for K = 2) and it is zero at normal incidence.
SI units; angles θ in degrees from the plate normal, α = 90° − θ.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact import ImpactResult, Material
from contact.theory import sphere_mass
from wear.laws.declaration import Constants, Law, angle_from_surface, flow_pressure_of, need
from wear.laws.records import particle_mass, record_arrays

__all__ = ["LAW", "FinnieLaw", "finnie_peak_angle", "finnie_volume"]

DESCRIPTION = "Finnie (1960) micro-cutting from the particle's kinematics"


def finnie_volume(
    mass,
    speed,
    angle,
    flow_pressure: float,
    force_ratio: float = 2.0,
    depth_ratio: float = 2.0,
    cutting_fraction: float = 0.5,
) -> np.ndarray:
    """Finnie's (1960) cutting volume (m³) of particles of ``mass`` (kg) at ``speed`` (m/s) and ``angle`` (deg from
    the normal) on a plate of plastic ``flow_pressure`` (Pa); see the module docstring.

    At the peak (16.85° from the surface), 0.5 · 1e-6 kg · (10 m/s)² / (1e9 Pa · 2 · 2) · (sin 33.69° − 3 sin² 16.85°):

    >>> f"{float(finnie_volume(1e-6, 10.0, 90.0 - finnie_peak_angle(2.0), 1e9)):.4e}"
    '3.7847e-15'
    """
    a = angle_from_surface(angle)
    k = force_ratio
    kinetic = np.asarray(mass, float) * np.asarray(speed, float) ** 2
    scale = cutting_fraction * kinetic / (flow_pressure * depth_ratio * k)
    shallow = np.sin(2.0 * a) - 6.0 / k * np.sin(a) ** 2
    steep = k * np.cos(a) ** 2 / 6.0
    return scale * np.where(np.tan(a) <= k / 6.0, shallow, steep)


def finnie_peak_angle(force_ratio: float = 2.0) -> float:
    """Angle (deg, from the surface) of Finnie's maximum: tan 2α = K/3 (16.85° for K = 2)."""
    return math.degrees(0.5 * math.atan(force_ratio / 3.0))


def _closed_form(constants: Constants, radius: float, ball_density: float, plate: Material, speed, angle) -> np.ndarray:
    """The cutting volume (m³) of one impact of a ball of ``radius`` (m) and ``ball_density`` (kg/m³)."""
    c, k, psi = need(constants, "finnie", "cutting_fraction", "force_ratio", "depth_ratio")
    return finnie_volume(sphere_mass(radius, ball_density), speed, angle, flow_pressure_of(constants, plate), k, psi, c)


def _volumes(
    constants: Constants, impact: ImpactResult, *, local: float | None, plate_work: float | None
) -> dict[str, float]:
    """The cutting of one impact, from its speed and angle."""
    ball = impact.ball
    return {
        "cutting": float(_closed_form(constants, impact.radius, ball.density, impact.plate, impact.speed, impact.angle))
    }


@dataclass(frozen=True)
class FinnieLaw:
    """Finnie's (1960) cutting per record of a wall (:func:`finnie_volume`): ``flow_pressure`` p (Pa),
    ``force_ratio`` K, ``depth_ratio`` ψ, ``cutting_fraction`` c."""

    flow_pressure: float
    force_ratio: float
    depth_ratio: float
    cutting_fraction: float
    name: str = "finnie"
    description: str = ""

    def __post_init__(self) -> None:
        if not self.description:
            k, psi, c = self.force_ratio, self.depth_ratio, self.cutting_fraction
            constants = f"p = {self.flow_pressure:g} Pa, K = {k:g}, psi = {psi:g}, c = {c:g}"
            object.__setattr__(self, "description", f"{DESCRIPTION}, per record: {constants}")

    def volume(self, angle_deg, speed_m_s, diameter_m, density_kg_m3, count) -> np.ndarray:
        """Eroded volume (m³) of each record: N finnie(m, V, θ)."""
        theta, speed, d, rho, n = record_arrays(angle_deg, speed_m_s, diameter_m, density_kg_m3, count)
        mass = particle_mass(d, rho)
        k, psi, c = self.force_ratio, self.depth_ratio, self.cutting_fraction
        return n * finnie_volume(mass, speed, theta, self.flow_pressure, k, psi, c)


def _per_record(constants: Constants, plate: Material) -> FinnieLaw:
    """The law per record of a wall of ``plate``."""
    return FinnieLaw(
        flow_pressure_of(constants, plate),
        constants["force_ratio"],
        constants["depth_ratio"],
        constants["cutting_fraction"],
    )


LAW = Law(
    name="finnie",
    description=DESCRIPTION,
    volumes=_volumes,
    constants=("cutting_fraction", "force_ratio", "depth_ratio"),
    scale="cutting_fraction",
    log_constants=("cutting_fraction", "force_ratio", "depth_ratio"),
    closed_form=_closed_form,
    per_record=_per_record,
    plate_keys=("rigid", "density", "hardness", "yield_strength", "name"),
)
