"""Benchmark of a wall's per-face erosion (not a timed test): run ``python3 benchmarks/bench_wall.py``.

Side by side in one run, on a synthetic pipe wall of ``--faces`` triangles (10⁵; normals out of the fluid):

1. impacts per second per core of the per-impact work on records in memory, faces given: a closed-form law
   (Finnie, :func:`wear.laws.finnie.finnie_volume`) and a response-table lookup (the numba
   :func:`wear.erosion.table.table_entries` of the erosion response table, on a synthetic 9 × 17 table: the
   lookup an FE-informed law does per impact), each with the per-face sums (volume, mass, count, speed, angle
   histogram); and the whole chunk path of :func:`wear.wall.engine.chunk_sums` (impact table checks, the angle
   against the face, the law, the sums), with the faces given and found from the positions;
2. the nearest face of records located from their positions: the numba grid (:mod:`wear.wall.grid`) against the
   exact k-d tree search (:func:`wear.wall.locate.nearest_faces`), same answers checked;
3. ``--impacts`` (10⁸) synthetic impacts written as Parquet (row groups of 5 · 10⁵) in a temporary folder, summed by
   :func:`wear.wall.engine.erode_wall` on 2 worker processes: wall time and peak memory (Linux's ``VmHWM``: this
   process's, reset before the run, and each worker's, read while it runs; the peak of the whole run is at most
   their sum); and 1 worker against 2 on the first ``--compare`` impacts, beside the speed-up of a pure-Python
   loop on 2 processes against 1 (the cores the run gets on a shared machine).

Goals (the issue): ≥ 1e7 impacts/s/core for a closed-form law, ≥ 1e6 for a response-table law; 10⁸ impacts on a
10⁵-face wall on 2 cores in ≤ 5 min with ≤ 2 GB. The machine's load is printed (other work shares its cores).
"""

from __future__ import annotations

import argparse
import math
import os
import shutil
import sys
import tempfile
import threading
import time
from dataclasses import dataclass

import numba
import numpy as np

from wear.case.workers import worker_pool
from wear.erosion.table import table_entries
from wear.laws.finnie import finnie_volume
from wear.wall.engine import DEFAULT_ANGLE_EDGES_DEG, chunk_sums, erode_wall
from wear.wall.grid import face_grid
from wear.wall.locate import nearest_faces
from wear.wall.mesh import Wall
from wear.wall.options import WallOptions
from wear.wall.records import ImpactRecords
from wear.wall.sources import plan_chunks

GOAL_CLOSED_FORM = 1e7
GOAL_TABLE = 1e6
GOAL_SECONDS = 300.0
GOAL_MEMORY = 2e9
DIAMETER, DENSITY = 200e-6, 2650.0


@dataclass(frozen=True)
class FinnieLaw:
    """Finnie's volume per record (OpenFOAM's constants: p = 1e9 Pa, K = ψ = 2, c = 1)."""

    flow_pressure: float = 1e9

    def volume(self, angle_deg, speed_m_s, diameter_m, density_kg_m3, count):
        mass = density_kg_m3 * math.pi * diameter_m**3 / 6.0
        return count * finnie_volume(mass, speed_m_s, angle_deg, self.flow_pressure, 2.0, 2.0, 1.0)


@dataclass(frozen=True)
class TableLaw:
    """A response-table law: the volume per unit particle mass at (speed, angle) from a table over normal speed
    and angle (:func:`wear.erosion.table.table_entries`), times the record's mass."""

    normal_speeds: np.ndarray
    angles: np.ndarray
    volume_per_kg: np.ndarray

    def volume(self, angle_deg, speed_m_s, diameter_m, density_kg_m3, count):
        mass = density_kg_m3 * math.pi * diameter_m**3 / 6.0
        out = np.empty(len(angle_deg))
        _lookup(self.normal_speeds, self.angles, self.volume_per_kg, speed_m_s, angle_deg, out)
        return count * mass * out


@numba.njit(cache=True)
def _lookup(normal_speeds, angles, volume, speed, angle, out):
    for i in range(speed.size):
        out[i] = table_entries(normal_speeds, angles, volume, speed[i], angle[i])[1]


def synthetic_table() -> TableLaw:
    speeds = np.geomspace(1.0, 60.0, 9)
    angles = np.linspace(0.0, 85.0, 17)
    v, a = np.meshgrid(speeds, np.radians(angles), indexing="ij")
    volume = 1e-9 * (v / np.cos(a)) ** 2.4 * (0.2 + np.sin(2 * a) ** 2)  # m³/kg, smooth and positive
    return TableLaw(speeds, angles, volume)


def pipe_wall(faces: int, radius: float = 0.05, length: float = 0.5) -> Wall:
    """A pipe along z of about ``faces`` triangles; the fluid inside, the normals pointing out of it."""
    around = max(8, int(round(math.sqrt(faces * math.pi * radius / length / 2.0))))
    along = max(1, faces // (2 * around))
    t = np.linspace(0.0, 2 * math.pi, around, endpoint=False)
    z = np.linspace(0.0, length, along + 1)
    points = np.column_stack(
        [np.tile(radius * np.cos(t), along + 1), np.tile(radius * np.sin(t), along + 1), np.repeat(z, around)]
    )
    i, j = np.meshgrid(np.arange(around), np.arange(along), indexing="ij")
    a = j * around + i
    b = j * around + (i + 1) % around
    c, d = a + around, b + around
    tri = np.concatenate([np.stack([a, b, d], -1).reshape(-1, 3), np.stack([a, d, c], -1).reshape(-1, 3)])
    return Wall(
        points, tri.ravel(), np.arange(0, 3 * len(tri) + 1, 3), np.zeros(len(tri)), ("pipe",), np.arange(len(tri))
    )


def synthetic_impacts(wall: Wall, n: int, rng) -> dict[str, np.ndarray]:
    """``n`` impacts on random faces at their centres, 5–40 m/s, 0–89° from the face normal."""
    face = rng.integers(0, len(wall), n)
    normal = wall.normal[face]
    side = np.cross(normal, [0.0, 0.0, 1.0])
    side /= np.linalg.norm(side, axis=1)[:, None]
    theta = np.radians(rng.random(n) * 89.0)
    speed = 5.0 + 35.0 * rng.random(n)
    velocity = speed[:, None] * (np.cos(theta)[:, None] * normal + np.sin(theta)[:, None] * side)
    return {"face": face, "velocity": velocity}


def kernel_rate(law, wall: Wall, angle, speed, face, repeat: int = 3) -> float:
    """Impacts/s of the law and the per-face sums on arrays in memory (faces given)."""
    n = len(angle)
    d, rho, count = np.full(n, DIAMETER), np.full(n, DENSITY), np.ones(n)
    edges = np.asarray(DEFAULT_ANGLE_EDGES_DEG)
    b = len(edges) - 1
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        volume = law.volume(angle, speed, d, rho, count)
        mass = count * rho * math.pi * d**3 / 6.0
        f = len(wall)
        for w in (volume, mass, count, count * speed):
            np.bincount(face, weights=w, minlength=f)
        np.bincount(face, minlength=f)
        which = np.clip(np.searchsorted(edges, angle, side="right") - 1, 0, b - 1)
        np.bincount(face * b + which, weights=count, minlength=f * b)
        best = min(best, time.perf_counter() - t0)
    return n / best


def chunk_rate(law, wall: Wall, impacts, given: bool = True, repeat: int = 2) -> float:
    """Impacts/s of wear.wall.engine.chunk_sums on a chunk in memory, as the engine calls it (the wall's grid
    built beforehand): faces ``given``, or found from the positions (1e-6 m off the face centres)."""
    n = len(impacts["face"])
    grid = face_grid(wall)
    position = wall.centre[impacts["face"]]
    if not given:
        position = position + 1e-6 * np.random.default_rng(0).normal(size=(n, 3))
    best = np.inf
    for _ in range(repeat):
        t0 = time.perf_counter()
        records = ImpactRecords(
            position=position,
            velocity=impacts["velocity"],
            diameter=np.full(n, DIAMETER),
            density=np.full(n, DENSITY),
            count=np.ones(n),
            time=np.zeros(n),
            face=impacts["face"] if given else np.full(n, -1),
        )
        chunk_sums(records, wall, law, locator=grid)
        best = min(best, time.perf_counter() - t0)
    return n / best


def write_parquet(wall: Wall, n: int, folder: str, rng, group: int = 500_000) -> str:
    import pyarrow as pa
    import pyarrow.parquet as pq

    path = os.path.join(folder, "impacts.parquet")
    schema = pa.schema(
        [("face", pa.int32()), ("u_m_s", pa.float32()), ("v_m_s", pa.float32()), ("w_m_s", pa.float32())]
        + [("diameter_m", pa.float32()), ("density_kg_m3", pa.float32())]
    )
    with pq.ParquetWriter(path, schema) as writer:
        for start in range(0, n, group):
            m = min(group, n - start)
            s = synthetic_impacts(wall, m, rng)
            u = s["velocity"].astype(np.float32)
            columns = [s["face"].astype(np.int32), u[:, 0], u[:, 1], u[:, 2]]
            columns += [np.full(m, DIAMETER, np.float32), np.full(m, DENSITY, np.float32)]
            writer.write_table(pa.Table.from_arrays(columns, schema=schema), row_group_size=group)
    return path


class PeakMemory:
    """Peak resident memory (B, Linux's VmHWM) of this process from now on and of each of its child processes,
    read every 0.2 s while they run (a child's peak is its own: a spawned worker's image is new)."""

    def __init__(self) -> None:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")  # resets this process's VmHWM
        self.children: dict[int, float] = {}
        self.running = True
        self.thread = threading.Thread(target=self._watch, daemon=True)
        self.thread.start()

    @staticmethod
    def _hwm(pid: int | str) -> float:
        try:
            with open(f"/proc/{pid}/status") as f:
                return next(float(line.split()[1]) * 1024 for line in f if line.startswith("VmHWM"))
        except (OSError, StopIteration):
            return 0.0

    def _watch(self) -> None:
        me = str(os.getpid())
        while self.running:
            for pid in os.listdir("/proc"):
                if pid.isdigit():
                    try:
                        with open(f"/proc/{pid}/stat") as f:
                            parent = f.read().rsplit(")", 1)[1].split()[1]
                    except OSError:
                        continue
                    if parent == me:
                        self.children[int(pid)] = max(self.children.get(int(pid), 0.0), self._hwm(pid))
            time.sleep(0.2)

    def stop(self) -> tuple[float, list[float]]:
        self.running = False
        self.thread.join()
        return self._hwm("self"), sorted(self.children.values(), reverse=True)


def _spin(n: int) -> float:
    t0 = time.perf_counter()
    total = 0
    for i in range(n):
        total += i
    return time.perf_counter() - t0


def cpu_seconds() -> float:
    """CPU seconds (user + system) of this process and of its child processes that have ended: a run's threads
    (Arrow decodes Parquet on a pool of its own) and its pool's workers, once the pool is shut."""
    t = os.times()
    return t.user + t.system + t.children_user + t.children_system


def parallel_cores(n: int = 10_000_000) -> float:
    """The cores this run gets now: a pure-Python loop on 1 process against the same loop on each of 2 at once
    (2 on an idle 2-core machine; less when other work shares the cores)."""
    one = _spin(n)
    with worker_pool(2) as pool:
        two = list(pool.map(_spin, [n, n]))
    return 2.0 * one / max(two)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--faces", type=int, default=100_000)
    parser.add_argument("--impacts", type=float, default=1e8)
    parser.add_argument("--compare", type=float, default=2e7, help="impacts of the 1 against 2 workers runs")
    parser.add_argument("--quick", action="store_true", help="1e6 impacts, 1e4 faces")
    args = parser.parse_args(argv)
    if args.quick:
        args.faces, args.impacts, args.compare = 10_000, 1e6, 1e6
    print(f"machine: {os.cpu_count()} cores, load average {os.getloadavg()[0]:.2f} (1 min) at the start")
    rng = np.random.default_rng(1)
    wall = pipe_wall(args.faces)
    print(f"wall: a pipe of {len(wall)} triangles")
    finnie, table = FinnieLaw(), synthetic_table()

    n = 2_000_000
    impacts = synthetic_impacts(wall, n, rng)
    speed = np.linalg.norm(impacts["velocity"], axis=1)
    cosine = np.einsum("ij,ij->i", wall.normal[impacts["face"]], impacts["velocity"]) / speed
    angle = np.degrees(np.arccos(np.clip(cosine, -1, 1)))
    table.volume(angle[:10], speed[:10], np.full(10, DIAMETER), np.full(10, DENSITY), np.ones(10))  # compile
    closed = kernel_rate(finnie, wall, angle, speed, impacts["face"])
    looked = kernel_rate(table, wall, angle, speed, impacts["face"])
    part = {k: v[:1_000_000] for k, v in impacts.items()}
    whole, located = chunk_rate(finnie, wall, part), chunk_rate(finnie, wall, part, given=False)
    print("\n1. per-impact work, one core, faces given (law + per-face sums, arrays in memory):")
    print(f"   closed form (Finnie):   {closed:.3g} impacts/s   goal >= {GOAL_CLOSED_FORM:.0e}")
    print(
        f"   response-table lookup:  {looked:.3g} impacts/s   goal >= {GOAL_TABLE:.0e}  (ratio {closed / looked:.2f})"
    )
    print(f"   whole chunk path (checks, angle from the face, Finnie, sums): {whole:.3g} impacts/s")
    print(f"   whole chunk path, faces found from the positions (the grid): {located:.3g} impacts/s")

    points = wall.centre[impacts["face"][:200_000]] + 1e-5 * rng.normal(size=(200_000, 3))
    t0 = time.perf_counter()
    grid = face_grid(wall)
    built = time.perf_counter() - t0
    grid.nearest(points[:10])
    t0 = time.perf_counter()
    face, distance = grid.nearest(points)
    fast = len(points) / (time.perf_counter() - t0)
    t0 = time.perf_counter()
    exact_face, exact = nearest_faces(wall, points[:20_000])
    slow = 20_000 / (time.perf_counter() - t0)
    same = np.array_equal(distance[:20_000], exact) and np.mean(face[:20_000] == exact_face)
    print("\n2. nearest face of records located from positions (1e-5 m off the wall), one core:")
    print(f"   numba grid: {fast:.3g} points/s (built in {built:.2f} s)   goal >= 1e6")
    print(f"   k-d tree (exact reference): {slow:.3g} points/s   ratio {fast / slow:.0f}")
    print(f"   same distances on 20000 points: {bool(same)}, same faces: {float(same):.6f}")

    folder = tempfile.mkdtemp(prefix="bench_wall_")
    try:
        total = int(args.impacts)
        t0 = time.perf_counter()
        path = write_parquet(wall, total, folder, rng)
        size = os.path.getsize(path)
        print(
            f"\n3. {total:.3g} impacts written as Parquet ({size / 1e9:.2f} GB, row groups of 5e5) in "
            f"{time.perf_counter() - t0:.0f} s"
        )
        chunks = plan_chunks(path, 500_000)
        part = chunks[: max(1, int(args.compare) // 500_000)]
        rows = sum(c.rows for c in part)
        times, fixed, busy = {}, {}, {}
        cores = parallel_cores()
        os.makedirs(os.path.join(folder, "tiny"))
        tiny = plan_chunks(write_parquet(wall, 2000, os.path.join(folder, "tiny"), rng, group=1000), 500_000)
        for workers in (1, 2):
            # the fixed cost of a run: the pool's start (spawned processes importing the toolkit) and each
            # worker's first chunk (the wall's grid, numba's cached kernels): two chunks of 1000 impacts
            t0 = time.perf_counter()
            erode_wall(tiny, wall, finnie, WallOptions(workers=workers), progress=False)
            fixed[workers] = time.perf_counter() - t0
            t0, cpu0 = time.perf_counter(), cpu_seconds()
            sums = erode_wall(part, wall, finnie, WallOptions(workers=workers), progress=False)
            times[workers] = time.perf_counter() - t0
            busy[workers] = (cpu_seconds() - cpu0) / times[workers]
            assert sums.records.sum() == rows
        steady = (times[1] - fixed[1]) / (times[2] - fixed[2])
        print(
            f"   {rows:.3g} impacts: 1 worker (this process) {times[1]:.1f} s, 2 workers {times[2]:.1f} s, "
            f"speed-up {times[1] / times[2]:.2f}; a pure-Python loop on 2 processes against 1 at the same time: "
            f"{cores:.2f} (the cores this run gets; load average {os.getloadavg()[0]:.2f})\n"
            f"   fixed cost of a run (2 chunks of 1000 impacts): 1 worker {fixed[1]:.1f} s, 2 workers {fixed[2]:.1f} s "
            f"(the pool's start); speed-up without it {steady:.2f}\n"
            f"   cores busy on average (CPU seconds of this process and its finished workers per second): "
            f"1 worker {busy[1]:.2f}, 2 workers {busy[2]:.2f}: the most 2 cores can give over 1 worker is "
            f"{2.0 / busy[1]:.2f}"
        )
        del impacts, points, angle, speed, face, distance
        peak = PeakMemory()
        t0 = time.perf_counter()
        sums = erode_wall(chunks, wall, finnie, WallOptions(workers=2), progress=sys.stderr.isatty())
        seconds = time.perf_counter() - t0
        own, children = peak.stop()
        assert sums.records.sum() == total
        print(
            f"   {total:.3g} impacts on {len(wall)} faces, 2 workers: {seconds:.0f} s ({total / seconds:.3g} "
            f"impacts/s)   goal <= {GOAL_SECONDS:.0f} s"
        )
        workers = " + ".join(f"{c / 1e9:.2f}" for c in children)
        print(
            f"   peak memory (VmHWM): this process {own / 1e9:.2f} GB, workers {workers} GB: the run at most "
            f"{(own + sum(children)) / 1e9:.2f} GB   goal <= {GOAL_MEMORY / 1e9:.0f} GB"
        )
        print(f"   load average at the end {os.getloadavg()[0]:.2f}")
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
