"""The functions of the sweep stages, their listing (:data:`STAGES`), and the function a worker process calls for
one case.

Each stage is a :class:`wear.app.sweep.stage.Stage` (name, job, tables, description, function, units). A stage's
function is ``case -> dict``: it takes one full, validated case (tables of values, :meth:`wear.Case.to_dict`, SI
units, angles in degrees from the plate normal) and returns a flat dict of JSON scalars (float, int, bool, str or
None). The stage's ``tables`` list the case tables it reads: only those enter the case id, so a change elsewhere in
the schema does not invalidate finished cases.

This module is imported by every worker (local pool or Dask).
"""

from __future__ import annotations

import math
import os
import socket
import time
import traceback
import warnings
from collections.abc import Mapping
from typing import Any

import numpy as np

from contact import simulate_impact
from contact.results import OUTPUT_UNITS
from fem import worst_regime
from wear.app.outputs.fields import unit_of
from wear.app.sweep.stage import Stage
from wear.case import TABLES, Case, check_job_case, default_case
from wear.chain.axisymmetric_run import one_way
from wear.chain.calibrate import calibrate
from wear.chain.calibration_data import read_data
from wear.chain.records import CSV_COLUMNS
from wear.chain.repeated_impacts import repeat
from wear.chain.single import run
from wear.erosion.run import erode_case
from wear.wall import erode_component, read_wall

__all__ = [
    "CALIBRATE_UNITS",
    "ERODE_UNITS",
    "WALL_UNITS",
    "INDENT_UNITS",
    "REPEAT_UNITS",
    "RUN_UNITS",
    "STAGES",
    "calibrate_stage",
    "check_stage_case",
    "erode_stage",
    "execute_case",
    "impact_stage",
    "indent_stage",
    "repeat_stage",
    "run_stage",
    "wall_stage",
    "stage_case",
]


def stage_case(case: dict, job: str) -> Case:
    """The :class:`wear.Case` of a sweep case (tables of values) over ``job``'s default case."""
    return check_job_case(Case.from_dict(case, base=default_case(job)), job)


def _indent_case(case: dict) -> Case:
    """The indent stage's case: the run job's default case, checked as ``impactwear indent`` checks its own (e.g.
    the axisymmetric plate only)."""
    return check_job_case(stage_case(case, "run"), "indent")


def _wall_case(case: dict) -> Case:
    """The wall stage's case, which must name its records and its wall: a sweep has no command line to give them."""
    c = stage_case(case, "wall")
    for key in ("records", "surface"):
        if getattr(c.wall, key) is None:
            raise ValueError(f"wall.{key} is missing: a wall sweep reads its records and wall from the case")
    return c


#: The stages whose function checks more than :func:`stage_case` does: the sweep file is checked with the same
#: function case by case (:func:`check_stage_case`), so that such a case is refused before any case runs instead of
#: failing in a worker after the output folder is made.
_STAGE_CASES = {"indent": _indent_case, "wall": _wall_case}


def check_stage_case(stage: str, case: dict, job: str) -> Case:
    """The :class:`wear.Case` of a sweep case as ``stage`` (of ``job``) will run it, checked as its function checks
    it: a one-line ``ValueError`` naming the key otherwise."""
    check = _STAGE_CASES.get(stage)
    return stage_case(case, job) if check is None else check(case)


def impact_stage(case: dict) -> dict:
    """One impact (:func:`contact.simulate_impact`) of the case's ``[ball]``, ``[plate]``, ``[impact]``.

    Returns the scalar outputs of :class:`contact.ImpactResult` under their own names (SI: restitutions
    dimensionless, angles deg, ``spin`` rad/s, velocities m/s, times s, forces N, lengths m, pressure Pa,
    energies J, ``steps`` count); a non-finite value (e.g. ``tangential_restitution`` at angle 0) is None.
    """
    result = simulate_impact(**stage_case(case, "impact").impact_arguments(), history=False).to_dict()
    return {k: result[k] for k in OUTPUT_UNITS}


def indent_stage(case: dict) -> dict:
    """The FE plate along the case's impact (:func:`fem.indent_impact`, ``fem.load_steps + fem.unload_steps``
    increments, the mesh of ``fem.mesh_scale`` as in ``impactwear run``), one-way: the impact uses the case's
    ``impact.normal_model``.

    Results (SI): ``impact_max_overlap`` (m), ``impact_max_force`` (N), ``max_force`` (N, FE), ``max_contact_radius``
    (m), ``max_pressure`` and ``max_mean_pressure`` (Pa), ``first_yield_force`` (N), ``first_yield_overlap`` (m),
    ``first_yield_depth`` (m below the surface), ``first_yield_radius`` (m; all None if the plate never yields),
    ``residual_max_depth`` (m, dent depth after unloading), ``max_equivalent_plastic_strain``, ``regime`` (the
    most plastic one reached), ``newton_iterations`` (total).
    """
    # the run job's default case, pressed one-way like impactwear indent: on the plates indent runs
    c = _indent_case(case)
    impact = simulate_impact(**c.impact_arguments(history=True))
    res = one_way(c, impact)  # the ball comes with the impact
    fy = res.first_yield
    return {
        "impact_max_overlap": impact.max_overlap,
        "impact_max_force": impact.max_force,
        "max_force": float(np.max(res.force)),
        "max_contact_radius": float(np.max(res.contact_radius)),
        "max_pressure": float(np.max(res.max_pressure)),
        "max_mean_pressure": float(np.nanmax(res.mean_pressure)),
        "first_yield_force": None if fy is None else fy.force,
        "first_yield_overlap": None if fy is None else fy.overlap,
        "first_yield_depth": None if fy is None else fy.depth,
        "first_yield_radius": None if fy is None else fy.radius,
        "residual_max_depth": float(np.max(res.residual_depth)),
        "max_equivalent_plastic_strain": float(np.max(res.max_equivalent_plastic_strain)),
        "regime": worst_regime(res.regime),
        "newton_iterations": int(np.sum(res.newton_iterations)),
    }


#: The indent stage's results that have a unit (SI).
INDENT_UNITS = {
    "impact_max_overlap": "m",
    "impact_max_force": "N",
    "max_force": "N",
    "max_contact_radius": "m",
    "max_pressure": "Pa",
    "max_mean_pressure": "Pa",
    "first_yield_force": "N",
    "first_yield_overlap": "m",
    "first_yield_depth": "m",
    "first_yield_radius": "m",
    "residual_max_depth": "m",
}


def _flat(summary: dict, skip: tuple[str, ...]) -> dict:
    """A summary's scalar numbers under dotted names (``section.key``), without the sections ``skip`` and the
    ``units`` strings."""
    out: dict = {}
    for section, values in summary.items():
        if section in skip:
            continue
        if isinstance(values, dict):
            for key, value in values.items():
                if key != "units" and not isinstance(value, (dict, list, tuple)):
                    out[f"{section}.{key}"] = value
        elif values is not None and not isinstance(values, (list, tuple)):
            out[section] = values
    return out


def run_stage(case: dict) -> dict:
    """The whole chain (:func:`wear.run`: impact, FE plate, coupling, wear, surface; no files written).

    Results: the numbers of ``summary.json`` flattened to dotted names — ``impact.*`` (rebound, times s, forces N,
    lengths m, pressure Pa), ``yield.*`` (N, m/s), ``regime``, ``wear.*`` (``volume_m3``, ``mass_kg``,
    ``max_depth_m``, ``scar_length_m``, ``scar_width_m``, law, pressure source), ``dent.*`` (m) and
    ``coupling.*`` — without the input case and without the stage wall times (not reproducible).
    """
    return _flat(run(stage_case(case, "run")).summary(), ("case", "stage_times_s"))


def erode_stage(case: dict) -> dict:
    """A particle-stream erosion (:func:`wear.erode_case`; no files written). Results: ``stream.*`` (m/s, deg,
    kg/(m² s), s), ``patch.*`` (m, m²), ``results.*`` (``impacts``, ``mass_loss_kg``, ``erosion_rate_kg_per_kg``,
    ``max_depth_m``, ``rms_slope``, ...), without the wall times."""
    return _flat(erode_case(stage_case(case, "erode")).summary(), ("case", "seconds", "table"))


def repeat_stage(case: dict) -> dict:
    """Repeated impacts at one site (:func:`wear.repeat`; no files written). Results: ``impacts``,
    ``computed_impacts``, ``shakedown_impact``, ``first_impact.*``, ``last_computed_impact.*`` and
    ``after_last_impact.*`` (the columns of repeat.csv: SI units in their names), without the wall time."""
    summary = repeat(stage_case(case, "repeat")).summary()
    out = _flat(summary, ("wall_time_s", "notes"))
    return {k: v for k, v in out.items() if not isinstance(v, str)}


def calibrate_stage(case: dict) -> dict:
    """A calibration of the wear law (:func:`wear.chain.calibrate.calibrate`) to the data file ``calibration.data``
    (e.g. one law per case, to compare them on the same data). Results: each fitted constant (its units in the
    schema) with its 95% interval (``*_low``, ``*_high``; None where the data do not determine it), ``rms_log_error``,
    ``fitted_rows``, ``evaluations``."""
    c = stage_case(case, "calibrate")
    result = calibrate(c, read_data(c.calibration.data), c.calibration.free_constants())
    f = result.fit
    out: dict = {"rms_log_error": f.rms_log_error, "fitted_rows": int(f.residuals.size), "evaluations": f.evaluations}
    for name, value, interval in zip(f.names, f.values, f.intervals, strict=True):
        out[name] = value
        out[f"{name}_low"], out[f"{name}_high"] = interval if interval is not None else (None, None)
    return out


#: The run stage's results that have a unit (SI).
RUN_UNITS = {
    **{f"impact.{k}": u for k, u in OUTPUT_UNITS.items()},
    "yield.F_y_paper": "N",
    "yield.F_c_exact": "N",
    "yield.fe_first_yield_force": "N",
    "yield.V_y": "m/s",
    "dent.max_depth_m": "m",
    "dent.centre_x_m": "m",
}

#: The calibrate stage's results that have a unit (SI): the wear law's constants and their intervals, in the units of
#: the case schema (a constant whose unit depends on the law's exponents, as K, is in "SI": docs/keys.md).
CALIBRATE_UNITS = {
    f"{name}{end}": key.units
    for name, key in TABLES["wear"].keys().items()
    if key.units
    for end in ("", "_low", "_high")
}

#: The repeat stage's results that have a unit (SI): those of its first and last computed impact, in the units of
#: their repeat.csv columns (the other results carry theirs in the name).
REPEAT_UNITS = {
    f"{block}.{field}": unit_of(column)
    for block in ("first_impact", "last_computed_impact")
    for field, column in CSV_COLUMNS.items()
    if unit_of(column)
}

#: The erode stage's results that have a unit (SI).
ERODE_UNITS = {
    "stream.speed_m_s": "m/s",
    "stream.angle_deg": "deg",
    "patch.size_m": "m",
    "results.mass_loss_kg": "kg",
    "results.max_depth_m": "m",
}


def wall_stage(case: dict) -> dict:
    """The erosion of a component's wall (:func:`wear.wall.erode_component`; no files written) from the records
    ``wall.records`` on the wall ``wall.surface`` (e.g. one wall material, law or sand rate per case, on the same CFD
    run). Results: ``records.*`` (counts, kg, s), ``wall.*`` (faces, m²), ``exposure_s``, ``rate_scale``,
    ``results.*`` (m³, kg, kg/kg, m/s, mm/year, s, years, m, the allowable sand rate kg/s), without the wall times."""
    c = _wall_case(case)
    result = erode_component(c, c.wall.records, read_wall(c.wall.surface), progress=False)
    return _flat(result.summary(), ("case", "seconds", "law", "exposure_source"))


#: The wall stage's results that have a unit (SI).
WALL_UNITS = {
    "records.particle_mass_kg": "kg",
    "exposure_s": "s",
    "results.eroded_volume_m3": "m^3",
    "results.eroded_mass_kg": "kg",
    "results.max_thickness_loss_mm_year": "mm/year",
    "results.min_remaining_life_year": "year",
    "results.max_wear_depth_m": "m",
    "results.allowable_sand_rate_kg_s": "kg/s",
}


#: The sweep stages by name (``[sweep] stage``), job by job in the order of :data:`wear.case.JOBS`.
STAGES: dict[str, Stage] = {
    stage.name: stage
    for stage in (
        Stage(
            "run",
            "run",
            ("ball", "plate", "impact", "wear", "fem"),
            "the whole chain impact -> FE -> coupling -> wear (wear.run)",
            run_stage,
            RUN_UNITS,
        ),
        Stage(
            "indent",
            "run",
            ("ball", "plate", "impact", "fem"),
            "the FE plate along the impact's overlap history (fem.indent_impact)",
            indent_stage,
            INDENT_UNITS,
        ),
        Stage(
            "impact",
            "impact",
            ("ball", "plate", "impact"),
            "one H-DD impact (contact.simulate_impact)",
            impact_stage,
            OUTPUT_UNITS,
        ),
        Stage(
            "repeat",
            "repeat",
            ("ball", "plate", "impact", "wear", "fem", "repeat"),
            "repeated impacts at one site (wear.repeat)",
            repeat_stage,
            REPEAT_UNITS,
        ),
        Stage(
            "erode",
            "erode",
            ("ball", "plate", "impact", "wear", "erosion"),
            "particle-stream erosion of a plate patch (wear.erode_case)",
            erode_stage,
            ERODE_UNITS,
        ),
        Stage(
            "calibrate",
            "calibrate",
            ("ball", "plate", "impact", "wear", "fem", "calibration"),
            "a calibration of the wear law to measured wear (wear.chain.calibrate)",
            calibrate_stage,
            CALIBRATE_UNITS,
        ),
        Stage(
            "wall",
            "wall",
            ("ball", "plate", "impact", "wear", "wall"),
            "the erosion of a component's wall from CFD or DEM impact records (wear.wall.erode_component)",
            wall_stage,
            WALL_UNITS,
        ),
    )
}


def flat_results(values: Mapping[str, Any], stage: str) -> dict[str, Any]:
    """Check a stage's output: a flat dict of str → JSON scalar (numpy scalars converted; NaN and inf → None)."""
    if not isinstance(values, Mapping):
        raise TypeError(f"stage {stage!r} returned {type(values).__name__}, not a dict")
    out: dict[str, Any] = {}
    for key, value in values.items():
        if hasattr(value, "item") and not isinstance(value, (str, bytes)):
            value = value.item()
        if isinstance(value, float) and not math.isfinite(value):
            value = None
        if not (value is None or isinstance(value, (bool, int, float, str))):
            raise TypeError(f"stage {stage!r} result {key!r} is a {type(value).__name__}, not a JSON scalar")
        out[str(key)] = value
    return out


def execute_case(stage: str, case: dict) -> dict:
    """Run ``case`` through ``stage`` in this process; never raises for an error of the case itself.

    Returns ``{"status": "ok" | "failed", "results": dict | None, "error": str | None, "traceback": str | None,
    "warnings": [str], "elapsed_s": float, "worker": "host:pid"}`` (warnings are recorded, not printed).
    """
    start = time.perf_counter()
    record: dict[str, Any] = {"status": "ok", "results": None, "error": None, "traceback": None}
    # warnings are kept with the case instead of flooding the driver's terminal with one copy per case
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            record["results"] = flat_results(STAGES[stage].run(case), stage)
        except Exception as exc:  # a failed case is recorded and the sweep goes on
            error = f"{type(exc).__name__}: {exc}".splitlines()[0]
            record.update(status="failed", error=error, traceback=traceback.format_exc())
    record["warnings"] = list(dict.fromkeys(f"{w.category.__name__}: {w.message}" for w in caught))
    record["elapsed_s"] = time.perf_counter() - start
    record["worker"] = f"{socket.gethostname()}:{os.getpid()}"
    return record
