r"""Least squares on log residuals with confidence intervals and a plain statement of what the data cannot determine.

The model predicts positive quantities y_i(θ); the fit minimises Σ (ln y_i(θ) − ln m_i)² over the free constants θ,
each in its own coordinate: the logarithm for a positive scale constant (a wear coefficient, ε), the value itself
for an exponent. At the optimum, with J the Jacobian of the residuals in those coordinates, n rows and p constants,

.. math:: s^2 = \frac{\sum r_i^2}{n - p}, \qquad C = s^2 (J^T J)^{-1}, \qquad
          \theta_k \pm t_{0.975,\,n-p}\sqrt{C_{kk}}

(an interval in log coordinates is mapped back: multiplicative), clipped to the constant's valid range. A direction
along which the residuals do not change (a singular value of J below 1e-7 of the largest: e.g. a speed exponent
fitted to a single speed, where it trades off exactly against the scale constant) has no interval: the constants that
move along it are reported as not determined by the data, instead of a number. Two constants whose correlation
:math:`\rho` exceeds 0.999 in magnitude are reported as nearly interchangeable: each interval is
:math:`1/\sqrt{1 - \rho^2}` times as wide as with the other held (e.g. Eq. 15's K and α, where the pressure varies
little between rows next to its size). A constant the fit leaves on a bound of its valid range is reported so.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.optimize import least_squares
from scipy.stats import t as student_t

__all__ = ["Constant", "LogFit", "log_fit"]

#: A singular value of the Jacobian below this × the largest is a direction the data do not determine.
SINGULAR = 1e-7
#: A constant whose component in such a direction exceeds this is not determined.
LOADING = 0.05
#: Two determined constants correlated beyond this (in magnitude) are nearly interchangeable.
INTERCHANGEABLE = 0.999


@dataclass(frozen=True)
class Constant:
    """A free constant: ``name``, its ``start`` value, whether it is fitted in ``log`` coordinates (a positive scale
    constant) or as is (an exponent), and its bounds ``low``/``high`` (None: unbounded)."""

    name: str
    start: float
    log: bool
    low: float | None = None
    high: float | None = None

    def to_coordinate(self, value: float) -> float:
        return math.log(value) if self.log else value

    def from_coordinate(self, x: float) -> float:
        return math.exp(x) if self.log else x

    def bounds(self) -> tuple[float, float]:
        def coordinate(v: float | None, inf: float) -> float:
            if v is None or (self.log and v <= 0.0):
                return inf
            return self.to_coordinate(v)

        return coordinate(self.low, -math.inf), coordinate(self.high, math.inf)


@dataclass(frozen=True)
class LogFit:
    """A log least-squares fit: ``names``, ``values`` (the fitted constants), ``intervals`` (95% (low, high), or None
    where not determined or without residual degrees of freedom), ``determined`` (per constant), ``statements`` (plain
    sentences on what the data cannot determine), ``residuals`` (ln predicted − ln measured per fitted row),
    ``rms_log_error``, ``correlations`` (p × p, NaN where undefined), ``dof`` (n − p), ``evaluations``,
    ``on_bound`` (per constant: "low" or "high" where the fit sits on that bound of its valid range, else None)."""

    names: tuple[str, ...]
    values: tuple[float, ...]
    intervals: tuple[tuple[float, float] | None, ...]
    determined: tuple[bool, ...]
    statements: tuple[str, ...]
    residuals: np.ndarray
    rms_log_error: float
    correlations: np.ndarray
    dof: int
    evaluations: int
    on_bound: tuple[str | None, ...]

    def as_dict(self) -> dict[str, float]:
        return dict(zip(self.names, self.values, strict=True))


def log_fit(
    predict: Callable[[dict[str, float]], np.ndarray], measured: np.ndarray, constants: list[Constant]
) -> LogFit:
    """Fit ``constants`` so that ``predict(values)`` (positive, one per measured row) matches ``measured``
    (positive) in the log (see the module docstring)."""
    measured = np.asarray(measured, float)
    log_measured = np.log(measured)
    evaluations = [0]

    def values_of(x: np.ndarray) -> dict[str, float]:
        return {c.name: c.from_coordinate(float(v)) for c, v in zip(constants, x, strict=True)}

    def residuals(x: np.ndarray) -> np.ndarray:
        evaluations[0] += 1
        pred = np.asarray(predict(values_of(x)), float)
        return np.log(np.maximum(pred, 1e-300)) - log_measured

    x0, low, high = _start_inside_bounds(constants)
    solution = least_squares(
        residuals, x0, bounds=(low, high), method="trf", xtol=1e-12, ftol=1e-12, gtol=1e-12, max_nfev=2000
    )
    r = solution.fun
    n, p = r.size, len(constants)
    dof = n - p
    _, sv, vt = np.linalg.svd(np.asarray(solution.jac, float), full_matrices=False)
    determined, statements = _undetermined(constants, sv, vt)
    s2 = float(r @ r / dof) if dof > 0 else math.nan
    if dof <= 0:
        statements.append(
            f"{n} row{'' if n == 1 else 's'} for {p} constants: no residual degree of freedom, no interval"
        )
    inv_sv = np.where(sv > SINGULAR * max(sv[0], 1e-300), 1.0 / np.maximum(sv, 1e-300), 0.0)
    # the correlations do not depend on s², so they are given without residual degrees of freedom too
    shape = (vt.T * inv_sv**2) @ vt
    intervals = _intervals(constants, solution.x, shape * s2, s2, dof, determined, low, high)
    corr = _correlations(shape, determined)
    statements += _interchangeable(constants, corr)
    on_bound = [_on_bound(x, lo, hi) for x, lo, hi in zip(solution.x, low, high, strict=True)]
    statements += _on_bound_statements(constants, solution.x, on_bound)
    return LogFit(
        names=tuple(c.name for c in constants),
        values=tuple(c.from_coordinate(float(v)) for c, v in zip(constants, solution.x, strict=True)),
        intervals=tuple(intervals),
        determined=tuple(determined),
        statements=tuple(statements),
        residuals=r,
        rms_log_error=float(np.sqrt(np.mean(r**2))) if n else math.nan,
        correlations=corr,
        dof=dof,
        evaluations=evaluations[0],
        on_bound=tuple(on_bound),
    )


def _start_inside_bounds(constants: list[Constant]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The start (in the constants' coordinates) and the lower and upper bounds (±inf where unbounded); the start
    is moved just inside a finite bound, where least_squares requires it to be."""
    x0 = np.array([c.to_coordinate(c.start) for c in constants])
    low, high = (np.array(b) for b in zip(*(c.bounds() for c in constants), strict=True))
    inside = 1e-9 * (1.0 + np.abs(np.where(np.isfinite(low), low, 0.0)))
    x0 = np.clip(x0, np.where(np.isfinite(low), low + inside, low), np.where(np.isfinite(high), high - inside, high))
    return x0, low, high


def _undetermined(constants: list[Constant], sv: np.ndarray, vt: np.ndarray) -> tuple[list[bool], list[str]]:
    """Per constant, whether the data determine it, and a statement per direction they do not: the right singular
    vectors ``vt`` of the Jacobian whose singular values ``sv`` are below :data:`SINGULAR` × the largest (or that
    it lacks, with fewer rows than constants)."""
    p = len(constants)
    null = [vt[k] for k in range(len(sv)) if sv[k] <= SINGULAR * max(sv[0], 1e-300)]
    null += [vt[k] for k in range(len(sv), p)] if len(sv) < p else []
    determined = [all(abs(v[k]) <= LOADING for v in null) for k in range(p)]
    statements = []
    for v in null:
        names = [constants[k].name for k in range(p) if abs(v[k]) > LOADING]
        statements.append(
            f"the data cannot determine {' and '.join(names)} separately: the residuals do not change "
            f"along a combination of them (e.g. a speed exponent from a single speed)"
        )
    return determined, statements


def _intervals(
    constants: list[Constant],
    x: np.ndarray,
    cov: np.ndarray,
    s2: float,
    dof: int,
    determined: list[bool],
    low: np.ndarray,
    high: np.ndarray,
) -> list[tuple[float, float] | None]:
    """The 95% interval of each constant in its own units (None where not determined or without residual degrees
    of freedom): Student's t on the coordinates ``x`` with covariance ``cov``, clipped to the bounds."""
    intervals: list[tuple[float, float] | None] = []
    quantile = float(student_t.ppf(0.975, dof)) if dof > 0 else math.nan
    for k, c in enumerate(constants):
        if not determined[k] or not math.isfinite(s2):
            intervals.append(None)
            continue
        half = quantile * math.sqrt(max(cov[k, k], 0.0))
        lo, hi = (c.from_coordinate(float(v)) for v in np.clip([x[k] - half, x[k] + half], low[k], high[k]))
        # once more in the constant's own units: exp(ln b) may differ from the bound b by a rounding
        bottom, top = -math.inf if c.low is None else c.low, math.inf if c.high is None else c.high
        intervals.append((min(max(lo, bottom), top), min(max(hi, bottom), top)))
    return intervals


def _correlations(shape: np.ndarray, determined: list[bool]) -> np.ndarray:
    """The correlation matrix of the covariance ``shape`` (up to s²), NaN where undefined or for a constant that is
    not determined."""
    sd = np.sqrt(np.maximum(np.diag(shape), 0.0))
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = shape / np.outer(sd, sd)
    corr[~np.isfinite(corr)] = math.nan
    for k in range(len(determined)):
        if not determined[k]:
            corr[k, :] = corr[:, k] = math.nan
    return corr


def _interchangeable(constants: list[Constant], corr: np.ndarray) -> list[str]:
    """A statement per pair of constants correlated beyond :data:`INTERCHANGEABLE`, with how much wider that makes
    each interval."""
    statements = []
    p = len(constants)
    for j in range(p):
        for k in range(j + 1, p):
            rho = float(corr[j, k])
            if abs(rho) > INTERCHANGEABLE:
                statements.append(
                    f"the data hardly tell {constants[j].name} and {constants[k].name} apart: they are nearly "
                    f"interchangeable (correlation {'-' if rho < 0 else '+'}(1 - {1.0 - abs(rho):.2g})), so each "
                    "interval is "
                    f"{1.0 / math.sqrt(max(1.0 - rho * rho, 1e-300)):.3g} times as wide as with the other held; "
                    "fix one of them to determine the other"
                )
    return statements


def _on_bound_statements(constants: list[Constant], x: np.ndarray, on_bound: list[str | None]) -> list[str]:
    """A statement per constant the fit leaves on a bound of its valid range (``on_bound``: "low", "high" or None
    per constant, at the coordinates ``x``)."""
    statements = []
    for c, v, side in zip(constants, x, on_bound, strict=True):
        if side is not None:
            valid = f"[{c.low if c.low is not None else '-inf'}, {c.high if c.high is not None else 'inf'}]"
            statements.append(
                f"{c.name} = {c.from_coordinate(float(v)):.6g} sits on the {'lower' if side == 'low' else 'upper'} "
                f"bound of its valid range {valid}: the data pull it further; its interval is cut there"
            )
    return statements


def _on_bound(x: float, low: float, high: float) -> str | None:
    """The bound ("low" or "high") the coordinate ``x`` is on (within 1e-6), else None."""
    for side, bound in (("low", low), ("high", high)):
        if math.isfinite(bound) and abs(x - bound) <= 1e-6 * (1.0 + abs(bound)):
            return side
    return None
