"""What the commands share: the case options (a case file, ``--set``, ``--print-default``), the progress bar, the
notes collected from library warnings, and JSON printing."""

from __future__ import annotations

import argparse
import json
import sys
import warnings
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager

from tqdm import tqdm

from wear.app.outputs.writer import to_jsonable
from wear.case import JOBS, Case, dump_case, load_case, override_tables

__all__ = ["add_case_options", "case_from_args", "collect_notes", "print_default", "print_json", "print_notes",
           "progress_bar", "show_progress"]  # fmt: skip


def add_case_options(parser: argparse.ArgumentParser, job: str, *, flag: bool = False) -> None:
    """The options every case-reading command has: the case file (positional ``CASE.toml``, or ``--config`` with
    ``flag``), ``--set TABLE.KEY=VALUE`` (repeatable) and ``--print-default``."""
    what = f"case file (TOML; keys left out take `impactwear {job}`'s default)"
    parser.set_defaults(case_option="config" if flag else "case")
    if flag:
        parser.add_argument("--config", dest="case", metavar="CASE.toml", help=what)
    else:
        parser.add_argument("case", nargs="?", metavar="CASE.toml", help=f"{what}; default: the default case")
    parser.add_argument("--set", dest="overrides", action="append", default=[], metavar="TABLE.KEY=VALUE",
                        help="override any case key (a TOML value, e.g. --set impact.angle=45); "
                        "repeatable")  # fmt: skip
    parser.add_argument("--print-default", "--print-defaults", dest="print_default", action="store_true",
                        help=f"print `impactwear {job}`'s default case as TOML (every key it reads, with its units "
                        "and valid range) and exit")  # fmt: skip


def case_from_args(args: argparse.Namespace, job: str,
                   options: dict[str, dict[str, object]] | None = None) -> Case:  # fmt: skip
    """The checked case of a command: the case file (or ``job``'s default case), then the command's own ``options``
    (tables of values), then each ``--set`` — all laid on at once, so keys that depend on each other may be given
    by different options."""
    tables = {t: dict(v) for t, v in (options or {}).items()}
    for table, values in override_tables(args.overrides).items():
        tables.setdefault(table, {}).update(values)
    return load_case(args.case, job, args.case_option).with_(**tables)


def print_default(job: str) -> int:
    """Print ``job``'s default case (the tables it reads) as commented TOML."""
    print(f"# impactwear {job}: the default case ({JOBS[job].doc}).")
    print("# Every key the command reads, with its meaning and valid range; SI units, angles in degrees from the plate")
    print("# normal. Keys left out of a case file take these values.\n")
    sys.stdout.write(dump_case(JOBS[job].default_case(), JOBS[job].tables))
    return 0


def show_progress(quiet: bool) -> bool:
    """A progress bar is shown unless ``quiet`` or stderr is not a terminal."""
    return not quiet and sys.stderr.isatty()


@contextmanager
def progress_bar(total: int, desc: str, unit: str, quiet: bool) -> Iterator[Callable[[int, str], None]]:
    """Yield ``update(done, label)`` drawing a bar on stderr (nothing when quiet or not on a terminal)."""
    bar = tqdm(total=total, desc=desc, unit=unit, file=sys.stderr, leave=False, disable=not show_progress(quiet))

    def update(done: int, label: str = "") -> None:
        bar.update(done - bar.n)
        if label:
            bar.set_postfix_str(label)

    try:
        yield update
    finally:
        bar.close()


@contextmanager
def collect_notes() -> Iterator[list[str]]:
    """Collect the library warnings raised inside as notes (each message once), instead of printing them."""
    notes: list[str] = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            yield notes
        finally:
            notes.extend(dict.fromkeys(str(w.message) for w in caught))


def print_notes(command: str, notes: Sequence[str]) -> None:
    """One stderr line per note: ``impactwear COMMAND: note: ...``."""
    for note in dict.fromkeys(notes):
        print(f"impactwear {command}: note: {note}", file=sys.stderr)


def print_json(data: object) -> None:
    """``data`` as indented JSON on stdout (non-finite numbers as null)."""
    print(json.dumps(to_jsonable(data), indent=2))
