"""``impactwear run [CASE.toml] [--out DIR] [--quiet] [--json]``: the whole chain for one impact case.

With no CASE it runs the default case (``impactwear run --print-default``: an alumina ball on a Ti-6Al-4V plate,
3 m/s at 30°, elastic–plastic, two-way FE coupling). The case is checked completely before anything runs; a
malformed case is one line naming the key, exit status 2, and no output. The output folder is written atomically
(:mod:`wear.app.outputs.run`).
"""

from __future__ import annotations

import argparse

from wear.app.commands.common import (
    add_case_options,
    add_out_option,
    case_from_args,
    collect_notes,
    print_default,
    print_json,
    print_notes,
    progress_bar,
)
from wear.app.outputs.folder import check_output_folder
from wear.app.outputs.run import ENTRIES, write_run
from wear.chain.single import STEPS, run

HELP = "run one impact case through impact, FE plate, coupling and wear; write meshes, numbers and figures"

DEFAULT_OUT = "impactwear-run"

#: Steps shown by the progress bar: the chain's, then the writer's.
BAR_STEPS = (*STEPS, "meshes", "figures", "render")


def configure(parser: argparse.ArgumentParser) -> None:
    add_case_options(parser, "run")
    add_out_option(parser, DEFAULT_OUT)
    parser.add_argument("--quiet", action="store_true", help="no progress bar and no table")
    parser.add_argument("--json", action="store_true", help="print summary.json to stdout instead of a table")


def _table(summary: dict, out: str) -> str:
    imp, w, y, d = summary["impact"], summary["wear"], summary["yield"], summary["dent"]
    c = summary.get("coupling") or {}

    def num(x, scale=1.0, fmt=".4g"):
        return "n/a" if x is None else format(x * scale, fmt)

    rows = [
        ("normal restitution", num(imp["normal_restitution"]), ""),
        ("rebound angle (centre)", num(imp["rebound_angle"]), "deg"),
        ("contact time", num(imp["contact_time"], 1e6), "us"),
        ("sliding time", num(imp["sliding_time"], 1e6), "us"),
        ("max normal force", num(imp["max_force"]), "N"),
        ("max overlap", num(imp["max_overlap"], 1e6), "um"),
        ("F_y (Eq. 18, C = 1.6) / F_c (exact C)", f"{num(y['F_y_paper'])} / {num(y['F_c_exact'])}", "N"),
        ("FE first-yield force", num(y["fe_first_yield_force"]), "N"),
        ("regime", summary["regime"], ""),
        ("coupling iterations / final change", f"{c.get('iterations', 'n/a')} / {num(c.get('final_change'))}", ""),
        ("worn volume", num(w["volume_m3"]), "m^3"),
        ("worn mass", num(w["mass_kg"]), "kg"),
        ("max wear depth", num(w["max_depth_m"], 1e9), "nm"),
        ("scar length x width", f"{num(w['scar_length_m'], 1e6)} x {num(w['scar_width_m'], 1e6)}", "um"),
        ("max dent depth", num(d["max_depth_m"], 1e6), "um"),
        ("dent length x width", f"{num(d['length_m'], 1e6)} x {num(d['width_m'], 1e6)}", "um"),
        ("pile-up height", num(d["pile_up_m"], 1e9), "nm"),
    ]
    if summary.get("plate_3d"):
        s = summary["plate_3d"]
        rows.append(("3-D plate: max tangential force", num(s["max_tangential_force_N"]), "N"))
        rows.append(("3-D plate: cycles (converged)", f"{s['iterations']} ({s['converged']})", ""))
    width = max(len(r[0]) for r in rows)
    lines = [f"{label:<{width}}  {value} {unit}".rstrip() for label, value, unit in rows]
    times = ", ".join(f"{k} {v:.2f} s" for k, v in summary["stage_times_s"].items())
    lines.append(f"stage times: {times}")
    lines.append(f"output: {out}")
    return "\n".join(lines)


def main(args: argparse.Namespace) -> int:
    case = case_from_args(args, "run")  # a malformed case raises ValueError here, before any output
    if args.print_default:
        return print_default(args, "run", case)
    check_output_folder(args.out, "run", ENTRIES)
    with progress_bar(len(BAR_STEPS), "impactwear run", "stage", args.quiet) as bar, collect_notes() as notes:
        started: list[str] = []

        def progress(step: str) -> None:
            bar(len(started), step)
            started.append(step)

        summary = write_run(run(case, progress=progress), args.out, progress=progress, notes=notes)
    print_notes("run", summary["notes"])
    if args.json:
        print_json(summary)
    elif not args.quiet:
        print(_table(summary, args.out))
    return 0
