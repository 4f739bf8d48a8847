"""``impactwear calibrate DATA.csv [CASE.toml] --law NAME [--free K,alpha,...] --out DIR``: fit a wear law's
constants to measured wear (:mod:`wear.chain.calibrate`; outputs: :mod:`wear.app.outputs.calibration`).

DATA.csv: one row per measurement, columns ``angle_deg`` (from the normal), ``speed_m_s``, one of
``erosion_kg_per_kg``, ``mass_per_impact_kg``, ``volume_per_impact_m3`` (empty: predicted, not fitted), and
optional case keys per row (``ball.radius``, ...). The case (default: ``impactwear calibrate --print-default``)
gives the particle, the plate, the contact models and the law's other constants.
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
)
from wear.app.outputs.calibration import ENTRIES, write_calibration
from wear.app.outputs.folder import check_output_folder
from wear.chain.calibrate import calibrate
from wear.chain.calibration_data import read_data
from wear.laws.registry import LAWS

HELP = "fit a wear law's constants to measured wear (least squares on logs, with intervals); write calibrated.toml"

DEFAULT_OUT = "impactwear-calibrate"


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("data", nargs="?", metavar="DATA.csv", help="measured wear (see above)")
    add_case_options(parser, "calibrate")
    parser.add_argument("--law", choices=LAWS, help="the wear law to fit [wear.law]")
    parser.add_argument(
        "--free",
        metavar="K,alpha,...",
        help="the constants to fit [calibration.free]; default: the law's scale constant",
    )
    add_out_option(parser, DEFAULT_OUT)
    parser.add_argument("--quiet", action="store_true", help="no table")
    parser.add_argument("--json", action="store_true", help="print calibration.json to stdout instead of a table")


def _table(summary: dict, out: str) -> str:
    lines = [
        f"law {summary['law']!r}: {summary['fitted_rows']} rows fitted of {summary['rows']} "
        f"({summary['quantity']}); RMS log error {summary['rms_log_error']:.3g}"
    ]
    for name, c in summary["constants"].items():
        interval = c["interval_95"]
        if not c["determined"]:
            ci = "not determined by the data"
        elif interval is None:
            ci = "no interval: no residual degree of freedom"
        else:
            ci = f"95% [{interval[0]:.4g}, {interval[1]:.4g}]"
        bound = "" if c["on_bound"] is None else f"; on its {'lower' if c['on_bound'] == 'low' else 'upper'} bound"
        lines.append(f"  {name} = {c['value']:.6g} {c['units']}  ({ci}{bound})".rstrip())
    lines += [f"  note: {s}" for s in summary["statements"]]
    lines.append(
        f"{summary['evaluations']} evaluations of the forward model ({summary['evaluations_per_s']:.3g}/s); "
        f"output: {out}"
    )
    return "\n".join(lines)


def main(args: argparse.Namespace) -> int:
    options: dict[str, dict[str, object]] = {"calibration": {} if args.data is None else {"data": args.data}}
    if args.law is not None:
        options["wear"] = {"law": args.law}
    if args.free is not None:
        options["calibration"]["free"] = args.free
    case = case_from_args(args, "calibrate", options)
    if args.print_default:
        return print_default(args, "calibrate", case)
    if args.data is None:
        raise ValueError("DATA.csv is missing: give the file of measured wear (see impactwear calibrate --help)")
    data = read_data(case.calibration.data)  # bad data: one line naming the column and row, before any output
    check_output_folder(args.out, "calibrate", ENTRIES)
    # what the libraries warn (the figure's layout, a fit's round-off) is a note in one line, not their raw lines
    with collect_notes() as notes:
        result = calibrate(case, data, case.calibration.free_constants())
        summary = write_calibration(result, args.out)
    print_notes("calibrate", notes)
    if args.json:
        print_json(summary)
    elif not args.quiet:
        print(_table(summary, args.out))
    return 0
