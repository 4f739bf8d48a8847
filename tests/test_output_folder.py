"""Outputs a user can trust: a command's output folder never loses what impactwear did not write, a bad ``--out`` is
one line and exit 2 before any work, an interrupted write (a real ``kill -9``) never leaves a complete-looking
folder, and files get the permissions of the user's umask."""

from __future__ import annotations

import json
import os
import signal
import stat
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from output_commands import FAST, command_args

import wear.app.commands.calibrate as calibrate_cmd
import wear.app.commands.erode as erode_cmd
import wear.app.commands.indent as indent_cmd
import wear.app.commands.repeat as repeat_cmd
import wear.app.commands.run as run_cmd
import wear.app.sweep.execution as sweep_execution
from wear.app.cli import main
from wear.app.outputs.folder import MANIFEST, check_output_folder, output_folder, read_manifest
from wear.app.outputs.writer import write_csv, write_json


def _foreign_folder(path: Path) -> dict[str, bytes]:
    """A user's folder: a file and a sub-folder with a file; returns {relative path: content}."""
    (path / "data").mkdir(parents=True)
    files = {"notes.txt": b"my notes\n", "data/m.csv": b"x,y\n1,2\n"}
    for name, content in files.items():
        (path / name).write_bytes(content)
    return files


def _unchanged(path: Path, files: dict[str, bytes]) -> bool:
    return all((path / name).read_bytes() == content for name, content in files.items())


@pytest.mark.parametrize("command", [*FAST, "sweep"])
def test_a_folder_of_user_files_is_refused_before_any_work(command, tmp_path, capsys, monkeypatch):
    """``--out`` on a non-empty folder impactwear did not write: one line naming --out, exit 2, the user's files
    untouched, and nothing computed (the command's runner would raise if it were called)."""

    def no_work(*_a, **_k):
        raise AssertionError("work started before --out was checked")

    runners = (
        (run_cmd, "run"),
        (indent_cmd, "indent_case"),
        (erode_cmd, "erode_case"),
        (repeat_cmd, "repeat"),
        (calibrate_cmd, "calibrate"),
        (sweep_execution, "execute_case"),
    )
    for module, name in runners:
        monkeypatch.setattr(module, name, no_work)
    out = tmp_path / "mine"
    files = _foreign_folder(out)
    args = command_args(command, tmp_path)
    assert main([*args, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--out=" in err[0] and "did not write" in err[0] and "data" in err[0], err
    assert _unchanged(out, files) and sorted(p.name for p in out.iterdir()) == ["data", "notes.txt"]


@pytest.mark.parametrize("command", list(FAST))
def test_a_rerun_replaces_its_own_files_and_keeps_the_users(command, tmp_path, capsys):
    """The files a user puts in an earlier output folder survive a rerun of the command, while the command's own
    files are replaced: no stale output of the earlier run is left; another command refuses the folder."""
    out = tmp_path / "out"
    args = command_args(command, tmp_path)
    assert main([*args, "--out", str(out)]) == 0
    first = read_manifest(out)
    assert first["command"] == command and first["complete"] and all((out / n).exists() for n in first["entries"])
    (out / "notes.txt").write_text("mine\n")
    stale = out / first["entries"][0]
    os.utime(stale, (1, 1))  # an old time stamp: a rerun must replace the file
    assert main([*args, "--out", str(out)]) == 0
    assert (out / "notes.txt").read_text() == "mine\n"
    assert stale.stat().st_mtime > 1
    second = read_manifest(out)
    assert second["complete"] and sorted(second["entries"]) == sorted(first["entries"])
    listed = {*second["entries"], "notes.txt", MANIFEST}
    assert {p.name for p in out.iterdir()} == listed  # nothing else: no temporary, no stale entry
    # another command's output is refused before any work, never deleted
    other = "run" if command != "run" else "calibrate"
    capsys.readouterr()
    before = {p.name: p.stat().st_mtime_ns for p in out.iterdir()}
    assert main([*command_args(other, tmp_path), "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"is the output folder of `impactwear {command}`" in err[0], err
    assert {p.name: p.stat().st_mtime_ns for p in out.iterdir()} == before
    assert read_manifest(out) == second


def _bad_outs(tmp_path: Path) -> list[tuple[str, str]]:
    a_file = tmp_path / "a_file"
    a_file.write_text("x")
    return [
        (str(a_file), "is a file"),
        (str(a_file / "sub"), "is a file"),
        ("/proc/impactwear_out/x", "cannot be written"),
    ]


@pytest.mark.parametrize("command", [*FAST, "sweep", "reproduce", "validate"])
def test_every_bad_out_is_one_line_exit_2(command, tmp_path, capsys):
    """A file, a path under a file, or a folder that cannot be written (``/proc``): exit 2, one line naming --out,
    for every command (before any work: the runs here would otherwise take minutes)."""
    for out, why in _bad_outs(tmp_path):
        args = command_args(command, tmp_path)
        started = time.perf_counter()
        assert main([*args, "--out", out]) == 2, (command, out)
        assert time.perf_counter() - started < 5.0
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and "--out=" in err[0] and why in err[0], (command, err)


#: The names the tests' output folder may hold.
NAMES = ("summary.json", "history.csv", "stale.txt")


def test_output_folder_is_atomic_and_keeps_foreign_files(tmp_path):
    """The output folder itself: an error inside leaves nothing (a new folder) or the previous output untouched; a
    success replaces the earlier output; a name clash with a user's file is refused before the block runs."""
    target = tmp_path / "out"
    with pytest.raises(RuntimeError), output_folder(target, "run", NAMES) as tmp:
        write_json(tmp / "summary.json", {"a": 1})
        raise RuntimeError("interrupted")
    assert list(tmp_path.iterdir()) == []
    with output_folder(target, "run", NAMES) as tmp:
        write_json(tmp / "summary.json", {"a": np.float64(1.5), "b": np.arange(2), "c": float("inf")})
        (tmp / "stale.txt").write_text("old")
    (target / "mine.txt").write_text("user")
    with pytest.raises(RuntimeError), output_folder(target, "run", NAMES) as tmp:
        write_csv(tmp / "history.csv", {"time_s": [0.0]})
        raise RuntimeError("interrupted")
    assert sorted(p.name for p in target.iterdir()) == [MANIFEST, "mine.txt", "stale.txt", "summary.json"]
    with output_folder(target, "run", NAMES) as tmp:
        write_csv(tmp / "history.csv", {"time_s": [0.0, 1.0], "force_N": [2.0, 3.0]})
    assert sorted(p.name for p in target.iterdir()) == [MANIFEST, "history.csv", "mine.txt"]
    assert (target / "history.csv").read_text().splitlines() == ["time_s,force_N", "0,2", "1,3"]
    assert read_manifest(target) == {**read_manifest(target), "entries": ["history.csv"], "complete": True}
    with pytest.raises(ValueError, match="mine.txt"), output_folder(target, "run", (*NAMES, "mine.txt")) as tmp:
        raise AssertionError("the clash is found before the work")
    assert (target / "mine.txt").read_text() == "user"
    with pytest.raises(ValueError, match="output folder of `impactwear run`"):
        check_output_folder(target, "sweep")


def _mode(path: Path) -> int:
    return stat.S_IMODE(path.stat().st_mode)


@pytest.mark.parametrize("umask", [0o022, 0o027])
def test_outputs_get_the_permissions_of_the_users_umask(umask, tmp_path):
    """Every file and folder of an output (summary.json, history.csv, pressure.npz, meshes, the folder itself) has
    the mode the user's umask gives (0644/0755 for umask 022), as files the user makes otherwise have."""
    out = tmp_path / "out"
    code = (
        f"import os, sys; os.umask({umask}); from wear.app.cli import main; "
        f"sys.exit(main({[*FAST['run'], '--out', str(out)]!r}))"
    )
    subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, timeout=300)
    file_mode, dir_mode = 0o666 & ~umask, 0o777 & ~umask
    assert _mode(out) == dir_mode
    paths = [p for p in out.rglob("*")]
    assert {"summary.json", "history.csv", "pressure.npz", "surface.vtu"} <= {p.name for p in paths}
    for p in paths:
        assert _mode(p) == (dir_mode if p.is_dir() else file_mode), (p.name, oct(_mode(p)))


def _has_entries(folder: Path) -> bool:
    """Whether ``folder`` holds anything; False once it is gone (renamed into place between two looks at it)."""
    try:
        return folder.is_dir() and any(folder.iterdir())
    except FileNotFoundError:
        return False


def _kill_while_writing(args: list[str], parent: Path, name: str) -> None:
    """Start ``impactwear args`` and ``kill -9`` it as soon as its output is being built (its temporary folder
    ``.NAME.partial-*`` in ``parent``, or ``.impactwear.partial-*`` inside an existing ``NAME``)."""
    proc = subprocess.Popen(
        [sys.executable, "-m", "wear.app.cli", *args], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    deadline = time.monotonic() + 240
    try:
        while time.monotonic() < deadline:
            partial = list(parent.glob(f".{name}.partial-*")) + list((parent / name).glob(".impactwear.partial-*"))
            if any(_has_entries(p) for p in partial):
                break
            if proc.poll() is not None:
                pytest.fail(f"impactwear {args[0]} ended before it could be killed while writing")
            time.sleep(0.005)
        else:
            pytest.fail("no output was being written")
        os.kill(proc.pid, signal.SIGKILL)
    finally:
        proc.wait(timeout=60)
    assert proc.returncode == -signal.SIGKILL


@pytest.mark.parametrize("command", ["run", "indent", "erode"])
def test_kill_9_while_writing_leaves_no_complete_looking_output(command, tmp_path):
    """A real ``kill -9`` while the output is being written: a new folder is absent; an earlier output is left as it
    was (complete, its summary intact). The rerun removes the killed process's temporary folder and completes."""
    out = tmp_path / "out"
    # figures on: the writing lasts long enough (about a second) to be caught
    args = [*[a for a in FAST[command] if a != "--no-figures"], "--out", str(out)]
    if command == "run":
        args = [
            "run",
            "--quiet",
            "--set",
            'fem.coupling="none"',
            "--set",
            'wear.pressure="hertz"',
            "--set",
            'wear.speed="sliding"',
            "--set",
            "output.render=false",
            "--out",
            str(out),
        ]
    _kill_while_writing(args, tmp_path, "out")
    assert not out.exists()
    leftovers = list(tmp_path.glob(".out.partial-*"))
    assert len(leftovers) == 1
    assert (
        subprocess.run([sys.executable, "-m", "wear.app.cli", *args], capture_output=True, timeout=300).returncode == 0
    )
    assert not list(tmp_path.glob(".out.partial-*"))
    before = (out / "summary.json").read_bytes()
    manifest = read_manifest(out)
    _kill_while_writing(args, tmp_path, "out")
    assert (out / "summary.json").read_bytes() == before and read_manifest(out) == manifest
    assert all((out / n).exists() for n in manifest["entries"])
    json.loads(before)
