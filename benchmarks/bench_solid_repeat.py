"""Benchmark of repeated oblique impacts at one site on the 3-D plate (``impactwear repeat`` with
``fem.model = "3d"``): the default case (alumina R 2.5 mm on Ti-6Al-4V, 3 m/s at 30° from the normal, μ = 0.3),
N impacts each coupled to the plate the previous ones left (:mod:`wear.chain.solid_repeat`).

Prints one row per impact (dent, pile-up, plastic work, wear, e_n, e_t, wall time) and the mean wall time per
repeated impact (impacts 2..N: the first also builds the plate and runs the axisymmetric start), side by side with
the axisymmetric repeat of the same case in the same run (its frictionless (r, z) plate, every impact computed:
no elastic shortcut), and their ratio.

Run: ``python benchmarks/bench_solid_repeat.py`` (default mesh, 4 elements across the contact; ``--quick``: 3
elements, 4 + 3 increments; ``--impacts N``, ``--mesh-scale S``).
"""

from __future__ import annotations

import argparse
import time
import warnings

import numpy as np

from wear.case import JOBS
from wear.case.check import on_plate
from wear.chain.repeated_impacts import repeat


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="3 elements across the contact, 4 + 3 increments")
    parser.add_argument("--impacts", type=int, default=5)
    parser.add_argument("--mesh-scale", type=float, default=None)
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

    result = repeat(case, progress=progress)
    axisymmetric = repeat(
        on_plate(case, "axisymmetric", "repeat").with_(repeat={"elastic_after_shakedown": False}), progress=progress
    )
    print(
        f"{'impact':>6} {'dent_um':>8} {'pileup_um':>9} {'Wp_mJ':>8} {'wear_m3':>10} {'total_m3':>10} {'e_n':>7} "
        f"{'e_t':>7} {'wall_s':>7}"
    )
    for r in result.records:
        print(
            f"{r.first:6d} {r.dent_depth * 1e6:8.4f} {r.pile_up_height * 1e6:9.4f} {r.plastic_work * 1e3:8.4f} "
            f"{r.wear_volume:10.4g} {r.total_wear_volume:10.4g} {r.normal_restitution:7.4f} "
            f"{r.tangential_restitution:7.4f} {r.wall_time:7.1f}"
        )
    solid = _per_repeated_impact(result)
    plane = _per_repeated_impact(axisymmetric)
    print(f"3-D plate: {result.plate.state.u.size} DOFs; wall time {result.wall_time:.1f} s")
    print(f"per repeated impact (2..N): 3-D {solid:.1f} s, axisymmetric {plane:.2f} s, ratio {solid / plane:.0f}")


def _per_repeated_impact(result) -> float:
    """Mean wall time (s) of the computed impacts 2..N of a repeat."""
    later = [r.wall_time for r in result.records[1:] if r.kind == "computed"]
    return float(np.mean(later)) if later else float("nan")


if __name__ == "__main__":
    main()
