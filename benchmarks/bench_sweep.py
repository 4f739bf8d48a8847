"""Benchmark of ``impactwear sweep`` (not a timed test): run ``python3 benchmarks/bench_sweep.py``.

Measured side by side in one run (issue 5, acceptance 4):

1. Speed-up of 2 local workers over 1 on 20 ``run`` cases (``wear.chain.single.run``: impact, FE plate, two-way
   coupling, wear) of the default run case over 20 impact angles, on a mesh twice as coarse as the default
   (``fem.mesh_scale = 2``; with ``--quick`` 4 and fewer increments) so the benchmark takes minutes. Wall time
   includes starting the worker processes (what a user waits for). The load average is printed: other work on
   the machine lowers the speed-up.
2. Per-case overhead of the Dask path (``distributed.LocalCluster``, 2 processes, loopback) against the local
   pool (2 processes), on cheap ``impact`` cases (~1 ms of compute each): the marginal wall time per case,
   (T(N2) − T(N1)) / (N2 − N1), which removes the start-up of pool or cluster; start-up printed separately.

Options: ``--cases N`` for part 1 (default 20), ``--quick`` for a smoke run.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

from wear.app.sweep.runner import run_sweep
from wear.app.sweep.spec import parse_sweep
from wear.app.sweep.stages import STAGES


def heavy_sweep(cases: int, quick: bool) -> tuple[dict, str]:
    """A sweep of ``cases`` cases of the heaviest available stage, and a note on what it is."""
    angles = [round(5 + 80 * i / max(cases - 1, 1), 6) for i in range(cases)]
    if "run" in STAGES:
        # the default run case on a coarser FE mesh with fewer increments, so 20 cases take minutes, not an hour
        fem = {"mesh_scale": 4.0} if quick else {"mesh_scale": 2.0}
        note = f"run stage (wear.chain.single.run), default run case with fem = {fem}"
        return {"sweep": {"stage": "run"}, "base": {"fem": fem}, "grid": {"impact.angle": angles}}, note
    # fallback, should the run stage be unavailable: heavy impacts (~3e6 engine steps each, ~0.2 s)
    dt = 2e-11 if quick else 2e-12
    note = f"impact stage with time_step={dt:g} s (the run stage is not available)"
    return {"sweep": {"stage": "impact"}, "base": {"impact": {"time_step": dt}}, "grid": {"impact.angle": angles}}, note


def timed(spec, **how) -> tuple[float, object]:
    with tempfile.TemporaryDirectory(prefix="bench_sweep_") as tmp:
        start = time.perf_counter()
        outcome = run_sweep(spec, Path(tmp) / "out", quiet=True, **how)
        wall = time.perf_counter() - start
    if outcome.failed:  # a failed case cost its time too; say so rather than hide it
        first = next(iter(outcome.failures.values()))
        print(f"   ({outcome.failed} of {outcome.total} cases failed, e.g. {first[:120]})")
    return wall, outcome


def cheap_sweep(n: int):
    # distinct cases: sweep the speed finely; each impact is ~1 ms of compute
    speeds = [round(1.0 + 4.0 * i / n, 9) for i in range(n)]
    return parse_sweep({"sweep": {"stage": "impact"}, "grid": {"impact.speed": speeds}})


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=20, help="cases in the speed-up part")
    parser.add_argument("--quick", action="store_true", help="smoke run at reduced size")
    parser.add_argument("--part", type=int, choices=(1, 2), help="run only part 1 (speed-up) or 2 (Dask overhead)")
    args = parser.parse_args()
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"impactwear sweep benchmark — {os.cpu_count()} CPUs, Python {sys.version.split()[0]}, load average {load}")

    if args.part != 2:
        part_one(args)
    if args.part != 1:
        part_two(args)
    return 0


def part_one(args) -> None:
    data, note = heavy_sweep(args.cases, args.quick)
    spec = parse_sweep(data)
    print(f"\n1. speed-up of 2 workers over 1: {len(spec.cases)} cases, {note}")
    t1, o1 = timed(spec, workers=1)
    t2, o2 = timed(spec, workers=2)
    print(f"   1 worker : {t1:8.2f} s  ({t1 / len(spec.cases):.3f} s/case, pool start-up included)")
    print(f"   2 workers: {t2:8.2f} s  ({t2 / len(spec.cases):.3f} s/case)")
    print(f"   speed-up : {t1 / t2:8.2f}x  (ideal 2.00x on 2 free cores)")
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"   load average after part 1: {load} (other processes on the machine lower the speed-up)")


def part_two(args) -> None:
    n1, n2 = (20, 60) if args.quick else (50, 250)
    print("\n2. per-case overhead, Dask LocalCluster(2 processes) vs local pool(2 processes), cheap impact cases")
    rows = {}
    for name, how in (("local pool", {"workers": 2}), ("dask local", {"dask_local": 2})):
        ta, _ = timed(cheap_sweep(n1), **how)
        tb, _ = timed(cheap_sweep(n2), **how)
        per_case = (tb - ta) / (n2 - n1)
        startup = ta - n1 * per_case
        rows[name] = per_case
        print(
            f"   {name:10s}: {per_case * 1e3:7.2f} ms/case marginal, start-up ≈ {startup:5.2f} s "
            f"(N={n1}: {ta:.2f} s, N={n2}: {tb:.2f} s)"
        )
    extra = rows["dask local"] - rows["local pool"]
    print(
        f"   Dask overhead per case over the local pool: {extra * 1e3:+.2f} ms "
        f"(ratio {rows['dask local'] / rows['local pool']:.2f}x)"
    )


if __name__ == "__main__":
    sys.exit(main())
