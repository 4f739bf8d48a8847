"""Running sweeps (wear.app.sweep.runner): same numbers as a direct call, local pool = Dask, resume after kill -9.

What each test checks against:
- the impact stage returns exactly (bit for bit) what a direct ``contact.simulate_impact`` call returns for the
  same case (the numbers themselves are validated in tests/test_impact_*.py);
- a real ``distributed.LocalCluster`` (2 worker processes, loopback) gives a ``results.csv`` byte-identical to the
  local process pool's (issue 5 §3);
- a sweep whose driver is killed with SIGKILL mid-way, or one of whose workers is, or which gets SIGINT, ends
  (after a rerun where needed) with the same ``results.csv`` as an uninterrupted run, and every case file once
  (issue 5 §3: "nothing lost, nothing duplicated");
- a failing case is recorded with its error, the others go on, and the exit status is 1.
"""

from __future__ import annotations

import csv
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from wear.app import cli
from wear.app.sweep.execution import worker_pool
from wear.app.sweep.runner import run_sweep
from wear.app.sweep.spec import load_sweep
from wear.case import Case, default_case

POSIX = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="signals and /proc: Linux only")

# 40 cases of ~20 ms each (a tiny time step makes each impact ~3e5 engine steps): slow enough to kill mid-way.
SLOW_SWEEP = """
[sweep]
stage = "impact"
[base]
impact.time_step = 2e-11
[grid]
"impact.angle" = [0, 5, 10, 15, 20, 25, 30, 35, 40, 45, 50, 55, 60, 65, 70, 75, 80, 85, 88, 89]
"impact.friction" = [0.1, 0.3]
"""


def _repeat_summary(case: Case) -> dict:
    """The repeat stage's summary of ``case``, run directly (no sweep)."""
    from wear import repeat
    from wear.app.sweep.stages import stage_case

    return repeat(stage_case(case, "repeat")).summary()


def _sweep_file(tmp_path: Path, text: str, name: str = "sweep.toml") -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _sigint_default() -> None:
    # a shell started without job control (a CI script, `cmd &`) runs its background jobs with SIGINT ignored, and the
    # child inherits that; the sweep is started as a terminal starts a foreground job, where Ctrl-C interrupts
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _cli_process(sweep: Path, out: Path, *extra: str) -> subprocess.Popen:
    return subprocess.Popen(
        [sys.executable, "-m", "wear.app.cli", "sweep", str(sweep), "--out", str(out), "--quiet", *extra],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,  # our own process group, so a leftover can be cleaned up by group
        preexec_fn=_sigint_default,
    )


def _case_files(out: Path) -> list[Path]:
    return sorted((out / "cases").glob("*.json"))


def _wait_for_cases(out: Path, count: int, proc: subprocess.Popen, timeout: float = 60.0) -> int:
    end = time.monotonic() + timeout
    while time.monotonic() < end:
        n = len(_case_files(out)) if (out / "cases").is_dir() else 0
        if n >= count:
            return n
        assert proc.poll() is None, f"sweep ended early: {proc.communicate()}"
        time.sleep(0.01)
    raise AssertionError(f"no {count} case files after {timeout} s")


def _session_processes(sid: int) -> list[int]:
    """Pids of the live (non-zombie) processes in session ``sid`` (Linux /proc)."""
    pids = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            text = stat.read_text()
        except OSError:
            continue
        fields = text[text.rindex(")") + 2 :].split()
        if int(fields[3]) == sid and fields[0] != "Z":
            pids.append(int(stat.parent.name))
    return pids


def _children(pid: int) -> list[int]:
    path = Path(f"/proc/{pid}/task/{pid}/children")
    return [int(p) for p in path.read_text().split()] if path.exists() else []


def _cleanup(proc: subprocess.Popen) -> None:
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    proc.wait()


def _records(out: Path) -> dict[str, dict]:
    return {p.stem: json.loads(p.read_text()) for p in _case_files(out)}


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """The slow sweep run once, uninterrupted, on the local pool: (sweep file, output folder)."""
    tmp = tmp_path_factory.mktemp("sweep_ref")
    sweep = _sweep_file(tmp, SLOW_SWEEP)
    outcome = run_sweep(load_sweep(sweep), tmp / "out", workers=2, quiet=True)
    assert (outcome.computed, outcome.failed) == (40, 0)
    return sweep, tmp / "out"


def test_impact_stage_returns_exactly_what_simulate_impact_returns(tmp_path):
    from contact import simulate_impact
    from contact.results import OUTPUT_UNITS
    from wear.app.outputs.fields import with_units

    sweep = _sweep_file(
        tmp_path,
        """
        [sweep]
        stage = "impact"
        [base]
        plate.yield_strength = 3e8
        [grid]
        "impact.angle" = [0, 35.5, 80]
        "impact.normal_model" = ["hertz", "thornton"]
        """.replace("\n        ", "\n"),
    )
    spec = load_sweep(sweep)
    outcome = run_sweep(spec, tmp_path / "out", workers=2, quiet=True)
    assert (outcome.total, outcome.computed, outcome.failed) == (6, 6, 0)
    records = _records(tmp_path / "out")
    with open(tmp_path / "out" / "results.csv", newline="") as f:
        rows = {row["case_id"]: row for row in csv.DictReader(f)}
    for sc in spec.cases:
        direct = simulate_impact(
            **Case.from_dict(sc.case, default_case("impact")).impact_arguments(), history=False
        ).to_dict()
        expected = {k: direct[k] for k in OUTPUT_UNITS}
        assert records[sc.case_id]["results"] == expected  # bit-identical floats through JSON
        assert records[sc.case_id]["case"] == sc.case
        for key, value in expected.items():  # and through the CSV (repr round-trips floats exactly), unit in the name
            text = rows[sc.case_id][with_units(key, OUTPUT_UNITS[key])]
            assert (None if text == "" else type(value)(text)) == value, key
    assert records[spec.cases[0].case_id]["results"]["tangential_restitution"] is None  # angle 0: NaN → empty
    assert (tmp_path / "out" / "sweep_2d.png").stat().st_size > 10_000


def test_rerun_skips_finished_cases_and_recomputes_only_missing_ones(tmp_path):
    sweep = _sweep_file(
        tmp_path,
        '[sweep]\nstage = "impact"\n[[cases]]\nimpact.angle = 10\n[[cases]]\nimpact.angle = 20\n'
        "[[cases]]\nimpact.angle = 30\n[[cases]]\nimpact.angle = 40\n",
    )
    spec = load_sweep(sweep)
    out = tmp_path / "out"
    run_sweep(spec, out, workers=1, quiet=True)
    table = (out / "results.csv").read_bytes()
    stamps = {p.name: p.stat().st_mtime_ns for p in _case_files(out)}
    again = run_sweep(spec, out, workers=1, quiet=True)
    assert (again.skipped, again.computed) == (4, 0)
    assert {p.name: p.stat().st_mtime_ns for p in _case_files(out)} == stamps
    (out / "results.csv").unlink()
    _case_files(out)[0].unlink()
    third = run_sweep(spec, out, workers=1, quiet=True)
    assert (third.skipped, third.computed) == (3, 1)
    assert (out / "results.csv").read_bytes() == table  # rewritten on every rerun
    assert not list(out.glob("*.png"))  # an explicit list of cases has no grid to plot


def test_failed_case_is_recorded_others_go_on_exit_status_1(tmp_path, capsys):
    # Thornton's law needs a yield strength: the schema accepts each key, contact rejects the combination at run
    # time, so this case fails inside the worker.
    sweep = _sweep_file(
        tmp_path,
        '[sweep]\nstage = "impact"\n[[cases]]\nimpact.angle = 10\n[[cases]]\nimpact.normal_model = "thornton"\n'
        "[[cases]]\nimpact.angle = 50\n",
    )
    out = tmp_path / "out"
    assert cli.main(["sweep", str(sweep), "--out", str(out), "--workers", "2"]) == 1
    err = capsys.readouterr().err
    spec = load_sweep(sweep)
    bad = spec.cases[1].case_id
    assert f"failed {bad}: ValueError: yield_strength=None" in err
    records = _records(out)
    assert records[bad]["status"] == "failed" and "yield_strength" in records[bad]["error"]
    assert "Traceback" in records[bad]["traceback"]
    assert [records[c.case_id]["status"] for c in spec.cases] == ["ok", "failed", "ok"]
    with open(out / "results.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [r["status"] for r in rows] == ["ok", "failed", "ok"]
    assert rows[1]["error"].startswith("ValueError: yield_strength=None") and rows[1]["max_force_N"] == ""
    # a rerun retries the failed case only (it fails again, deterministically)
    again = run_sweep(spec, out, workers=1, quiet=True)
    assert (again.skipped, again.computed, again.failed) == (2, 0, 1)


def test_local_cluster_gives_results_identical_to_local_pool(tmp_path):
    pytest.importorskip("distributed")
    sweep = _sweep_file(
        tmp_path,
        '[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [0, 20, 40, 60, 80]\n"impact.speed" = [0.5, 3.9]\n',
    )
    spec = load_sweep(sweep)
    pool = run_sweep(spec, tmp_path / "pool", workers=2, quiet=True)
    dask = run_sweep(spec, tmp_path / "dask", dask_local=2, quiet=True)
    assert (pool.computed, dask.computed, pool.failed, dask.failed) == (10, 10, 0, 0)
    assert (tmp_path / "pool" / "results.csv").read_bytes() == (tmp_path / "dask" / "results.csv").read_bytes()
    a, b = _records(tmp_path / "pool"), _records(tmp_path / "dask")
    assert a.keys() == b.keys() and all(a[k]["results"] == b[k]["results"] for k in a)
    assert len({r["worker"] for r in b.values()}) == 2  # both Dask worker processes took cases


@POSIX
def test_driver_killed_with_sigkill_mid_sweep_resumes_to_same_results(reference, tmp_path):
    sweep, ref = reference
    out = tmp_path / "out"
    proc = _cli_process(sweep, out, "--workers", "2")
    try:
        _wait_for_cases(out, 4, proc)
        os.kill(proc.pid, signal.SIGKILL)
        proc.wait()
        written = len(_case_files(out))
        assert 4 <= written < 40, f"{written} cases written before the kill: not mid-way"
        # the orphaned workers notice and exit by themselves (no stray CPU hogs, no late writes)
        end = time.monotonic() + 10
        while _session_processes(proc.pid) and time.monotonic() < end:
            time.sleep(0.1)
        assert not _session_processes(proc.pid), "workers outlived the killed driver"
    finally:
        _cleanup(proc)
    assert not (out / "results.csv").exists()  # an interrupted sweep has no complete-looking table
    outcome = run_sweep(load_sweep(sweep), out, workers=2, quiet=True)
    assert outcome.skipped == written and outcome.computed == 40 - written and outcome.failed == 0
    assert (out / "results.csv").read_bytes() == (ref / "results.csv").read_bytes()
    assert [p.name for p in _case_files(out)] == [p.name for p in _case_files(ref)]
    assert not list((out / "cases").glob(".*"))  # no temp files left


@POSIX
def test_worker_killed_with_sigkill_is_retried_and_sweep_completes(reference, tmp_path):
    sweep, ref = reference
    out = tmp_path / "out"
    proc = _cli_process(sweep, out, "--workers", "2")
    try:
        _wait_for_cases(out, 3, proc)
        workers = [p for p in _children(proc.pid) if b"spawn_main" in Path(f"/proc/{p}/cmdline").read_bytes()]
        assert workers, "no worker process found"
        os.kill(workers[0], signal.SIGKILL)
        stdout, stderr = proc.communicate(timeout=120)
    finally:
        _cleanup(proc)
    assert proc.returncode == 0, stderr
    assert (out / "results.csv").read_bytes() == (ref / "results.csv").read_bytes()


@POSIX
def test_sigint_stops_with_status_130_keeping_finished_cases(reference, tmp_path):
    sweep, ref = reference
    out = tmp_path / "out"
    proc = _cli_process(sweep, out, "--workers", "2")
    try:
        _wait_for_cases(out, 3, proc)
        os.kill(proc.pid, signal.SIGINT)
        stdout, stderr = proc.communicate(timeout=60)
    finally:
        _cleanup(proc)
    assert proc.returncode == 130, stderr
    assert stderr.strip().splitlines()[-1] == "impactwear sweep: interrupted"
    assert not (out / "results.csv").exists()
    kept = _records(out)
    assert 3 <= len(kept) < 40
    expected = _records(ref)
    assert all(kept[k]["results"] == expected[k]["results"] for k in kept)  # finished cases are complete and right


def test_erode_and_repeat_are_sweep_stages(tmp_path):
    """The erosion and the repeated impacts run as sweep stages: each case's results are the runner's own summary
    numbers (wear.erode_case, wear.repeat called directly on the same case)."""
    from wear import erode_case
    from wear.app.sweep.stages import stage_case

    erosion = load_sweep(
        _sweep_file(
            tmp_path,
            """
        [sweep]
        stage = "erode"
        [base]
        erosion.grid = 128
        erosion.exposure_time = 20.0
        erosion.table_speeds = 2
        erosion.angle_step = 10.0
        [grid]
        "impact.angle" = [15.0, 45.0]
        """,
        )
    )
    out = run_sweep(erosion, tmp_path / "erode", workers=1, quiet=True)
    assert (out.computed, out.failed) == (2, 0)
    records = _records(tmp_path / "erode")
    for sc in erosion.cases:
        direct = erode_case(stage_case(sc.case, "erode")).summary()["results"]
        assert records[sc.case_id]["results"]["results.mass_loss_kg"] == direct["mass_loss_kg"] > 0
    many = load_sweep(
        _sweep_file(
            tmp_path,
            """
        [sweep]
        stage = "repeat"
        [base]
        fem.mesh_scale = 4.0
        plate.yield_strength = inf
        [grid]
        "repeat.impacts" = [2]
        """,
        )
    )
    out = run_sweep(many, tmp_path / "repeat", workers=1, quiet=True)
    assert (out.computed, out.failed) == (1, 0), out.failures
    result = _records(tmp_path / "repeat")[many.cases[0].case_id]["results"]
    # the reference runs as the sweep's workers do (a spawned process, one thread: THREAD_VARIABLES), since a
    # threaded reduction's last digits depend on the thread count
    with worker_pool(1) as pool:
        direct = pool.submit(_repeat_summary, many.cases[0].case).result()
    assert result["impacts"] == 2
    assert result["after_last_impact.total_wear_volume_m3"] == direct["after_last_impact"]["total_wear_volume_m3"]
