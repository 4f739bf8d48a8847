"""``impactwear repeat [CASE.toml] --impacts N [--out DIR] [--quiet] [--json]``: N impacts at one site.

The case is a run case (``impactwear run``'s tables ``[ball]``, ``[plate]``, ``[impact]``, ``[wear]``, ``[fem]``,
``[output]``) plus an optional ``[repeat]`` table; with no CASE the default case (``impactwear repeat
--print-default``); ``--impacts`` overrides ``repeat.impacts``. See :mod:`wear.chain.axisymmetric_repeat` for the
physics (plate state kept, dented and worn surface, shakedown, cycle jump; with ``fem.model = "3d"`` oblique impacts
with friction on the 3-D plate, every one computed, :mod:`wear.chain.solid_repeat`) and :mod:`wear.app.outputs.repeat`
for the files.
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
from wear.app.outputs.folder import output_folder
from wear.app.outputs.repeat import ENTRIES, RepeatWriter
from wear.chain.repeated_impacts import repeat

HELP = "N impacts of the same ball at one site on the plate the previous ones left: dent, wear, shakedown"

DEFAULT_OUT = "impactwear-repeat"


def _integer(name: str, text: str) -> int:
    try:
        value = float(text)
    except ValueError:
        raise ValueError(
            f"--{name}={text!r} is not a number: the number of impacts must be an integer in [1, 1e9]"
        ) from None
    if not value.is_integer():
        raise ValueError(f"--{name}={text} is not an integer: the number of impacts must be an integer in [1, 1e9]")
    if not 1 <= value <= 1e9:
        raise ValueError(f"--{name}={text} is out of range: the number of impacts must be an integer in [1, 1e9]")
    return int(value)


def configure(parser: argparse.ArgumentParser) -> None:
    add_case_options(parser, "repeat")
    parser.add_argument("--impacts", metavar="N", help="number of impacts (overrides repeat.impacts)")
    add_out_option(parser, DEFAULT_OUT)
    parser.add_argument("--quiet", action="store_true", help="no progress bar and no table")
    parser.add_argument("--json", action="store_true", help="print summary.json to stdout instead of a table")


def _table(summary: dict, out: str) -> str:
    first, last = summary["first_impact"], summary["last_computed_impact"]
    after = summary["after_last_impact"]
    check = summary["halfspace_check"]
    rows = [
        (
            "impacts (computed; of them elastic)",
            f"{summary['impacts']} ({summary['computed_impacts']}; {summary['elastic_computed_impacts']})",
            "",
        ),
        (
            "shakedown",
            "none" if summary["shakedown_impact"] is None else f"at impact {summary['shakedown_impact']}",
            "",
        ),
        (
            "normal restitution first / last computed",
            f"{first['normal_restitution']:.4g} / {last['normal_restitution']:.4g}",
            "",
        ),
        (
            "max pressure first / last computed",
            f"{first['max_pressure'] / 1e9:.4g} / {last['max_pressure'] / 1e9:.4g}",
            "GPa",
        ),
        (
            "last computed: max pressure FE / half-space",
            "no half-space check on the 3-D plate"
            if check is None
            else f"{check['fe_max_pressure_Pa'] / 1e9:.4g} / {check['halfspace_max_pressure_Pa'] / 1e9:.4g}",
            "" if check is None else "GPa",
        ),
        ("dent depth after the last impact", f"{after['dent_depth_m'] * 1e6:.4g}", "um"),
        ("pile-up height after the last impact", f"{after['pile_up_height_m'] * 1e6:.4g}", "um"),
        (
            "wear: max depth / volume",
            f"{after['total_wear_max_depth_m'] * 1e6:.4g} um / {after['total_wear_volume_m3']:.4g}",
            "m^3",
        ),
        ("wall time", f"{summary['wall_time_s']:.1f}", "s"),
    ]
    width = max(len(r[0]) for r in rows)
    lines = [f"{label:<{width}}  {value} {unit}".rstrip() for label, value, unit in rows]
    lines.append(f"output: {out}")
    return "\n".join(lines)


def main(args: argparse.Namespace) -> int:
    options = {} if args.impacts is None else {"repeat": {"impacts": _integer("impacts", args.impacts)}}
    case = case_from_args(args, "repeat", options)  # bad input raises here, before any output
    if args.print_default:
        return print_default(args, "repeat", case)
    total = case.repeat.impacts
    bar = progress_bar(total, "impactwear repeat", "impact", args.quiet)
    with output_folder(args.out, "repeat", ENTRIES) as out, bar as update:
        writer = RepeatWriter(out, case.repeat.save_every)
        with collect_notes() as notes:
            result = repeat(case, progress=lambda done, _total: update(done), on_computed=writer.on_computed)
        summary = writer.finish(result, notes)
    print_notes("repeat", summary["notes"])
    if args.json:
        print_json(summary)
    elif not args.quiet:
        print(_table(summary, args.out))
    return 0
