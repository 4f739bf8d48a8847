"""Run a sweep (:mod:`wear.app.sweep.spec`) on a local process pool or a Dask cluster, resumably.

Output folder ``DIR``:

- ``DIR/cases/<case-id>.json``: one file per finished case (``case_id``, ``stage``, ``case``, ``status``,
  ``results``, ``error``, ``traceback``, ``elapsed_s``, ``worker``), written by the driver atomically (temp file
  in the same folder, then ``os.replace``) as soon as the case returns. A case is either absent or complete.
- ``DIR/sweep.toml``: the sweep file that was run; ``DIR/results.csv``: one row per case (inputs, results,
  error) in expansion order; ``DIR/sweep_1d.png`` or ``DIR/sweep_2d.png`` for 1-D and 2-D grids. These are
  rewritten (atomically) at the end of every run, including a rerun that finds everything done.

Resuming: a rerun skips every case whose file says ``"status": "ok"`` and runs the rest (failed cases are
retried). Because the driver writes each file once, atomically, after the case returned, killing the driver or a
worker at any moment (Ctrl-C, ``kill -9``) loses at most the cases then running, which the rerun computes again:
nothing is lost, nothing is duplicated. A worker process that dies takes its case with it: the local pool
restarts and retries the cases that were running, and gives a case up (recorded as failed) after it was running
in :data:`~wear.app.sweep.execution.MAX_ATTEMPTS` pool breakdowns; Dask does the same through its
``allowed-failures`` setting (default 3). Where the cases run: :mod:`wear.app.sweep.execution`; the tables:
:mod:`wear.app.sweep.results`.

Workers run each case in a fresh process (``spawn``) with one thread for numba, OpenMP and BLAS (the sweep's
parallelism is across cases), so the same case gives the same numbers, bit for bit, whichever way and with how
many workers the sweep runs. Workers of an existing cluster (``--scheduler``) should set the same variables
(:data:`~wear.case.workers.THREAD_VARIABLES` = 1) for that guarantee.
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from tqdm import tqdm

from wear.app.outputs.folder import check_output_folder, claim_output_folder
from wear.app.outputs.writer import remove_stale_temps, write_text
from wear.app.sweep.execution import dask_client, run_dask, run_local
from wear.app.sweep.results import write_outputs
from wear.app.sweep.spec import SweepCase, SweepSpec
from wear.case.workers import bound_workers, machine_cores

__all__ = ["SweepOutcome", "run_sweep"]

#: What a sweep writes in its folder (the rest of the folder is left alone).
ENTRIES = ("sweep.toml", "cases", "results.csv", "sweep_1d.png", "sweep_2d.png")


@dataclass
class SweepOutcome:
    """What a run did: counts of ``total`` cases, ``skipped`` (already done), ``computed`` now (ok), ``failed``
    (with ``failures``: case id → error), whether it was ``interrupted``, and the output folder ``out``."""

    out: Path
    total: int
    skipped: int = 0
    computed: int = 0
    failed: int = 0
    failures: dict[str, str] = field(default_factory=dict)
    interrupted: bool = False


# ----------------------------------------------------------------------------------------------- files
def _case_path(out: Path, cid: str) -> Path:
    return out / "cases" / f"{cid}.json"


def _read_record(out: Path, sc: SweepCase, stage: str) -> dict | None:
    """The finished record of a case, or None (absent, unreadable or for another stage/case)."""
    try:
        record = json.loads(_case_path(out, sc.case_id).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    if not isinstance(record, dict) or record.get("case_id") != sc.case_id or record.get("stage") != stage:
        return None
    return record


def _write_record(out: Path, sc: SweepCase, stage: str, outcome: dict) -> None:
    record = {"case_id": sc.case_id, "stage": stage, "inputs": sc.inputs, "case": sc.case, **outcome}
    write_text(_case_path(out, sc.case_id), json.dumps(record, indent=1, allow_nan=True) + "\n", fsync=True)


# -------------------------------------------------------------------------------------------- driver
def run_sweep(
    spec: SweepSpec,
    out: str | os.PathLike,
    *,
    workers: int | None = None,
    dask_local: int | None = None,
    scheduler: str | None = None,
    quiet: bool = False,
) -> SweepOutcome:
    """Run every unfinished case of ``spec`` into folder ``out`` (see the module doc) and write the tables.

    Exactly one way of running: ``workers`` local processes (default and at most: one per core, and one per case),
    a loopback ``LocalCluster`` of ``dask_local`` processes (as many at most), or the Dask cluster at
    ``scheduler``. A KeyboardInterrupt stops the workers, keeps every finished case and re-raises (``results.csv``
    is then not rewritten).
    """
    if sum(x is not None for x in (workers, dask_local, scheduler)) > 1:
        raise ValueError("workers/dask_local/scheduler: give at most one way of running the sweep")
    for name, value in (("workers", workers), ("dask_local", dask_local)):
        if value is not None and (isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= 4096):
            raise ValueError(f"{name}={value!r} is out of range: must be an integer in [1, 4096] processes")
    check_output_folder(out, "sweep", ENTRIES)
    # an existing cluster that cannot be reached is refused before the folder is made
    client = None if scheduler is None else dask_client(None, scheduler)
    try:
        return _run_sweep(spec, claim_output_folder(out, "sweep", ENTRIES), workers, dask_local, client, quiet)
    finally:
        if client is not None:
            client.close()


def _run_sweep(spec: SweepSpec, out: Path, workers, dask_local, client, quiet: bool) -> SweepOutcome:
    """:func:`run_sweep` in its claimed folder ``out`` (``client``: the existing cluster's, which the caller
    closes)."""
    (out / "cases").mkdir(exist_ok=True)
    remove_stale_temps(out / "cases")
    if spec.source:
        write_text(out / "sweep.toml", spec.source, fsync=True)

    records: dict[str, dict] = {}
    pending: list[SweepCase] = []
    for sc in spec.cases:
        record = _read_record(out, sc, spec.stage)
        if record is not None and record.get("status") == "ok":
            records[sc.case_id] = record
        else:
            pending.append(sc)
    outcome = SweepOutcome(out=out, total=len(spec.cases), skipped=len(spec.cases) - len(pending))
    if pending:  # the tables are rewritten when every case is done; until then there is no stale one
        for name in ("results.csv", "sweep_1d.png", "sweep_2d.png"):
            (out / name).unlink(missing_ok=True)
    bar = tqdm(
        total=outcome.total,
        initial=outcome.skipped,
        desc=f"sweep {spec.stage}",
        unit="case",
        disable=quiet or not sys.stderr.isatty(),
        file=sys.stderr,
        dynamic_ncols=True,
    )

    def done(sc: SweepCase, result: dict) -> None:
        _write_record(out, sc, spec.stage, result)
        records[sc.case_id] = {
            "status": result["status"],
            "results": result.get("results"),
            "error": result.get("error"),
        }
        if result["status"] == "ok":
            outcome.computed += 1
        else:
            outcome.failed += 1
            outcome.failures[sc.case_id] = result.get("error") or "failed"
            bar.set_postfix(failed=outcome.failed)
        bar.update(1)

    try:
        if pending and client is not None:
            run_dask(pending, spec.stage, client, done)
        elif pending and dask_local is not None:
            local = dask_client(bound_workers(dask_local, len(pending), "dask_local"), None)
            try:
                run_dask(pending, spec.stage, local, done)
            finally:
                cluster = local.cluster
                local.close()
                cluster.close()
        elif pending:
            run_local(pending, spec.stage, bound_workers(workers or machine_cores(), len(pending), "workers"), done)
    except KeyboardInterrupt:
        outcome.interrupted = True
        bar.close()
        raise
    bar.close()
    write_outputs(spec, out, records)
    return outcome


def summary_line(outcome: SweepOutcome) -> str:
    """One line for people: counts and where the table is."""
    return (
        f"{outcome.total} cases: {outcome.computed} computed, {outcome.skipped} already done, "
        f"{outcome.failed} failed; results in {outcome.out / 'results.csv'}"
    )


def failed_lines(outcome: SweepOutcome, limit: int = 10) -> Iterable[str]:
    """Up to ``limit`` lines ``case-id: error`` for the failed cases."""
    for i, (cid, err) in enumerate(outcome.failures.items()):
        if i == limit:
            yield f"... and {len(outcome.failures) - limit} more (see {outcome.out / 'cases'})"
            return
        yield f"{cid}: {err}"
