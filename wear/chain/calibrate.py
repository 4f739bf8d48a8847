"""Calibration of a wear law's constants to measured wear: the forward model (:mod:`wear.chain.forward_model`:
batched impacts and the law of :mod:`wear.laws.impact`) fitted by least squares on log residuals (:mod:`wear.chain.fit`)
to the data (:mod:`wear.chain.calibration_data`). SI units; angles in degrees from the plate normal.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from functools import cached_property

import numpy as np
from scipy.optimize import nnls

from wear.case import TABLES, Case, check_job_case
from wear.case.check import fem_keys_read
from wear.chain.calibration_data import CalibrationData
from wear.chain.fit import Constant, LogFit, log_fit
from wear.chain.forward_model import ForwardModel, check_rows, fe_coupled
from wear.chain.plate import wear_constants
from wear.laws.registry import LAWS, parts_of, wear_keys

__all__ = ["CalibrationResult", "calibrate", "check_data_keys", "law_constants"]


def _log_constants() -> set[str]:
    """The constants fitted in log coordinates (positive scales) of every law; the others (exponents) as they are."""
    return {name for law in LAWS.values() for name in law.log_constants}


def _scale_powers() -> dict[str, float]:
    """How each law's scale enters it: the worn volume of its part is proportional to scale ** power."""
    return {law.scale: law.scale_power for law in LAWS.values() if law.scale is not None}


def law_constants(case: Case) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """(the constants of the case's wear law a calibration may fit, those it fits when none is named: the scale of
    each law it adds up, :func:`wear.laws.registry.parts_of`)."""
    parts = parts_of(case.wear.law, case.wear.values())
    constants = tuple(name for part in parts for name in part.constants)
    return constants, tuple(part.scale for part in parts if part.scale is not None)


@dataclass(frozen=True, eq=False)
class CalibrationResult:
    """A calibration: ``case`` (the case with the fitted constants), ``data``, ``fit`` (:class:`LogFit`: values,
    intervals, statements), ``start`` (the constants before the fit), ``predicted`` (every row, the measured
    quantity), ``left_out`` (measured rows the law predicts no wear at, left out of the fit), ``seconds`` (impacts
    and fit), ``evaluations_per_s`` (forward-model evaluations of all rows per second)."""

    case: Case
    data: CalibrationData
    fit: LogFit
    start: dict[str, float]
    predicted: np.ndarray
    left_out: tuple[int, ...]
    seconds: dict[str, float]
    evaluations_per_s: float

    @cached_property  # computed once: a writer reading it row by row made 40,000 rows take a minute
    def log_residual(self) -> np.ndarray:
        """ln predicted − ln measured per row (NaN where not measured or nothing is predicted)."""
        with np.errstate(divide="ignore", invalid="ignore"):
            r = np.log(self.predicted) - np.log(self.data.measured)
        return np.where(np.isfinite(r), r, np.nan)

    def summary(self) -> dict:
        """The numbers of calibration.json (SI units)."""
        f = self.fit
        constants = {}
        for k, name in enumerate(f.names):
            interval = f.intervals[k]
            constants[name] = {
                "value": f.values[k],
                "start": self.start[name],
                "interval_95": None if interval is None else list(interval),
                "determined": f.determined[k],
                "on_bound": f.on_bound[k],
                "units": TABLES["wear"].keys()[name].units,
            }
        law = self.case.wear.law
        return {
            "law": law,
            "cutting": self.case.wear.cutting if "cutting" in wear_keys(law, self.case.wear.values()) else None,
            "quantity": self.data.quantity,
            "data": self.data.source,
            "rows": int(self.data.angle.size),
            "fitted_rows": int(self.data.fitted.sum()) - len(self.left_out),
            "constants": constants,
            "statements": list(f.statements)
            + [
                f"row {i + 1} (angle {self.data.angle[i]:g} deg, speed "
                f"{self.data.speed[i]:g} m/s): the law predicts no wear there; "
                "left out of the fit"
                for i in self.left_out
            ],
            "rms_log_error": f.rms_log_error,
            "residual_degrees_of_freedom": f.dof,
            "correlations": {"names": list(f.names), "matrix": f.correlations.tolist()},
            "evaluations": f.evaluations,
            "evaluations_per_s": self.evaluations_per_s,
            "seconds": dict(self.seconds),
        }


def check_data_keys(case: Case, data: CalibrationData, free: tuple[str, ...]) -> None:
    """A one-line ``ValueError`` naming a per-row case-key column of ``data`` that a calibration of ``case`` fitting
    ``free`` would not read: a table other than ``[ball]``, ``[plate]``, ``[impact]``, ``[wear]`` and (with the FE
    plate coupled) ``[fem]``; ``impact.speed`` or ``impact.angle`` (a row's ``speed_m_s`` and ``angle_deg``); a wear
    key the law does not read, or a free constant (one value for all rows)."""
    law_keys, _ = law_constants(case)
    for dotted in data.keys:
        table, _, name = dotted.partition(".")
        why = ""
        if table == "impact" and name in ("speed", "angle"):
            why = f"a row's {name} is its {'speed_m_s' if name == 'speed' else 'angle_deg'} column"
        elif table == "wear" and name in free:
            why = f"{name} is a free constant: the fit gives it one value for all rows"
        elif table == "wear" and name not in law_keys:
            why = f"wear.law={case.wear.law!r} does not read it (it reads {', '.join(law_keys)})"
        elif table == "fem" and not fe_coupled(case):
            why = "this calibration computes no FE plate (fem.coupling='two-way' and a law that uses the FE do)"
        elif table == "fem" and name not in fem_keys_read(case, "calibrate")[0]:
            why = fem_keys_read(case, "calibrate")[1].format(job="calibrate")
        elif table not in ("ball", "plate", "impact", "wear", "fem"):
            why = f"impactwear calibrate does not read [{table}] per row"
        if why:
            raise ValueError(f"column {dotted!r} of data={data.source!r} is a case key calibrate does not read: {why}")


def _constant(name: str, start: float) -> Constant:
    spec = TABLES["wear"].keys()[name]
    return Constant(name, start, name in _log_constants(), spec.low, spec.high)


def _absent_value(case: Case, constants: dict, name: str) -> float | None:
    """The value the case's law takes for its constant ``name`` absent from ``constants`` (Oka's E90 and k2 from the
    plate's hardness), or None."""
    for part in parts_of(case.wear.law, constants):
        if part.absent_values is not None and name in part.constants:
            return part.absent_values(constants, case.plate.material()).get(name)
    return None


def _start(case: Case, model: ForwardModel, rows: np.ndarray, free: tuple[str, ...]) -> dict[str, float]:
    r"""The start of the fit: the case's values of the free exponents (Oka's E90 and k2 from the hardness where not
    given, :attr:`wear.laws.declaration.Law.absent_values`) and free scales from the data. The prediction is linear in
    :math:`u_j = s_j^{q_j}` of each free scale :math:`s_j` (:attr:`wear.laws.declaration.Law.scale_power`): :math:`y_i =
    y^0_i + \sum_j c_j t_{ij}`, with :math:`t_{ij}` the part of row i that :math:`u_j` multiplies (found by doubling it)
    and :math:`y^0_i` the rest; the :math:`c_j \ge 0` minimising :math:`\sum_i ((y^0_i + \sum_j c_j t_{ij}) / m_i -
    1)^2` (non-negative least squares on relative errors) scale each :math:`u_j`. A part the data do not need starts at
    1% of the data."""
    base = wear_constants(case)
    powers = _scale_powers()
    start = {}
    for name in free:
        value = base[name]
        if value is None:
            value = _absent_value(case, base, name)
        if value is None and name not in powers:
            raise ValueError(f"wear.{name}=None: give a starting value for the free constant {name}")
        # a scale without a value (Bitter's ε) starts anywhere positive: it is rescaled by the data just below
        start[name] = 1.0 if value is None else float(value)
    scales = [name for name in free if name in powers]
    if not scales:
        return start
    measured = model.data.measured[rows]
    at = model.predict(start)[rows]
    parts = []
    for name in scales:
        doubled = {**start, name: start[name] * 2.0 ** (1.0 / powers[name])}
        parts.append(model.predict(doubled)[rows] - at)
    parts_m = np.array(parts).T
    rest = at - parts_m.sum(axis=1)
    total = parts_m.sum(axis=1)
    useful = total > 1e-12 * total.max(initial=0.0)
    if not useful.any():
        return start
    scale, _ = nnls(parts_m[useful] / measured[useful, None], 1.0 - rest[useful] / measured[useful])
    for j, name in enumerate(scales):
        own = parts_m[useful, j] > 0.0
        if not own.any():
            continue
        floor = 0.01 * float(np.exp(np.mean(np.log(measured[useful][own] / parts_m[useful, j][own]))))
        start[name] *= max(float(scale[j]), floor) ** (1.0 / powers[name])
    return start


def calibrate(case: Case, data: CalibrationData, free: tuple[str, ...] | None = None) -> CalibrationResult:
    """Fit the constants ``free`` (default: the law's scale; :func:`law_constants`) of the case's wear law to
    ``data`` (see the module docstring); the other constants stay as in the case.

    Examples
    --------
    Erosion ratios made with DNV-RP-O501's closed form E = K U^n F(α), F(α) = 0.6 (sin α + 7.2 (sin α − sin²α))^0.6
    (1 − e^(−20α)), α from the surface (DNV 2015), with K = 5e-9 and n = 2.4 (the case's law starts from n = 2.6):
    fitting K and n recovers them (a closed-form law runs no impact, so this takes milliseconds):

    >>> import math
    >>> import numpy as np
    >>> from wear.case import default_case
    >>> from wear.chain.calibration_data import CalibrationData
    >>> def dnv(speed, theta, K=5e-9, n=2.4):
    ...     a = math.radians(90.0 - theta)
    ...     return K * speed**n * 0.6 * (math.sin(a) + 7.2 * (math.sin(a) - math.sin(a) ** 2)) ** 0.6 * (
    ...         1.0 - math.exp(-20.0 * a))
    >>> angle, speed = np.array([30.0, 60.0, 30.0, 60.0]), np.array([20.0, 20.0, 40.0, 40.0])  # deg, m/s
    >>> measured = np.array([dnv(v, a) for a, v in zip(angle, speed)])  # kg/kg
    >>> data = CalibrationData(angle, speed, "erosion_kg_per_kg", measured, keys={})
    >>> result = calibrate(default_case("calibrate").with_(wear={"law": "dnv"}), data, ("dnv_K", "dnv_n"))
    >>> [round(value / expected, 6) for value, expected in zip(result.fit.values, (5e-9, 2.4))]
    [1.0, 1.0]
    >>> round(result.case.wear.dnv_n, 6)
    2.4
    """
    check_job_case(case, "calibrate")
    allowed, default = law_constants(case)
    free = tuple(default if not free else free)
    for name in free:
        if name not in allowed:
            raise ValueError(
                f"--free {name!r} is not a constant of wear.law={case.wear.law!r}: its constants are "
                f"{', '.join(allowed)}"
            )
    if len(set(free)) != len(free):
        raise ValueError(f"--free {','.join(free)} names a constant twice")
    n_fit = int(data.fitted.sum())
    if n_fit < len(free):
        raise ValueError(
            f"data has {n_fit} measured rows for {len(free)} free constants ({', '.join(free)}): give "
            "at least as many rows as constants"
        )
    check_data_keys(case, data, free)
    check_rows(data, case)
    t0 = time.perf_counter()
    model = ForwardModel(case, data)
    t1 = time.perf_counter()
    fitted = np.flatnonzero(data.fitted)
    start = _start(case, model, fitted, free)
    at_start = model.predict(start)
    # no wear, or a round-off remainder of it (Finnie's cos²α at normal incidence): no log to fit
    left_out = tuple(int(i) for i in fitted if at_start[i] <= 1e-12 * at_start[fitted].max(initial=0.0))
    rows = np.array([i for i in fitted if i not in left_out], dtype=int)
    if rows.size < len(free):
        raise ValueError(
            f"wear.law={case.wear.law!r} predicts no wear at {len(left_out)} of the {n_fit} measured rows "
            "(e.g. no sliding at normal incidence): too few rows left to fit"
        )
    constants = [_constant(name, start[name]) for name in free]
    result = log_fit(lambda v: model.predict(v)[rows], data.measured[rows], constants)
    t2 = time.perf_counter()
    fitted_case = case.with_(wear=result.as_dict())
    predicted = model.predict(result.as_dict())
    return CalibrationResult(
        fitted_case,
        data,
        result,
        start,
        predicted,
        left_out,
        {"impacts": t1 - t0, "fit": t2 - t1},
        result.evaluations / max(t2 - t1, 1e-9),
    )
