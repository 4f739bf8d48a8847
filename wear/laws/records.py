"""The impact records of a wall as a law takes them (:class:`RecordLaw`): one array per field (:func:`record_arrays`)
and the mass each particle delivers (:func:`particle_mass`). SI units; angles in degrees from the wall normal.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np

from contact.theory import sphere_mass

__all__ = ["FIELDS", "RecordLaw", "particle_mass", "record_arrays"]

#: The per-record arrays of a law's ``volume``, in order.
FIELDS = ("angle_deg", "speed_m_s", "diameter_m", "density_kg_m3", "count")


def particle_mass(diameter, density) -> np.ndarray:
    """Mass (kg) of a spherical particle of ``diameter`` (m) and ``density`` (kg/m³), ρ_p π d³ / 6."""
    return sphere_mass(0.5 * np.asarray(diameter, float), np.asarray(density, float))


def record_arrays(angle, speed, diameter, density, count) -> tuple[np.ndarray, ...]:
    """The five per-record arrays as float arrays of one length, or a one-line ``ValueError``."""
    arrays = [np.asarray(a, float).reshape(-1) for a in (angle, speed, diameter, density, count)]
    sizes = {a.size for a in arrays}
    if len(sizes) > 1:
        lengths = ", ".join(f"{n}={a.size}" for n, a in zip(FIELDS, arrays, strict=True))
        raise ValueError(f"the per-record arrays differ in length: {lengths}")
    theta = arrays[0]
    if theta.size and not (theta.min() >= 0.0 and theta.max() <= 90.0):
        i = int(np.flatnonzero(~((theta >= 0.0) & (theta <= 90.0)))[0])
        raise ValueError(f"angle_deg[{i}]={theta[i]:.6g} is out of range: an impact angle is in [0, 90] deg")
    return tuple(arrays)


class RecordLaw(Protocol):
    """A wear law per impact record of a wall: its ``name`` (``wear.law``), a one-line ``description`` and
    :meth:`volume`."""

    name: str
    description: str

    def volume(self, angle_deg, speed_m_s, diameter_m, density_kg_m3, count) -> np.ndarray:
        """Eroded volume (m³) of each record of ``count`` particles of ``diameter_m`` (m) and ``density_kg_m3``
        (kg/m³) at ``speed_m_s`` (m/s) and ``angle_deg`` (deg from the wall normal)."""
        ...
