"""The forward model of a calibration (:mod:`wear.chain.calibrate`): the impacts of every data row, computed once,
and the wear law of :mod:`wear.laws` evaluated on them for any constants. SI units; angles in degrees from the plate
normal.

The impacts do not depend on the wear law's constants, so they are computed once (``contact.simulate_impacts``,
one batch per group of rows with the same case keys); each evaluation only re-evaluates the law: the Eq. 15 volume
K ∫ v^β ∫ p^α dA dt on the stored pressure histories (:func:`wear.laws.local.local_volume`), or the plastic work.
A closed-form law (:func:`wear.laws.registry.closed_form_laws`: Finnie, Oka, DNV) needs no impact at all: its formula
(:func:`wear.laws.impact.closed_form_volume`) is evaluated on the speeds and angles of each group of rows. With
``fem.coupling = "two-way"`` and a law that uses the FE (the ``"fe"`` pressure, or the plastic work of the
deformation laws) each row's coupled FE impact is computed once too (seconds per row).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

import fem
from contact import ImpactResult, simulate_impacts
from contact.theory import sphere_mass
from wear.case import Case
from wear.case.budget import check_budget
from wear.chain.calibration_data import CalibrationData
from wear.chain.estimate import estimate_arguments, estimate_impact
from wear.chain.plate import case_plate, coupling_settings, impact_on_law, plate_sliding_speed, wear_constants
from wear.law import WearLaw
from wear.laws.impact import closed_form_volume, impact_wear
from wear.laws.local import local_volume, pressed_area
from wear.laws.registry import law_named, parts_of
from wear.pressure import PressureHistory, pressure_history
from wear.slip import SlidingSpeed

__all__ = [
    "ForwardModel",
    "BYTES_PER_ROW",
    "CLOSED_FORM_BYTES_PER_ROW",
    "CLOSED_FORM_SECONDS_PER_ROW",
    "SECONDS_PER_ROW",
    "check_rows",
    "closed_form",
    "fe_coupled",
]


def _uses_local(case: Case) -> bool:
    """Whether the case's law evaluates Eq. 15 on the pressure histories."""
    return any(part.uses_local for part in parts_of(case.wear.law, case.wear.values()))


def closed_form(case: Case) -> bool:
    """Whether the case's law is a formula of each row's speed, angle, particle and plate
    (:attr:`wear.laws.declaration.Law.closed_form`), so that the forward model needs no impact."""
    return law_named(case.wear.law).closed_form is not None


def fe_coupled(case: Case) -> bool:
    """Whether the forward model computes each row's coupled FE impact (and so reads ``[fem]``): a two-way coupling
    and a law that uses the FE (its pressure or the plastic work of the deformation laws)."""
    uses_work = any(part.uses_work for part in parts_of(case.wear.law, case.wear.values()))
    return case.fem.coupling == "two-way" and ((_uses_local(case) and case.wear.pressure == "fe") or uses_work)


#: Peak memory (B) of the forward model: base + per data row (its impact, pressure history and the fit's arrays).
#: Measured with ``impactwear calibrate --law dnv`` when that law still ran every row's impact (default case, erosion
#: rates at 10-80 deg, 20-60 m/s): 0.73 GB at 1000 rows, 1.98 GB at 4000 (200,000 rows were past 4 GB after 41 s).
BYTES_PER_ROW = (3.1e8, 4.2e5)
#: Wall time per data row (s), the same measurement: 54 s for 1000 rows, 221 s for 4000 (2 shared cores).
SECONDS_PER_ROW = 0.056
#: The same of a closed-form law (:func:`closed_form`: no impact, only the rows' arrays, the outputs and the figure),
#: measured with ``impactwear calibrate --law dnv`` on the same kind of data: 216 MB and 5.7 s at 1000 rows, 218 MB
#: and 6.3 s at 4000, 240 MB and 13.6 s at 40,000 (0.7 kB and 0.2 ms a row; about 3.5 s of it is the imports).
#: Bounds taken 6 and 5 times larger.
CLOSED_FORM_BYTES_PER_ROW = (3.1e8, 4.2e3)
CLOSED_FORM_SECONDS_PER_ROW = 1e-3


def check_rows(data: CalibrationData, case: Case | None = None) -> None:
    """Refuse ``data`` with more rows than the forward model's memory (:data:`BYTES_PER_ROW`) or time
    (:data:`SECONDS_PER_ROW`) budget allows (:mod:`wear.case.budget`; those of a closed form for a ``case`` whose
    law is one), before any impact: one line naming the file, its rows and the most rows that fit."""
    rows = data.angle.size
    formula = case is not None and closed_form(case)
    (base, per_row), seconds = (
        (CLOSED_FORM_BYTES_PER_ROW, CLOSED_FORM_SECONDS_PER_ROW) if formula else (BYTES_PER_ROW, SECONDS_PER_ROW)
    )
    context = f"data={data.source!r}: " if data.source else ""
    what = "the law's formula on the rows" if formula else "the impacts of the rows, computed once"
    said = {"what": what, "valid": (1, rows), "context": context}
    check_budget("rows", rows, lambda n: base + per_row * n, **said)
    check_budget("rows", rows, lambda n: seconds * n, memory=False, **said)


def _row_case(case: Case, data: CalibrationData, i: int) -> Case:
    tables: dict[str, dict[str, float]] = {"impact": {"speed": float(data.speed[i]), "angle": float(data.angle[i])}}
    for dotted, values in data.keys.items():
        table, _, name = dotted.partition(".")
        tables.setdefault(table, {})[name] = float(values[i])
    try:
        return case.with_(**tables)
    except ValueError as exc:
        raise ValueError(f"row {i + 1} of data={data.source!r}: {exc}") from None


@dataclass(frozen=True, eq=False)
class _Row:
    impact: ImpactResult
    pressure: PressureHistory | None
    speed: SlidingSpeed | None
    plate_work: float | None
    to_quantity: float  # the measured quantity per m^3 worn


@dataclass(frozen=True, eq=False)
class _Group:
    """Rows of a closed-form law that differ only in their speed and angle: their ``case`` (at speed 1, angle 0),
    indices ``rows``, ``speed`` (m/s) and ``angle`` (deg), and the measured quantity per m^3 worn."""

    case: Case
    rows: np.ndarray
    speed: np.ndarray
    angle: np.ndarray
    to_quantity: float


class ForwardModel:
    """The impacts of every data row, computed once, and the law evaluated on them for any constants
    (:meth:`predict`: the measured quantity per row)."""

    def __init__(self, case: Case, data: CalibrationData) -> None:
        self.case, self.data = case, data
        cases = [_row_case(case, data, i) for i in range(data.angle.size)]
        self.constants = [wear_constants(c) for c in cases]
        self._groups: list[_Group] = []
        if closed_form(case):
            # a formula of the particle's kinematics: no impact (they took 99 s and 1.9 GB for 4000 rows)
            self.rows: list[_Row] = []
            self._groups = self._closed_form(cases, data)
            return
        uses_local = _uses_local(case)
        coupled = fe_coupled(case)
        if case.wear.pressure == "fe" and uses_local and not coupled:
            raise ValueError("wear.pressure='fe' needs the FE plate: set fem.coupling='two-way' (or another pressure)")
        impacts = self._coupled(cases) if coupled else self._batched(cases)
        rows = []
        for c, (impact, tables, work) in zip(cases, impacts, strict=True):
            ph = sp = None
            if uses_local:
                table, radial = tables or (None, None)
                ph = pressure_history(impact, c.wear.pressure, fe=table, limiting_pressure=c.impact.limiting_pressure)
                sp = plate_sliding_speed(c, impact, radial)
            density = c.plate.material().density
            per_volume = {
                "volume_per_impact_m3": 1.0,
                "mass_per_impact_kg": density,
                "erosion_kg_per_kg": density / sphere_mass(c.ball.radius, c.ball.density),
            }
            rows.append(_Row(impact, ph, sp, work, per_volume[data.quantity]))
        self.rows = rows
        self._areas: list[tuple[float, np.ndarray | None]] = [(math.nan, None)] * len(rows)

    @staticmethod
    def _closed_form(cases: list[Case], data: CalibrationData) -> list[_Group]:
        """The rows of a closed-form law grouped by all but their speed and angle (one evaluation of the formula on
        the arrays of a group), with what turns a worn volume into the measured quantity."""
        groups: dict[Case, list[int]] = {}
        for i, c in enumerate(cases):
            groups.setdefault(c.with_(impact={"speed": 1.0, "angle": 0.0}), []).append(i)
        out = []
        for key, idx in groups.items():
            density = key.plate.material().density
            per_volume = {
                "volume_per_impact_m3": 1.0,
                "mass_per_impact_kg": density,
                "erosion_kg_per_kg": density / sphere_mass(key.ball.radius, key.ball.density),
            }
            rows = np.array(idx, dtype=int)
            out.append(_Group(key, rows, data.speed[rows], data.angle[rows], per_volume[data.quantity]))
        return out

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
            out.append((coupled.impact, (coupled.pressure_table, coupled.radial_table), coupled.plastic_work))
        return out

    def predict(self, values: dict[str, float]) -> np.ndarray:
        """The measured quantity of every row for the law's constants with ``values`` replacing some."""
        law = self.case.wear.law
        if self._groups:
            out = np.empty(self.data.angle.size)
            for g in self._groups:
                constants = {**self.constants[int(g.rows[0])], **values}  # the same for every row of the group
                ball, plate = g.case.ball, g.case.plate.material()
                worn = closed_form_volume(law, constants, ball.radius, ball.density, plate, g.speed, g.angle)
                out[g.rows] = worn * g.to_quantity
            return out
        out = np.empty(len(self.rows))
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
