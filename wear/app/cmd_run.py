"""``impactwear run [CASE.toml] [--out DIR] [--quiet] [--json]``: the whole chain for one impact case.

With no CASE it runs the embedded default case (``wear/app/default_run.toml``: an alumina ball on a
Ti-6Al-4V plate, 3 m/s at 30°, elastic–plastic, two-way FE coupling). The case is checked completely before
anything runs; a malformed case is one line naming the key, exit status 2, and no output. The output folder
is written atomically (see :mod:`wear.app.outputs`).
"""

from __future__ import annotations

import argparse
import json
import sys

HELP = "run one impact case through impact, FE plate, coupling and wear; write meshes, numbers and figures"

DEFAULT_OUT = "impactwear-run"

# stages shown by the progress bar (the pipeline's, then the writer's)
_BAR_STAGES = ("impact", "fem", "coupling", "wear", "surface", "meshes", "figures", "render")


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("case", nargs="?", metavar="CASE.toml", help="run case file (default: the embedded case)")
    parser.add_argument("--out", default=DEFAULT_OUT, metavar="DIR", help=f"output folder (default: {DEFAULT_OUT})")
    parser.add_argument("--quiet", action="store_true", help="no progress bar and no table")
    parser.add_argument("--json", action="store_true", help="print summary.json to stdout instead of a table")
    parser.add_argument("--print-default", action="store_true", help="print the embedded default run case (TOML)")


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
    ]
    width = max(len(r[0]) for r in rows)
    lines = [f"{label:<{width}}  {value} {unit}".rstrip() for label, value, unit in rows]
    times = ", ".join(f"{k} {v:.2f} s" for k, v in summary["stage_times_s"].items())
    lines.append(f"stage times: {times}")
    lines.append(f"output: {out}")
    return "\n".join(lines)


def main(args: argparse.Namespace) -> int:
    from .run_case import default_run_text, load_run_case

    if args.print_default:
        sys.stdout.write(default_run_text())
        return 0
    case = load_run_case(args.case)  # a malformed case raises ValueError here, before any output

    from wear.pipeline import run

    from .outputs import write_run

    show = not args.quiet and sys.stderr.isatty()
    bar = None
    if show:
        from tqdm import tqdm

        bar = tqdm(total=len(_BAR_STAGES), desc="impactwear run", unit="stage", file=sys.stderr, leave=False)
    done: list[str] = []

    def progress(stage: str) -> None:
        if bar is not None:
            if done:
                bar.update(1)
            bar.set_postfix_str(stage)
        done.append(stage)

    import warnings

    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            result = run(case, progress=progress)
        summary = write_run(result, args.out, progress=progress)
    finally:
        if bar is not None:
            bar.update(bar.total - bar.n)
            bar.close()
    notes = list(dict.fromkeys(str(w.message) for w in caught)) + list(summary.get("notes", []))
    for note in notes:
        print(f"impactwear run: note: {note}", file=sys.stderr)
    if args.json:
        from .outputs import to_jsonable

        print(json.dumps(to_jsonable(summary), indent=2))
    elif not args.quiet:
        print(_table(summary, args.out))
    return 0
