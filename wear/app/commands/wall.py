"""``impactwear wall RECORDS WALL [CASE.toml] [--out DIR]`` (or the paths as ``wall.records``, ``wall.surface``):
erosion of a component's wall from CFD or DEM impact records.

RECORDS: OpenFOAM's ``patchPostProcessing`` output (a ``.post`` file or its folder of write times), an Ansys
Fluent DPM sample file, or the plain table (CSV or Parquet; a folder of them: every file, by name) —
:mod:`wear.wall.sources`. WALL: a surface file meshio reads (STL, OBJ, VTU, VTP, ...), a folder of them (a wall
split into parts) or an OpenFOAM case (its wall patches) — :func:`wear.wall.component.read_wall`. The case's
``[plate]`` is the wall material, ``[wear]`` the wear law, ``[wall]`` the thickness, exposure, service time, sand
rates and the response table of an FE-informed law; ``[ball]`` and ``[impact]`` the particle's material and the
impact models of the table (the records carry the particles' sizes, speeds and angles). Outputs:
:mod:`wear.app.outputs.wall`. SI units; angles in degrees from the wall normal.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from wear.app.commands.common import (
    add_case_options,
    add_out_option,
    add_workers_options,
    case_from_args,
    check_scheduler_address,
    collect_notes,
    print_default,
    print_json,
    print_notes,
    show_progress,
)
from wear.app.outputs.folder import check_output_folder
from wear.app.outputs.wall import ENTRIES, write_wall
from wear.wall.component import erode_component, read_wall
from wear.wall.options import NORMALS, WallOptions

__all__ = ["HELP", "configure", "main"]

HELP = (
    "erode a component's wall from CFD or DEM impact records: per-face rates (mm/year), remaining life, hot "
    "spots and the worn wall"
)


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "records",
        nargs="?",
        metavar="RECORDS",
        help="impact records: OpenFOAM patchPostProcessing (file or folder), Fluent DPM sample, CSV or Parquet",
    )
    parser.add_argument(
        "wall",
        nargs="?",
        metavar="WALL",
        help="the wall: a surface file (STL, OBJ, VTU, ...), a folder of them, or an OpenFOAM case",
    )
    add_case_options(parser, "wall")
    add_out_option(parser, "wall")
    parser.add_argument(
        "--patches", metavar="A,B", help="the OpenFOAM wall patches (default: every patch of type wall)"
    )
    parser.add_argument("--flip", action="store_true", help="reverse the orientation of the wall's surface files")
    parser.add_argument(
        "--normal",
        choices=NORMALS,
        help="measure the angle against the normal the records carry (OpenFOAM's) or the wall face's "
        "(default: recorded where the records carry one)",
    )
    parser.add_argument(
        "--skip-bad",
        action="store_true",
        help="count and report the records that leave the wall or hit far from it instead of refusing them",
    )
    add_workers_options(parser, "1")
    parser.add_argument("--no-figures", action="store_true", help="write no figures")
    parser.add_argument("--quiet", action="store_true", help="no progress bar or summary lines")
    parser.add_argument("--json", action="store_true", help="print summary.json to stdout instead of the lines")


def main(args: argparse.Namespace) -> int:
    if args.case is None and args.wall is None and str(args.records).endswith(".toml"):
        args.case, args.records = args.records, None  # `impactwear wall CASE.toml`: the paths are in the case
    case = case_from_args(args, "wall")
    if args.print_default:
        return print_default(args, "wall", case)
    given = {"records": args.records, "surface": args.wall}
    case = case.with_(wall={k: v for k, v in given.items() if v is not None})  # the arguments win, and are recorded
    for name, key in (("RECORDS", "records"), ("WALL", "surface")):
        path = getattr(case.wall, key)
        if path is None:
            raise ValueError(f"{name} is missing: give impactwear wall RECORDS WALL [CASE.toml] (or wall.{key})")
        if not Path(path).exists():
            raise ValueError(f"{'records' if key == 'records' else 'wall'}={path!r}: no such file or folder")
    check_scheduler_address(args.scheduler)
    patches = _patches(args.patches)
    check_output_folder(args.out, "wall", ENTRIES)
    wall = read_wall(case.wall.surface, patches, flip=args.flip)
    if args.dask_local is not None:
        workers, scheduler = args.dask_local, "local"
    else:
        workers, scheduler = args.workers or 1, args.scheduler
    options = WallOptions(normal=args.normal, skip_bad=args.skip_bad, workers=workers, scheduler=scheduler)
    progress = show_progress(args.quiet)
    with collect_notes() as notes:
        run = erode_component(case, case.wall.records, wall, options, progress=progress)
        skipped = dict(run.sums.skipped)
        elsewhere = skipped.pop("other_patches", 0)
        if elsewhere:  # the run's other patches were left out on purpose: counted, not refused
            notes.append(
                f"{elsewhere} of {run.sums.records_read} records hit patches of the mesh that are not part of the wall "
                f"(its patches: {', '.join(wall.patch_names)}): left out"
            )
        if any(skipped.values()):
            reasons = ", ".join(f"{n} {reason.replace('_', ' ')}" for reason, n in skipped.items() if n)
            notes.append(f"--skip-bad: {sum(skipped.values())} of {run.sums.records_read} records skipped ({reasons})")
        summary = write_wall(run, args.out, notes=notes, figures=not args.no_figures)
    print_notes("wall", notes)
    if args.json:
        print_json(summary)
    elif not args.quiet:
        _say(summary, args.out)
    return 0


def _patches(text: str | None) -> list[str] | None:
    """The patch names of ``--patches A,B`` (None: not given), each once."""
    if text is None:
        return None
    names = [p.strip() for p in text.split(",") if p.strip()]
    if not names:
        raise ValueError(f"--patches={text!r} names no patch: give the wall's patch names, comma-separated (A,B)")
    twice = next((name for name in names if names.count(name) > 1), None)
    if twice is not None:  # its faces would be counted twice: twice the area, half the worn depth
        raise ValueError(f"--patches={text}: the patch {twice!r} is named twice: name each patch once")
    return names


def _say(summary: dict, out: str) -> None:
    records, wall, r = summary["records"], summary["wall"], summary["results"]
    print(
        f"wall: {records['on_wall']} of {records['read']} impact records on {wall['faces_hit']} of {wall['faces']} "
        f"faces ({summary['law']['name']} law), exposure {summary['exposure_s']:.4g} s ({summary['exposure_source']})"
    )
    life = r["min_remaining_life_year"]
    life_text = "" if life is None else f", shortest remaining life {life:.4g} years"
    allowed = r["allowable_sand_rate_kg_s"]
    if allowed is not None:
        life_text += f"; allowable sand rate {allowed:.4g} kg/s"
    elif r["allowable_rate_factor"] is not None:
        life_text += f"; allowable sand rate {r['allowable_rate_factor']:.4g} x the records'"
    x, y, z = r["max_thickness_loss_position_m"]
    print(
        f"  eroded mass {r['eroded_mass_kg']:.6g} kg; largest thickness loss {r['max_thickness_loss_mm_year']:.4g} "
        f"mm/year at face {r['max_thickness_loss_face']} ({x:.4g}, {y:.4g}, {z:.4g}) m{life_text} -> {out}"
    )
