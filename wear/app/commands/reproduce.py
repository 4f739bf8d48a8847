"""``impactwear reproduce``: recompute the paper's figures and write ``reproduce.md`` beside them.

Writes ``DIR/figures/<name>.png`` and ``DIR/reproduce.md`` (figure by figure: what the paper shows, what we get,
where and why they differ). ``--quick`` runs at reduced sizes (for tests); ``--only NAME`` runs some figures.
Exit status 1 if a figure could not be produced (listed with the reason in reproduce.md).
"""

from __future__ import annotations

import argparse
import sys

from wear.app.commands.common import path_option
from wear.app.outputs.folder import check_writable_folder
from wear.app.reproduce.run import FIGURES, check_outputs, reproduce

HELP = "recompute the paper's figures (PNG) from this toolkit and write reproduce.md"


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--out", default="reproduce", type=path_option, metavar="DIR", help="output folder (default: ./reproduce)"
    )
    parser.add_argument("--quick", action="store_true", help="reduced sizes (fewer angles, coarse FE): for tests")
    parser.add_argument("--only", action="append", metavar="NAME", help="run only this figure (repeatable)")
    parser.add_argument("--quiet", action="store_true", help="no progress lines")


def main(args: argparse.Namespace) -> int:
    unknown = [n for n in args.only or () if n not in FIGURES]
    if unknown:
        raise ValueError(f"--only={unknown[0]!r} is not a figure: choose from {', '.join(FIGURES)}")
    check_writable_folder(args.out)
    check_outputs(args.out, args.only or list(FIGURES))

    def progress(name: str) -> None:
        if not args.quiet:
            print(f"reproduce: {name} ...", file=sys.stderr, flush=True)

    reports = reproduce(args.out, quick=args.quick, only=args.only, progress=progress)
    for r in reports:
        status = f"missing: {r.missing}" if r.missing else f"{r.seconds:.1f} s"
        print(f"{r.name}.png  {status}")
    print(f"wrote {args.out}/reproduce.md")
    return 1 if any(r.missing for r in reports) else 0
