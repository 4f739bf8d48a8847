"""What a plate model is to the chains (SI units, angles in degrees from the plate normal): :class:`PlateModel`,
the one entry a plate declares (its checks, its coupling of a run's impact, its repetition), and :class:`PlateRun`,
what a run asks of the plate its impact acted on.

A run and a repeat ask the plate, never which plate it is. What only some plates have (the axisymmetric start of
the 3-D plate, its plane of incidence, its coupling, its FE mesh) is in a mapping under a name, absent where a plate
has none (:attr:`PlateRun.fields`, :meth:`PlateRun.summary_blocks`, :meth:`PlateRun.meshes`), so that outputs and
figures ask a result what it holds.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Protocol

import meshio
import numpy as np

from contact import ImpactResult
from wear.case import Case
from wear.case.plate_cases import PlateCase
from wear.chain.records import RepeatResult
from wear.integrate import WearMap
from wear.laws.impact import ImpactWear
from wear.pressure import PressureHistory
from wear.surface import DeformedSurface

__all__ = ["PlateModel", "PlateRun", "Timed", "Wear", "untimed"]

#: A stage runner: ``timed(stage, function, *args)`` runs ``function(*args)`` and records its wall time (s).
Timed = Callable[..., object]
#: What a plate's wear stage returns: (pressure history, wear map, worn volumes).
Wear = tuple[PressureHistory, WearMap, ImpactWear]


def untimed(stage: str, function: Callable, *args):
    """A stage runner that only runs the stage: ``function(*args)``."""
    del stage
    return function(*args)


class PlateRun(Protocol):
    """What a run asks of the plate its impact acted on."""

    #: ``fem.model`` of the plate, None without an FE plate (``fem.coupling = "none"``).
    model: str | None
    #: The final impact (coupled to the plate where it is two-way).
    impact: ImpactResult

    @property
    def fields(self) -> Mapping[str, object]:
        """What this plate's result holds beyond the common by name, absent where it has none: ``fe`` (the
        axisymmetric plate's cycle or indentation), ``coupling`` (the impact coupled to it), ``solid`` (the impact
        coupled to the 3-D plate), ``start_dent`` ((r m, residual depth m) of the plate a 3-D plate started from),
        ``plastic_section`` (the plane of incidence: points (n, 2) x, z m; triangles (m, 3); equivalent plastic
        strain (m,); largest contact radius m)."""
        ...

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

    def peak_pressure(self) -> tuple[float, str]:
        """(largest contact pressure (Pa) of the plate the impact acted on: its field's, or the impact's own where it
        has none; its source)."""
        ...

    def summary_blocks(self, estimate: ImpactResult) -> dict[str, object]:
        """The plate's own blocks of summary.json by name, absent where it has none: ``coupling`` (the coupling it
        ran, from ``estimate``, the impact on the case's own normal law), ``plate_3d`` (the 3-D plate's),
        ``axisymmetric_start_regime`` (the regime of the plate a 3-D plate started from)."""
        ...

    def pressure_arrays(self) -> dict[str, np.ndarray]:
        """The plate's arrays of pressure.npz (SI units in the names)."""
        ...

    def meshes(self, case: Case, pressure: PressureHistory) -> dict[str, meshio.Mesh]:
        """The plate's own meshes by name, absent where it has none: ``plate_fe`` (the FE plate after the impact,
        with the wear of ``pressure`` where it is axisymmetric)."""
        ...

    def force_steps(self) -> list[tuple[np.ndarray, np.ndarray, str]]:
        """(overlap m, force N, label) of the plate's steps, for the force–overlap figure."""
        ...


@dataclass(frozen=True)
class PlateModel:
    """A plate model of ``fem.model``, declared by the plate's own module and listed in
    :data:`wear.chain.plates.PLATES`.

    ``declaration``: what the case schema reads of it (:class:`wear.case.plate_cases.PlateCase`: its name, its own
    ``[fem]`` keys, its work check); ``prepare(case)``: the case as the model runs it (e.g. on the plate's own
    tangential law), a one-line ``ValueError`` first for a case it cannot run; ``couple(case, estimate, timed)``:
    the case's impact coupled to the plate from ``estimate`` (the impact on the case's own normal law), each stage
    run by ``timed``; ``repeat(case, progress, on_computed)``: ``case.repeat.impacts`` impacts at one site
    (:func:`wear.chain.repeated_impacts.repeat`)."""

    declaration: PlateCase
    prepare: Callable[[Case], Case]
    couple: Callable[[Case, ImpactResult, Timed], PlateRun]
    repeat: Callable[..., RepeatResult]

    @property
    def name(self) -> str:
        """Its ``fem.model`` (its declaration's name)."""
        return self.declaration.name
