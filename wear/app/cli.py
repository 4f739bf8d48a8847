"""The ``impactwear`` command line.

Each command is a module of :mod:`wear.app.commands` exposing its help line ``HELP``, ``configure(parser)`` and
``main(args) -> int``: parse → load the case → call the runner → write. The commands that run a case are the jobs
(:data:`JOB_COMMANDS`, one for each job of :data:`wear.case.JOBS`, in its order); the tools (:data:`TOOLS`: sweep,
reproduce, validate) run no case of their own. Bad input (``ValueError``) is reported as one line naming the
parameter, with exit status 2 and no traceback; so is a write the file system refuses
(:data:`wear.app.outputs.writer.WRITE_ERRORS`: a full disk, a quota, a read-only or forbidden folder), naming the
file and the cause.
"""

from __future__ import annotations

import argparse
import os
import re
import sys
from importlib.metadata import PackageNotFoundError, version
from types import ModuleType
from typing import NoReturn

from fem import ConvergenceError
from wear.app.commands import calibrate, erode, impact, indent, repeat, reproduce, run, sweep, validate, wall
from wear.app.outputs.writer import WRITE_ERRORS

#: The commands that run a case: the job's name (:data:`wear.case.JOBS`, the same order) → its command's module.
JOB_COMMANDS: dict[str, ModuleType] = {
    "run": run,
    "impact": impact,
    "indent": indent,
    "repeat": repeat,
    "erode": erode,
    "calibrate": calibrate,
    "wall": wall,
}

#: The commands that are not jobs: name → module, after the jobs in ``--help``.
TOOLS: dict[str, ModuleType] = {"sweep": sweep, "reproduce": reproduce, "validate": validate}


def commands() -> dict[str, tuple[str, ModuleType]]:
    """name → (help line, command module), in the order of ``impactwear --help``: the jobs, then the tools."""
    return {name: (module.HELP, module) for name, module in {**JOB_COMMANDS, **TOOLS}.items()}


class _Parser(argparse.ArgumentParser):
    """argparse's parser with its errors in one line (the option, its value and what is wrong, then where the help
    is), as every other bad input is reported, instead of the usage block and a second line."""

    #: The commands' parsers by name (set by :func:`build_parser`), for :func:`parse_command_line`'s second pass.
    commands: dict[str, argparse.ArgumentParser]

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="impactwear",
        description="Impact, plate and wear of a ball hitting a flat plate (SI units; angles in degrees "
        "from the plate normal).",
    )
    try:
        ver = version("impactwear")
    except PackageNotFoundError:
        ver = "unknown"
    parser.add_argument("--version", action="version", version=f"impactwear {ver}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    parser.commands = {}
    for name, (text, module) in commands().items():
        p = sub.add_parser(name, help=text, description=text)
        module.configure(p)
        p.set_defaults(_module=module)
        parser.commands[name] = p
    return parser


#: A negative number argparse would take for an option (it knows only -1 and -1.5, not -1e-6), or a comma-separated
#: list of numbers that starts with one (``--angles -5,30``).
_NUMBER = r"(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?"
_NEGATIVE_NUMBER = re.compile(rf"^-{_NUMBER}(,\s*[-+]?{_NUMBER})*$")


def join_negative_values(argv: list[str]) -> list[str]:
    """``--opt -1e-6`` as ``--opt=-1e-6`` (and ``--opt -5,30`` as ``--opt=-5,30``), so that a negative number in
    exponent notation or a list starting with one reaches the option (and its range check) instead of argparse's
    "expected one argument"."""
    out: list[str] = []
    for arg in argv:
        if out and _NEGATIVE_NUMBER.match(arg) and out[-1].startswith("--") and "=" not in out[-1]:
            out[-1] = f"{out[-1]}={arg}"
        else:
            out.append(arg)
    return out


def parse_command_line(parser: argparse.ArgumentParser, argv: list[str]) -> tuple[argparse.Namespace, list[str]]:
    """(the parsed arguments, those left unrecognised). A command with several optional positionals (``calibrate
    DATA.csv [CASE.toml]``, ``wall RECORDS WALL [CASE.toml]``) loses a positional given after an option to argparse's
    first pass, which fills every positional from the first run of them; such a command line is parsed again by the
    command's parser with positionals and options intermixed (``parse_known_intermixed_args``), which the top-level
    parser cannot do itself (its sub-commands are a positional of their own). A command line the first pass reads
    whole is not parsed again."""
    args, unknown = parser.parse_known_args(argv)
    command = getattr(args, "command", None)
    sub = getattr(parser, "commands", {}).get(command)
    if not unknown or sub is None:
        return args, unknown
    again, unknown = sub.parse_known_intermixed_args(argv[argv.index(command) + 1 :])
    again.command = command
    return again, unknown


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args, unknown = parse_command_line(parser, join_negative_values(sys.argv[1:] if argv is None else list(argv)))
    if unknown:  # named in the command's own error line, not in the top-level parser's
        command = getattr(args, "command", None)
        prog = parser.prog if command is None else f"{parser.prog} {command}"
        print(f"{prog}: error: unrecognized arguments: {' '.join(unknown)} (see {prog} --help)", file=sys.stderr)
        return 2
    if getattr(args, "_module", None) is None:
        parser.print_help()
        return 2
    try:
        return int(args._module.main(args) or 0)
    except ValueError as exc:
        print(f"impactwear {args.command}: error: {exc}", file=sys.stderr)
        return 2
    except ConvergenceError as exc:
        # A physical solve that did not converge is not a programming error: one line, exit 1.
        print(f"impactwear {args.command}: FE did not converge: {exc}", file=sys.stderr)
        return 1
    except OSError as exc:
        if exc.errno not in WRITE_ERRORS:
            raise
        # the file system refused a write (a full disk, a quota, a read-only or forbidden folder): not a bug
        where = f": {exc.filename}" if exc.filename else ""
        print(f"impactwear {args.command}: error: {exc.strerror or exc}{where}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # the reader of stdout stopped (e.g. `| head`): not a failure of the command
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except KeyboardInterrupt:
        print(f"impactwear {args.command}: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
