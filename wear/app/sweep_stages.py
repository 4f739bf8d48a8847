"""The stages a sweep can run, and the function a worker process calls for one case.

A stage is a function ``case -> dict``: it takes one full, validated case (the nested dict of
:func:`wear.app.case.case_to_dict`, SI units, angles in degrees from the plate normal) and returns a flat dict of
JSON scalars (float, int, bool, str or None). ``tables`` lists the case tables the stage reads: only those enter
the case id, so a change elsewhere in the schema does not invalidate finished cases.

This module is imported by every worker (local pool or Dask): keep its top-level imports light.
"""

from __future__ import annotations

import math
import os
import socket
import time
import traceback
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

__all__ = ["Stage", "STAGES", "execute_case", "impact_stage"]


@dataclass(frozen=True)
class Stage:
    """A sweep stage: ``name``, ``function`` (case dict → flat result dict), ``tables`` it reads (None = all),
    ``check``: a cheap validation of a checked case beyond the schema, run before anything runs (raises
    ``ValueError`` naming the key), ``units``: result name → SI unit (for figures), and ``defaults``: the case
    (tables of values) that a sweep's ``[base]`` is laid over — empty means the case schema's embedded default
    case (that of ``impactwear impact``)."""

    name: str
    function: Callable[[dict], dict]
    tables: tuple[str, ...] | None
    description: str
    check: Callable[[dict], None] = lambda case: None
    units: Callable[[], dict[str, str]] = dict
    defaults: Callable[[], dict] = dict


def impact_stage(case: dict) -> dict:
    """One impact (:func:`contact.simulate_impact`) of the case's ``[ball]``, ``[plate]``, ``[impact]``.

    Returns the scalar outputs of :class:`contact.ImpactResult` under their own names (SI: restitutions
    dimensionless, angles deg, ``spin`` rad/s, velocities m/s, times s, forces N, lengths m, pressure Pa,
    energies J, ``steps`` count); a non-finite value (e.g. ``tangential_restitution`` at angle 0) is None.
    """
    from contact import simulate_impact
    from contact.results import OUTPUT_UNITS

    from .case import impact_arguments

    result = simulate_impact(**impact_arguments(case), history=False).to_dict()
    return {k: result[k] for k in OUTPUT_UNITS}


def _impact_units() -> dict[str, str]:
    from contact.results import OUTPUT_UNITS

    return dict(OUTPUT_UNITS)


def _check_impact(case: dict) -> None:
    """Build the materials (Material's own checks) without running anything."""
    from .case import impact_arguments

    impact_arguments(case)


STAGES: dict[str, Stage] = {
    "impact": Stage(
        "impact",
        impact_stage,
        ("ball", "plate", "impact"),
        "one H-DD impact (contact.simulate_impact)",
        _check_impact,
        _impact_units,
    ),
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
    "elapsed_s": float, "worker": "host:pid"}``.
    """
    start = time.perf_counter()
    record: dict[str, Any] = {"status": "ok", "results": None, "error": None, "traceback": None}
    try:
        record["results"] = flat_results(STAGES[stage].function(case), stage)
    except Exception as exc:  # a failed case is recorded and the sweep goes on
        record.update(
            status="failed", error=f"{type(exc).__name__}: {exc}".splitlines()[0], traceback=traceback.format_exc()
        )
    record["elapsed_s"] = time.perf_counter() - start
    record["worker"] = f"{socket.gethostname()}:{os.getpid()}"
    return record
