"""The replace of an earlier output and what can go wrong around it: a kill at any step of the replace leaves the
earlier output as it was or the complete new one (and the next run loses nothing); a user's file under an output's
name is refused before any work, for every command that writes files; a write the file system refuses (a full disk,
a quota, a read-only or forbidden folder) is one line, exit status 2, nothing left and the earlier output intact."""

from __future__ import annotations

import errno
import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest
from output_commands import FAST, SWEEP, command_args

import wear.app.commands.calibrate as calibrate_cmd
import wear.app.commands.erode as erode_cmd
import wear.app.commands.indent as indent_cmd
import wear.app.commands.repeat as repeat_cmd
import wear.app.commands.reproduce as reproduce_cmd
import wear.app.commands.run as run_cmd
import wear.app.commands.validate as validate_cmd
import wear.app.commands.wall as wall_cmd
import wear.app.outputs.exchange as exchange
import wear.app.outputs.folder as folder
import wear.app.outputs.writer as writer
import wear.app.sweep.execution as sweep_execution
from wear.app.cli import build_parser, main
from wear.app.outputs import calibration, erosion, indent, repeat, run, wall
from wear.app.outputs.folder import MANIFEST, output_folder, read_manifest
from wear.app.reproduce.report import HEADER as REPRODUCE_HEADER
from wear.app.reproduce.run import check_outputs
from wear.app.sweep.runner import ENTRIES as SWEEP_ENTRIES
from wear.app.validation.runner import HEADER as VALIDATION_HEADER
from wear.app.validation.runner import Validation
from wear.case import JOBS
from wear.chain.indent import indent_case

ROOT = Path(__file__).resolve().parents[1]

#: The names the tests' outputs hold.
NAMES = ("summary.json", "history.csv", "frames")


def _write_output(tmp: Path, tag: str) -> None:
    """An output of the tests' command: a data file, a sub-folder with a file and the summary (``tag`` in each; the
    child process below writes the same)."""
    (tmp / "history.csv").write_text(f"time_s\n{tag}\n")
    (tmp / "frames").mkdir()
    (tmp / "frames" / "f1.vtu").write_text(tag)
    (tmp / "summary.json").write_text(json.dumps({"tag": tag}))


def _snapshot(folder: Path) -> dict[str, str]:
    """Every visible entry of ``folder`` (recursively: relative path → content, a symlink's target, or "dir"), and
    its manifest."""
    out = {}
    for p in sorted(folder.rglob("*")):
        rel = p.relative_to(folder)
        if any(part.startswith(".") and part != MANIFEST for part in rel.parts):
            continue
        if p.is_symlink():
            out[str(rel)] = f"-> {os.readlink(p)}"
        elif p.is_dir():
            out[str(rel)] = "dir"
        else:
            out[str(rel)] = p.read_text()
    return out


def _user_files(folder: Path) -> None:
    """A user's note, a folder of data and a symbolic link beside the results."""
    (folder / "notes.txt").write_text("my notes\n")
    (folder / "data").mkdir()
    (folder / "data" / "m.csv").write_text("x,y\n1,2\n")
    (folder / "link").symlink_to("notes.txt")


#: A child process that builds a new output into ``out`` and kills itself (SIGKILL) at its K-th file-system step of
#: the block's end (every rename, link, folder made, swap and removal is a step); prints the number of steps.
CHILD = textwrap.dedent(
    """
    import json, os, shutil, signal, sys
    from pathlib import Path
    import wear.app.outputs.folder as folder

    out, kill_at, steps = Path(sys.argv[1]), int(sys.argv[2]), [0]

    def step(f):
        def at_step(*args, **kwargs):
            steps[0] += 1
            if steps[0] == kill_at:
                os.kill(os.getpid(), signal.SIGKILL)
            return f(*args, **kwargs)
        return at_step

    with folder.output_folder(out, "run", ("summary.json", "history.csv", "frames")) as tmp:
        (tmp / "history.csv").write_text("time_s\\nnew\\n")
        (tmp / "frames").mkdir()
        (tmp / "frames" / "f1.vtu").write_text("new")
        (tmp / "summary.json").write_text(json.dumps({"tag": "new"}))
        for name in ("replace", "rename", "link", "symlink", "mkdir"):
            setattr(os, name, step(getattr(os, name)))
        shutil.rmtree = step(shutil.rmtree)
        folder.exchange = step(folder.exchange)
    print(steps[0])
    """
)


def _child(out: Path, kill_at: int) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    return subprocess.run(
        [sys.executable, "-c", CHILD, str(out), str(kill_at)],
        capture_output=True,
        text=True,
        timeout=120,
        env=env,
    )


def _earlier_output(out: Path) -> dict[str, str]:
    """``out`` as an earlier output with the user's files beside it; returns its snapshot."""
    with output_folder(out, "run", NAMES) as tmp:
        _write_output(tmp, "old")
    _user_files(out)
    return _snapshot(out)


def test_a_kill_at_every_step_of_the_replace_keeps_the_earlier_output_or_the_new_one(tmp_path):
    """SIGKILL at each file-system step of replacing an earlier output (with a note, a folder of data and a link of
    the user's beside it): the folder is, file for file, the earlier output as it was or the complete new one, with
    the user's files; the next run completes, keeps the user's files and leaves no hidden folder behind."""
    probe = tmp_path / "probe" / "out"
    _earlier_output(probe)
    done = _child(probe, 0)
    assert done.returncode == 0, done.stderr
    steps = int(done.stdout)
    assert steps >= 8  # links of the user's 3 entries, the manifest, the swap, the removal at least
    new = _snapshot(probe)
    assert new["summary.json"] == json.dumps({"tag": "new"}) and new["notes.txt"] == "my notes\n"
    seen = set()
    for kill_at in range(1, steps + 1):
        out = tmp_path / f"k{kill_at}" / "out"
        old = _earlier_output(out)
        killed = _child(out, kill_at)
        assert killed.returncode == -signal.SIGKILL, (kill_at, killed.stderr)
        now = _snapshot(out)
        assert now in (old, new), (kill_at, now)
        seen.add("old" if now == old else "new")
        # the next run: the killed process's temporary folder goes, nothing of the user's or of the output does
        with output_folder(out, "run", NAMES) as tmp:
            _write_output(tmp, "next")
        after = _snapshot(out)
        assert after == {
            **new,
            "summary.json": json.dumps({"tag": "next"}),
            "history.csv": "time_s\nnext\n",
            "frames/f1.vtu": "next",
        }, kill_at
        assert sorted(p.name for p in out.parent.iterdir()) == ["out"], kill_at
        assert sorted(p.name for p in out.iterdir() if p.name.startswith(".")) == [MANIFEST], kill_at
    assert seen == {"old", "new"}  # the kills fell on both sides of the swap


def test_the_users_files_are_the_same_files_after_a_replace(tmp_path):
    """The user's files beside an earlier output are carried over as the same files (hard links: same inode, a
    large data file is not copied), the folder keeps its mode, and a file the user adds during the run is kept."""
    out = tmp_path / "out"
    _earlier_output(out)
    os.chmod(out, 0o750)
    inodes = {n: (out / n).stat().st_ino for n in ("notes.txt", "data/m.csv")}
    with output_folder(out, "run", NAMES) as tmp:
        _write_output(tmp, "new")
        (out / "late.txt").write_text("written while the run ran\n")
    assert {n: (out / n).stat().st_ino for n in inodes} == inodes
    assert (out / "late.txt").read_text() == "written while the run ran\n"
    assert oct(out.stat().st_mode & 0o777) == oct(0o750) and (out / "link").readlink() == Path("notes.txt")


def test_a_failed_swap_leaves_the_earlier_output(tmp_path, monkeypatch):
    """The swap itself failing (an OSError from the file system): the earlier output as it was, nothing beside it,
    and one line naming --out and the cause."""

    out = tmp_path / "out"
    old = _earlier_output(out)

    def refuse(a, b):
        raise OSError(errno.EROFS, os.strerror(errno.EROFS), str(a))

    monkeypatch.setattr(folder, "exchange", refuse)
    with pytest.raises(ValueError) as err, output_folder(out, "run", NAMES) as tmp:
        _write_output(tmp, "new")
    assert (
        str(err.value)
        == f"--out={str(out)!r} cannot be written (Read-only file system): the earlier output is as it was"
    )
    assert _snapshot(out) == old and sorted(p.name for p in tmp_path.iterdir()) == ["out"]


def test_an_earlier_output_that_cannot_be_swapped_is_refused_before_any_work(tmp_path, monkeypatch):
    """Where the folder cannot be swapped (here: the file system says so), a complete earlier output is refused
    before the block runs, naming --out and why; an empty folder, or what a killed filling left (manifest
    incomplete, no summary), is filled entry by entry, the user's files kept."""

    def unsupported(a, b):
        raise OSError(errno.EINVAL, os.strerror(errno.EINVAL), str(a))

    monkeypatch.setattr(exchange, "exchange", unsupported)
    out = tmp_path / "out"
    out.mkdir()
    assert folder.can_exchange(out.resolve()) == f"Invalid argument in {str(tmp_path)!r}"
    with output_folder(out, "run", NAMES) as tmp:  # empty: filled entry by entry
        _write_output(tmp, "old")
    assert read_manifest(out)["complete"] and (out / "frames" / "f1.vtu").read_text() == "old"
    with pytest.raises(ValueError, match="cannot be replaced in one step .Invalid argument"):
        with output_folder(out, "run", NAMES):
            raise AssertionError("the refusal comes before the work")
    assert (out / "summary.json").read_text() == json.dumps({"tag": "old"})
    # a filling killed before the summary: the manifest says incomplete; the next run fills the folder again
    (out / "summary.json").unlink()
    (out / MANIFEST).write_text(json.dumps({**read_manifest(out), "complete": False}))
    (out / "notes.txt").write_text("mine\n")
    with output_folder(out, "run", NAMES) as tmp:
        _write_output(tmp, "new")
    assert _snapshot(out) == {
        MANIFEST: (out / MANIFEST).read_text(),
        "frames": "dir",
        "frames/f1.vtu": "new",
        "history.csv": "time_s\nnew\n",
        "notes.txt": "mine\n",
        "summary.json": json.dumps({"tag": "new"}),
    }
    assert read_manifest(out)["complete"] and sorted(p.name for p in tmp_path.iterdir()) == ["out"]


# --------------------------------------------------------------- a user's file under an output's name, up front
def _no_work(monkeypatch) -> None:
    def no_work(*_a, **_k):
        raise AssertionError("work started before --out was checked")

    for module, name in (
        (run_cmd, "run"),
        (indent_cmd, "indent_case"),
        (erode_cmd, "erode_case"),
        (erode_cmd, "erode_angles"),
        (repeat_cmd, "repeat"),
        (calibrate_cmd, "calibrate"),
        (wall_cmd, "erode_component"),
        (sweep_execution, "execute_case"),
        (reproduce_cmd, "reproduce"),
        (validate_cmd, "run_validation"),
    ):
        monkeypatch.setattr(module, name, no_work)


#: command → (the names it writes, a user's file under one of them).
COLLISIONS = {
    "run": (run.ENTRIES, "plastic_zone.png"),
    "indent": (indent.ENTRIES, "pressure.png"),
    "erode": (erosion.ENTRIES, "angle_30"),
    "repeat": (repeat.ENTRIES, "repeat.png"),
    "calibrate": (calibration.ENTRIES, "calibrated.toml"),
    "wall": (wall.ENTRIES, "hot_spots.csv"),
    "sweep": (SWEEP_ENTRIES, "results.csv"),
}


@pytest.mark.parametrize("command", list(COLLISIONS))
def test_a_users_file_under_an_output_name_is_refused_before_any_work(command, tmp_path, capsys, monkeypatch):
    """An earlier output folder of the command (its manifest lists other entries) where the user put a file under a
    name the command writes: one line naming --out and the file, exit 2, nothing computed, nothing written (the
    trial found it after the whole run: 21 s, 18 min for a 3-D run)."""
    _no_work(monkeypatch)
    entries, name = COLLISIONS[command]
    out = tmp_path / "out"
    out.mkdir()
    manifest = {"command": command, "entries": [], "complete": True}
    (out / MANIFEST).write_text(json.dumps(manifest))
    (out / name).write_text("the user's\n")
    args = command_args(command, tmp_path)
    before = _snapshot(out)
    assert main([*args, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"--out={str(out)!r}" in err[0] and name in err[0] and "did not write" in err[0], err
    assert _snapshot(out) == before and sorted(p.name for p in tmp_path.iterdir()) == sorted(
        [
            "out",
            *(["data.csv"] if command == "calibrate" else []),
            *(["sweep.toml"] if command == "sweep" else []),
            *(["hits.csv", "plate.stl"] if command == "wall" else []),
        ]
    )


def test_commands_that_write_files_name_them():
    """Every command with an output folder states its names (the check above needs them), and impact writes none."""
    assert set(COLLISIONS) == {*FAST, "sweep"}
    parser = build_parser()
    assert all(hasattr(parser.parse_args([c, "--out", "x"]), "out") for c in ("reproduce", "validate"))
    assert not hasattr(parser.parse_args(["impact"]), "out")


@pytest.mark.parametrize(
    ("command", "name"),
    [("validate", "validation.md"), ("reproduce", "reproduce.md"), ("reproduce", "figures/fig06_spin.png")],
)
def test_reproduce_and_validate_refuse_a_users_file_they_would_replace(command, name, tmp_path, capsys, monkeypatch):
    """validation.md, reproduce.md or a figure reproduce writes, there and not impactwear's: refused before any
    work, one line naming --out and the file; impactwear's own (its first lines) are replaced as before."""
    _no_work(monkeypatch)
    out = tmp_path / "docs"
    (out / "figures").mkdir(parents=True)
    (out / name).write_text("the user's\n")
    assert main([command, "--quiet", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"--out={str(out)!r}" in err[0] and name in err[0] and "did not write" in err[0], err
    assert (out / name).read_text() == "the user's\n"
    # impactwear's own files: accepted (the figure is impactwear's when reproduce.md is)
    (out / "validation.md").write_text(VALIDATION_HEADER + " --quick` (do not edit by hand).\n")
    (out / "reproduce.md").write_text(REPRODUCE_HEADER + "` (do not edit by hand).\n")
    check_outputs(out, ["fig06_spin"])
    monkeypatch.setattr(validate_cmd, "run_validation", lambda **_k: Validation())
    assert main(["validate", "--quiet", "--out", str(out)]) == 0
    assert (out / "validation.md").read_text().startswith(VALIDATION_HEADER)


def test_a_folder_under_the_name_of_a_report_is_one_line(tmp_path, capsys, monkeypatch):
    """A folder where reproduce writes reproduce.md: one line naming --out and the folder, exit 2, before any work."""
    _no_work(monkeypatch)
    (tmp_path / "reproduce.md").mkdir()
    assert main(["reproduce", "--quiet", "--out", str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"--out={str(tmp_path)!r} holds a folder 'reproduce.md'" in err[0], err


# ------------------------------------------------------------------------------- a full disk, a quota, read-only
@pytest.fixture(scope="module")
def indent_run():
    """One small indentation, computed once (the tests below only write it)."""

    case = JOBS["indent"].default_case().with_(fem={"load_steps": 3, "unload_steps": 2, "mesh_scale": 4.0})
    return indent_case(case)


def _full_disk_at(monkeypatch, n: int, code: int = errno.ENOSPC) -> None:
    """The ``n``-th file the one writer writes (and every later one) fails in the middle with ``code``."""
    real = writer.atomic_write
    count = [0]

    def failing(path, dump, **kwargs):
        count[0] += 1
        if count[0] < n:
            return real(path, dump, **kwargs)

        def half(f):
            raise OSError(code, os.strerror(code))

        return real(path, half, **kwargs)

    monkeypatch.setattr(writer, "atomic_write", failing)


INDENT = ["indent", "--quiet", "--no-figures", "--load-steps", "3", "--unload-steps", "2", "--set", "fem.mesh_scale=4"]


@pytest.mark.parametrize("n", [1, 3, 5, 6])
def test_a_full_disk_is_one_line_exit_2_and_leaves_nothing(n, indent_run, tmp_path, capsys, monkeypatch):
    """ENOSPC at the n-th file written (the data, the summary, the manifest): exit 2, one line naming --out and
    the cause; a new folder is not made and nothing is left beside it; an earlier output is as it was."""
    monkeypatch.setattr(indent_cmd, "indent_case", lambda *a, **k: indent_run)
    out = tmp_path / "out"
    with monkeypatch.context() as m:
        _full_disk_at(m, n)
        assert main([*INDENT, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"--out={str(out)!r}" in err[0] and "No space left on device" in err[0], err
    assert "nothing was written" in err[0] and list(tmp_path.iterdir()) == []
    assert main([*INDENT, "--out", str(out)]) == 0
    (out / "notes.txt").write_text("mine\n")
    before = _snapshot(out)
    with monkeypatch.context() as m:
        _full_disk_at(m, n)
        assert main([*INDENT, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "No space left on device" in err[0] and "earlier output is as it was" in err[0], err
    assert _snapshot(out) == before and sorted(p.name for p in tmp_path.iterdir()) == ["out"]
    assert sorted(p.name for p in out.iterdir() if p.name.startswith(".")) == [MANIFEST]


@pytest.mark.parametrize("code", [errno.EDQUOT, errno.EROFS, errno.EACCES, errno.EFBIG])
def test_other_refused_writes_are_one_line_too(code, indent_run, tmp_path, capsys, monkeypatch):
    """A quota, a read-only file system, a forbidden folder, a file too large: the same one line with the cause."""
    monkeypatch.setattr(indent_cmd, "indent_case", lambda *a, **k: indent_run)
    _full_disk_at(monkeypatch, 2, code)
    out = tmp_path / "out"
    assert main([*INDENT, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"--out={str(out)!r}" in err[0] and os.strerror(code) in err[0], err
    assert list(tmp_path.iterdir()) == []


def test_a_full_disk_in_validate_and_sweep_is_one_line(tmp_path, capsys, monkeypatch):
    """The commands that write file by file (validate's report, a sweep's case files): one line naming the file
    and the cause, exit 2, no traceback; no temporary file left."""
    monkeypatch.setattr(validate_cmd, "run_validation", lambda **_k: Validation())
    _full_disk_at(monkeypatch, 1)
    out = tmp_path / "v"
    assert main(["validate", "--quiet", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "No space left on device" in err[0] and str(out / "validation.md") in err[0], err
    assert list(out.iterdir()) == []
    spec = tmp_path / "sweep.toml"
    spec.write_text(SWEEP)
    started = time.perf_counter()
    assert main(["sweep", str(spec), "--quiet", "--workers", "1", "--out", str(tmp_path / "s")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "No space left on device" in err[0] and str(tmp_path / "s") in err[0], err
    assert time.perf_counter() - started < 60
