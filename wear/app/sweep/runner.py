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
in :data:`MAX_ATTEMPTS` pool breakdowns; Dask does the same through its ``allowed-failures`` setting (default 3).

Workers run each case in a fresh process (``spawn``) with one thread for numba, OpenMP and BLAS (the sweep's
parallelism is across cases), so the same case gives the same numbers, bit for bit, whichever way and with how
many workers the sweep runs. Workers of an existing cluster (``--scheduler``) should set the same variables
(:data:`THREAD_VARIABLES` = 1) for that guarantee.
"""

from __future__ import annotations

import concurrent.futures as cf
import csv
import io
import json
import logging
import multiprocessing
import os
import sys
import threading
import time
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path

from tqdm import tqdm

from wear.app.figures.sweep import plot_sweep
from wear.app.outputs.folder import claim_output_folder
from wear.app.outputs.writer import remove_stale_temps, write_text
from wear.app.sweep.spec import SweepCase, SweepSpec, flatten
from wear.app.sweep.stages import execute_case
from wear.case import STAGES, TABLES

__all__ = ["SweepOutcome", "SweepAborted", "run_sweep", "results_table", "worker_pool", "MAX_ATTEMPTS"]

#: A case is recorded as failed after the worker running it died this many times.
#: What a sweep writes in its folder (the rest of the folder is left alone).
ENTRIES = ("sweep.toml", "cases", "results.csv", "sweep_1d.png", "sweep_2d.png")

MAX_ATTEMPTS = 3

#: Environment variables set to the thread count (1) of every worker, before numpy and numba load.
THREAD_VARIABLES = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS")


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


# ------------------------------------------------------------------------------------------ execution
def _worker_init(parent_pid: int, threads: int) -> None:
    """Limit the worker's threads (before numpy/numba load) and make it exit when the driver disappears."""
    for var in THREAD_VARIABLES:
        os.environ[var] = str(threads)

    def watch() -> None:
        while os.getppid() == parent_pid:
            time.sleep(0.5)
        os._exit(1)  # orphaned by a killed driver: its result would have nowhere to go

    threading.Thread(target=watch, daemon=True).start()


def _threads_per_worker(workers: int) -> int:
    """One: a reduction's result may depend on its thread count, and a sweep's speed comes from its cases."""
    return 1


def worker_pool(workers: int) -> cf.ProcessPoolExecutor:
    """A pool of ``workers`` processes set up as a local sweep's: spawned, each with the thread count of
    :func:`_threads_per_worker` (:data:`THREAD_VARIABLES`), each ending when this process does. A function run on it
    gives the very numbers a sweep's case would (a threaded reduction's last digits depend on its thread count)."""
    return cf.ProcessPoolExecutor(
        max_workers=workers,
        mp_context=multiprocessing.get_context("spawn"),
        initializer=_worker_init,
        initargs=(os.getpid(), _threads_per_worker(workers)),
    )


Done = Callable[[SweepCase, dict], None]


class SweepAborted(RuntimeError):
    """The local worker processes keep dying without finishing any case (e.g. they cannot start)."""


def _run_local(pending: list[SweepCase], stage: str, workers: int, done: Done) -> None:
    """Run ``pending`` on a pool of ``workers`` spawned processes, at most ``workers`` cases in flight.

    When a worker dies the pool is replaced and the cases that were in flight are retried; a case in flight
    during :data:`MAX_ATTEMPTS` breakdowns is recorded as failed. After ``MAX_ATTEMPTS + 2`` breakdowns in a row
    with no case finishing in between, the workers evidently cannot run at all: :class:`SweepAborted`.
    """
    queue = list(reversed(pending))
    attempts: dict[str, int] = {}
    breaks_in_a_row = 0
    while queue:
        pool = worker_pool(workers)
        running: dict[cf.Future, SweepCase] = {}
        broken = False
        try:
            while queue or running:
                while queue and len(running) < workers and not broken:
                    sc = queue.pop()
                    running[pool.submit(execute_case, stage, sc.case)] = sc
                finished, _ = cf.wait(running, return_when=cf.FIRST_COMPLETED)
                for fut in finished:
                    sc = running.pop(fut)
                    try:
                        outcome = fut.result()
                    except cf.process.BrokenProcessPool:
                        broken = True
                        attempts[sc.case_id] = attempts.get(sc.case_id, 0) + 1
                        if attempts[sc.case_id] >= MAX_ATTEMPTS:
                            msg = f"worker process died while running this case ({MAX_ATTEMPTS} times)"
                            done(sc, {"status": "failed", "results": None, "error": msg, "traceback": None})
                        else:
                            queue.append(sc)
                        continue
                    breaks_in_a_row = 0
                    done(sc, outcome)
                if broken and not running:
                    break  # every in-flight case is accounted for: start a fresh pool
        except BaseException:
            _kill_pool(pool)
            raise
        pool.shutdown(wait=True, cancel_futures=True)
        if broken:
            breaks_in_a_row += 1
            if breaks_in_a_row >= MAX_ATTEMPTS + 2:
                raise SweepAborted(
                    f"local worker processes died {breaks_in_a_row} times in a row without finishing a case "
                    "(see their messages above); finished cases are kept"
                )


def _kill_pool(pool: cf.ProcessPoolExecutor) -> None:
    """Stop a pool now (Ctrl-C): cancel queued work and terminate the worker processes."""
    processes = list(getattr(pool, "_processes", {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for proc in processes:
        proc.terminate()


def dask_client(dask_local: int | None = None, scheduler: str | None = None):
    """A ``distributed.Client``: a new loopback ``LocalCluster`` of ``dask_local`` worker processes (one thread
    each) or the existing cluster at ``scheduler`` (``tcp://host:port``). The caller closes it (and its
    ``.cluster`` for a local one)."""
    try:
        import distributed
    except ImportError:
        raise ValueError(
            "--dask-local/--scheduler need dask.distributed, which is not installed: pip install 'impactwear[dask]'"
        ) from None
    if scheduler is not None:
        try:
            return distributed.Client(scheduler, timeout="30s")
        except (OSError, TimeoutError) as exc:
            raise ValueError(f"scheduler={scheduler!r}: cannot connect to a Dask scheduler ({exc})") from None
    threads = _threads_per_worker(dask_local)
    cluster = distributed.LocalCluster(
        n_workers=dask_local,
        threads_per_worker=1,
        processes=True,
        host="127.0.0.1",
        dashboard_address=None,
        silence_logs=logging.ERROR,
        env={v: str(threads) for v in THREAD_VARIABLES},
    )
    return distributed.Client(cluster)


def _run_dask(pending: list[SweepCase], stage: str, client, done: Done) -> None:
    """Submit every pending case to the Dask ``client`` and record each as it completes."""
    import distributed

    futures = {
        client.submit(execute_case, stage, sc.case, key=f"impactwear-{stage}-{sc.case_id}", pure=False): sc
        for sc in pending
    }
    try:
        for fut in distributed.as_completed(futures):
            sc = futures[fut]
            try:
                outcome = fut.result()
            except Exception as exc:  # e.g. KilledWorker after allowed-failures, or the worker cannot import us
                outcome = {
                    "status": "failed",
                    "results": None,
                    "error": f"{type(exc).__name__}: {exc}".splitlines()[0],
                    "traceback": None,
                }
            done(sc, outcome)
            fut.release()
    except BaseException:
        client.cancel(list(futures))
        raise


# ---------------------------------------------------------------------------------------------- tables
def _csv_text(value) -> str:
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)  # shortest text that reads back to the same float
    return str(value)


def results_table(spec: SweepSpec, records: dict[str, dict]) -> tuple[list[str], list[dict], list[str]]:
    """The ``results.csv`` table: (header, rows as dicts column → value, result column names).

    Columns: ``case_id``, ``status``, the swept inputs, the other inputs (dotted keys), the results (union over
    cases, first-seen order; a name clashing with an input gets ``result.``) and ``error``. Rows in expansion
    order; a case without a record has status ``pending``."""
    swept = spec.swept_keys
    others: dict[str, None] = {}
    for sc in spec.cases:
        others.update(dict.fromkeys(k for k in flatten(sc.case) if k not in swept))
    inputs = swept + list(others)
    result_keys: dict[str, None] = {}
    for sc in spec.cases:
        result_keys.update(dict.fromkeys((records.get(sc.case_id) or {}).get("results") or {}))
    named = {k: (f"result.{k}" if k in inputs else k) for k in result_keys}
    header = ["case_id", "status", *inputs, *named.values(), "error"]
    rows = []
    for sc in spec.cases:
        record = records.get(sc.case_id) or {"status": "pending"}
        results = record.get("results") or {}
        row = {"case_id": sc.case_id, "status": record["status"]}
        row.update(flatten(sc.case))
        row.update(sc.inputs)  # the values as written in the sweep file (the figure's axis values)
        row.update({named[k]: results.get(k) for k in result_keys})
        row["error"] = record.get("error")
        rows.append(row)
    return header, rows, list(named.values())


def _write_outputs(spec: SweepSpec, out: Path, records: dict[str, dict]) -> None:
    header, rows, results = results_table(spec, records)
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(header)
    writer.writerows([[_csv_text(row.get(k)) for k in header] for row in rows])
    write_text(out / "results.csv", buf.getvalue(), fsync=True)
    if spec.axes is not None:
        units = {**_input_units(spec.axes), **STAGES[spec.stage].result_units()}
        plot_sweep(spec.axes, rows, results, out, units=units)


def _input_units(keys: Iterable[str]) -> dict[str, str]:
    """SI units of dotted case keys, from the case schema."""
    units = {}
    for dotted in keys:
        table, _, name = dotted.partition(".")
        key = TABLES[table].keys().get(name) if table in TABLES else None
        if key is not None and key.units:
            units[dotted] = key.units
    return units


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

    Exactly one way of running: ``workers`` local processes (default: ``os.cpu_count()``), a loopback
    ``LocalCluster`` of ``dask_local`` processes, or the Dask cluster at ``scheduler``. A KeyboardInterrupt stops
    the workers, keeps every finished case and re-raises (``results.csv`` is then not rewritten).
    """
    if sum(x is not None for x in (workers, dask_local, scheduler)) > 1:
        raise ValueError("workers/dask_local/scheduler: give at most one way of running the sweep")
    for name, value in (("workers", workers), ("dask_local", dask_local)):
        if value is not None and (isinstance(value, bool) or not isinstance(value, int) or not 1 <= value <= 4096):
            raise ValueError(f"{name}={value!r} is out of range: must be an integer in [1, 4096] processes")
    out = claim_output_folder(out, "sweep", ENTRIES)
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
        if pending and (dask_local is not None or scheduler is not None):
            client = dask_client(dask_local, scheduler)
            try:
                _run_dask(pending, spec.stage, client, done)
            finally:
                cluster = client.cluster if dask_local is not None else None
                client.close()
                if cluster is not None:
                    cluster.close()
        elif pending:
            _run_local(pending, spec.stage, workers or os.cpu_count() or 1, done)
    except KeyboardInterrupt:
        outcome.interrupted = True
        bar.close()
        raise
    bar.close()
    _write_outputs(spec, out, records)
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
