"""``impactwear sweep SWEEP.toml --out DIR``: run a parameter sweep, resumably, locally or on a Dask cluster.

The sweep file names a stage (``impact``, ``indent`` or ``run``), an optional ``[base]`` case and either a
``[grid]`` (Cartesian product of dotted keys to lists) or ``[[cases]]`` (see :mod:`wear.app.sweep.spec`). Every
case is validated before anything runs. Results go to ``DIR/cases/<case-id>.json`` (one file per case, atomic),
``DIR/results.csv`` and, for 1-D and 2-D grids, a figure; a rerun skips finished cases.

Exit status: 0 all cases ok, 1 some case failed, 2 bad sweep file or options, 130 interrupted (rerun to resume).
"""

from __future__ import annotations

import argparse
import re
import sys

from wear.app.commands.common import path_option
from wear.app.outputs.folder import check_output_folder
from wear.app.sweep.execution import SweepAborted
from wear.app.sweep.runner import failed_lines, run_sweep, summary_line
from wear.app.sweep.spec import load_sweep

#: A Dask scheduler address: ``tcp://host:8786``, ``tls://host:8786``, ``inproc://...`` or ``host:8786``.
_ADDRESS = re.compile(r"^([a-z][a-z0-9+.-]*://\S+|[\w.-]+:\d+)$")

HELP = "run a parameter sweep (SWEEP.toml) on local processes or a Dask cluster; reruns resume"


def _positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"{value} must be >= 1")
    return value


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("sweep", metavar="SWEEP.toml", help="sweep file: [sweep] stage, [base], [grid] or [[cases]]")
    parser.add_argument(
        "--out",
        required=True,
        type=path_option,
        metavar="DIR",
        help="output folder (reused: finished cases are kept)",
    )
    how = parser.add_mutually_exclusive_group()
    how.add_argument("--workers", type=_positive_int, metavar="N", help="local worker processes (default: CPU count)")
    how.add_argument(
        "--dask-local", type=_positive_int, metavar="N", help="run on a new loopback dask LocalCluster of N processes"
    )
    how.add_argument("--scheduler", metavar="ADDRESS", help="run on an existing Dask cluster, e.g. tcp://host:8786")
    parser.add_argument("--quiet", action="store_true", help="no progress bar and no summary line")


def main(args: argparse.Namespace) -> int:
    if args.scheduler is not None and not _ADDRESS.match(args.scheduler):
        raise ValueError(
            f"--scheduler={args.scheduler!r} is not a Dask scheduler address: give PROTOCOL://HOST:PORT or HOST:PORT, "
            "e.g. tcp://host:8786"
        )
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
