"""The clean refusal of bad input at the command line, asserted in one place: exit status 2, exactly one line on
stderr (no traceback, no argparse usage), nothing on stdout, found quickly (before any work) and nothing written."""

from __future__ import annotations

import time
from pathlib import Path

from wear.app.cli import main

QUICK = 2.0  # s: a refusal comes before any impact, FE or wear work


def snapshot(root: Path) -> dict[str, bytes | None]:
    """Every path under ``root`` with its bytes (None for a folder): what "nothing written" compares."""
    return {str(p.relative_to(root)): None if p.is_dir() else p.read_bytes() for p in sorted(root.rglob("*"))}


def refused(argv: list[str], tmp_path: Path, capsys, *, out: bool = True, quick: float = QUICK) -> str:
    """Run ``impactwear argv`` in-process (with ``--out tmp_path/out`` unless ``out`` is false or argv has one) and
    assert the clean refusal; return its stderr line. Nothing under ``tmp_path`` may change."""
    if out and "--out" not in argv:
        argv = [*argv, "--out", str(tmp_path / "out")]
    before = snapshot(tmp_path)
    capsys.readouterr()
    start = time.perf_counter()
    try:
        status = main(argv)
    except SystemExit as exc:  # argparse's own errors
        status = exc.code
    seconds = time.perf_counter() - start
    captured = capsys.readouterr()
    err = captured.err.strip()
    assert status == 2, (status, err)
    assert len(err.splitlines()) == 1, err
    assert captured.out == "", captured.out
    assert seconds < quick, f"{seconds:.2f} s: {err}"
    assert snapshot(tmp_path) == before, f"written: {err}"
    return err
