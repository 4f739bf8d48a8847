"""Benchmark of repeated oblique impacts at one site on the 3-D plate (``impactwear repeat`` with
``fem.model = "3d"``): the default case (alumina R 2.5 mm on Ti-6Al-4V, 3 m/s at 30° from the normal, μ = 0.3),
N impacts each coupled to the plate the previous ones left (:mod:`wear.chain.solid_repeat`).

Prints one row per impact (dent, pile-up, plastic work, wear, e_n, e_t, 3-D plate cycles, wall time) and the mean
wall time per repeated impact (impacts 2..N: the first also builds the plate and runs the axisymmetric start), side
by side with the axisymmetric repeat of the same case in the same run (its frictionless (r, z) plate, every impact
computed: no elastic shortcut), and their ratio. Before them, unless ``--no-before``, the same 3-D repeat with each
later impact's coupling started from the previous impact (the chain before the reloading law,
:func:`fem.force_law.reloading_law`), side by side.

Run: ``python benchmarks/bench_solid_repeat.py`` (default mesh, 4 elements across the contact; ``--quick``: 3
elements, 4 + 3 increments; ``--impacts N``, ``--mesh-scale S``, ``--no-before``).
"""

from __future__ import annotations

import argparse
import time
import warnings

import numpy as np

import wear.chain.solid_repeat as solid_repeat
from wear.case import JOBS
from wear.case.check import on_plate
from wear.chain.repeated_impacts import repeat

_NEXT_START = solid_repeat._next_start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="3 elements across the contact, 4 + 3 increments")
    parser.add_argument("--impacts", type=int, default=5)
    parser.add_argument("--mesh-scale", type=float, default=None)
    parser.add_argument("--no-before", action="store_true", help="skip the repeat started from the previous impact")
    args = parser.parse_args()
    warnings.filterwarnings("ignore")
    fem = {"model": "3d"}
    if args.quick:
        fem.update(mesh_scale=2.6, solid_load_steps=4, solid_unload_steps=3, solid_iterations=2)
    if args.mesh_scale is not None:
        fem["mesh_scale"] = args.mesh_scale
    case = (
        JOBS["repeat"]
        .default_case()
        .with_(
            fem=fem,
            repeat={"impacts": args.impacts, "geometry_update": False},
            output={"render": False, "figures": False},
        )
    )
    t0 = time.perf_counter()

    def progress(done: int, total: int) -> None:
        print(f"  impact {done}/{total} at {time.perf_counter() - t0:.1f} s", flush=True)

    runs = {}
    if not args.no_before:
        print("3-D repeat, each later impact started from the previous impact:", flush=True)
        runs["from the previous impact"] = _solid_repeat(case, progress, lambda on_law, coupled: coupled.impact)
    print("3-D repeat, each later impact started on the reloading law:", flush=True)
    runs["on the reloading law"] = _solid_repeat(case, progress)
    axisymmetric = repeat(
        on_plate(case, "axisymmetric", "repeat").with_(repeat={"elastic_after_shakedown": False}), progress=progress
    )
    plane = _per_repeated_impact(axisymmetric)
    for name, (result, cycles) in runs.items():
        print(f"\n3-D repeat, later impacts started {name}:")
        print(
            f"{'impact':>6} {'dent_um':>8} {'pileup_um':>9} {'Wp_mJ':>8} {'wear_m3':>10} {'total_m3':>10} "
            f"{'e_n':>7} {'e_t':>7} {'cycles':>6} {'wall_s':>7}"
        )
        for r, n in zip(result.records, cycles, strict=True):
            print(
                f"{r.first:6d} {r.dent_depth * 1e6:8.4f} {r.pile_up_height * 1e6:9.4f} {r.plastic_work * 1e3:8.4f} "
                f"{r.wear_volume:10.4g} {r.total_wear_volume:10.4g} {r.normal_restitution:7.4f} "
                f"{r.tangential_restitution:7.4f} {n:6d} {r.wall_time:7.1f}"
            )
        solid = _per_repeated_impact(result)
        print(f"3-D plate: {result.plate.state.u.size} DOFs; wall time {result.wall_time:.1f} s")
        print(f"per repeated impact (2..N): 3-D {solid:.1f} s, axisymmetric {plane:.2f} s, ratio {solid / plane:.0f}")


def _solid_repeat(case, progress, start=None):
    """The 3-D repeat of ``case`` and each impact's 3-D plate cycles; ``start(on_law, coupled)`` in place of the
    chain's start of the next impact's coupling, if given."""
    cycles = []
    couple = solid_repeat.couple_solid_plate

    def counted(*args, **kwargs):
        coupled = couple(*args, **kwargs)
        cycles.append(coupled.iterations)
        return coupled

    solid_repeat.couple_solid_plate = counted
    if start is not None:
        solid_repeat._next_start = start
    try:
        return repeat(case, progress=progress), cycles
    finally:
        solid_repeat.couple_solid_plate = couple
        solid_repeat._next_start = _NEXT_START


def _per_repeated_impact(result) -> float:
    """Mean wall time (s) of the computed impacts 2..N of a repeat."""
    later = [r.wall_time for r in result.records[1:] if r.kind == "computed"]
    return float(np.mean(later)) if later else float("nan")


if __name__ == "__main__":
    main()
