"""What the commands share: the case options (a case file, ``--set``, ``--print-default``), the progress bar, the
notes collected from library warnings, and JSON printing."""

from __future__ import annotations

import argparse
import json
import math
import re
import sys
import warnings
from collections.abc import Iterator, Sequence
from contextlib import contextmanager

from wear.app.outputs.writer import to_jsonable
from wear.case import JOBS, Case, check_job_case, dump_case, load_case, override_tables
from wear.case.progress import progress_bar, show_progress

__all__ = [
    "add_case_options",
    "add_out_option",
    "add_workers_options",
    "check_scheduler_address",
    "positive_int",
    "case_from_args",
    "case_json",
    "path_option",
    "collect_notes",
    "print_default",
    "print_json",
    "print_notes",
    "progress_bar",
    "show_progress",
]


def add_case_options(parser: argparse.ArgumentParser, job: str, *, flag: bool = False) -> None:
    """The options every case-reading command has: the case file (positional ``CASE.toml``, or ``--config`` with
    ``flag``), ``--set TABLE.KEY=VALUE`` (repeatable) and ``--print-default``."""
    what = f"case file (TOML; keys left out take `impactwear {job}`'s default)"
    parser.set_defaults(case_option="config" if flag else "case")
    if flag:
        parser.add_argument("--config", dest="case", metavar="CASE.toml", help=what)
    else:
        parser.add_argument("case", nargs="?", metavar="CASE.toml", help=f"{what}; default: the default case")
    parser.add_argument(
        "--set",
        dest="overrides",
        action="append",
        default=[],
        metavar="TABLE.KEY=VALUE",
        help="override any case key (a TOML value, e.g. --set impact.angle=45); repeatable",
    )
    parser.add_argument(
        "--print-default",
        "--print-defaults",
        dest="print_default",
        action="store_true",
        help=f"print `impactwear {job}`'s default case as TOML (every key it reads, with its units "
        "and valid range) and exit",
    )


def path_option(text: str) -> str:
    """An ``--out`` or ``--report`` path, not empty (an unset shell variable would make it the current folder)."""
    if not text.strip():
        raise argparse.ArgumentTypeError(f"{text!r} is empty: give a path")
    return text


def add_out_option(parser: argparse.ArgumentParser, default: str) -> None:
    """``--out DIR``: a command's output folder (:mod:`wear.app.outputs.folder`)."""
    parser.add_argument(
        "--out",
        default=default,
        type=path_option,
        metavar="DIR",
        help=f"output folder (default: {default}): a new or empty folder, or an earlier output folder "
        "of this command, whose files are replaced while every other file in it is left alone; a "
        "folder holding other files, or another command's output, is refused before any work",
    )


#: A Dask scheduler address: ``tcp://host:8786``, ``tls://host:8786``, ``inproc://...`` or ``host:8786``.
_ADDRESS = re.compile(r"^([a-z][a-z0-9+.-]*://\S+|[\w.-]+:\d+)$")


def positive_int(text: str) -> int:
    """An integer option >= 1 (argparse type)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not an integer") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"{value} must be >= 1")
    return value


def add_workers_options(parser: argparse.ArgumentParser, default: str) -> None:
    """Where the work runs, one of: ``--workers N`` local processes (default ``default``), ``--dask-local N`` a new
    loopback Dask cluster of N processes, ``--scheduler ADDRESS`` an existing Dask cluster."""
    how = parser.add_mutually_exclusive_group()
    how.add_argument("--workers", type=positive_int, metavar="N", help=f"local worker processes (default: {default})")
    how.add_argument(
        "--dask-local", type=positive_int, metavar="N", help="run on a new loopback dask LocalCluster of N processes"
    )
    how.add_argument("--scheduler", metavar="ADDRESS", help="run on an existing Dask cluster, e.g. tcp://host:8786")


def check_scheduler_address(address: str | None) -> None:
    """A one-line ``ValueError`` naming ``--scheduler`` unless ``address`` is None or a Dask scheduler address."""
    if address is not None and not _ADDRESS.match(address):
        raise ValueError(
            f"--scheduler={address!r} is not a Dask scheduler address: give PROTOCOL://HOST:PORT or HOST:PORT, "
            "e.g. tcp://host:8786"
        )


def case_from_args(args: argparse.Namespace, job: str, options: dict[str, dict[str, object]] | None = None) -> Case:
    """The checked case of a command: the case file (or ``job``'s default case), then the command's own ``options``
    (tables of values), then each ``--set`` — all laid on at once, so keys that depend on each other may be given
    by different options. A plate model (``fem.model``) the command does not run is refused
    (:func:`wear.case.check_job_case`)."""
    tables = {t: dict(v) for t, v in (options or {}).items()}
    reads = JOBS[job].tables
    for table, values in override_tables(args.overrides).items():
        if table not in reads:
            key, value = next(iter(values.items()))
            raise ValueError(
                f"--set {table}.{key}={value!r}: impactwear {job} does not read [{table}] (it reads "
                f"{', '.join(f'[{t}]' for t in reads)})"
            )
        tables.setdefault(table, {}).update(values)
    return check_job_case(load_case(args.case, job, args.case_option).with_(**tables), job)


def case_json(case: Case, job: str) -> dict:
    """The tables of ``case`` that ``job`` reads, JSON-safe: an infinite value (a rigid body's E, a yield strength
    that is never reached) as the string "inf", as in TOML."""

    def finite(value: object) -> object:
        if isinstance(value, dict):
            return {k: finite(v) for k, v in value.items()}
        if isinstance(value, float) and math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return value

    tables = case.to_dict(JOBS[job].tables)
    for table, keys in read_keys(job).items():
        tables[table] = {k: v for k, v in tables[table].items() if k in keys}
    return finite(tables)


def read_keys(job: str) -> dict[str, tuple[str, ...]]:
    """The tables of which ``job`` reads a fixed part, and those keys (``--print-default`` prints only them)."""
    fem_keys = JOBS[job].fem_keys
    return {"fem": fem_keys} if fem_keys else {}


def print_default(args: argparse.Namespace, job: str, case: Case) -> int:
    """``--print-default``: print ``case`` (the tables ``job`` reads) as commented TOML, or as JSON with ``--json``.
    Without a case file or options ``case`` is the default case; with them, the case the command would run."""
    tables = JOBS[job].tables
    if getattr(args, "json", False):
        print_json(case_json(case, job))
        return 0
    if case == JOBS[job].default_case():
        print(f"# impactwear {job}: the default case ({JOBS[job].doc}).")
        print("# Every key the command reads, with its meaning and valid range; SI units, angles in degrees from the")
        print("# plate normal. Keys left out of a case file take these values.\n")
    else:
        print(f"# impactwear {job}: the case it would run (the case file and options laid on its default case).")
        print("# Every key the command reads, with its meaning and valid range; SI units, angles in degrees from the")
        print("# plate normal.\n")
    sys.stdout.write(dump_case(case, tables, only=read_keys(job)))
    return 0


@contextmanager
def collect_notes() -> Iterator[list[str]]:
    """Collect the library warnings raised inside as notes (each message once, in the list as soon as raised, so
    that a summary written inside holds them), instead of printing them."""
    notes: list[str] = []

    def note(message: Warning | str, *_args: object, **_kwargs: object) -> None:
        if str(message) not in notes:
            notes.append(str(message))

    with warnings.catch_warnings():
        warnings.simplefilter("always")
        warnings.showwarning = note
        yield notes


def print_notes(command: str, notes: Sequence[str]) -> None:
    """One stderr line per note: ``impactwear COMMAND: note: ...``."""
    for note in dict.fromkeys(notes):
        print(f"impactwear {command}: note: {note}", file=sys.stderr)


def print_json(data: object) -> None:
    """``data`` as indented JSON on stdout (non-finite numbers as null)."""
    print(json.dumps(to_jsonable(data), indent=2))
