"""The tables of one impact: the ball (``[ball]``), the plate (``[plate]``) and how they meet (``[impact]``: speed,
angle, friction and the contact models). SI units; angles in degrees from the plate normal; the defaults are those of
``impactwear run`` (:mod:`wear.case.tables`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from contact import Material
from contact.checks import FRICTION_MAX
from contact.impact import SPEED_MAX
from wear.case.choices import NORMAL_MODELS, SCHEMES, TANGENTIAL_MODELS
from wear.case.schema import Table, key

__all__ = ["BallSpec", "PlateSpec", "ImpactSpec"]

_E = dict(low=1e5, high=1e13, allow_inf=True)
_NU = dict(low=0.0, high=0.5, high_open=True)
_DENSITY = dict(low=0.0, low_open=True, high=1e5)
_YIELD = dict(low=1e3, high=1e11, optional=True, inf_is_absent=True, absent="never yields")


class _MaterialTable(Table):
    """A table that describes a material (E, nu, density, yield_strength, name)."""

    def check(self) -> None:
        self.material()

    def material(self) -> Material:
        """The table's :class:`contact.Material` (errors name ``table.key``)."""
        try:
            return Material(self.E, self.nu, self.density, self.yield_strength, self.name)  # type: ignore[attr-defined]
        except ValueError as exc:
            raise ValueError(f"{self.table}.{exc}") from None


@dataclass(frozen=True)
class BallSpec(_MaterialTable):
    """The ball (or particle): ``radius`` (m), ``E`` (Pa; inf = rigid), ``nu``, ``density`` (kg/m³),
    ``yield_strength`` (Pa; None = never yields), ``name`` (a label)."""

    table: ClassVar[str] = "ball"
    radius: float = key(float, 2.5e-3, "ball radius", "m", low=0.0, low_open=True, high=10.0)
    E: float = key(float, 3.8e11, "Young's modulus (inf: rigid)", "Pa", **_E)
    nu: float = key(float, 0.23, "Poisson's ratio", **_NU)
    density: float = key(float, 3950.0, "density", "kg/m^3", **_DENSITY)
    yield_strength: float | None = key(float, None, "yield strength", "Pa", **_YIELD)
    name: str = key(str, "alumina", "label of the ball material")


@dataclass(frozen=True)
class PlateSpec(_MaterialTable):
    """The plate: ``rigid`` (E, nu, density ignored), ``E`` (Pa), ``nu``, ``density`` (kg/m³), ``yield_strength``
    (Pa; None = never yields), ``name`` (a label)."""

    table: ClassVar[str] = "plate"
    rigid: bool = key(bool, False, "rigid plate (E, nu, density ignored)")
    E: float = key(float, 1.14e11, "Young's modulus", "Pa", **_E)
    nu: float = key(float, 0.34, "Poisson's ratio", **_NU)
    density: float = key(float, 4430.0, "density", "kg/m^3", **_DENSITY)
    yield_strength: float | None = key(float, 8.8e8, "yield strength", "Pa", **_YIELD)
    hardness: float | None = key(
        float,
        None,
        "hardness: plastic flow pressure (Finnie) and Vickers hardness (Oka)",
        "Pa",
        low=1e6,
        high=1e11,
        optional=True,
        absent="3 x yield strength",
    )
    name: str = key(str, "Ti-6Al-4V", "label of the plate material")

    def material(self) -> Material:
        """The plate's :class:`contact.Material` (``Material.rigid`` if ``rigid``)."""
        return Material.rigid(name=self.name) if self.rigid else super().material()


@dataclass(frozen=True)
class ImpactSpec(Table):
    """The impact (or the stream's particles): ``speed`` (m/s), ``angle`` (deg from the normal), ``friction`` μ,
    ``restitution`` (Hertz dashpot), ``normal_model`` (the impact model without FE coupling, and the first estimate
    of a coupled run), ``tangential_model``, ``limiting_pressure`` (Pa), ``scheme``, ``time_step`` (s)."""

    table: ClassVar[str] = "impact"
    speed: float = key(float, 3.0, "impact speed", "m/s", low=0.0, low_open=True, high=SPEED_MAX)
    angle: float = key(float, 30.0, "impact angle from the plate normal", "deg", low=0.0, high=90.0, high_open=True)
    friction: float = key(float, 0.3, "Coulomb friction coefficient", low=0.0, high=FRICTION_MAX)
    restitution: float = key(
        float, 1.0, "normal restitution setting the Hertz dashpot", low=0.0, low_open=True, high=1.0
    )
    normal_model: str = key(
        str, "thornton", "normal force law (without FE coupling; else the first estimate)", choices=NORMAL_MODELS
    )
    tangential_model: str = key(str, "hdd", "tangential force law", choices=TANGENTIAL_MODELS)
    limiting_pressure: float | None = key(
        float,
        None,
        "Thornton limiting pressure",
        "Pa",
        low=1e3,
        high=1e12,
        optional=True,
        absent="C(nu)*Y of the body that yields first",
    )
    scheme: str = key(str, "verlet", "time integration scheme", choices=SCHEMES)
    time_step: float | None = key(
        float, None, "time step", "s", low=0.0, low_open=True, optional=True, absent="Hertz contact time / 2000"
    )
