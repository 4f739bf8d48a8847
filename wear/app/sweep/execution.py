"""Where a sweep's cases run: a local pool of spawned processes or a Dask cluster (:mod:`wear.app.sweep.runner`
records each case as it returns).

A worker process that dies takes its case with it: the local pool restarts and retries the cases that were
running, and gives a case up (recorded as failed) after it was running in :data:`MAX_ATTEMPTS` pool breakdowns; Dask
does the same through its ``allowed-failures`` setting (default 3). Workers run each case with one thread for numba,
OpenMP and BLAS (:data:`~wear.case.workers.THREAD_VARIABLES` = 1; the pool and the client are
:mod:`wear.case.workers`'s).
"""

from __future__ import annotations

import concurrent.futures as cf
from collections.abc import Callable

from wear.app.sweep.spec import SweepCase
from wear.app.sweep.stages import execute_case
from wear.case.workers import THREAD_VARIABLES, dask_client, worker_pool

__all__ = ["MAX_ATTEMPTS", "THREAD_VARIABLES", "SweepAborted", "dask_client", "run_dask", "run_local", "worker_pool"]

#: A case is recorded as failed after the worker running it died this many times.
MAX_ATTEMPTS = 3

Done = Callable[[SweepCase, dict], None]


class SweepAborted(RuntimeError):
    """The local worker processes keep dying without finishing any case (e.g. they cannot start)."""


def run_local(pending: list[SweepCase], stage: str, workers: int, done: Done) -> None:
    """Run ``pending`` on a pool of ``workers`` spawned processes, at most ``workers`` cases in flight.

    When a worker dies the pool is replaced and the cases that were in flight are retried; a case in flight
    during :data:`MAX_ATTEMPTS` breakdowns is recorded as failed. After ``MAX_ATTEMPTS + 2`` breakdowns in a row
    with no case finishing in between, the workers evidently cannot run at all: :class:`SweepAborted`.
    """
    queue = list(reversed(pending))
    attempts: dict[str, int] = {}
    breaks_in_a_row = 0
    while queue:
        running: dict[cf.Future, SweepCase] = {}
        broken = False
        with worker_pool(workers) as pool:  # Ctrl-C terminates the workers
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
        if broken:
            breaks_in_a_row += 1
            if breaks_in_a_row >= MAX_ATTEMPTS + 2:
                raise SweepAborted(
                    f"local worker processes died {breaks_in_a_row} times in a row without finishing a case "
                    "(see their messages above); finished cases are kept"
                )


def run_dask(pending: list[SweepCase], stage: str, client, done: Done) -> None:
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
