"""The hand-written docs agree with the code and the reports they describe (the docs build checks the rest: maths
offline, whole API summaries, no runaway emphasis; docs/_ext/build_checks.py); the public-API page lists every
exported name."""

from __future__ import annotations

import argparse
import importlib
import pkgutil
import re
import sys
from pathlib import Path

import pytest

from wear.app.cli import build_parser
from wear.wall.fluent import FLUENT_COLUMNS, FLUENT_MASS_COLUMNS, FLUENT_TIME
from wear.wall.table import TABLE_COLUMNS

DOCS = Path(__file__).resolve().parents[1] / "docs"


def test_commands_table_lists_every_command():
    parser = build_parser()
    commands = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction)).choices
    text = (DOCS / "commands.md").read_text(encoding="utf-8")
    table = re.findall(r"^\| `impactwear (\w+)[ `]", text, flags=re.MULTILINE)
    assert sorted(table) == sorted(commands)


def test_checks_page_states_the_reports_count_and_time():
    header = re.search(
        r"(\d+) checks, (\d+) passed, 0 failed; (\d+) s", (DOCS / "validation.md").read_text(encoding="utf-8")
    )
    checks, passed, seconds = header.groups()
    assert checks == passed
    text = " ".join((DOCS / "checks.md").read_text(encoding="utf-8").split())
    assert f"({checks} checks, all passing; {seconds} s" in text


#: The packages whose ``__all__`` the public-API page lists, name by name.
PUBLIC_PACKAGES = ("contact", "fem", "wear", "wear.case", "wear.chain", "wear.erosion", "wear.wall")
#: A row of the public-API page: the public path, then its one-line description.
PUBLIC_ROW = re.compile(r"^\| \{py:obj\}`([\w.]+)` \| (.+?) \|$", flags=re.MULTILINE)


def test_public_api_page_describes_every_exported_name():
    """Every name of each package's ``__all__`` is on docs/api.md with a description, under a path that imports it
    (the same object re-exported elsewhere counts once: ``wear.case.Case`` is ``wear.Case``); every path on the page
    still imports, so the page can go stale in neither direction."""
    rows = PUBLIC_ROW.findall((DOCS / "api.md").read_text(encoding="utf-8"))
    paths = [path for path, _ in rows]
    assert len(paths) == len(set(paths)), "a name is listed twice"
    described = {}
    for path, description in rows:
        assert len(description.split()) >= 3, f"{path}: no description"
        described[id(pkgutil.resolve_name(path))] = path  # raises if the page names something that is gone
    missing = []
    for package in PUBLIC_PACKAGES:
        module = importlib.import_module(package)
        for name in module.__all__:
            if id(getattr(module, name)) not in described:
                missing.append(f"{package}.{name}")
    assert not missing, f"not on docs/api.md: {missing}"


def test_runaway_italics_are_caught():
    """The docs build's italics checks (docs/_ext/build_checks.py) flag the runaway emphasis a stray ``*`` opens, in
    the Markdown source and in the built HTML, and leave a title in italics alone."""
    pytest.importorskip("sphinx")
    sys.path.insert(0, str(DOCS / "_ext"))
    try:
        build_checks = importlib.import_module("build_checks")
    finally:
        sys.path.remove(str(DOCS / "_ext"))
    # a stray "*" inside a word opens an emphasis that the next "*" closes, a sentence later
    runaway = "The spring k = 8G*a·ξ with Coulomb truncation (equations 3, 8 and 9) slides at F_t = μ*F_n."
    assert build_checks._emphasis_problems(runaway)
    assert not build_checks._emphasis_problems("After *Granular Matter* (1999), k = 8G\\*a·ξ.")
    long_em = "<p>k = 8G<em>a·ξ with Coulomb truncation (equations 3, 8 and 9), as DEM codes do, slides at F = μ</em>F"
    assert build_checks._long_italics(long_em)
    assert not build_checks._long_italics("<p><em>A Computational Wear Model of the Oblique Impact of a Ball</em></p>")


def _section_columns(page: str, title: str) -> list[str]:
    """The column names (in backticks) of the first cell of each table row of the section ``## title``."""
    text = (DOCS / page).read_text(encoding="utf-8")
    section = text.split(f"## {title}\n", 1)[1].split("\n## ", 1)[0]
    rows = re.findall(r"^\| (.+?) \|", section, flags=re.MULTILINE)
    return [name for cell in rows for name in re.findall(r"`([^`]+)`", cell)]


def test_the_wall_records_page_lists_exactly_the_plain_table_s_and_fluent_s_columns():
    """docs/wall-records.md's tables are the readers' column constants: the plain table's every column, once, and
    Fluent's required, mass and time columns."""
    listed = _section_columns("wall-records.md", "Plain table: CSV or Parquet")
    assert sorted(listed) == sorted(TABLE_COLUMNS)
    fluent = set(_section_columns("wall-records.md", "Ansys Fluent: DPM sample files"))
    read = {c for cs in FLUENT_COLUMNS.values() for c in cs} | set(FLUENT_MASS_COLUMNS) | {FLUENT_TIME}
    assert read <= fluent and fluent - read == {"t", "time", "name"}
