"""The 3-D plate of a run (SI units): the case's impact coupled to it (:func:`on_solid_plate`, started from the
axisymmetric coupled impact) and what a run asks of it (:class:`wear.chain.plate_model.PlateRun`) — its wear, dent,
first yield, regime, summary blocks, arrays and meshes; the axisymmetric plate it started from is kept."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property

import meshio
import numpy as np

from contact import ImpactResult
from fem import worst_regime
from fem.solid_coupling import SolidCoupledImpact
from wear.case import Case
from wear.chain.axisymmetric_run import AxisymmetricRun, on_axisymmetric_plate
from wear.chain.plate_model import PlateRun, Timed, Wear
from wear.chain.solid import check_solid_case, solid_case, solid_impact, solid_surface, solid_wear
from wear.integrate import WearMap
from wear.pressure import PressureHistory
from wear.surface import DeformedSurface

__all__ = ["SOLID_PLASTIC_REGIME", "SolidRun", "on_solid_plate", "prepare_solid_case"]

#: The regime of a 3-D plate that yielded: its plastic strain says that it yielded, not where (the regimes of
#: :data:`fem.REGIMES` are classified on the axisymmetric plate's surface layer).
SOLID_PLASTIC_REGIME = "plastic (3-D plate: extent not classified)"


@dataclass(frozen=True, eq=False)
class SolidRun:
    """The 3-D half plate with friction: ``coupled`` the impact coupled to it, ``start`` the axisymmetric coupled
    impact it started from."""

    coupled: SolidCoupledImpact
    start: AxisymmetricRun
    model: str | None = "3d"

    @property
    def impact(self) -> ImpactResult:
        return self.coupled.impact

    @cached_property
    def fields(self) -> Mapping[str, object]:
        return {
            **self.start.fields,
            "solid": self.coupled,
            "start_dent": self._start_dent(),
            "plastic_section": self._plastic_section(),
        }

    def wear(self, case: Case) -> Wear:
        return solid_wear(case, self.coupled)

    def surface(self, wm: WearMap) -> DeformedSurface:
        return solid_surface(self.coupled, wm)

    def yield_info(self, info: dict) -> dict:
        start = self.start.yield_info(info)
        return {
            **start,
            "fe_first_yield_plate": "3d",
            "fe_first_yield_force": self.first_yield_force(),
            "axisymmetric_first_yield_force": start["fe_first_yield_force"],
        }

    def first_yield_force(self) -> float | None:
        """The normal force (N) of the first step along the impact's path with plastic strain (an upper bound at
        the path's resolution, ``fem.solid_load_steps``), None if the plate never yielded."""
        solid = self.coupled.solid
        yielded = np.flatnonzero(solid.max_equivalent_plastic_strain > 0.0)
        return float(solid.normal_force[yielded[0]]) if yielded.size else None

    def regime(self, info: dict) -> str:
        return "elastic" if np.max(self.coupled.solid.max_equivalent_plastic_strain) == 0.0 else SOLID_PLASTIC_REGIME

    def peak_pressure(self) -> tuple[float, str]:
        return float(np.max(self.coupled.solid.max_pressure)), "3-D FE plate"

    def summary_blocks(self, estimate: ImpactResult) -> dict[str, object]:
        # the coupling of the plate the impact ran on; the axisymmetric one it started from is kept inside
        s = self.coupled
        coupling = {
            "plate": "3d",
            "iterations": s.iterations,
            "final_change": s.change,
            "converged": s.converged,
            "max_overlaps_m": list(s.max_overlaps),
            "start": "the axisymmetric coupled impact",
            "start_max_overlap_m": s.max_overlaps[0],
            "axisymmetric_start": self.start.summary_blocks(estimate).get("coupling"),
        }
        return {
            "axisymmetric_start_regime": worst_regime(self.start.fe.regime),
            "coupling": coupling,
            "plate_3d": self._summary(),
        }

    def _summary(self) -> dict:
        """The 3-D plate's block of summary.json (SI units)."""
        coupled = self.coupled
        solid, stats = coupled.solid, coupled.work
        shear_strength = solid.solver.surface.shear_strength
        return {
            "iterations": coupled.iterations,
            "converged": coupled.converged,
            "final_change": coupled.change,
            "max_overlaps_m": list(coupled.max_overlaps),
            "tangential_restitutions": list(coupled.tangential_restitutions),
            "max_normal_force_N": float(np.max(solid.normal_force)),
            "max_tangential_force_N": float(np.max(np.abs(solid.tangential_force))),
            "tangential_model": coupled.impact.tangential_model,
            "tangential_mismatch": coupled.tangential_mismatch,
            "surface_shear_strength_Pa": None if math.isinf(shear_strength) else shear_strength,
            "max_contact_radius_m": float(np.max(solid.contact_radius)),
            "max_stick_radius_m": float(np.max(solid.stick_radius)),
            "first_yield_force_N": self.first_yield_force(),
            "max_equivalent_plastic_strain": float(np.max(solid.max_equivalent_plastic_strain)),
            "increments": stats.increments,
            "factorisations": stats.factorisations,
            "linear_solves": stats.solves,
            "dofs": int(solid.final.u.size),
        }

    def pressure_arrays(self) -> dict[str, np.ndarray]:
        s = self.coupled.solid
        return {
            **self.start.pressure_arrays(),
            "fe3d_time_s": self.coupled.times,
            "fe3d_surface_xy_m": s.surface_vertices[:, :2],
            "fe3d_pressure_Pa": s.pressure,
            "fe3d_shear_Pa": s.shear,
            "fe3d_sticking": s.sticking,
            "fe3d_slip_m": s.slip,
        }

    def meshes(self, case: Case, pressure: PressureHistory) -> dict[str, meshio.Mesh]:
        return {"plate_fe": self.coupled.solid.to_meshio()}

    def force_steps(self) -> list[tuple[np.ndarray, np.ndarray, str]]:
        steps = self.coupled.solid
        return [
            *self.start.force_steps(),
            (steps.overlap[:-1], steps.normal_force[:-1], "3-D plate steps"),
        ]

    def _start_dent(self) -> tuple[np.ndarray, np.ndarray]:
        """(r m, residual depth m) of the axisymmetric plate this one started from, for the cross sections."""
        fe = self.start.fe
        order = np.argsort(fe.surface_r)
        return np.asarray(fe.surface_r, float)[order], np.asarray(fe.residual_depth, float)[order]

    def _plastic_section(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
        """The plane of incidence y = 0 of the half plate as the triangles the elements' faces on it tile: their
        vertices (n, 2) (x, z in m, reference configuration), the triangles (m, 3) and their element's mean
        equivalent plastic strain (m,) after the impact; and the largest contact radius (m)."""
        solid = self.coupled.solid
        mesh = solid.solver.disc.mesh
        on_plane = np.abs(mesh.p[1]) <= 1e-9 * float(np.ptp(mesh.p[0]))
        touching = on_plane[mesh.t].sum(axis=0) >= 3
        elements = mesh.t[:, touching].T
        faces = elements[on_plane[elements]].reshape(-1, 3)  # the three vertices of each such element on the plane
        used, local = np.unique(faces, return_inverse=True)
        strain = solid.final.alpha.mean(axis=1)[touching]
        return mesh.p[[0, 2]][:, used].T, local.reshape(-1, 3), strain, float(np.max(solid.contact_radius))


def on_solid_plate(case: Case, estimate: ImpactResult, timed: Timed) -> PlateRun:
    """The case's impact on the 3-D plate, started from the axisymmetric coupled impact (the cheapest start
    measured: its normal law is the 3-D one's within about 1 % at μ = 0); ``timed`` runs each stage."""
    start = on_axisymmetric_plate(case, estimate, timed)
    coupled = timed("plate3d", solid_impact, case, start.impact)
    return SolidRun(coupled, start)


def prepare_solid_case(case: Case) -> Case:
    """The case as the 3-D plate runs it (one-line ``ValueError`` first for one it cannot run)."""
    check_solid_case(case)
    return solid_case(case)
