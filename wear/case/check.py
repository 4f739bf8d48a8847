"""Checks of a whole case against the job that runs it, found before any work (one-line ``ValueError`` naming the
key, its value and what the job accepts)."""

from __future__ import annotations

from wear.case.case import Case
from wear.case.jobs import JOBS
from wear.case.plate_cases import PLATE_CASES
from wear.case.work import check_wear_grid

__all__ = ["FEM_KEYS_OF_COUPLING", "on_plate", "check_job_case", "check_work", "fem_keys_read"]

#: The ``[fem]`` keys each coupling reads, besides ``fem.model`` and ``fem.coupling``.
FEM_KEYS_OF_COUPLING: dict[str, tuple[str, ...]] = {
    "none": (),
    "one-way": ("load_steps", "unload_steps", "mesh_scale"),
    "two-way": ("tolerance", "max_iterations", "load_steps", "unload_steps", "overshoot", "mesh_scale"),
}


def on_plate(case: Case, model: str, job: str = "run") -> Case:
    """``case`` on the plate ``model`` (one of ``fem.model``'s): the keys only the other plate models read (their
    :attr:`wear.case.plate_cases.PlateCase.fem_keys`) back to ``job``'s defaults, as :func:`check_job_case`
    refuses them at other values."""
    default = JOBS[job].default_case().fem
    others = {key for other, plate in PLATE_CASES.items() if other != model for key in plate.fem_keys}
    return case.with_(fem={"model": model, **{key: getattr(default, key) for key in sorted(others)}})


def fem_keys_read(case: Case, job: str) -> tuple[tuple[str, ...], str]:
    """(the ``[fem]`` keys ``job`` reads for ``case``, what decides it: a phrase for a refusal)."""
    spec = JOBS[job]
    if spec.fem_keys:
        return spec.fem_keys, f"impactwear {job} reads only fem.{', fem.'.join(spec.fem_keys)}"
    coupling = spec.fem_coupling or case.fem.coupling
    own = PLATE_CASES[case.fem.model].fem_keys
    keys = ("model", "coupling", *FEM_KEYS_OF_COUPLING[coupling], *own)
    if own:
        return keys, f"impactwear {job} on the plate fem.model={case.fem.model!r} does not read it"
    if coupling == "none":
        return keys, "with fem.coupling='none' there is no FE plate"
    if coupling == "one-way":
        return keys, f"the one-way coupling reads only fem.{', fem.'.join(FEM_KEYS_OF_COUPLING['one-way'])}"
    readers = [repr(m) for m, plate in PLATE_CASES.items() if plate.fem_keys]
    return keys, f"only the plate fem.model={' or '.join(readers)} reads it"


def check_work(case: Case, job: str) -> None:
    """Refuse ``case`` for ``job`` (``run``, ``repeat`` or ``indent``; other jobs are not estimated here) if its wear
    grid (:func:`wear.case.work.check_wear_grid`) or its plate (its declaration's
    :attr:`wear.case.plate_cases.PlateCase.check_work`) would need more memory or time than the budget: a one-line
    ``ValueError`` naming the key, its value, the estimate and the value of the key that fits (of the keys behind
    the FE time, the first the case changed from the job's default)."""
    check_wear_grid(case, job)
    if job in ("run", "repeat", "indent"):
        PLATE_CASES[case.fem.model].check_work(case, job)


def check_job_case(case: Case, job: str) -> Case:
    """``case`` if ``job`` (one of :data:`wear.case.JOBS`) runs it as given, else a one-line ``ValueError``: a job
    that reads ``[fem]`` runs only the plate models (``fem.model``) of its :attr:`wear.case.Job.fem_models`, so
    that a model it would not run is refused, never ignored; a ``[fem]`` key the job would not read for this case
    (:func:`fem_keys_read`) is refused at any value but the job's default; a job that always runs one coupling
    refuses another ``fem.coupling``; work past the memory or time budget is refused
    (:func:`check_work`)."""
    spec = JOBS[job]
    if "fem" in spec.tables and case.fem.model not in spec.fem_models:
        accepted = " or ".join(repr(m) for m in spec.fem_models)
        plates = "the axisymmetric plate only" if spec.fem_models == ("axisymmetric",) else f"fem.model={accepted}"
        why = f" ({spec.fem_models_why})" if spec.fem_models_why else ""
        raise ValueError(f"fem.model={case.fem.model!r}: impactwear {job} runs {plates}{why}; set fem.model={accepted}")
    if "fem" in spec.tables:
        if spec.fem_coupling and case.fem.coupling != spec.fem_coupling:
            raise ValueError(
                f"fem.coupling={case.fem.coupling!r}: impactwear {job} couples every impact {spec.fem_coupling}; "
                f"leave fem.coupling out or set it to {spec.fem_coupling!r}"
            )
        read, why = fem_keys_read(case, job)
        default = spec.default_case().fem
        for key, value in case.fem.values().items():
            if key not in read and value != getattr(default, key):
                raise ValueError(f"fem.{key}={value!r}: {why}; leave it out (default {getattr(default, key)!r})")
    check_work(case, job)
    return case
