r"""The local wear law (errata equation 15) and the units of its coefficient.

.. math:: \frac{dw}{dt} = K\,p^{\alpha}\,v^{\beta}

at each plate point in contact: ``w`` is a wear **depth** (m), ``p`` the local contact pressure (Pa),
``v`` the local sliding speed (m/s). The unit of ``K`` therefore depends on the exponents:

.. math:: [K] = \mathrm{m}^{1-\beta}\,\mathrm{s}^{\beta-1}\,\mathrm{Pa}^{-\alpha}

(e.g. m s⁻¹ Pa⁻¹ for α = 1, β = 0; the paper's fit α = 1, β = 0.3 has K in m^0.7 s^-0.7 Pa^-1, with
K between 1e-13 and 1e-10 for steel). No unit conversion is hidden: give K in exactly this SI unit.
If you also pass the unit you mean as ``K_units`` it is parsed and checked against α and β.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from contact.checks import check_number

__all__ = ["WearLaw", "wear_coefficient_units", "parse_units"]

#: Exponent ranges accepted for α (pressure) and β (speed); wear laws in the literature use 0-3.
EXPONENT_RANGE = (0.0, 4.0)

_TOKEN = re.compile(r"^(m|s|Pa)(?:\^\(?([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\)?)?$")


def _fmt_exponent(x: float) -> str:
    return f"{x:.6g}"


def wear_coefficient_units(alpha: float, beta: float) -> str:
    """The SI unit of K for exponents ``alpha`` and ``beta``, e.g. ``"m^(0.7) s^(-0.7) Pa^(-1)"``."""
    return f"m^({_fmt_exponent(1.0 - beta)}) s^({_fmt_exponent(beta - 1.0)}) Pa^({_fmt_exponent(-alpha)})"


def parse_units(text: str) -> dict[str, float]:
    """Exponents of m, s and Pa in a unit string such as ``"m^(0.7) s^(-0.7) Pa^(-1)"`` or ``"m/(Pa s)"``-free
    forms written as space- or ``*``-separated powers (``"m s^-1 Pa^-1"``). Raises ``ValueError`` if unparsable."""
    if not isinstance(text, str):
        raise ValueError(f"K_units={text!r} is not a string: give e.g. {wear_coefficient_units(1.0, 0.0)!r}")
    exps = {"m": 0.0, "s": 0.0, "Pa": 0.0}
    tokens = [t for t in re.split(r"[\s*·]+", text.strip()) if t]
    if not tokens:
        raise ValueError(f"K_units={text!r} is empty: give e.g. {wear_coefficient_units(1.0, 0.0)!r}")
    for tok in tokens:
        match = _TOKEN.match(tok)
        if match is None:
            raise ValueError(
                f"K_units={text!r} cannot be read at {tok!r}: write powers of m, s and Pa, "
                f"e.g. {wear_coefficient_units(1.0, 0.0)!r}"
            )
        exps[match.group(1)] += float(match.group(2)) if match.group(2) is not None else 1.0
    return exps


@dataclass(frozen=True)
class WearLaw:
    r"""Wear law dw/dt = K p^α v^β (errata equation 15); ``w`` is a depth in m.

    Parameters
    ----------
    K : float
        Wear coefficient, ≥ 0, in m^(1−β) s^(β−1) Pa^(−α) (see :func:`wear_coefficient_units`).
    alpha : float
        Pressure exponent α in [0, 4] (dimensionless).
    beta : float
        Sliding-speed exponent β in [0, 4] (dimensionless). With β > 0 a point that does not slide
        does not wear; with β = 0 the speed does not enter (0⁰ = 1).
    K_units : str or None
        Optional statement of the unit you gave K in; if given it must equal m^(1−β) s^(β−1) Pa^(−α).

    >>> law = WearLaw(K=1e-12, alpha=1.0, beta=0.3)
    >>> f"{law.rate(pressure=1e9, speed=2.0):.4e}"  # 1e-12 · 1e9 · 2^0.3 m/s
    '1.2311e-03'
    """

    K: float
    alpha: float = 1.0
    beta: float = 0.0
    K_units: str | None = None

    def __post_init__(self) -> None:
        alpha = check_number(
            "alpha", self.alpha, low=EXPONENT_RANGE[0], high=EXPONENT_RANGE[1], what="pressure exponent"
        )
        beta = check_number("beta", self.beta, low=EXPONENT_RANGE[0], high=EXPONENT_RANGE[1], what="speed exponent")
        units = wear_coefficient_units(alpha, beta)
        K = check_number("K", self.K, low=0.0, units=units, what="wear coefficient")
        object.__setattr__(self, "alpha", alpha)
        object.__setattr__(self, "beta", beta)
        object.__setattr__(self, "K", K)
        if self.K_units is not None:
            got = parse_units(self.K_units)
            want = {"m": 1.0 - beta, "s": beta - 1.0, "Pa": -alpha}
            if any(not math.isclose(got[k], want[k], abs_tol=1e-9) for k in want):
                raise ValueError(
                    f"K_units={self.K_units!r} does not match alpha={alpha:g}, beta={beta:g}: "
                    f"K must be given in {units} (errata Eq. 15 with w a depth in m)"
                )

    @property
    def units(self) -> str:
        """SI unit of :attr:`K` for this α and β."""
        return wear_coefficient_units(self.alpha, self.beta)

    def rate(self, pressure, speed):
        """Wear depth rate dw/dt (m/s) at ``pressure`` (Pa, clipped at 0) and sliding ``speed`` (m/s, sign ignored)."""
        p = np.maximum(np.asarray(pressure, dtype=float), 0.0)
        v = np.abs(np.asarray(speed, dtype=float))
        return self.K * p**self.alpha * v**self.beta

    def __str__(self) -> str:
        return f"dw/dt = {self.K:.4g} {self.units} × p^{self.alpha:g} v^{self.beta:g}"
