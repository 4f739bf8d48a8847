r"""Per-face erosion of a wall from impact records read in chunks (:mod:`wear.wall.sources`), on this process, a
local pool of processes or a Dask cluster, in bounded memory.

Each chunk's records are placed on the wall (:func:`wear.wall.hits.hits_on_wall`; the faces of records without one
by the grid of :mod:`wear.wall.grid`), each kept record i (on face :math:`f_i`, :math:`N_i` particles of mass
:math:`m_i`, speed :math:`V_i`, angle :math:`\theta_i` from the normal) gets its eroded volume :math:`W_i` from the
law, and the chunk's per-face sums are

.. math:: W_f = \sum_{f_i = f} W_i, \quad M_f = \sum_{f_i = f} N_i m_i, \quad R_f = \sum_{f_i = f} 1, \quad
          N_f = \sum_{f_i = f} N_i, \quad S_f = \sum_{f_i = f} N_i V_i, \quad
          H_{fb} = \sum_{f_i = f,\ \theta_i \in [e_b, e_{b+1})} N_i

(one ``np.bincount`` each; the last angle bin is closed at 90°), and over the whole wall the particles by speed
:math:`G_c = \sum_{V_i \in [s_c, s_{c+1})} N_i` (:data:`SPEED_EDGES_M_S`; slower and faster particles in the first
and last bins) and the first and last hit times of the records read. Sums of chunks add face by face (:func:`add_sums`),
so the chunks may be summed anywhere; they are added in the plan's order, and the plan does not depend on the
number of workers (:func:`chunk_rows_for`), so that the sums are the same to the last digit on 1 worker or many.
The mean speed of a face's particles is :math:`S_f / N_f`.

**The law** is any object with ``volume(angle_deg, speed_m_s, diameter_m, density_kg_m3, count) -> ndarray``: the
eroded volume (m³) of each record, given arrays of equal length (``count``: particles per record).

**Memory.** Each worker reads and sums one chunk at a time, needing about :data:`BYTES_PER_RECORD` per record;
at most :func:`in_flight` chunks are submitted ahead (the next as a result comes back) and their per-face results
wait to be added in order. :func:`chunk_rows_for` is the largest chunk that fits the budget of
:mod:`wear.case.budget` with a worker on every core, and a plan of larger chunks is refused before any work.

**Workers.** A local pool (``workers``) or a loopback Dask cluster has at most one process per chunk and per core
(:func:`wear.case.workers.bound_workers`); Ctrl-C terminates its processes.
"""

from __future__ import annotations

import concurrent.futures as cf
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from contact.checks import check_instance
from wear.case.budget import check_budget, memory_budget
from wear.case.progress import progress_bar
from wear.case.workers import bound_workers, dask_client, machine_cores, worker_pool
from wear.wall.grid import FaceGrid, face_grid
from wear.wall.hits import hits_on_wall
from wear.wall.mesh import Wall
from wear.wall.options import WallOptions
from wear.wall.records import ImpactRecords
from wear.wall.sources import Chunk, read_chunk
from wear.wall.sums import face_sum, record_volumes

__all__ = [
    "BYTES_PER_RECORD",
    "DEFAULT_ANGLE_EDGES_DEG",
    "SPEED_EDGES_M_S",
    "WallSums",
    "add_sums",
    "chunk_rows_for",
    "chunk_sums",
    "empty_sums",
    "erode_wall",
    "in_flight",
]

#: Edges (deg from the normal) of the angle histogram's bins by default: 10° wide.
DEFAULT_ANGLE_EDGES_DEG = tuple(float(a) for a in range(0, 91, 10))
#: Edges (m/s) of the bins of the wall's speed histogram: 10 per decade from 0.01 to 1000 m/s.
SPEED_EDGES_M_S = tuple(float(v) for v in np.geomspace(0.01, 1000.0, 51))
#: Peak memory (B) per record of a chunk being read and summed, by format: its text as Python strings (a CSV row,
#: a 40-column OpenFOAM line) or its Arrow columns, the impact table, the hits and the law's temporaries. Measured
#: (tracemalloc, 2e5-row chunks on a 1e5-face wall, Finnie): 680 (Parquet), 800 (CSV), 2600 (OpenFOAM v1912's
#: lines); these bounds add half (and Arrow's own memory, which tracemalloc does not see). Fluent's lines (14
#: columns) are not measured: bounded as OpenFOAM's.
BYTES_PER_RECORD = {"parquet": 1000.0, "csv": 1200.0, "openfoam": 4000.0, "fluent": 4000.0}
#: Largest chunk (rows) :func:`chunk_rows_for` gives: bigger chunks are not faster.
MAX_CHUNK_ROWS = 1_000_000


@dataclass(frozen=True, eq=False)
class WallSums:
    """Per-face sums of the records on a wall of f faces (see the module docstring): ``volume_m3`` W, ``mass_kg``
    M (particle mass delivered), ``records`` R (int), ``particles`` N, ``speed_sum_m_s`` S, ``angle_histogram``
    (f, b) H (particles) over the bins ``angle_edges_deg`` (b + 1,); ``skipped`` the records left out, by reason
    (:class:`wear.wall.hits.Hits`; ``other_patches``: on patches of the mesh left out of the wall), the particles
    on the wall by speed ``speed_histogram`` (c,) over the bins
    ``speed_edges_m_s`` (c + 1,), and of every record read: ``records_read``, ``particles_read``, ``mass_read_kg``
    and the first and last hit times ``time_first_s``, ``time_last_s`` (±inf: none read)."""

    volume_m3: np.ndarray
    mass_kg: np.ndarray
    records: np.ndarray
    particles: np.ndarray
    speed_sum_m_s: np.ndarray
    angle_histogram: np.ndarray
    angle_edges_deg: np.ndarray
    skipped: Mapping[str, int] = field(default_factory=dict)
    records_read: int = 0
    particles_read: float = 0.0
    mass_read_kg: float = 0.0
    speed_histogram: np.ndarray = field(default_factory=lambda: np.zeros(len(SPEED_EDGES_M_S) - 1))
    speed_edges_m_s: np.ndarray = field(default_factory=lambda: np.array(SPEED_EDGES_M_S))
    time_first_s: float = np.inf
    time_last_s: float = -np.inf

    def __len__(self) -> int:
        return len(self.volume_m3)

    @property
    def mean_speed_m_s(self) -> np.ndarray:
        """Mean speed of the particles on each face, S / N (m/s; NaN on a face no particle hit)."""
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(self.particles > 0, self.speed_sum_m_s / np.maximum(self.particles, 1e-300), np.nan)


def empty_sums(n_faces: int, edges: Sequence[float] = DEFAULT_ANGLE_EDGES_DEG) -> WallSums:
    """The sums of no record on ``n_faces`` faces."""
    edges = np.asarray(edges, float)
    zero = np.zeros(n_faces)
    return WallSums(
        zero, zero, np.zeros(n_faces, np.int64), zero, zero, np.zeros((n_faces, len(edges) - 1)), edges, {}, 0, 0.0
    )


def add_sums(a: WallSums, b: WallSums) -> WallSums:
    """The sums of the records of ``a`` and ``b`` together, face by face."""
    if len(a) != len(b) or not np.array_equal(a.angle_edges_deg, b.angle_edges_deg):
        raise ValueError("sums of different walls or angle bins cannot be added")
    skipped = {k: a.skipped.get(k, 0) + b.skipped.get(k, 0) for k in sorted({*a.skipped, *b.skipped})}
    return WallSums(
        volume_m3=a.volume_m3 + b.volume_m3,
        mass_kg=a.mass_kg + b.mass_kg,
        records=a.records + b.records,
        particles=a.particles + b.particles,
        speed_sum_m_s=a.speed_sum_m_s + b.speed_sum_m_s,
        angle_histogram=a.angle_histogram + b.angle_histogram,
        angle_edges_deg=a.angle_edges_deg,
        skipped=skipped,
        records_read=a.records_read + b.records_read,
        particles_read=a.particles_read + b.particles_read,
        mass_read_kg=a.mass_read_kg + b.mass_read_kg,
        speed_histogram=a.speed_histogram + b.speed_histogram,
        speed_edges_m_s=a.speed_edges_m_s,
        time_first_s=min(a.time_first_s, b.time_first_s),
        time_last_s=max(a.time_last_s, b.time_last_s),
    )


def chunk_sums(
    records: ImpactRecords,
    wall: Wall,
    law,
    *,
    angle_edges_deg: Sequence[float] = DEFAULT_ANGLE_EDGES_DEG,
    options: WallOptions | None = None,
    locator: FaceGrid | None = None,
) -> WallSums:
    """The per-face sums of ``records`` on ``wall`` with ``law`` (see the module docstring); ``options``,
    ``locator``: as :func:`wear.wall.hits.hits_on_wall`'s."""
    edges = np.asarray(angle_edges_deg, float)
    hits = hits_on_wall(records, wall, options, locator)
    kept = hits.kept
    volume = record_volumes(law, records, hits)
    n = len(wall)
    mass = records.count * records.mass
    b = len(edges) - 1
    which = np.clip(np.searchsorted(edges, hits.angle, side="right") - 1, 0, b - 1)  # 90° in the last bin
    histogram = np.bincount(hits.face[kept] * b + which[kept], weights=records.count[kept], minlength=n * b).reshape(
        n, b
    )
    speed_edges = np.array(SPEED_EDGES_M_S)
    speed_bin = np.clip(np.searchsorted(speed_edges, hits.speed[kept], side="right") - 1, 0, len(speed_edges) - 2)
    return WallSums(
        volume_m3=face_sum(n, hits, volume),
        mass_kg=face_sum(n, hits, mass),
        records=np.bincount(hits.face[kept], minlength=n),
        particles=face_sum(n, hits, records.count),
        speed_sum_m_s=face_sum(n, hits, records.count * hits.speed),
        angle_histogram=histogram,
        angle_edges_deg=edges,
        # the hits on patches left out of the wall were read too: counted apart, so that a note can say so
        skipped={**hits.skipped, **({"other_patches": records.off_wall} if records.off_wall else {})},
        records_read=len(records) + records.off_wall,
        particles_read=float(records.count.sum()),
        mass_read_kg=float(mass.sum()),
        speed_histogram=np.bincount(speed_bin, weights=records.count[kept], minlength=len(speed_edges) - 1),
        speed_edges_m_s=speed_edges,
        time_first_s=float(records.time.min()) if len(records) else np.inf,
        time_last_s=float(records.time.max()) if len(records) else -np.inf,
    )


def in_flight(workers: int) -> int:
    """Chunks read or summed at a time (and results waiting to be added in order): two per worker."""
    return 2 * max(workers, 1)


def _memory_need(rows: float, per_record: float, wall: Wall, workers: int, edges: Sequence[float]) -> float:
    """Upper bound of the peak memory (B) with chunks of ``rows`` rows of ``per_record`` B: the chunks being
    summed (one per worker), and the wall, its grid and the per-face sums (in every worker and the results
    waiting)."""
    per_face = 8.0 * (5 + len(edges))
    fixed = (workers + 1) * (2000.0 * len(wall)) + (in_flight(workers) + 2) * per_face * len(wall)
    return fixed + workers * rows * per_record


def chunk_rows_for(
    wall: Wall, workers: int | None = None, format: str = "openfoam", edges: Sequence[float] = DEFAULT_ANGLE_EDGES_DEG
) -> int:
    """The largest chunk (rows, at most :data:`MAX_CHUNK_ROWS`) of records of ``format`` whose chunks being summed
    on ``workers`` workers (default: one per core, :func:`wear.case.workers.machine_cores`, whatever the workers
    asked for: the plan, and so the sums' last digits, do not depend on them) fit the memory budget
    (:func:`wear.case.budget.memory_budget`; see the module docstring)."""
    workers = machine_cores() if workers is None else workers
    per_record = BYTES_PER_RECORD[format]
    free = memory_budget() - _memory_need(0, per_record, wall, workers, edges)
    return int(max(1, min(MAX_CHUNK_ROWS, free // (workers * per_record))))


@dataclass(frozen=True, eq=False)
class _Job:
    """What every chunk's sums need: the wall, the law, the angle bins and the run's options (:func:`chunk_sums`);
    the wall's grid (:mod:`wear.wall.grid`) is built once per process, for the first chunk."""

    wall: Wall
    law: object
    edges: tuple[float, ...]
    options: WallOptions

    @cached_property
    def grid(self) -> FaceGrid:
        return face_grid(self.wall)

    def sums(self, chunk: Chunk) -> WallSums:
        records = read_chunk(chunk, self.wall)
        return chunk_sums(
            records,
            self.wall,
            self.law,
            angle_edges_deg=self.edges,
            options=self.options,
            locator=self.grid,
        )


_JOB: _Job | None = None  # a pool worker's job, set once by _set_job


def _set_job(job: _Job) -> None:
    global _JOB
    _JOB = job


def _pool_sums(chunk: Chunk) -> WallSums:
    return _JOB.sums(chunk)


def _dask_sums(job: _Job, chunk: Chunk) -> WallSums:
    return job.sums(chunk)


def erode_wall(
    chunks: Sequence[Chunk],
    wall: Wall,
    law,
    options: WallOptions | None = None,
    *,
    progress: bool = True,
    histogram_bins_deg: Sequence[float] = DEFAULT_ANGLE_EDGES_DEG,
) -> WallSums:
    """The per-face sums (:class:`WallSums`) of the records of ``chunks`` (:func:`wear.wall.sources.plan_chunks`)
    on ``wall`` with ``law`` (see the module docstring).

    ``options`` (:class:`wear.wall.options.WallOptions`; default: its defaults): where (``workers``, ``scheduler``) and
    how the records are placed on the wall (``normal``, ``tolerance``, ``skip_bad``: as
    :func:`wear.wall.hits.hits_on_wall`'s). ``progress``: a bar on stderr (on a terminal). ``histogram_bins_deg``: the
    edges of the angle bins (deg from the normal, increasing from 0 to 90). A bad record raises ``ValueError`` naming
    its file and row; a plan whose chunks would not fit the memory budget is refused before any work."""
    options = WallOptions() if options is None else options
    check_instance("options", options, WallOptions, "a wear.wall.options.WallOptions(workers=..., skip_bad=..., ...)")
    workers, scheduler = options.workers, options.scheduler
    edges = np.asarray(histogram_bins_deg, float)
    if len(edges) < 2 or edges[0] != 0.0 or edges[-1] != 90.0 or np.any(np.diff(edges) <= 0):
        raise ValueError(
            f"histogram_bins_deg={list(histogram_bins_deg)!r}: give increasing angle bin edges (deg from the "
            "normal) from 0 to 90"
        )
    chunks = list(chunks)
    if scheduler is None or scheduler == "local":
        workers = bound_workers(workers, len(chunks), "workers")
    if chunks:
        per_record = max(BYTES_PER_RECORD.get(c.format, max(BYTES_PER_RECORD.values())) for c in chunks)
        check_budget(
            "chunk_rows",
            max(c.rows for c in chunks),
            lambda rows: _memory_need(rows, per_record, wall, workers, edges),
            what=f"the records of a chunk on each of {workers} workers",
            valid=(1, MAX_CHUNK_ROWS),
            context=f"{chunks[0].path}: ",
        )
    job = _Job(wall, law, tuple(edges.tolist()), options)
    total = empty_sums(len(wall), edges)
    with progress_bar(sum(c.rows for c in chunks), "impactwear wall", "record", not progress) as update:
        done = 0

        def add(result: WallSums, chunk: Chunk) -> None:
            nonlocal total, done
            total = add_sums(total, result)
            done += chunk.rows
            update(done)

        if scheduler is None and workers == 1:
            for chunk in chunks:
                add(job.sums(chunk), chunk)
        elif scheduler is None:
            with worker_pool(workers, _set_job, (job,)) as pool:
                _run(lambda c: pool.submit(_pool_sums, c), _first_done, chunks, workers, add)
        else:
            _run_dask(job, chunks, workers, scheduler, add)
    return total


def _first_done(futures: list) -> set:
    return cf.wait(futures, return_when=cf.FIRST_COMPLETED)[0]


def _run(submit, wait, chunks: list[Chunk], workers: int, add) -> None:
    """Submit the chunks at most :func:`in_flight` ahead of the next to add (``submit(chunk)`` a future,
    ``wait(futures)`` those finished), and add the results in plan order."""
    window = in_flight(workers)
    running: dict = {}
    ready: dict[int, WallSums] = {}
    nxt = 0  # the next chunk to add
    sent = 0
    try:
        while nxt < len(chunks):
            while sent < len(chunks) and sent < nxt + window:
                running[submit(chunks[sent])] = sent
                sent += 1
            for fut in wait(list(running)):
                ready[running.pop(fut)] = fut.result()
            while nxt in ready:
                add(ready.pop(nxt), chunks[nxt])
                nxt += 1
    except BaseException:
        for fut in running:
            fut.cancel()
        raise


def _run_dask(job: _Job, chunks: list[Chunk], workers: int, scheduler: str, add) -> None:
    """:func:`_run` on a Dask cluster: the job sent once to every worker, the chunks as tasks."""
    import distributed  # optional, and found by dask_client

    client = dask_client(workers, None) if scheduler == "local" else dask_client(None, scheduler)
    try:
        shared = client.scatter(job, broadcast=True)
        _run(
            lambda c: client.submit(_dask_sums, shared, c, pure=False),
            lambda futures: distributed.wait(futures, return_when="FIRST_COMPLETED").done,
            chunks,
            workers if scheduler == "local" else max(1, len(client.nthreads())),
            add,
        )
    finally:
        cluster = client.cluster if scheduler == "local" else None
        client.close()
        if cluster is not None:
            cluster.close()
