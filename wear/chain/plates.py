"""The plate a run's impact acted on, behind one seam (SI units, angles in degrees from the plate normal).

A run couples its impact to the plate of ``fem.model`` (``fem.coupling`` saying how), and from then on asks that
plate, never which plate it is: its wear (Eq. 15 over its pressure), its residual dent, its first yield and regime,
its coupling's and its own blocks of ``summary.json``, its arrays of ``pressure.npz``, its mesh ``plate_fe.vtu`` and
what the figures draw of it. :data:`PLATES` names the models: a new plate model is a class beside these (its FE in
a folder of :mod:`fem`) and one line there.

- :class:`wear.chain.axisymmetric_run.NoPlateRun` (``fem.coupling = "none"``): the impact on its own normal law, no
  dent;
- :class:`wear.chain.axisymmetric_run.AxisymmetricRun`: the (r, z) frictionless FE plate, two-way
  (:func:`fem.couple`) or one-way (:func:`fem.indent_impact`);
- :class:`wear.chain.solid_run.SolidRun`: the 3-D half plate with Coulomb friction (:mod:`wear.chain.solid`),
  started from the axisymmetric coupled impact.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

import meshio
import numpy as np

import fem
from contact import ImpactResult
from fem.solid_coupling import SolidCoupledImpact
from wear.case import Case
from wear.chain.axisymmetric_run import AxisymmetricRun, NoPlateRun, Wear, one_way
from wear.chain.plate import case_plate, coupling_settings, impact_on_law
from wear.chain.solid import check_solid_case, solid_case, solid_impact
from wear.chain.solid_run import SolidRun
from wear.integrate import WearMap
from wear.pressure import PressureHistory
from wear.surface import DeformedSurface

__all__ = ["PLATES", "PlateModel", "PlateRun", "couple_plate", "prepare_case", "untimed"]

#: A stage runner: ``timed(stage, function, *args)`` runs ``function(*args)`` and records its wall time (s).
Timed = Callable[..., object]


class PlateRun(Protocol):
    """What a run asks of the plate its impact acted on."""

    #: ``fem.model`` of the plate ("axisymmetric", "3d"), None without an FE plate.
    model: str | None
    #: The final impact (coupled to the plate where it is two-way).
    impact: ImpactResult
    #: The axisymmetric plate of the run (itself, or the one a 3-D plate started from; None without one).
    axisymmetric: AxisymmetricRun | None
    #: The impact coupled to the 3-D plate (None on another plate).
    solid: SolidCoupledImpact | None

    def wear(self, case: Case) -> Wear:
        """Stage ``wear``: (pressure history, wear map, worn volumes) of the case's wear law on this plate."""
        ...

    def surface(self, wm: WearMap) -> DeformedSurface:
        """Stage ``surface``: the residual dent (m) with the wear map ``wm`` on its grid."""
        ...

    def yield_info(self, info: dict) -> dict:
        """``info`` (the closed forms) with the plate's first-yield force (N) and the plate it is from."""
        ...

    def regime(self, info: dict) -> str:
        """The plate's regime (:data:`fem.REGIMES`, or the closed form's where there is no FE)."""
        ...

    def peak_pressure(self) -> tuple[float | None, str]:
        """(largest contact pressure (Pa) of the plate's field, None for the impact's own; its source)."""
        ...

    def coupling_summary(self, estimate: ImpactResult) -> dict | None:
        """The ``coupling`` block of summary.json (None: not coupled)."""
        ...

    def summary_blocks(self) -> dict:
        """The plate's own blocks of summary.json (``plate_3d``, the start's regime)."""
        ...

    def pressure_arrays(self) -> dict[str, np.ndarray]:
        """The plate's arrays of pressure.npz (SI units in the names)."""
        ...

    def fe_mesh(self, case: Case, pressure: PressureHistory) -> meshio.Mesh | None:
        """``plate_fe.vtu``: the FE plate after the impact (None without one)."""
        ...

    def force_steps(self) -> list[tuple[np.ndarray, np.ndarray, str]]:
        """(overlap m, force N, label) of the plate's steps, for the force–overlap figure."""
        ...

    def start_dent(self) -> tuple[np.ndarray, np.ndarray] | None:
        """(r m, residual depth m) of the axisymmetric plate a 3-D plate started from, for the cross sections."""
        ...

    def plastic_section(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, float] | None:
        """The plane of incidence of a 3-D plate, or None: (points (n, 2) x, z m; triangles (m, 3) tiling it;
        equivalent plastic strain (m,) on each; largest contact radius m)."""
        ...


def _axisymmetric(case: Case, estimate: ImpactResult, timed: Timed) -> PlateRun:
    """The case's impact on the axisymmetric plate, coupled as ``fem.coupling`` says."""
    mode = case.fem.coupling
    if mode == "two-way":
        plate = timed("fem", case_plate, case, (1.0 + case.fem.overshoot) * estimate.max_overlap)
        settings = coupling_settings(case)
        coupled = timed("coupling", fem.couple, plate, impact_on_law(case), estimate.max_overlap, settings)
        return AxisymmetricRun(coupled.impact, coupled.cycle, coupled, coupled.pressure_table, coupled.radial_table)
    if mode == "one-way":
        fe = timed("fem", one_way, case, estimate)
        timed("coupling", lambda: None)
        rows = fem.contact_pressure(fe.pressure, fe.surface_r, fe.contact_radius)
        time = np.asarray(fe.time, float)
        # a plastic rebound separates at an overlap above 0: the plate's steps below it (its recovery once the ball
        # has left, for the residual dent) all sit at the separation time and carry no impact pressure
        during = np.r_[True, np.diff(time) > 0.0]
        r = np.asarray(fe.surface_r, float)
        table = (time[during], r, rows[during])
        radial = (time[during], r, np.asarray(fe.radial_displacement, float)[during])
        return AxisymmetricRun(estimate, fe, None, table, radial)
    return NoPlateRun(estimate)


def _solid(case: Case, estimate: ImpactResult, timed: Timed) -> PlateRun:
    """The case's impact on the 3-D plate, started from the axisymmetric coupled impact (the cheapest start
    measured: its normal law is the 3-D one's within about 1 % at μ = 0)."""
    start = _axisymmetric(case, estimate, timed)
    coupled = timed("plate3d", solid_impact, case, start.impact)
    return SolidRun(coupled, start)


def _solid_case(case: Case) -> Case:
    """The case as the 3-D plate runs it (one-line ``ValueError`` first for one it cannot run)."""
    check_solid_case(case)
    return solid_case(case)


@dataclass(frozen=True)
class PlateModel:
    """A plate model of ``fem.model``: ``prepare`` checks a case before any work and returns it as the model runs
    it (e.g. with the plate's own tangential law), ``couple`` couples the case's impact from the estimate on its own
    normal law."""

    prepare: Callable[[Case], Case]
    couple: Callable[[Case, ImpactResult, Timed], PlateRun]


#: The plate models by ``fem.model``.
PLATES: dict[str, PlateModel] = {
    "axisymmetric": PlateModel(lambda case: case, _axisymmetric),
    "3d": PlateModel(_solid_case, _solid),
}


def prepare_case(case: Case) -> Case:
    """``case`` as the plate of its ``fem.model`` runs it, checked before any work (:attr:`PlateModel.prepare`)."""
    return PLATES[case.fem.model].prepare(case)


def untimed(stage: str, function: Callable, *args):
    """A stage runner that only runs the stage: ``function(*args)``."""
    del stage
    return function(*args)


def couple_plate(case: Case, estimate: ImpactResult, timed: Timed | None = None) -> PlateRun:
    """The case's impact coupled to the plate of ``fem.model`` (:data:`PLATES`), starting from ``estimate`` (the
    impact on the case's own normal law); ``timed(stage, function, *args)`` runs each stage (default: untimed)."""

    return PLATES[case.fem.model].couple(case, estimate, timed or untimed)
