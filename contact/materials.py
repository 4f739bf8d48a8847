"""Materials of the ball and the plate, and their effective contact moduli.

All quantities are SI: moduli and strengths in Pa, density in kg/m³.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from contact.checks import check_number

__all__ = ["Material", "effective_modulus", "effective_shear_modulus"]

#: Accepted range of Young's modulus (Pa). Soft polymers are ~1e6 Pa, diamond ~1.2e12 Pa; a value
#: below 1e5 is almost always a modulus given in GPa or MPa by mistake.
E_RANGE = (1e5, 1e13)


@dataclass(frozen=True)
class Material:
    """An isotropic material.

    Parameters
    ----------
    E : float
        Young's modulus (Pa), in [1e5, 1e13], or ``math.inf`` for a rigid body.
    nu : float
        Poisson's ratio (dimensionless), 0 <= ν < 0.5.
    density : float
        Mass density (kg/m³), > 0 (``math.inf`` allowed only for a rigid body).
    yield_strength : float or None
        Uniaxial yield strength Y (Pa), > 0; ``None`` means the material never yields.
    name : str
        Free label used in reports.
    """

    E: float
    nu: float
    density: float
    yield_strength: float | None = None
    name: str = ""

    def __post_init__(self) -> None:
        E = check_number(
            "E",
            self.E,
            low=E_RANGE[0],
            high=E_RANGE[1],
            units="Pa",
            what="Young's modulus",
            allow_inf=True,
            hint="give Pa, not GPa: steel is 210e9",
        )
        nu = check_number("nu", self.nu, low=0.0, high=0.5, high_open=True, what="Poisson's ratio")
        density = check_number(
            "density",
            self.density,
            low=0.0,
            low_open=True,
            high=1e5,
            units="kg/m^3",
            what="density",
            allow_inf=math.isinf(E),
        )
        object.__setattr__(self, "E", E)
        object.__setattr__(self, "nu", nu)
        object.__setattr__(self, "density", density)
        if self.yield_strength is not None:
            Y = check_number(
                "yield_strength",
                self.yield_strength,
                low=1e3,
                high=1e11,
                units="Pa",
                what="yield strength",
                hint="give Pa, not MPa: mild steel is 250e6",
            )
            object.__setattr__(self, "yield_strength", Y)
        if not isinstance(self.name, str):
            raise ValueError(f"name={self.name!r} is not a string")

    @classmethod
    def rigid(cls, name: str = "rigid") -> Material:
        """A rigid, non-yielding body (E = ∞, density = ∞)."""
        return cls(E=math.inf, nu=0.0, density=math.inf, yield_strength=None, name=name)

    @property
    def is_rigid(self) -> bool:
        return math.isinf(self.E)

    @property
    def shear_modulus(self) -> float:
        """G = E / (2(1 + ν)) (Pa)."""
        return self.E / (2.0 * (1.0 + self.nu))


def effective_modulus(ball: Material, plate: Material) -> float:
    r"""Effective contact modulus (Pa), errata equation 5.

    .. math:: \frac{1}{E^*} = \frac{1-\nu_1^2}{E_1} + \frac{1-\nu_2^2}{E_2}

    A rigid body contributes nothing; two rigid bodies are rejected.
    """
    compliance = sum((1.0 - m.nu**2) / m.E for m in (ball, plate) if not m.is_rigid)
    if compliance == 0.0:
        raise ValueError("ball and plate are both rigid: at least one must have a finite E (Pa)")
    return 1.0 / compliance


def effective_shear_modulus(ball: Material, plate: Material) -> float:
    r"""Effective tangential contact modulus (Pa), errata equation 9.

    .. math:: \frac{1}{G^*} = \frac{2-\nu_1}{G_1} + \frac{2-\nu_2}{G_2}, \quad G = \frac{E}{2(1+\nu)}
    """
    compliance = sum((2.0 - m.nu) / m.shear_modulus for m in (ball, plate) if not m.is_rigid)
    if compliance == 0.0:
        raise ValueError("ball and plate are both rigid: at least one must have a finite E (Pa)")
    return 1.0 / compliance
