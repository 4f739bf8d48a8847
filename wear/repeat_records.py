"""Inputs and records of repeated impacts (:mod:`wear.repeat`): the repetition spec, one row per computed impact
or cycle-jump block, the run's result and its repeat.csv columns. SI units."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from contact import ImpactResult, TabulatedLaw
from contact.validation import check_bool, check_number

from .integrate import WearMap

__all__ = ["CSV_COLUMNS", "ComputedImpact", "ImpactRecord", "RepeatResult", "RepeatSpec"]


@dataclass(frozen=True)
class RepeatSpec:
    """The repetition: ``impacts`` N (≥ 1); ``geometry_update`` (the wear moves the FE surface nodes);
    ``shakedown_tolerance`` (Δᾱ of an impact below this × Y/E counts as no new plastic strain);
    ``surface_fraction`` (a cycle-jump block moves the surface by at most this × the approach of the
    last computed impact, its max overlap from first contact); ``max_plastic_impacts``
    (impacts computed one by one before giving up on shakedown: then blocks continue, see the module docstring);
    ``save_every`` (the CLI writes the FE mesh of every k-th computed impact, plus the first and the last; 0 = none);
    ``wear_smoothing`` (width of the Gaussian filter of the wear profile the FE surface takes, × the contact radius;
    0 = off, which lets a node-scale ripple grow: see :func:`wear.repeat.smooth_profile`);
    ``elastic_after_shakedown`` (after a shaken-down impact the next computed one is solved on the plate's elastic
    response, :func:`fem.elastic_reload`, unless its elastic field yields; false: always the elastic–plastic FE)."""

    impacts: int = 100
    geometry_update: bool = True
    shakedown_tolerance: float = 1e-3
    surface_fraction: float = 0.1
    max_plastic_impacts: int = 20
    save_every: int = 1
    wear_smoothing: float = 0.1
    elastic_after_shakedown: bool = True

    def __post_init__(self) -> None:
        if isinstance(self.impacts, bool) or not isinstance(self.impacts, (int, np.integer)):
            raise ValueError(f"repeat.impacts={self.impacts!r} is not an integer: the number of impacts must be an "
                             "integer in [1, 1e9]")  # fmt: skip
        check_number("repeat.impacts", self.impacts, low=1, high=1e9, what="number of impacts")
        check_bool("repeat.geometry_update", self.geometry_update)
        check_bool("repeat.elastic_after_shakedown", self.elastic_after_shakedown)
        check_number("repeat.shakedown_tolerance", self.shakedown_tolerance, low=0.0, low_open=True, high=1.0,
                     what="shakedown tolerance (fraction of the yield strain)")  # fmt: skip
        check_number("repeat.wear_smoothing", self.wear_smoothing, low=0.0, high=1.0,
                     what="width of the wear profile's filter (fraction of the contact radius)")  # fmt: skip
        check_number("repeat.surface_fraction", self.surface_fraction, low=0.0, low_open=True, high=1.0,
                     what="surface change per cycle-jump block (fraction of the impact's approach)")  # fmt: skip
        for name in ("max_plastic_impacts", "save_every"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
                raise ValueError(f"repeat.{name}={value!r} is not an integer")
        check_number("repeat.max_plastic_impacts", self.max_plastic_impacts, low=1, high=100000)
        check_number("repeat.save_every", self.save_every, low=0, high=1e9)


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
    the plate's elastic response, :func:`wear.repeat.elastic_impact_on_plate`; for a block: its impacts')."""

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
}


@dataclass(frozen=True, eq=False)
class ComputedImpact:
    """One impact solved on the plate: ``impact`` (:class:`contact.ImpactResult`), ``law`` (shifted FE law),
    ``loading``/``unloading`` (fem results, overlaps from the original plane), ``first_contact`` δ₀ (m),
    ``wear`` (:class:`wear.WearMap`, x in the first impact's frame), ``wear_profile`` (m, azimuthal average on the
    FE surface nodes), ``max_pressure`` (Pa), ``contact_radius`` (m), ``iterations``, ``change``,
    ``peak_pressure_curve`` (force (N), FE peak pressure (Pa)) along the loading steps, ``elastic`` (solved on the
    plate's elastic response, the plate's state unchanged) and then ``trial_increment``, the largest Δᾱ a return
    mapping of its elastic field gives (below the shakedown tolerance)."""

    impact: ImpactResult
    law: TabulatedLaw
    loading: Any
    unloading: Any
    first_contact: float
    wear: WearMap
    wear_profile: np.ndarray
    max_pressure: float
    contact_radius: float
    iterations: int
    change: float
    peak_pressure_curve: tuple = ((), ())
    elastic: bool = False
    trial_increment: float = 0.0

    def peak_pressure_at(self, force: float) -> float:
        """FE peak pressure (Pa) when this impact's loading passes ``force`` (N), interpolated between the
        loading steps; NaN beyond its largest force."""
        f, p = (np.asarray(v, float) for v in self.peak_pressure_curve)
        if f.size == 0 or force > f.max():
            return float("nan")
        f = np.maximum.accumulate(f)
        return float(np.interp(force, f, p))


@dataclass(frozen=True, eq=False)
class RepeatResult:
    """``records`` (:class:`ImpactRecord` per computed impact or block), ``plate`` (the :class:`fem.Plate` after
    the last impact), ``wear`` (cumulative 2-D :class:`wear.WearMap` on the first impact's grid, padded),
    ``shakedown_impact`` (first impact with Δᾱ below the tolerance, or None), ``computed`` (number of impacts
    solved), ``wall_time`` (s), ``notes``, ``axis_x`` (m: x of the FE axis, the dent centre, in the wear map's
    frame), ``met_surface``: the surface the last computed impact met — (dent depth, axisymmetric wear depth) on
    the FE surface nodes (m); :attr:`elastic_computed`."""

    case: Any
    spec: RepeatSpec
    records: list
    plate: Any
    wear: WearMap
    shakedown_impact: int | None
    computed: int
    wall_time: float
    notes: list = field(default_factory=list)
    axis_x: float = 0.0
    met_surface: tuple = ()

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
            "impacts": self.spec.impacts,
            "computed_impacts": self.computed,
            "elastic_computed_impacts": self.elastic_computed,
            "rows": len(self.records),
            "shakedown_impact": self.shakedown_impact,
            "shakedown_tolerance_strain": self.spec.shakedown_tolerance * _yield_strain(self.case),
            "first_impact": {f: getattr(first, f) for f in CSV_COLUMNS},
            "last_computed_impact": {f: getattr(computed[-1], f) for f in CSV_COLUMNS},
            "after_last_impact": {
                "dent_depth_m": last.dent_depth,
                "total_wear_volume_m3": last.total_wear_volume,
                "total_wear_mass_kg": last.total_wear_volume * self.case.plate.density,
                "total_wear_max_depth_m": last.total_wear_max_depth,
                "surface_depth_m": last.surface_depth,
                "max_equivalent_plastic_strain": last.max_plastic_strain,
                "fe_wear_depth_over_taper_depth": float(self.plate.wear_depth.max() / self.plate.taper_depth),
            },
            "wall_time_s": self.wall_time,
            "notes": list(self.notes),
        }


def _yield_strain(case) -> float:
    plate = case.plate.material()
    return plate.yield_strength / plate.E if plate.yield_strength else 0.0
