"""``impactwear sweep SWEEP.toml --out DIR``: run a parameter sweep, resumably, locally or on a Dask cluster.

The sweep file names a stage (``impact``, ``indent`` or ``run``), an optional ``[base]`` case and either a
``[grid]`` (Cartesian product of dotted keys to lists) or ``[[cases]]`` (see :mod:`wear.app.sweep.spec`). Every
case is validated before anything runs. Results go to ``DIR/cases/<case-id>.json`` (one file per case, atomic),
``DIR/results.csv`` and, for 1-D and 2-D grids, a figure; a rerun skips finished cases.

Exit status: 0 all cases ok, 1 some case failed, 2 bad sweep file or options, 130 interrupted (rerun to resume).
"""

from __future__ import annotations

import argparse
import sys

from wear.app.commands.common import add_workers_options, check_scheduler_address, path_option
from wear.app.outputs.folder import check_output_folder
from wear.app.sweep.execution import SweepAborted
from wear.app.sweep.runner import failed_lines, run_sweep, summary_line
from wear.app.sweep.spec import load_sweep

HELP = "run a parameter sweep (SWEEP.toml) on local processes or a Dask cluster; reruns resume"


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("sweep", metavar="SWEEP.toml", help="sweep file: [sweep] stage, [base], [grid] or [[cases]]")
    parser.add_argument(
        "--out",
        required=True,
        type=path_option,
        metavar="DIR",
        help="output folder (reused: finished cases are kept)",
    )
    add_workers_options(parser, "CPU count")
    parser.add_argument("--quiet", action="store_true", help="no progress bar and no summary line")


def main(args: argparse.Namespace) -> int:
    check_scheduler_address(args.scheduler)
    spec = load_sweep(args.sweep)
    check_output_folder(args.out, "sweep")  # a file, or a folder of user files or of another command: before any work
    try:
        outcome = run_sweep(
            spec, args.out, workers=args.workers, dask_local=args.dask_local, scheduler=args.scheduler, quiet=args.quiet
        )
    except SweepAborted as exc:
        print(f"impactwear sweep: error: {exc}", file=sys.stderr)
        return 1
    if outcome.failed:
        for line in failed_lines(outcome):
            print(f"failed {line}", file=sys.stderr)
    if not args.quiet:
        print(summary_line(outcome))
    return 1 if outcome.failed else 0
