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
import pickle
import re
import socket
import threading
import time
import warnings
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from multiprocessing.reduction import ForkingPickler

__all__ = ["THREAD_VARIABLES", "bound_workers", "dask_client", "machine_cores", "worker_pool"]

#: Seconds a Dask client waits for a scheduler that accepted the connection (a remote one may be slow to answer).
CONNECT_SECONDS = 30.0
#: Seconds to open a TCP connection to a scheduler's address before it is refused as unreachable.
PROBE_SECONDS = 5.0
_TCP_ADDRESS = re.compile(r"(?:tcp://)?\[?(?P<host>[^\[\]/]+?)\]?:(?P<port>\d+)")

#: Seconds the worker processes of a local pool have to start (spawn, import numpy and numba) before the pool is
#: given up: a worker that dies while starting would otherwise leave the pool waiting for ever.
STARTUP_SECONDS = 120.0

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


def _worker_init(parent_pid: int, threads: int, setup) -> None:
    """Make the worker exit when the driver disappears, then run the caller's initializer on its arguments, both
    pickled in the queue ``setup`` (None: no initializer; see :func:`worker_pool`). The thread count is in the
    environment the worker started with (:func:`_thread_environment`)."""
    for var in THREAD_VARIABLES:
        os.environ[var] = str(threads)

    def watch() -> None:
        while os.getppid() == parent_pid:
            time.sleep(0.5)
        os._exit(1)  # orphaned by a killed driver: its result would have nowhere to go

    threading.Thread(target=watch, daemon=True).start()
    if setup is not None:
        initializer, initargs = pickle.loads(setup.get())
        initializer(*initargs)


def _threads_per_worker(workers: int | None) -> int:
    """One: a reduction's result may depend on its thread count, and the speed comes from the workers."""
    return 1


def machine_cores() -> int:
    """The cores this process may run on (its CPU affinity where the system tells, else the machine's count)."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        return os.cpu_count() or 1


def bound_workers(workers: int, tasks: int, option: str) -> int:
    """The worker processes to start for ``tasks`` tasks when ``workers`` are asked for (by ``option``): at most
    one per task and one per core (:func:`machine_cores`; more processes than cores only share them, each holding
    its own memory). Fewer cores than asked for is a warning (the command's ``note:``)."""
    cores = machine_cores()
    bounded = max(1, min(workers, cores, tasks))
    if workers > cores:
        warnings.warn(
            f"{option}={workers}: this machine has {cores} cores; running {bounded} worker processes", stacklevel=2
        )
    return bounded


@contextmanager
def worker_pool(
    workers: int, initializer: Callable | None = None, initargs: tuple = ()
) -> Iterator[cf.ProcessPoolExecutor]:
    """A pool of ``workers`` processes for a ``with`` block: spawned, each with the thread count of
    :func:`_threads_per_worker` (:data:`THREAD_VARIABLES`), each ending when this process does, each running
    ``initializer(*initargs)`` once (e.g. to keep data every task of the pool reads). Leaving the block normally
    waits for the tasks submitted; leaving it by an exception (Ctrl-C, a task's error) cancels the queued tasks
    and terminates the workers at once.

    The workers start side by side: ``initializer`` and ``initargs`` (a wall of 10⁵ faces: 15 MB) reach each
    worker through a queue once it runs, not with its start. A spawned process reads what it is started with only
    after importing its driver's main module, and the pool starts its processes one after another, each start
    waiting until the process has read it (a pipe holds 64 KiB): started with the arguments, the workers imported
    one after another."""
    threads = _threads_per_worker(workers)
    context = multiprocessing.get_context("spawn")
    setup = None if initializer is None else context.Queue()
    pool = cf.ProcessPoolExecutor(
        max_workers=workers, mp_context=context, initializer=_worker_init, initargs=(os.getpid(), threads, setup)
    )
    try:
        if setup is not None:
            # a worker killed before reading its copy leaves its sender thread waiting: never wait for it at exit
            setup.cancel_join_thread()
            # pickled here, once: what cannot be pickled fails now, not in the queue's sender thread
            payload = bytes(ForkingPickler.dumps((initializer, initargs)))
            for _ in range(workers):
                setup.put(payload)
        with _thread_environment(threads):
            # the pool spawns a process per task submitted while none is idle: start them all now, in this environment
            try:
                for done in [pool.submit(_started) for _ in range(workers)]:
                    done.result(timeout=STARTUP_SECONDS)
            except BaseException as exc:
                _kill(pool)
                if isinstance(exc, cf.TimeoutError):
                    raise RuntimeError(
                        f"{workers} worker processes did not start within {STARTUP_SECONDS:g} s (see their messages "
                        "above)"
                    ) from None
                raise
        try:
            yield pool
        except BaseException:
            _kill(pool)
            raise
        pool.shutdown(wait=True, cancel_futures=True)
    finally:
        if setup is not None:
            setup.close()


def _kill(pool: cf.ProcessPoolExecutor) -> None:
    """Stop ``pool`` now: cancel its queued tasks and terminate its worker processes (a task running for minutes
    would otherwise hold Ctrl-C until it ends)."""
    processes = list((getattr(pool, "_processes", None) or {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for process in processes:
        process.terminate()
    for process in processes:
        process.join(timeout=5.0)


def _probe(address: str) -> None:
    """Refuse a TCP scheduler address where nothing listens, at once: Dask's client retries a refused connection
    until its timeout (:data:`CONNECT_SECONDS`). Other protocols (tls://, ucx://, ...) are left to Dask."""
    match = _TCP_ADDRESS.fullmatch(address)
    if match is None:
        return
    try:
        with socket.create_connection((match["host"], int(match["port"])), timeout=PROBE_SECONDS):
            pass
    except OSError as exc:
        raise ValueError(
            f"scheduler={address!r}: cannot connect to a Dask scheduler ({exc.strerror or exc or 'timed out'})"
        ) from None


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
        _probe(scheduler)
        try:
            return distributed.Client(scheduler, timeout=f"{CONNECT_SECONDS:g}s")
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
