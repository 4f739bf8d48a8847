"""``wear.wall.erode_component`` over record files in every form a user has them: a Fluent file in chunks, a folder
of Parquet parts against one CSV, a real Dask scheduler reached by its address; and the speed histogram and hit
times against the records written."""

from __future__ import annotations

import math
from pathlib import Path

import meshio
import numpy as np
import pytest
from wall_cases import flat_mesh, write_csv

from wear.case import default_case
from wear.wall import erode_component, read_fluent_dpm, read_wall
from wear.wall.options import WallOptions

FLUENT = Path(__file__).resolve().parent / "data" / "fluent" / "plate_unsteady.dpm"
SUMS = ("volume_m3", "mass_kg", "records", "particles", "speed_sum_m_s", "angle_histogram")


@pytest.fixture
def wall(tmp_path):
    meshio.write(tmp_path / "plate.stl", flat_mesh())
    return read_wall(tmp_path / "plate.stl")


def _case(**wall):
    return default_case("wall").with_(wall={"exposure": 1.0, **wall})


def test_a_fluent_file_read_in_chunks_gives_the_whole_file_s_sums(wall):
    """The 30 parcels of tests/data/fluent in chunks of 7 rows and in one chunk; the hit times span the file's
    flow times (1e-3 to 3e-2 s) and the mass is the file's n-in-parcel × mass."""
    case = default_case("wall")
    whole = erode_component(case, FLUENT, wall, progress=False, chunk_rows=1000)
    parts = erode_component(case, FLUENT, wall, progress=False, chunk_rows=7)
    for name in SUMS:
        assert np.allclose(getattr(parts.sums, name), getattr(whole.sums, name), rtol=1e-13, atol=0), name
    records = read_fluent_dpm(FLUENT)
    assert whole.sums.records_read == 30 and whole.exposure_s == pytest.approx(0.029, rel=1e-6)
    assert whole.sums.mass_kg.sum() == pytest.approx(float((records.count * records.mass).sum()), rel=1e-12)


def _rows(n: int, seed: int) -> list[list[str]]:
    rng = np.random.default_rng(seed)
    x, y = rng.uniform(0.001, 0.039, n).tolist(), rng.uniform(0.001, 0.029, n).tolist()
    speed, theta = rng.uniform(5.0, 60.0, n).tolist(), rng.uniform(0.0, 80.0, n).tolist()
    t = [math.radians(a) for a in theta]
    return [
        [repr(a), repr(b), "0.0", repr(s * math.sin(c)), "0.0", repr(-s * math.cos(c)), "2e-4", "2650.0", repr(k)]
        for k, (a, b, s, c) in enumerate(zip(x, y, speed, t, strict=True))
    ]


HEADER = ["x_m", "y_m", "z_m", "u_m_s", "v_m_s", "w_m_s", "diameter_m", "density_kg_m3", "time_s"]


def test_a_folder_of_parquet_parts_gives_the_sums_of_one_csv(wall, tmp_path):
    pq = pytest.importorskip("pyarrow.parquet")
    pa = pytest.importorskip("pyarrow")
    first, second = _rows(300, 1), _rows(200, 2)
    one = write_csv(tmp_path / "all.csv", HEADER, first + second)
    parts = tmp_path / "parts"
    parts.mkdir()
    for name, rows in (("part-0.parquet", first), ("part-1.parquet", second)):
        columns = {h: pa.array([float(r[i]) for r in rows]) for i, h in enumerate(HEADER)}
        pq.write_table(pa.table(columns), parts / name, row_group_size=128)
    a = erode_component(_case(), one, wall, progress=False)
    b = erode_component(_case(), parts, wall, WallOptions(workers=2), progress=False)
    assert b.records == (str(parts / "part-0.parquet"), str(parts / "part-1.parquet"))
    for name in SUMS:
        assert np.allclose(getattr(b.sums, name), getattr(a.sums, name), rtol=1e-13, atol=0), name


def test_a_dask_scheduler_reached_by_its_address_gives_the_serial_sums(wall, tmp_path):
    distributed = pytest.importorskip("distributed")
    records = write_csv(tmp_path / "hits.csv", HEADER, _rows(400, 3))
    serial = erode_component(_case(), records, wall, progress=False, chunk_rows=50)
    with distributed.LocalCluster(
        n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None, host="127.0.0.1"
    ) as cluster:
        remote = erode_component(
            _case(), records, wall, WallOptions(scheduler=cluster.scheduler_address), progress=False, chunk_rows=50
        )
    for name in SUMS:
        assert np.allclose(getattr(remote.sums, name), getattr(serial.sums, name), rtol=1e-13, atol=0), name


def test_the_speed_histogram_and_hit_times_are_the_records(wall, tmp_path):
    rows = _rows(500, 4)
    records = write_csv(tmp_path / "hits.csv", HEADER, rows)
    run = erode_component(default_case("wall"), records, wall, progress=False, chunk_rows=64)
    speed = np.array([math.hypot(float(r[3]), float(r[5])) for r in rows])
    edges = run.sums.speed_edges_m_s
    assert np.array_equal(run.sums.speed_histogram, np.histogram(speed, edges)[0])
    assert (run.sums.time_first_s, run.sums.time_last_s) == (0.0, 499.0)
    assert run.exposure_s == 499.0 and run.exposure_source == "the records' time span"
