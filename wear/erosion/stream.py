r"""A stream of particles: its speed, angle from the plate normal, azimuth, concentration or mass flux and exposure,
and the number of particles it delivers to a patch of the plate (SI units; angles in degrees). The patch it erodes:
:mod:`wear.erosion.patch`."""

from __future__ import annotations

import math
from dataclasses import dataclass

from contact.checks import check_number

__all__ = ["Stream", "impacts_on_patch", "MAX_PACKING"]

#: Largest particle volume fraction of a stream (random close packing of spheres).
MAX_PACKING = 0.64


@dataclass(frozen=True)
class Stream:
    """A particle stream: ``speed`` V (m/s), ``angle`` θ from the plate normal (deg, [0, 85]),
    ``exposure_time`` T (s), ``concentration`` c (kg/m³) or ``mass_flux`` q (kg m⁻² s⁻¹ through a plane
    normal to the stream; q = cV) — exactly one of them — and ``azimuth`` ψ (deg) of the stream's
    tangential direction from the grid x axis."""

    speed: float
    angle: float
    exposure_time: float
    concentration: float | None = None
    mass_flux: float | None = None
    azimuth: float = 0.0

    def __post_init__(self) -> None:
        check_number("speed", self.speed, low=0.0, low_open=True, high=1000.0, units="m/s", what="stream speed")
        check_number("angle", self.angle, low=0.0, high=85.0, units="deg", what="stream angle from the plate normal")
        check_number("exposure_time", self.exposure_time, low=0.0, low_open=True, high=1e10, units="s")
        check_number("azimuth", self.azimuth, low=-360.0, high=360.0, units="deg", what="stream azimuth")
        if (self.concentration is None) == (self.mass_flux is None):
            raise ValueError(
                f"concentration={self.concentration!r}, mass_flux={self.mass_flux!r}: give exactly one of them "
                "(kg/m^3 or kg/(m^2 s))"
            )
        if self.concentration is not None:
            check_number("concentration", self.concentration, low=0.0, low_open=True, units="kg/m^3")
        else:
            check_number("mass_flux", self.mass_flux, low=0.0, low_open=True, units="kg/(m^2 s)")

    @property
    def flux(self) -> float:
        """Mass flux q through a plane normal to the stream (kg m⁻² s⁻¹)."""
        return self.mass_flux if self.mass_flux is not None else self.concentration * self.speed

    @property
    def plate_flux(self) -> float:
        """Particle mass arriving per unit plate area and time, q cos θ (kg m⁻² s⁻¹)."""
        return self.flux * math.cos(math.radians(self.angle))

    def check_packing(self, particle_density: float) -> None:
        """Raise ValueError naming ``concentration`` or ``mass_flux`` if the stream is denser than close-packed
        particles of ``particle_density`` (kg/m³)."""
        c_max = MAX_PACKING * particle_density
        if self.concentration is not None and self.concentration > c_max:
            raise ValueError(
                f"concentration={self.concentration:.6g} is out of range: the particle mass concentration must be "
                f"in (0, {c_max:.6g}] kg/m^3 ({MAX_PACKING} x particle density: close-packed spheres)"
            )
        if self.mass_flux is not None and self.mass_flux > c_max * self.speed:
            raise ValueError(
                f"mass_flux={self.mass_flux:.6g} is out of range: the mass flux must be in "
                f"(0, {c_max * self.speed:.6g}] kg/(m^2 s) (close-packed spheres, {MAX_PACKING} x particle density, "
                f"moving at {self.speed:g} m/s)"
            )


def impacts_on_patch(stream: Stream, particle_mass: float, area: float) -> float:
    """Expected number of particles hitting ``area`` (m²) over the exposure: q cos θ A T / m_p (m_p in kg)."""
    return stream.plate_flux * area * stream.exposure_time / particle_mass
