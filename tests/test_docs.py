"""The hand-written docs agree with the code and the reports they describe (the docs build checks the rest: maths
offline, whole API summaries, no runaway emphasis; docs/_ext/build_checks.py)."""

from __future__ import annotations

import argparse
import re
from pathlib import Path

from wear.app.cli import build_parser

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
