"""The whole chain on the default case
===================================

The whole chain on the default case through the public API: impact → FE plate (two-way) → wear → meshes.

Equivalent to ``impactwear run`` (an alumina ball, R 2.5 mm, on a Ti-6Al-4V plate at 3 m/s, 30° from the
normal); prints the main results and writes the output folder (summary.json, history.csv, pressure.npz,
surface.vtu, plate.vtu, plate_fe.vtu, figures) into ``--out``/default_run. SI units.

Run: ``python examples/default_run.py [--out DIR]`` (IMPACTWEAR_QUICK=1: coarser FE mesh, fewer steps, no
3-D render, for the test suite).
"""

from __future__ import annotations

import argparse
import os
from pathlib import Path

from wear import Case, run
from wear.app.outputs.run import write_run


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="folder in which default_run/ is written")
    args = parser.parse_args()
    case = Case()
    if os.environ.get("IMPACTWEAR_QUICK") == "1":
        case = case.with_(
            fem={"mesh_scale": 4.0, "load_steps": 10, "unload_steps": 6},
            wear={"points_across": 40},
            output={"render": False},
        )
    result = run(case, progress=lambda stage: print(f"stage: {stage}", flush=True))
    summary = write_run(result, Path(args.out) / "default_run")
    imp, wear = result.impact, result.wear
    print(f"normal restitution e_n = {imp.normal_restitution:.4f}, max force {imp.max_force:.4g} N")
    print(f"coupling: {result.coupling.iterations} impact runs, final change {result.coupling.change:.2e}")
    print(
        f"regime: {result.regime}; FE first yield {result.yield_info['fe_first_yield_force']:.4g} N "
        f"(Eq. 18, C = 1.6: {result.yield_info['F_y_paper']:.4g} N)"
    )
    print(
        f"worn volume {wear.volume_m3:.4g} m^3, max wear depth {wear.max_depth_m:.4g} m, "
        f"dent depth {result.surface.max_dent_depth:.4g} m"
    )
    print("stage times (s):", {k: round(v, 2) for k, v in summary["stage_times_s"].items()})


if __name__ == "__main__":
    main()
