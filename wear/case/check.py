"""Checks of a whole case against the job that runs it, found before any work (one-line ``ValueError`` naming the
key, its value and what the job accepts)."""

from __future__ import annotations

from wear.case.case import Case
from wear.case.jobs import JOBS

__all__ = ["check_job_case"]


def check_job_case(case: Case, job: str) -> Case:
    """``case`` if ``job`` (one of :data:`wear.case.JOBS`) runs it as given, else a one-line ``ValueError``: a job
    that reads ``[fem]`` runs only the plate models (``fem.model``) of its :attr:`wear.case.Job.fem_models`, so
    that a model it would not run is refused, never ignored."""
    spec = JOBS[job]
    if "fem" in spec.tables and case.fem.model not in spec.fem_models:
        accepted = " or ".join(repr(m) for m in spec.fem_models)
        plates = "the axisymmetric plate only" if spec.fem_models == ("axisymmetric",) else f"fem.model={accepted}"
        why = f" ({spec.fem_models_why})" if spec.fem_models_why else ""
        raise ValueError(f"fem.model={case.fem.model!r}: impactwear {job} runs {plates}{why}; set fem.model={accepted}")
    return case
