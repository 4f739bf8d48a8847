"""Calibration of a wear law's constants to measured wear: the forward model (batched impacts and the law of
:mod:`wear.laws`) fitted by least squares on log residuals (:mod:`wear.chain.fit`). SI units; angles in degrees
from the plate normal.

Data: one row per measurement — ``angle_deg`` (from the normal), ``speed_m_s``, one measured quantity
(:data:`QUANTITIES`: the erosion ratio kg/kg, the mass or the volume worn per impact), and optionally case keys per
row as extra columns named as in the schema (``ball.radius``, ``impact.friction``, ``plate.hardness``, ...). A row
whose measured value is empty is predicted, not fitted.

The impacts do not depend on the wear law's constants, so they are computed once (``contact.simulate_impacts``,
one batch per group of rows with the same case keys); each evaluation of the residuals only re-evaluates the law:
the Eq. 15 volume K ∫ v^β ∫ p^α dA dt on the stored pressure histories (:func:`wear.laws.local_volume`), or the
closed forms. With ``fem.coupling = "two-way"`` and a law that uses the FE (the ``"fe"`` pressure, or the plastic
work of the deformation laws) each row's coupled FE impact is computed once too (seconds per row).
"""

from __future__ import annotations

import csv
import math
import os
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

import fem
from contact import ImpactResult, simulate_impacts
from contact.theory import sphere_mass
from wear.case import TABLES, Case, check_job_case
from wear.chain.fit import Constant, LogFit, log_fit
from wear.chain.plate import case_plate, coupling_settings, impact_on_law, wear_constants
from wear.chain.single import estimate_arguments, estimate_impact
from wear.law import WearLaw
from wear.laws import flow_pressure_of, impact_wear, local_volume, oka_exponents, pressed_area
from wear.pressure import PressureHistory, SlidingSpeed, pressure_history, sliding_speed

__all__ = [
    "QUANTITIES",
    "CalibrationData",
    "CalibrationResult",
    "ForwardModel",
    "calibrate",
    "law_constants",
    "read_data",
]

#: Measured quantities a data file may hold (column name → what it is).
QUANTITIES = {
    "erosion_kg_per_kg": "erosion ratio: mass of plate worn per mass of particles (kg/kg)",
    "mass_per_impact_kg": "mass of plate worn per impact (kg)",
    "volume_per_impact_m3": "volume of plate worn per impact (m^3)",
}
#: Constants of each law that a calibration may fit.
_CONSTANTS = {
    "local": ("K", "alpha", "beta"),
    "finnie": ("cutting_fraction", "force_ratio", "depth_ratio"),
    "deformation": ("deformation_factor",),
    "oka": ("oka_e90", "oka_k2"),
    "dnv": ("dnv_K", "dnv_n"),
}
#: The constant fitted when none is named: each law's scale.
_SCALE = {
    "local": "K",
    "finnie": "cutting_fraction",
    "deformation": "deformation_factor",
    "oka": "oka_e90",
    "dnv": "dnv_K",
}
#: Constants fitted in log coordinates (positive scales); the others (exponents) as they are.
_LOG = {"K", "cutting_fraction", "force_ratio", "depth_ratio", "deformation_factor", "oka_e90", "dnv_K"}


def law_constants(case: Case) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """(the constants of the case's wear law a calibration may fit, those it fits when none is named)."""
    law = case.wear.law
    if law == "combined":
        cut = case.wear.cutting
        return _CONSTANTS[cut] + _CONSTANTS["deformation"], (_SCALE[cut], _SCALE["deformation"])
    return _CONSTANTS[law], (_SCALE[law],)


@dataclass(frozen=True, eq=False)
class CalibrationData:
    """Measurements: ``angle`` (deg from the normal), ``speed`` (m/s), ``measured`` (NaN where only predicted) of
    ``quantity`` (:data:`QUANTITIES`), ``keys`` (dotted case key → per-row values), ``source`` (where they came
    from)."""

    angle: np.ndarray
    speed: np.ndarray
    quantity: str
    measured: np.ndarray
    keys: dict[str, np.ndarray]
    source: str = ""

    @property
    def fitted(self) -> np.ndarray:
        """Rows with a measured value."""
        return np.isfinite(self.measured)


def _number(text: str, column: str, row: int) -> float:
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{column}={text!r} in row {row} is not a number") from None
    if math.isnan(value) or math.isinf(value):
        raise ValueError(f"{column}={text!r} in row {row} is not finite")
    return value


def read_data(path: str | os.PathLike) -> CalibrationData:
    """Read and check a data file (CSV with a header row; see the module docstring). Errors are one line naming
    the column and the row (rows counted from 1 after the header)."""
    p = Path(path)
    if not p.is_file():
        raise ValueError(f"data={str(p)!r} is not a file")
    with open(p, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"data={str(p)!r} is empty: give a header row and one row per measurement")
    header, body = [h.strip() for h in rows[0]], [r for r in rows[1:] if any(c.strip() for c in r)]
    measured = [h for h in header if h in QUANTITIES]
    for need in ("angle_deg", "speed_m_s"):
        if need not in header:
            raise ValueError(
                f"column {need!r} is missing from data={str(p)!r}: the columns are angle_deg, speed_m_s, "
                f"one of {', '.join(QUANTITIES)} and optional case keys (table.key)"
            )
    if len(measured) != 1:
        raise ValueError(
            f"data={str(p)!r} has {len(measured)} measured columns {measured}: give exactly one of "
            f"{', '.join(QUANTITIES)}"
        )
    keys = [h for h in header if h not in ("angle_deg", "speed_m_s", measured[0])]
    for k in keys:
        table, _, name = k.partition(".")
        if table not in TABLES or name not in TABLES[table].keys():
            raise ValueError(
                f"column {k!r} of data={str(p)!r} is not a case key (table.key, e.g. ball.radius) nor "
                f"angle_deg, speed_m_s or a measured quantity"
            )
        if TABLES[table].keys()[name].type not in (int, float):
            raise ValueError(f"column {k!r} of data={str(p)!r} is not a numeric case key")
    if not body:
        raise ValueError(f"data={str(p)!r} has no rows: give one row per measurement")
    angle, speed, value = [], [], []
    extra: dict[str, list[float]] = {k: [] for k in keys}
    for i, row in enumerate(body, start=1):
        if len(row) != len(header):
            raise ValueError(f"row {i} of data={str(p)!r} has {len(row)} values for {len(header)} columns")
        cells = dict(zip(header, (c.strip() for c in row), strict=True))
        a = _number(cells["angle_deg"], "angle_deg", i)
        if not 0.0 <= a < 90.0:
            raise ValueError(
                f"angle_deg={a:g} in row {i} is out of range: the angle from the normal must be in [0, 90) deg"
            )
        v = _number(cells["speed_m_s"], "speed_m_s", i)
        if not 0.0 < v <= 1000.0:
            raise ValueError(f"speed_m_s={v:g} in row {i} is out of range: must be in (0, 1000] m/s")
        text = cells[measured[0]]
        if text == "":
            m = math.nan
        else:
            m = _number(text, measured[0], i)
            if m <= 0.0:
                raise ValueError(
                    f"{measured[0]}={m:g} in row {i} is out of range: must be > 0 (its log is fitted); "
                    "leave it empty to predict the row"
                )
        angle.append(a)
        speed.append(v)
        value.append(m)
        for k in keys:
            extra[k].append(_number(cells[k], k, i))
    data = CalibrationData(
        np.array(angle),
        np.array(speed),
        measured[0],
        np.array(value),
        {k: np.array(v) for k, v in extra.items()},
        str(p),
    )
    if not data.fitted.any():
        raise ValueError(f"{measured[0]} is empty in every row of data={str(p)!r}: no measured row to fit")
    return data


def _row_case(case: Case, data: CalibrationData, i: int) -> Case:
    tables: dict[str, dict[str, float]] = {"impact": {"speed": float(data.speed[i]), "angle": float(data.angle[i])}}
    for dotted, values in data.keys.items():
        table, _, name = dotted.partition(".")
        tables.setdefault(table, {})[name] = float(values[i])
    try:
        return case.with_(**tables)
    except ValueError as exc:
        raise ValueError(f"row {i + 1}: {exc}") from None


@dataclass(frozen=True, eq=False)
class _Row:
    impact: ImpactResult
    pressure: PressureHistory | None
    speed: SlidingSpeed | None
    plate_work: float | None
    to_quantity: float  # the measured quantity per m^3 worn


class ForwardModel:
    """The impacts of every data row, computed once, and the law evaluated on them for any constants
    (:meth:`predict`: the measured quantity per row)."""

    def __init__(self, case: Case, data: CalibrationData) -> None:
        self.case, self.data = case, data
        law, cut = case.wear.law, case.wear.cutting
        uses_local = law == "local" or (law == "combined" and cut == "local")
        uses_work = law in ("deformation", "combined")
        coupled = case.fem.coupling == "two-way" and ((uses_local and case.wear.pressure == "fe") or uses_work)
        if case.wear.pressure == "fe" and uses_local and not coupled:
            raise ValueError("wear.pressure='fe' needs the FE plate: set fem.coupling='two-way' (or another pressure)")
        cases = [_row_case(case, data, i) for i in range(data.angle.size)]
        impacts = self._coupled(cases) if coupled else self._batched(cases)
        rows = []
        for c, (impact, table, work) in zip(cases, impacts, strict=True):
            ph = sp = None
            if uses_local:
                ph = pressure_history(impact, c.wear.pressure, fe=table, limiting_pressure=c.impact.limiting_pressure)
                sp = sliding_speed(impact, c.wear.speed)
            density = c.plate.material().density
            per_volume = {
                "volume_per_impact_m3": 1.0,
                "mass_per_impact_kg": density,
                "erosion_kg_per_kg": density / sphere_mass(c.ball.radius, c.ball.density),
            }
            rows.append(_Row(impact, ph, sp, work, per_volume[data.quantity]))
        self.rows = rows
        self.constants = [wear_constants(c) for c in cases]
        self._areas: list[tuple[float, np.ndarray | None]] = [(math.nan, None)] * len(rows)

    @staticmethod
    def _batched(cases: list[Case]) -> list[tuple[ImpactResult, None, None]]:
        groups: dict[Case, list[int]] = {}
        for i, c in enumerate(cases):
            groups.setdefault(c.with_(impact={"speed": 1.0, "angle": 0.0}), []).append(i)
        out: list = [None] * len(cases)
        for key, idx in groups.items():
            kw = estimate_arguments(
                key,
                speed=np.array([cases[i].impact.speed for i in idx]),
                angle=np.array([cases[i].impact.angle for i in idx]),
            )
            batch = simulate_impacts(**kw, histories=True)
            for k, i in enumerate(idx):
                out[i] = (batch[k], None, None)
        return out

    @staticmethod
    def _coupled(cases: list[Case]) -> list[tuple[ImpactResult, tuple, float]]:
        out = []
        for c in cases:
            estimate = estimate_impact(c)
            plate = case_plate(c, (1.0 + c.fem.overshoot) * estimate.max_overlap)
            coupled = fem.couple(plate, impact_on_law(c), estimate.max_overlap, coupling_settings(c))
            out.append((coupled.impact, coupled.pressure_table, coupled.plastic_work))
        return out

    def predict(self, values: dict[str, float]) -> np.ndarray:
        """The measured quantity of every row for the law's constants with ``values`` replacing some."""
        out = np.empty(len(self.rows))
        law = self.case.wear.law
        for i, (row, base) in enumerate(zip(self.rows, self.constants, strict=True)):
            constants = {**base, **values}
            local = None
            if row.pressure is not None:
                alpha = constants["alpha"]
                if self._areas[i][0] != alpha:  # the area integral changes with α only: kept between evaluations
                    self._areas[i] = (alpha, pressed_area(row.pressure, alpha))
                local = local_volume(
                    row.pressure,
                    row.speed,
                    WearLaw(K=constants["K"], alpha=alpha, beta=constants["beta"]),
                    self._areas[i][1],
                )
            worn = impact_wear(law, constants, row.impact, local=local, plate_work=row.plate_work)
            out[i] = worn.volume_m3 * row.to_quantity
        return out


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

    @property
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
                "units": TABLES["wear"].keys()[name].units,
            }
        return {
            "law": self.case.wear.law,
            "cutting": self.case.wear.cutting if self.case.wear.law == "combined" else None,
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


def _constant(name: str, start: float) -> Constant:
    spec = TABLES["wear"].keys()[name]
    return Constant(name, start, name in _LOG, spec.low, spec.high)


def calibrate(case: Case, data: CalibrationData, free: tuple[str, ...] | None = None) -> CalibrationResult:
    """Fit the constants ``free`` (default: the law's scale; :func:`law_constants`) of the case's wear law to
    ``data`` (see the module docstring); the other constants stay as in the case."""
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
    t0 = time.perf_counter()
    model = ForwardModel(case, data)
    t1 = time.perf_counter()
    base = wear_constants(case)
    start = {}
    for name in free:
        value = base[name]
        if value is None and name == "oka_k2":
            value = oka_exponents(flow_pressure_of(base, case.plate.material()))[2]
        if value is None:
            raise ValueError(f"wear.{name}=None: give a starting value for the free constant {name}")
        start[name] = float(value)
    at_start = model.predict(start)
    fitted = np.flatnonzero(data.fitted)
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
