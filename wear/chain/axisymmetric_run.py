"""The axisymmetric plate of a run, and the run without an FE plate (SI units): the case's impact coupled to it
(:func:`on_axisymmetric_plate`) and what a run asks of them (:class:`wear.chain.plate_model.PlateRun`) — their
wear, dent, first yield, regime, summary blocks, arrays and meshes."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property

import meshio
import numpy as np

import fem
from contact import ImpactResult
from fem import CoupledImpact, IndentationResult, PlateCycle, worst_regime
from wear.case import Case
from wear.chain.plate import (
    case_mesh,
    case_plate,
    check_impact_overlap,
    coupling_settings,
    impact_on_law,
    plate_sliding_speed,
    wear_constants,
)
from wear.chain.plate_model import PlateRun, Timed, Wear
from wear.integrate import WearMap, axisymmetric_wear_depth
from wear.laws.impact import wear_of_impact
from wear.pressure import PressureHistory, pressure_history
from wear.surface import DeformedSurface

__all__ = ["AxisymmetricRun", "NoPlateRun", "impact_wear", "on_axisymmetric_plate", "one_way"]


def impact_wear(
    case: Case, impact: ImpactResult, fe_table=None, plate_work: float | None = None, radial_table=None
) -> Wear:
    """Stage ``wear``: the pressure history p(r, t) of ``impact`` (``case.wear.pressure``; ``fe_table`` the FE
    (time s, r m, pressure Pa) table where it is "fe"), the sliding speed (``case.wear.speed``; ``radial_table`` the
    FE surface's (time s, r m, u_r m) where it is "local"), the wear map (m) and the worn volumes of the case's wear
    law (:func:`wear.laws.impact.wear_of_impact`; ``plate_work`` the FE plate's plastic dissipation, J)."""
    w = case.wear
    ph = pressure_history(impact, w.pressure, fe=fe_table, limiting_pressure=case.impact.limiting_pressure)
    wm, worn = wear_of_impact(
        w.law,
        wear_constants(case),
        w.wear_law(),
        impact,
        ph,
        plate_sliding_speed(case, impact, radial_table),
        density=case.plate.material().density,
        points_across=w.points_across,
        plate_work=plate_work,
    )
    return ph, wm, worn


def one_way(case: Case, impact: ImpactResult) -> IndentationResult:
    """The FE plate along the impact's overlap history (``fem.indent_impact``, ``fem.load_steps + unload_steps``
    increments, the mesh of ``fem.mesh_scale``): the FE stage of a one-way run."""
    check_impact_overlap(case, impact.max_overlap)
    mesh = case_mesh(case, impact.max_overlap)
    steps = case.fem.load_steps + case.fem.unload_steps
    return fem.indent_impact(impact, case.plate.material(), steps=steps, mesh=mesh)


def _flat_surface(impact: ImpactResult, wm: WearMap, r: np.ndarray, depth: np.ndarray) -> DeformedSurface:
    """The wear map with an axisymmetric dent ``depth`` (m) at radii ``r`` (m) about the contact centre of the
    impact's maximum overlap."""
    h = impact.history
    i_max = int(np.argmax(h.overlap))
    order = np.argsort(r)
    centre = (float(h.contact_x[i_max]), 0.0)
    return DeformedSurface(wm.x, wm.y, wm.depth.T, np.asarray(r, float)[order], np.asarray(depth, float)[order], centre)


@dataclass(frozen=True, eq=False)
class NoPlateRun:
    """No FE plate (``fem.coupling = "none"``): the impact on its own normal law."""

    impact: ImpactResult
    model: str | None = None

    @property
    def fields(self) -> Mapping[str, object]:
        return {}

    def wear(self, case: Case) -> Wear:
        return impact_wear(case, self.impact)

    def surface(self, wm: WearMap) -> DeformedSurface:
        return _flat_surface(self.impact, wm, np.array([0.0, 1.0]), np.zeros(2))

    def yield_info(self, info: dict) -> dict:
        return info

    def regime(self, info: dict) -> str:
        if info["F_c_exact"] is None:
            return "elastic"
        return "elastic" if self.impact.max_force < info["F_c_exact"] else "plastic (no FE: regime not resolved)"

    def peak_pressure(self) -> tuple[float, str]:
        return self.impact.max_peak_pressure, f"normal law {self.impact.normal_model!r}"

    def summary_blocks(self, estimate: ImpactResult) -> dict[str, object]:
        return {}

    def pressure_arrays(self) -> dict[str, np.ndarray]:
        return {}

    def meshes(self, case: Case, pressure: PressureHistory) -> dict[str, meshio.Mesh]:
        return {}

    def force_steps(self) -> list[tuple[np.ndarray, np.ndarray, str]]:
        return []


@dataclass(frozen=True, eq=False)
class AxisymmetricRun:
    """The axisymmetric FE plate: ``fe`` its cycle (two-way, :class:`fem.PlateCycle`) or its indentation along the
    impact (one-way, :class:`fem.IndentationResult`), ``coupled`` the coupled impact (two-way, else None),
    ``fe_table`` its (time s, r m, pressure Pa) and ``radial_table`` its (time s, r m, u_r m) table on the impact's
    time axis."""

    impact: ImpactResult
    fe: PlateCycle | IndentationResult
    coupled: CoupledImpact | None
    fe_table: tuple[np.ndarray, np.ndarray, np.ndarray]
    radial_table: tuple[np.ndarray, np.ndarray, np.ndarray]
    model: str | None = "axisymmetric"

    @cached_property
    def fields(self) -> Mapping[str, object]:
        return {"fe": self.fe} if self.coupled is None else {"fe": self.fe, "coupling": self.coupled}

    def wear(self, case: Case) -> Wear:
        work = None if self.coupled is None else self.coupled.plastic_work
        return impact_wear(case, self.impact, self.fe_table, work, self.radial_table)

    def surface(self, wm: WearMap) -> DeformedSurface:
        return _flat_surface(self.impact, wm, self.fe.surface_r, self.fe.residual_depth)

    def yield_info(self, info: dict) -> dict:
        first = self.fe.first_yield
        return {
            **info,
            "fe_first_yield_plate": "axisymmetric",
            "fe_first_yield_force": None if first is None else float(first.force),
        }

    def regime(self, info: dict) -> str:
        if len(self.fe.regime):
            return worst_regime(self.fe.regime)
        return NoPlateRun(self.impact).regime(info)

    def peak_pressure(self) -> tuple[float, str]:
        return float(np.max(self.fe.pressure)), "FE plate"

    def summary_blocks(self, estimate: ImpactResult) -> dict[str, object]:
        c = self.coupled
        if c is None:  # one-way: the plate along the impact, not coupled to it
            return {}
        coupling = {
            "plate": "axisymmetric",
            "iterations": c.iterations,
            "final_change": c.change,
            "converged": c.converged,
            "max_overlaps_m": list(c.max_overlaps),
            "estimate_model": estimate.normal_model,
            "estimate_max_overlap_m": estimate.max_overlap,
        }
        return {"coupling": coupling}

    def pressure_arrays(self) -> dict[str, np.ndarray]:
        if self.coupled is None:
            return {}
        ft, fr, fp = self.coupled.pressure_table
        return {"fe_time_s": ft, "fe_surface_r_m": fr, "fe_pressure_Pa": fp}

    def meshes(self, case: Case, pressure: PressureHistory) -> dict[str, meshio.Mesh]:
        return {"plate_fe": self._fe_mesh(case, pressure)}

    def _fe_mesh(self, case: Case, pressure: PressureHistory) -> meshio.Mesh:
        """The FE plate after the impact: points (r, z, 0) m, point data ``u`` (m) and ``max_pressure`` (Pa: the
        largest contact pressure each surface node carried during the impact — after the rebound the pressure itself
        is 0), cell data ``von_mises`` (Pa) and ``equivalent_plastic_strain``. Where the contact centre never moves
        (a normal impact) the wear is axisymmetric too: the surface nodes are then moved down by its depth h(r)
        (point data ``wear_depth``, m); an oblique impact's wear is not axisymmetric and is in ``surface.vtu``
        only."""
        fe = self.fe
        mesh = fe.to_meshio()
        pts = np.asarray(mesh.points, dtype=float)
        u = np.asarray(mesh.point_data["u"], dtype=float)
        undeformed_z = pts[:, 1] - u[:, 1]
        undeformed_r = pts[:, 0] - u[:, 0]
        on_surface = np.abs(undeformed_z) <= 1e-9 * float(np.ptp(pts[:, 0]))
        point_data = {k: v for k, v in mesh.point_data.items() if k != "pressure"}
        order = np.argsort(fe.surface_r)
        peak = np.interp(undeformed_r, fe.surface_r[order], np.max(fe.pressure, axis=0)[order], right=0.0)
        point_data["max_pressure"] = np.where(on_surface, peak, 0.0)
        if np.ptp(np.asarray(self.impact.history.contact_x, float)) == 0.0:
            speed = plate_sliding_speed(case, self.impact, self.radial_table)
            h = axisymmetric_wear_depth(pressure, speed, case.wear.wear_law(), undeformed_r)
            wear = np.where(on_surface & (undeformed_r >= 0), h, 0.0)
            pts[:, 1] -= wear
            point_data["wear_depth"] = wear
        return meshio.Mesh(pts, mesh.cells, point_data=point_data, cell_data=dict(mesh.cell_data))

    def force_steps(self) -> list[tuple[np.ndarray, np.ndarray, str]]:
        return [(np.asarray(self.fe.overlap, float), np.asarray(self.fe.force, float), "FE steps (axisymmetric)")]


def on_axisymmetric_plate(case: Case, estimate: ImpactResult, timed: Timed) -> PlateRun:
    """The case's impact on the axisymmetric plate, coupled as ``fem.coupling`` says, from ``estimate`` (the impact
    on the case's own normal law); ``timed`` runs each stage."""
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
