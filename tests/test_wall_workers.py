"""The wall's workers as a user starts them: the same sums to the last digit on 1 worker or 2 (the chunk plan does
not depend on the workers), a pool bounded by the work and the machine, workers that stop on Ctrl-C, the pool's
initializer arguments reaching every worker, and an unreachable Dask scheduler refused at once."""

from __future__ import annotations

import os
import time

import meshio
import numpy as np
import pytest
from refusal import refused
from wall_cases import RECORDS, flat_mesh, write_csv

import wear.wall.engine as engine
from wear.app.cli import main
from wear.case import default_case
from wear.case.workers import bound_workers, machine_cores, worker_pool
from wear.wall import erode_component, read_wall
from wear.wall.options import WallOptions
from wear.wall.sources import plan_chunks, record_files

SUMS = ("volume_m3", "mass_kg", "records", "particles", "speed_sum_m_s", "angle_histogram", "speed_histogram")


@pytest.fixture(scope="module")
def bend():
    from wall_cases import OUTPUTS

    return read_wall(OUTPUTS)


def test_one_worker_and_two_give_the_same_sums_to_the_last_digit(bend, monkeypatch):
    """Before: the chunk plan was sized for the workers asked for, so 1 and 2 workers summed different chunks and
    the sums differed in the last digits. A small memory budget makes the plan many chunks."""
    budget = engine._memory_need(0, engine.BYTES_PER_RECORD["openfoam"], bend, 2, engine.DEFAULT_ANGLE_EDGES_DEG)
    monkeypatch.setattr(engine, "memory_budget", lambda: budget + 2 * 300 * engine.BYTES_PER_RECORD["openfoam"])
    monkeypatch.setattr(engine, "machine_cores", lambda: 2)
    rows = engine.chunk_rows_for(bend, None, "openfoam")
    assert rows < 400 and len(plan_chunks(RECORDS, rows)) > len(record_files(RECORDS))  # files split in chunks
    case = default_case("wall").with_(wall={"exposure": 0.1})
    one = erode_component(case, RECORDS, bend, WallOptions(workers=1), progress=False)
    two = erode_component(case, RECORDS, bend, WallOptions(workers=2), progress=False)
    for name in SUMS:
        assert np.array_equal(getattr(one.sums, name), getattr(two.sums, name)), name
    assert one.wear.volume_m3.sum() > 0.0


def test_the_pool_is_bounded_by_the_tasks_and_the_cores():
    cores = machine_cores()
    assert bound_workers(1, 10, "workers") == 1
    assert bound_workers(cores, 1, "workers") == 1  # one chunk: one worker
    with pytest.warns(UserWarning, match=rf"workers=1000: this machine has {cores} cores; running {min(cores, 3)} "):
        assert bound_workers(1000, 3, "workers") == min(cores, 3)


def test_a_thousand_workers_asked_for_run_on_the_cores_with_a_note(tmp_path, capsys):
    """Before: ``--workers 1000`` started processes without limit (141 processes and 8 GB after 25 s)."""
    meshio.write(tmp_path / "plate.stl", flat_mesh())
    rows = [["0.01", "0.01", "0.0", "3.0", "0.0", "-10.0", "3e-4", "2650.0", str(float(k))] for k in range(12)]
    records = write_csv(
        tmp_path / "hits.csv",
        ["x_m", "y_m", "z_m", "u_m_s", "v_m_s", "w_m_s", "diameter_m", "density_kg_m3", "time_s"],
        rows,
    )
    start = time.perf_counter()
    argv = ["wall", str(records), str(tmp_path / "plate.stl"), "--workers", "1000", "--out", str(tmp_path / "out")]
    assert main([*argv, "--set", "wall.exposure=1.0", "--no-figures", "--quiet"]) == 0
    err = capsys.readouterr().err
    assert f"workers=1000: this machine has {machine_cores()} cores; running 1 worker processes" in err, err
    assert time.perf_counter() - start < 60.0


def _sleep(seconds: float) -> int:
    time.sleep(seconds)
    return os.getpid()


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    with open(f"/proc/{pid}/stat") as f:  # a zombie is dead
        return f.read().split(")")[-1].split()[0] != "Z"


@pytest.mark.skipif(not os.path.isdir("/proc"), reason="reads /proc")
def test_ctrl_c_terminates_the_workers_at_once():
    """Before: the workers of ``wall --workers`` were still running 5 s after Ctrl-C (the pool waited for them)."""
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt), worker_pool(2) as pool:
        pids = [p.pid for p in pool._processes.values()]
        pool.submit(_sleep, 60.0)
        pool.submit(_sleep, 60.0)
        time.sleep(0.5)
        raise KeyboardInterrupt
    assert time.perf_counter() - start < 10.0
    assert len(pids) == 2 and not any(_alive(pid) for pid in pids), pids


_KEPT: bytes | None = None


def _keep(value: bytes) -> None:
    global _KEPT
    _KEPT = value


def _kept(seconds: float) -> tuple[int, bytes | None]:
    time.sleep(seconds)  # long enough for the other worker to take the next task
    return os.getpid(), _KEPT


def test_the_initializer_arguments_reach_every_worker_and_a_bad_one_fails_at_once():
    """The initializer's arguments (a wall: megabytes) reach the workers through a queue once they run, so that the
    workers start side by side (started with them, each waited for the previous one's imports); what cannot be
    pickled still fails at once, not after the workers' start timeout."""
    payload = os.urandom(1 << 22)
    with worker_pool(2, _keep, (payload,)) as pool:
        kept = list(pool.map(_kept, [1.0] * 4))
    assert all(value == payload for _, value in kept) and len({pid for pid, _ in kept}) == 2
    start = time.perf_counter()
    with pytest.raises(Exception, match="pickle"), worker_pool(2, _keep, (lambda: None,)):
        pass
    assert time.perf_counter() - start < 5.0


def test_an_unreachable_scheduler_is_refused_at_once(tmp_path, capsys):
    """Before: ``--scheduler tcp://127.0.0.1:1`` answered after 33 s (Dask retries until its timeout)."""
    pytest.importorskip("distributed")
    meshio.write(tmp_path / "plate.stl", flat_mesh())
    rows = [["0.01", "0.01", "0.0", "3.0", "0.0", "-10.0", "3e-4", "2650.0"]]
    records = write_csv(
        tmp_path / "hits.csv", ["x_m", "y_m", "z_m", "u_m_s", "v_m_s", "w_m_s", "diameter_m", "density_kg_m3"], rows
    )
    argv = ["wall", str(records), str(tmp_path / "plate.stl"), "--scheduler", "tcp://127.0.0.1:1"]
    line = refused([*argv, "--set", "wall.exposure=1.0"], tmp_path, capsys, quick=6.0)
    assert "scheduler='tcp://127.0.0.1:1': cannot connect to a Dask scheduler (Connection refused)" in line, line
