"""Where parallel work runs: a local pool of spawned processes or a Dask cluster, each worker with one thread for
numba, OpenMP and BLAS (:data:`THREAD_VARIABLES` = 1), so that a function gives the very numbers on any worker (a
threaded reduction's last digits depend on its thread count). Sweeps (:mod:`wear.app.sweep.execution`) and a wall's
per-face sums (:mod:`wear.wall.engine`) run on these.
"""

from __future__ import annotations

import concurrent.futures as cf
import logging
import multiprocessing
import os
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager

__all__ = ["THREAD_VARIABLES", "dask_client", "worker_pool"]

#: Environment variables set to the thread count (1) of every worker, before numpy and numba load.
THREAD_VARIABLES = ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "NUMBA_NUM_THREADS")


@contextmanager
def _thread_environment(threads: int) -> Iterator[None]:
    """:data:`THREAD_VARIABLES` set to ``threads`` in this process's environment for the block, then restored: a
    process spawned inside it starts with them, before it imports numpy or numba (a spawned worker imports the
    modules of its functions, and the driver's main module, before any initializer runs; numba reads
    NUMBA_NUM_THREADS once, at import, and refuses another value after its threads started)."""
    saved = {var: os.environ.get(var) for var in THREAD_VARIABLES}
    os.environ.update({var: str(threads) for var in THREAD_VARIABLES})
    try:
        yield
    finally:
        for var, value in saved.items():
            if value is None:
                os.environ.pop(var, None)
            else:
                os.environ[var] = value


def _started() -> int:
    return os.getpid()


def _worker_init(parent_pid: int, threads: int, initializer: Callable | None, initargs: tuple) -> None:
    """Make the worker exit when the driver disappears, then run the caller's ``initializer`` (the thread count is
    in the environment the worker started with, :func:`_thread_environment`)."""
    for var in THREAD_VARIABLES:
        os.environ[var] = str(threads)

    def watch() -> None:
        while os.getppid() == parent_pid:
            time.sleep(0.5)
        os._exit(1)  # orphaned by a killed driver: its result would have nowhere to go

    threading.Thread(target=watch, daemon=True).start()
    if initializer is not None:
        initializer(*initargs)


def _threads_per_worker(workers: int | None) -> int:
    """One: a reduction's result may depend on its thread count, and the speed comes from the workers."""
    return 1


def worker_pool(workers: int, initializer: Callable | None = None, initargs: tuple = ()) -> cf.ProcessPoolExecutor:
    """A pool of ``workers`` processes: spawned, each with the thread count of :func:`_threads_per_worker`
    (:data:`THREAD_VARIABLES`), each ending when this process does, each running ``initializer(*initargs)`` once
    (e.g. to keep data every task of the pool reads)."""
    threads = _threads_per_worker(workers)
    pool = cf.ProcessPoolExecutor(
        max_workers=workers,
        mp_context=multiprocessing.get_context("spawn"),
        initializer=_worker_init,
        initargs=(os.getpid(), threads, initializer, initargs),
    )
    with _thread_environment(threads):
        # the pool spawns a process per task submitted while none is idle: start them all now, in this environment
        for done in [pool.submit(_started) for _ in range(workers)]:
            done.result()
    return pool


def dask_client(dask_local: int | None = None, scheduler: str | None = None):
    """A ``distributed.Client``: a new loopback ``LocalCluster`` of ``dask_local`` worker processes (one thread
    each) or the existing cluster at ``scheduler`` (``tcp://host:port``). The caller closes it (and its
    ``.cluster`` for a local one)."""
    try:
        import distributed  # optional: only Dask runs need it
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
