"""Records of repeated impacts (:mod:`wear.chain.repeated_impacts`): one row per computed impact or cycle-jump block,
the run's result and its repeat.csv columns. SI units."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol

import meshio
import numpy as np

from contact import ImpactResult
from fem import CoupledImpact
from wear.case import Case
from wear.integrate import WearMap

__all__ = ["CSV_COLUMNS", "ComputedImpact", "ImpactRecord", "PlateState", "RepeatResult", "yield_strain"]


class PlateState(Protocol):
    """The FE plate a repeat leaves after an impact, as the outputs ask for it."""

    def to_meshio(self) -> meshio.Mesh:
        """The plate as it is now (its mesh, deformed, with its fields)."""
        ...


@dataclass(frozen=True)
class ImpactRecord:
    """One row of ``repeat.csv``: impacts ``first``..``last`` (``count`` of them; ``kind`` "computed" = one
    impact solved, "block" = ``count`` impacts extrapolated from the previous computed one). Per impact of the
    row: ``normal_restitution``, ``max_force`` (N), ``max_pressure`` (Pa, FE), ``contact_radius`` (m, FE at the
    maximum), ``max_overlap`` (m, from first contact), ``first_contact_overlap`` (m, from the original plane),
    ``plastic_strain_increment`` (largest pointwise Δᾱ; for blocks 0 after shakedown, else the last computed one's),
    ``wear_volume`` (m³), ``wear_max_depth`` (m); after the row: ``max_plastic_strain`` ᾱ_max, ``dent_depth``
    (m, largest −u_z of the surface), ``total_wear_volume`` (m³), ``total_wear_max_depth`` (m, of the 2-D map),
    ``surface_depth`` (m, largest dent + axisymmetric wear of the FE surface), ``wear_peak_to_mean`` (2-D max
    depth / azimuthal-average max depth of the impact), ``shaken_down``, ``max_pressure_at_first_force`` (Pa, the
    impact's FE peak pressure when its force passes the first impact's max force: the conforming-dent effect at
    equal force, whereas ``max_pressure`` is at equal impact energy, where a re-impact on its stiffer, elastic
    seat reaches a higher force; NaN if the force never gets there), ``elastic_response`` (the impact was solved on
    the plate's elastic response, :func:`fem.couple_elastic`; for a block: its impacts'), ``pile_up_height`` (m,
    after the row: the largest rise of the surface above the original plane), ``plastic_work`` (J, per impact of
    the row: the whole plate's plastic dissipation; for blocks as ``plastic_strain_increment``),
    ``tangential_restitution`` (of the impact; NaN at normal incidence) and ``wall_time`` (s spent on the row). On
    the 3-D plate (``fem.model = "3d"``, :mod:`wear.chain.solid_repeat`) every row is a computed impact,
    ``max_pressure`` and ``contact_radius`` are the 3-D plate's largest over the impact, ``surface_depth`` is the
    largest dent + accumulated 2-D wear and ``wear_peak_to_mean`` is 1 (no azimuthal average)."""

    first: int
    last: int
    count: int
    kind: str
    normal_restitution: float
    max_force: float
    max_pressure: float
    contact_radius: float
    max_overlap: float
    first_contact_overlap: float
    plastic_strain_increment: float
    wear_volume: float
    wear_max_depth: float
    max_plastic_strain: float
    dent_depth: float
    total_wear_volume: float
    total_wear_max_depth: float
    surface_depth: float
    wear_peak_to_mean: float
    shaken_down: bool
    max_pressure_at_first_force: float = float("nan")
    elastic_response: bool = False
    pile_up_height: float = 0.0
    plastic_work: float = 0.0
    tangential_restitution: float = float("nan")
    wall_time: float = 0.0


#: repeat.csv columns (record field → column name with units).
CSV_COLUMNS = {
    "first": "impact_first",
    "last": "impact_last",
    "count": "impacts_in_row",
    "kind": "computed",
    "normal_restitution": "normal_restitution",
    "max_force": "max_force_N",
    "max_pressure": "max_pressure_Pa",
    "contact_radius": "contact_radius_m",
    "max_overlap": "max_overlap_from_first_contact_m",
    "first_contact_overlap": "first_contact_overlap_m",
    "plastic_strain_increment": "plastic_strain_increment",
    "max_plastic_strain": "max_equivalent_plastic_strain",
    "dent_depth": "dent_depth_m",
    "wear_volume": "wear_volume_per_impact_m3",
    "wear_max_depth": "wear_max_depth_per_impact_m",
    "total_wear_volume": "total_wear_volume_m3",
    "total_wear_max_depth": "total_wear_max_depth_m",
    "surface_depth": "surface_depth_m",
    "wear_peak_to_mean": "wear_peak_to_azimuthal_mean",
    "shaken_down": "shaken_down",
    "max_pressure_at_first_force": "max_pressure_at_first_max_force_Pa",
    "elastic_response": "elastic_response",
    "pile_up_height": "pile_up_height_m",
    "plastic_work": "plastic_work_per_impact_J",
    "tangential_restitution": "tangential_restitution",
    "wall_time": "wall_time_s",
}


@dataclass(frozen=True, eq=False)
class ComputedImpact:
    """One impact solved on the plate: ``coupled`` (:class:`fem.CoupledImpact`: the impact, the plate's cycle and
    pressure, overlaps from first contact), ``wear`` (:class:`wear.WearMap`, x in the first impact's frame) and
    ``wear_profile`` (m, its filtered azimuthal average on the FE surface nodes)."""

    coupled: CoupledImpact
    wear: WearMap
    wear_profile: np.ndarray

    @property
    def impact(self) -> ImpactResult:
        """The coupled impact."""
        return self.coupled.impact


@dataclass(frozen=True, eq=False)
class RepeatResult:
    """``records`` (:class:`ImpactRecord` per computed impact or block), ``plate`` (the FE plate after the last
    impact, :class:`PlateState`: the :class:`fem.Plate`, or on the 3-D plate the
    :class:`fem.solid.plate.SolidPlate`), ``wear`` (cumulative 2-D
    :class:`wear.WearMap` on the first impact's grid, padded),
    ``shakedown_impact`` (first impact with Δᾱ below the tolerance, or None), ``computed`` (number of impacts
    solved), ``wall_time`` (s), ``notes``, ``axis_x`` (m: x of the FE axis, the dent centre, in the wear map's
    frame), ``met_surface``: the surface the last computed impact met — (dent depth, axisymmetric wear depth) on
    the FE surface nodes (m; empty on the 3-D plate); ``halfspace_check`` (the last computed impact's pressure
    against the half-space solution on the surface it met, :func:`wear.chain.check.halfspace_check`; None on the 3-D
    plate, whose dent is not axisymmetric), ``wear_depth_over_taper`` (the FE surface's largest wear depth over the
    plate's taper depth; None on the 3-D plate, whose surface the wear does not move); :attr:`elastic_computed`.
    The repetition's settings are ``case.repeat``."""

    case: Case
    records: list[ImpactRecord]
    plate: PlateState
    wear: WearMap
    shakedown_impact: int | None
    computed: int
    wall_time: float
    notes: list[str] = field(default_factory=list)
    axis_x: float = 0.0
    met_surface: tuple[np.ndarray, np.ndarray] = ()
    halfspace_check: dict | None = None
    wear_depth_over_taper: float | None = None

    @property
    def elastic_computed(self) -> int:
        """How many of the computed impacts were solved on the plate's elastic response (after shakedown)."""
        return sum(r.kind == "computed" and r.elastic_response for r in self.records)

    def columns(self) -> dict[str, list]:
        """repeat.csv columns (name with units → values; ``computed`` 1 for a solved impact, 0 for a block;
        ``shaken_down`` 1/0)."""

        def value(record, name):
            v = getattr(record, name)
            return float(v == "computed") if name == "kind" else float(v)

        return {col: [value(r, f) for r in self.records] for f, col in CSV_COLUMNS.items()}

    def summary(self) -> dict:
        first, last = self.records[0], self.records[-1]
        computed = [r for r in self.records if r.kind == "computed"]
        return {
            "impacts": self.case.repeat.impacts,
            "fem_model": self.case.fem.model,
            "computed_impacts": self.computed,
            "elastic_computed_impacts": self.elastic_computed,
            "rows": len(self.records),
            "shakedown_impact": self.shakedown_impact,
            "shakedown_tolerance_strain": self.case.repeat.shakedown_tolerance * yield_strain(self.case),
            "first_impact": {f: getattr(first, f) for f in CSV_COLUMNS},
            "last_computed_impact": {f: getattr(computed[-1], f) for f in CSV_COLUMNS},
            "after_last_impact": {
                "dent_depth_m": last.dent_depth,
                "total_wear_volume_m3": last.total_wear_volume,
                "total_wear_mass_kg": last.total_wear_volume * self.case.plate.density,
                "total_wear_max_depth_m": last.total_wear_max_depth,
                "surface_depth_m": last.surface_depth,
                "max_equivalent_plastic_strain": last.max_plastic_strain,
                "pile_up_height_m": last.pile_up_height,
                "fe_wear_depth_over_taper_depth": self.wear_depth_over_taper,
            },
            "wall_time_s": self.wall_time,
            "notes": list(self.notes),
        }


def yield_strain(case: Case) -> float:
    """The plate's yield strain Y/E (0 for a plate that never yields)."""
    plate = case.plate.material()
    return plate.yield_strength / plate.E if plate.yield_strength else 0.0
