"""What a wear law declares (:class:`Law`), and the constants every law reads the same way: a required ``[wear]``
key (:func:`need`), the plate's flow pressure (:func:`flow_pressure_of`) and the angle from the surface
(:func:`angle_from_surface`). SI units; angles in degrees from the plate normal.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np

from contact import Material
from wear.laws.records import RecordLaw

__all__ = ["Constants", "Law", "angle_from_surface", "flow_pressure_of", "need"]

#: A law's constants: the case's ``[wear]`` keys plus the plate's ``hardness`` (Pa), by name.
Constants = Mapping[str, float | str | None]


@dataclass(frozen=True)
class Law:
    r"""A wear law, declared by its own module of :mod:`wear.laws` and listed in :data:`wear.laws.registry.LAWS`.

    Parameters
    ----------
    name : str
        The value of the case key ``wear.law``.
    description : str
        What it computes, in one line.
    volumes : callable
        Its per-impact form: ``volumes(constants, impact, local=..., plate_work=...)`` → the worn volume (m³) of one
        :class:`contact.ImpactResult` by mechanism (``cutting``, ``deformation``, or the correlation's name);
        ``local`` is the impact's Eq. 15 volume (m³) where the law uses it, ``plate_work`` the FE plate's plastic
        dissipation (J) if the plate is the FE.
    constants : tuple of str
        Its constants: the ``[wear]`` keys a calibration may fit (their ranges are the case schema's,
        :class:`wear.case.model_tables.WearSpec`).
    inputs : tuple of str
        The other ``[wear]`` keys it reads (the local law's pressure source, sliding speed and grid).
    scale : str or None
        The constant a calibration fits when none is named; the worn volume is proportional to
        :math:`\mathrm{scale}^{q}`, ``q`` = ``scale_power``.
    log_constants : tuple of str
        The constants fitted in log coordinates (positive scales); the others (exponents) as they are.
    closed_form : callable or None
        Where the law is a formula of the particle's kinematics and the plate:
        ``closed_form(constants, radius, ball_density, plate, speed, angle)`` → the worn volume (m³) of one impact of a
        ball of ``radius`` (m) and ``ball_density`` (kg/m³) on the :class:`contact.Material` ``plate`` at each
        ``speed`` (m/s) and ``angle`` (deg); no impact need be simulated.
    per_record : callable or None
        With a closed form: ``per_record(constants, plate)`` → its law per impact record of a wall (an object with
        ``name``, ``description`` and ``volume(angle_deg, speed_m_s, diameter_m, density_kg_m3, count)``, m³).
    absent_values : callable or None
        ``absent_values(constants, plate)`` → the values its optional constants take when absent (a calibration
        starts from them).
    plate_keys : tuple of str
        The ``[plate]`` keys its per-record form reads, the density always (a wall's eroded mass is ρ V; a wall
        refuses the others).
    parts : callable or None
        A law made of others: ``parts(constants)`` → those laws (the combined law's cutting law and deformation).
    uses_local : bool
        Whether it reads the Eq. 15 volume of the impact's pressure history.
    uses_work : bool
        Whether it reads the impact's plastic work.
    """

    name: str
    description: str
    volumes: Callable[..., dict[str, float]]
    constants: tuple[str, ...] = ()
    inputs: tuple[str, ...] = ()
    scale: str | None = None
    scale_power: float = 1.0
    log_constants: tuple[str, ...] = ()
    closed_form: Callable[..., np.ndarray] | None = None
    per_record: Callable[[Constants, Material], RecordLaw] | None = None
    absent_values: Callable[[Constants, Material], dict[str, float]] | None = None
    plate_keys: tuple[str, ...] = ()
    parts: Callable[[Constants], tuple[Law, ...]] | None = None
    uses_local: bool = False
    uses_work: bool = False


def need(constants: Constants, law: str, *names: str) -> list[float]:
    """The ``constants`` ``names`` of the ``law`` (by name), or a one-line ``ValueError`` naming the first absent."""
    values = []
    for name in names:
        value = constants.get(name)
        if value is None:
            raise ValueError(f"wear.{name}=None: the {law} law needs it (see impactwear run --print-default)")
        values.append(value)
    return values


def flow_pressure_of(constants: Constants, plate: Material) -> float:
    """The plate's plastic flow pressure (Pa): ``hardness`` if given, else 3 × its yield strength (the indentation
    hardness of a rigid–perfectly plastic metal, Tabor 1951)."""
    hardness = constants.get("hardness")
    if hardness is not None:
        return float(hardness)
    if plate.yield_strength is None:
        raise ValueError("plate.hardness=None: give the plate's hardness (Pa), or a yield strength (3 Y is used)")
    return 3.0 * plate.yield_strength


def angle_from_surface(angle) -> np.ndarray:
    """Impact angle α (rad) from the surface, from θ (deg) from the normal."""
    return np.radians(90.0 - np.asarray(angle, dtype=float))
