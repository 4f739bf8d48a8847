"""Benchmark of the wear stage (not a timed test): run ``python3 benchmarks/bench_wear.py``.

Wear integration throughput, in grid-point updates per second (one update = the pressure looked up,
raised to α and accumulated at one grid point for one sub-step), of the parallel numba kernel against a
plain numpy implementation of the same quadrature, measured side by side in one run on the same impact
and grid. Target (issue 4): ≥ 1e8 point-updates/s.

The stage timings of the default ``impactwear run`` (impact, FE, coupling, wear, meshes, figures) are added
to this script by the pipeline.
"""

from __future__ import annotations

import argparse
import math
import os
import sys
import time

import numba
import numpy as np

from contact.materials import Material
from wear import Case, WearLaw, integrate_wear, pressure_history, run, sliding_speed, surface_grid
from wear.accumulate import accumulate_depth, powered_table
from wear.app.outputs.run import write_run
from wear.integrate import integrate_wear_numpy
from wear.substeps import wear_substeps

TARGET_UPDATES_PER_S = 1e8

BALL = Material(E=210e9, nu=0.3, density=7800.0, name="steel")
PLATE = Material(E=210e9, nu=0.3, density=7800.0, yield_strength=400e6, name="steel")


def benchmark_impact(angle: float = 45.0):
    """An oblique steel-on-steel impact (R = 5 mm, 5 m/s, μ = 0.3) from the H-DD engine."""
    from contact import simulate_impact

    return simulate_impact(
        radius=5e-3, ball=BALL, plate=PLATE, speed=5.0, angle=angle, friction=0.3, restitution=0.9, history=True
    )


def point_updates(pressure, sub, x, y) -> int:
    """Grid points visited by the kernel, summed over sub-steps (the same row/column bounds as the kernel)."""
    dx = float(x[1] - x[0])
    reach = np.maximum(pressure.extent[sub.step], pressure.extent[sub.step + 1])
    total = 0
    for yj in y:
        inside = reach > abs(yj)
        half = np.sqrt(reach[inside] ** 2 - yj * yj)
        xc = sub.contact_x[inside]
        lo = np.maximum(0, np.ceil((xc - half - x[0]) / dx))
        hi = np.minimum(x.size - 1, np.floor((xc + half - x[0]) / dx))
        total += int(np.maximum(hi - lo + 1, 0).sum())
    return total


def best_of(fn, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def bench_integration(points_across=(64, 160), repeats: int = 5) -> list[dict]:
    impact = benchmark_impact()
    law = WearLaw(1e-12, alpha=1.0, beta=0.3)
    law_pow = WearLaw(1e-12, alpha=1.5, beta=0.3)
    ph = pressure_history(impact, "hertz")
    speed = sliding_speed(impact, "kinematic")
    t0 = time.perf_counter()
    integrate_wear(ph, speed, law, density=PLATE.density)  # JIT compile (or load from the cache)
    integrate_wear(ph, speed, law_pow, density=PLATE.density)
    compile_s = time.perf_counter() - t0
    print(
        f"impact: steel on steel, R 5 mm, 5 m/s at 45 deg, mu 0.3; {ph.time.size} history samples, "
        f"contact radius {ph.max_extent * 1e6:.1f} um, contact time {impact.contact_time * 1e6:.2f} us"
    )
    print(
        f"numba threads: {numba.get_num_threads()} (cores: {os.cpu_count()}); first call incl. JIT/cache load: "
        f"{compile_s:.2f} s"
    )
    rows = []
    for n in points_across:
        x, y = surface_grid(ph, n)
        sub = wear_substeps(ph, speed, law, float(x[1] - x[0]))
        updates = point_updates(ph, sub, x, y)
        for lw in (law, law_pow):
            fast = best_of(
                lambda lw=lw, n=n: integrate_wear(ph, speed, lw, density=PLATE.density, points_across=n), repeats
            )
            slow = best_of(
                lambda lw=lw, n=n: integrate_wear_numpy(ph, speed, lw, density=PLATE.density, points_across=n), 1
            )
            table = powered_table(ph, lw.alpha)
            depth = np.zeros((y.size, x.size))
            args = (x[0], x[1] - x[0], y, sub.contact_x, sub.step, sub.fraction, sub.weight, ph.extent, table)
            kernel = best_of(lambda args=args, depth=depth: accumulate_depth(depth, *args), repeats)
            a = integrate_wear(ph, speed, lw, density=PLATE.density, points_across=n)
            b = integrate_wear_numpy(ph, speed, lw, density=PLATE.density, points_across=n)
            diff = float(np.abs(a.depth - b.depth).max() / a.max_depth_m)
            rows.append(
                dict(
                    points_across=n,
                    grid=f"{y.size}x{x.size}",
                    substeps=sub.weight.size,
                    alpha=lw.alpha,
                    updates=updates,
                    numba_s=fast,
                    numpy_s=slow,
                    numba_rate=updates / fast,
                    kernel_rate=updates / kernel,
                    numpy_rate=updates / slow,
                    ratio=slow / fast,
                    max_rel_diff=diff,
                )
            )
    return rows


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="timing repeats of the numba kernel (best of)")
    args = parser.parse_args(argv)
    print("== wear integration throughput (grid-point updates per second) ==")
    rows = bench_integration(repeats=args.repeats)
    header = (
        f"{'across':>6} {'grid':>9} {'substeps':>8} {'alpha':>5} {'updates':>10} {'numba s':>9} {'numpy s':>9} "
        f"{'numba upd/s':>12} {'kernel upd/s':>12} {'numpy upd/s':>12} {'ratio':>7} {'max diff':>9}"
    )
    print(header)
    for r in rows:
        print(
            f"{r['points_across']:>6} {r['grid']:>9} {r['substeps']:>8} {r['alpha']:>5.2g} {r['updates']:>10.3g} "
            f"{r['numba_s']:>9.2e} {r['numpy_s']:>9.2e} {r['numba_rate']:>12.3g} {r['kernel_rate']:>12.3g} "
            f"{r['numpy_rate']:>12.3g} "
            f"{r['ratio']:>6.0f}x {r['max_rel_diff']:>9.1e}"
        )
    print("numba s / upd/s: the whole integrate_wear call (sub-steps, grid, kernel, volume, scar); kernel upd/s: the")
    print("numba kernel alone; numpy: the same quadrature in plain numpy (one vectorised patch per sub-step);")
    print("ratio = numpy time / numba time of the whole call; max diff = max |depth difference| / max depth.")
    worst = min(r["numba_rate"] for r in rows)
    verdict = "meets" if worst >= TARGET_UPDATES_PER_S else "MISSES"
    print(f"slowest numba throughput {worst:.3g} updates/s {verdict} the target {TARGET_UPDATES_PER_S:.0e}/s")
    return 0 if math.isfinite(worst) else 1


TARGET_RUN_S = 60.0


def bench_run_stages(out: str | None = None) -> dict:
    """Wall time of each stage of the default ``impactwear run`` (impact, FE, coupling, wear, surface, meshes,
    figures, render), measured in one run of the pipeline as the CLI runs it (numba caches warm after the first
    call of the script; the impact's JIT compile is in the ``impact`` stage on a cold cache). Target: ≤ 60 s."""
    import tempfile

    case = Case()
    folder = out or tempfile.mkdtemp(prefix="bench-run-")
    t0 = time.perf_counter()
    summary = write_run(run(case), os.path.join(folder, "run"))
    total = time.perf_counter() - t0
    print("== default `impactwear run`: wall time per stage ==")
    for stage, seconds in summary["stage_times_s"].items():
        print(f"{stage:>10} {seconds:8.2f} s")
    verdict = "meets" if total <= TARGET_RUN_S else "MISSES"
    print(f"{'total':>10} {total:8.2f} s  ({verdict} the target {TARGET_RUN_S:.0f} s; {os.cpu_count()} CPUs)")
    c = summary["coupling"]
    print(f"coupling: {c['iterations']} impact runs, final change {c['final_change']:.2e}; regime {summary['regime']}")
    return {"total_s": total, **summary["stage_times_s"]}


if __name__ == "__main__":
    status = main()
    bench_run_stages()
    sys.exit(status)
