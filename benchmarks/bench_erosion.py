"""Benchmark of the stream erosion (not a timed test): run ``python3 benchmarks/bench_erosion.py``.

Impacts per second of :func:`wear.erosion.stream.erode` on a 512 × 512 periodic patch — every impact: local slope,
local angle and normal speed, table interpolation, rotated footprint stamped on the height field — with the
numba kernel against a plain numpy implementation of the same update (``engine="numpy"``: one impact at a
time, vectorised over the nodes of its footprint), side by side in one run on the same table and patch.
Both are timed as whole ``erode`` calls (time series, frames and sampling included), numba on many more
impacts than numpy (the rate per impact is what is compared). Target (issue 6): ≥ 1e5 impacts per minute
on 2 cores. The update is sequential (each impact sees the surface the previous ones left), so one core works.

The stream: silica sand (R = 150 µm) on steel at 20 m/s, 45° from the normal, 0.464 kg/m³ (the paper's Fig. 10
conditions); wear law α = 1, β = 0.3, K = 1e-11 (SI).
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time

import numba
import numpy as np

from contact import Material
from wear import WearLaw
from wear.erosion import ImpactResponse, Stream, build_response_table, erode, table_axes

TARGET_IMPACTS_PER_MINUTE = 1e5

SAND = Material(E=94e9, nu=0.17, density=2650.0, name="silica sand")
STEEL = Material(E=200e9, nu=0.3, density=7850.0, yield_strength=350e6, name="steel")


def build_table(angle: float = 45.0):
    law = WearLaw(K=1e-11, alpha=1.0, beta=0.3)
    response = ImpactResponse(150e-6, SAND, STEEL, 0.3, law)
    vn, angles = table_axes(20.0, angle)
    return build_response_table(response, vn, angles)


def exposure_for(table, stream_angle: float, impacts: int, grid: int) -> float:
    """Exposure time (s) giving about ``impacts`` impacts on the default patch of ``grid`` nodes."""
    probe = Stream(20.0, stream_angle, 1.0, concentration=0.464)
    _, _, length = table.interpolate(20.0 * math.cos(math.radians(stream_angle)), stream_angle)
    area = (grid * length / 4.0) ** 2
    per_second = probe.plate_flux * area / table.particle_mass
    return impacts / per_second


def run(engine: str, table, impacts: int, grid: int, angle: float) -> tuple[float, int, object]:
    stream = Stream(20.0, angle, exposure_for(table, angle, impacts, grid), concentration=0.464)
    t0 = time.perf_counter()
    result = erode(table, stream, grid=grid, seed=1, engine=engine, frames=1, samples=20)
    return time.perf_counter() - t0, result.n_impacts, result


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grid", type=int, default=512, help="nodes per side of the patch")
    parser.add_argument("--impacts", type=int, default=500_000, help="impacts of the numba run")
    parser.add_argument("--numpy-impacts", type=int, default=3_000, help="impacts of the numpy run")
    parser.add_argument("--angle", type=float, default=45.0, help="stream angle from the normal (deg)")
    args = parser.parse_args(argv)
    t0 = time.perf_counter()
    table = build_table(args.angle)
    t_table = time.perf_counter() - t0
    print(f"response table: {table.resolution}; built in {t_table:.2f} s")
    print(f"numba threads: {numba.get_num_threads()} (cores: {os.cpu_count()}); the update is sequential")
    run("numba", table, 1000, args.grid, args.angle)  # JIT compile or cache load
    rows = []
    for engine, n in (("numba", args.impacts), ("numpy", args.numpy_impacts)):
        seconds, count, result = run(engine, table, n, args.grid, args.angle)
        rows.append((engine, count, seconds, count / seconds, result))
    print(f"{'engine':>7} {'grid':>9} {'impacts':>9} {'seconds':>9} {'impacts/s':>11} {'impacts/min':>12}")
    for engine, count, seconds, rate, _ in rows:
        print(f"{engine:>7} {args.grid:>4}x{args.grid:<4} {count:>9} {seconds:>9.3f} {rate:>11.4g} {60 * rate:>12.4g}")
    fast, slow = rows[0][3], rows[1][3]
    print(f"ratio numba / numpy: {fast / slow:.0f}x (impacts per second, same update, same patch and table)")
    # the same first impacts give the same surface with both engines
    check = Stream(20.0, args.angle, exposure_for(table, args.angle, 200, args.grid), concentration=0.464)
    a = erode(table, check, grid=args.grid, seed=7, frames=1, samples=1)
    b = erode(table, check, grid=args.grid, seed=7, frames=1, samples=1, engine="numpy")
    diff = float(np.abs(a.wear - b.wear).max() / a.wear.max())
    print(f"numba vs numpy surfaces after {a.n_impacts} impacts: max |difference| / max depth = {diff:.1e}")
    verdict = "meets" if 60 * fast >= TARGET_IMPACTS_PER_MINUTE else "MISSES"
    print(f"numba: {60 * fast:.3g} impacts/min {verdict} the target {TARGET_IMPACTS_PER_MINUTE:.0e}/min")
    return 0


if __name__ == "__main__":
    sys.exit(main())
