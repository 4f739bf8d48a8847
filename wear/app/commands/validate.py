"""``impactwear validate``: run every validation check of the toolkit and write ``validation.md``.

One table row per check (quantity, case, reference and its source, obtained, error, tolerance, pass/fail); exit
status 1 if any check fails. Full resolution by default (several minutes); ``--quick`` runs reduced sizes.
The committed report is ``docs/validation.md``: regenerate it with ``impactwear validate --out docs``.
"""

from __future__ import annotations

import argparse
import shlex
import sys
from pathlib import Path

from wear.app.commands.common import collect_notes, path_option, print_notes
from wear.app.outputs.folder import check_named_file, check_writable_folder, is_own_file
from wear.app.validation.groups import GROUPS
from wear.app.validation.runner import HEADER, render_report, run_validation, write_report

HELP = "run every validation check (contact, fem, wear) and write validation.md; exit 1 if any fails"


#: The default folder of validation.md: its own, so that a validation.md in the current folder is never replaced.
DEFAULT_OUT = "impactwear-validate"


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--out",
        default=DEFAULT_OUT,
        type=path_option,
        metavar="DIR",
        help=f"folder of validation.md (default: {DEFAULT_OUT})",
    )
    parser.add_argument(
        "--report",
        type=path_option,
        metavar="PATH",
        help="write the report to this file instead of DIR/validation.md",
    )
    parser.add_argument("--quick", action="store_true", help="reduced sizes (the test suite's mode)")
    parser.add_argument("--only", action="append", metavar="TEXT", help="run the groups whose name contains TEXT")
    parser.add_argument("--list", action="store_true", help="list the check groups and exit")
    parser.add_argument("--quiet", action="store_true", help="no progress lines")


def main(args: argparse.Namespace) -> int:
    if args.list:
        for name, group in GROUPS.items():
            print(f"{group.area:8s} {name}")
        return 0

    def progress(name: str) -> None:
        if not args.quiet:
            print(f"validate: {name} ...", file=sys.stderr, flush=True)

    for text in args.only or ():  # each names some group ("" would name every one)
        if not text or not any(text in name for name in GROUPS):
            raise ValueError(f"--only={text!r} matches no check group: groups are {', '.join(GROUPS)}")
    path = Path(args.report) if args.report else Path(args.out) / "validation.md"
    if path.is_dir():
        raise ValueError(f"--report={args.report!r} is a folder: give the report's file name (e.g. validation.md)")
    option = "--report" if args.report else "--out"
    check_writable_folder(path.parent, option)
    if args.report and path.exists() and not is_own_file(path, HEADER):
        # --report names the file itself: the folder's wording ("holds ...; give another folder") would not fit
        raise ValueError(
            f"--report={args.report!r} is a file impactwear did not write, which `impactwear validate` would "
            "replace: move it, or give another file name"
        )
    check_named_file(path, "validate", HEADER, f"{option}={args.report or args.out!r}")
    with collect_notes() as notes:  # what the libraries warn (an elastic ball on the FE plate) is a note, once
        result = run_validation(quick=args.quick, only=args.only, progress=progress)
    print_notes("validate", notes)
    command = "impactwear validate" + (" --quick" if args.quick else "")
    command += "".join(f" --only {shlex.quote(s)}" for s in args.only or ())
    write_report(path, render_report(result, command))
    for c in result.failed:
        print(
            f"FAIL [{c.group}] {c.quantity} ({c.case}): obtained {c.obtained}, reference {c.reference}, "
            f"error {c.error:.4g} > tolerance {c.tolerance:.4g}"
        )
    n, bad = len(result.checks), len(result.failed)
    print(f"{n - bad}/{n} checks passed; report: {path}")
    return 1 if bad else 0
