"""``impactwear erode [CASE.toml] [--out DIR] [--angles 0,15,30,...]``: erosion of a plate patch by a particle stream.

The case's ``[ball]`` is the particle (radius, material), ``[plate]`` the plate, ``[impact]`` the stream speed,
angle (deg from the plate normal), friction and contact models, ``[wear]`` the wear law, ``[erosion]`` the stream's
concentration or mass flux, exposure, patch, table resolution and seed (:mod:`wear.erosion.run`). Outputs:
:mod:`wear.app.outputs.erosion`. With ``--angles`` one erosion per angle (the case's other keys unchanged) on a
common patch. SI units; angles in degrees from the plate normal.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from wear.app.commands.common import (
    add_case_options,
    add_out_option,
    case_from_args,
    collect_notes,
    print_default,
    print_json,
    print_notes,
    show_progress,
)
from wear.app.outputs.erosion import ENTRIES, write_erosion, write_erosion_angles
from wear.app.outputs.folder import check_output_folder
from wear.erosion.run import MAX_STREAM_ANGLE, erode_angles, erode_case

HELP = "erode a plate patch by a stream of particles (surface feedback); mass loss and erosion rate vs time or angle"


def configure(parser: argparse.ArgumentParser) -> None:
    add_case_options(parser, "erode")
    add_out_option(parser, "erosion")
    parser.add_argument("--angles", metavar="A,B,...", help="run one erosion per stream angle (deg from the normal)")
    parser.add_argument("--seed", type=int, metavar="N", help="random seed [erosion.seed]")
    parser.add_argument("--quiet", action="store_true", help="no progress bar or summary lines")
    parser.add_argument("--json", action="store_true", help="print summary.json to stdout instead of the lines")


def parse_angles(text: str) -> list[float]:
    """Angles (deg) from ``"0,15,30"``; ValueError naming ``--angles`` otherwise."""
    try:
        angles = [float(a) for a in text.split(",") if a.strip()]
    except ValueError:
        raise ValueError(f"--angles={text!r} is not a comma-separated list of numbers (deg)") from None
    if not angles:
        raise ValueError(f"--angles={text!r} is empty: give e.g. 0,15,30,45,60,75")
    for a in angles:
        if not 0.0 <= a <= MAX_STREAM_ANGLE:
            raise ValueError(
                f"--angles: angle={a:g} is out of range: stream angle from the normal must be in [0, "
                f"{MAX_STREAM_ANGLE:g}] deg"
            )
    # each angle's outputs go to angle_<a:g>/ (6 significant digits): angles that print alike would collide there
    # after all the work, so they are refused as one angle given twice
    seen: dict[str, float] = {}
    for a in angles:
        shown = f"{a:g}"
        if shown in seen:
            alike = "" if a == seen[shown] else f" ({seen[shown]!r} and {a!r} are one to the 6 digits of the outputs)"
            raise ValueError(f"--angles={text} gives the angle {shown} deg twice{alike}: give each stream angle once")
        seen[shown] = a
    return angles


def main(args: argparse.Namespace) -> int:
    case = case_from_args(args, "erode", {} if args.seed is None else {"erosion": {"seed": args.seed}})
    if args.print_default:
        return print_default(args, "erode", case)
    angles = None if args.angles is None else parse_angles(args.angles)
    check_output_folder(args.out, "erode", ENTRIES)
    out = Path(args.out)
    progress = show_progress(args.quiet)
    say = (lambda *a: None) if args.quiet or args.json else print
    if angles is None:
        with collect_notes() as notes:
            run = erode_case(case, progress=progress)
            summary = write_erosion(run, out, notes=notes)
        print_notes("erode", notes)
        if args.json:
            print_json(summary)
        r, result = summary["results"], run.result
        say(
            f"erode: {r['impacts']} impacts on a {result.patch_size * 1e3:.4g} mm patch ({result.x.size}^2 nodes), "
            f"{summary['seconds']['erosion']:.3g} s"
        )
        say(f"  table: {summary['table']['resolution']}")
        say(
            f"  mass loss {r['mass_loss_kg']:.6g} kg ({r['mass_loss_per_area_kg_m2']:.6g} kg/m^2), erosion rate "
            f"{r['erosion_rate_kg_per_kg']:.6g} kg/kg, max depth {r['max_depth_m'] * 1e6:.4g} um -> {out}"
        )
        return 0
    with collect_notes() as notes:
        rows = write_erosion_angles(erode_angles(case, angles, progress=progress), out)
    print_notes("erode", notes)
    if args.json:
        print_json([{"angle_deg": a, "erosion_rate": rate, "mass_loss_kg": mass} for a, rate, mass in rows])
    for a, rate, mass in rows:
        say(f"erode: angle {a:g} deg: erosion rate {rate:.6g} kg/kg, mass loss {mass:.6g} kg")
    best = max(rows, key=lambda r: r[1])
    say(f"erode: largest erosion rate {best[1]:.6g} kg/kg at {best[0]:g} deg -> {out / 'erosion_vs_angle.csv'}")
    return 0
