"""Records read in chunks and summed per face on this process, a process pool or Dask (wear.wall.sources,
wear.wall.engine), and the numba grid for the nearest face (wear.wall.grid).

References: the chunked result against the whole files read at once (wear.wall.openfoam, wear.wall.table and the
per-face sums of wear.wall.sums), against OpenFOAM's own eroded volume Q of the committed v1912 pipe-bend run
(examples/openfoam_bend, ``particleErosion``, Finnie: see tests/test_wall_openfoam.py), against closed forms (the
particle mass ρπd³/6, the mean of given speeds, the bins of given angles), and the grid against the exact k-d tree
search of wear.wall.locate.nearest_faces.
"""

from __future__ import annotations

import gzip
import math
import re

import numpy as np
import pyarrow as pa
import pyarrow.parquet as pq
import pytest
from wall_cases import OUTPUTS, RECORDS, flat_mesh, openfoam_finnie_case, write_csv

from wear.case import Case
from wear.case.workers import machine_cores
from wear.wall import (
    concat_records,
    face_sum,
    hits_on_wall,
    read_patch_field,
    read_patch_post_processing,
    read_polymesh,
    read_surface,
    read_table,
    record_volumes,
    wall_law,
)
from wear.wall.engine import chunk_rows_for, erode_wall
from wear.wall.grid import face_grid
from wear.wall.locate import distance_to_faces, nearest_faces
from wear.wall.options import WallOptions
from wear.wall.sources import Chunk, plan_chunks, read_chunk


def _finnie(flow_pressure: float):
    """Finnie's law (c = 1, K = psi = 2) on a plate of plastic flow pressure ``flow_pressure`` (Pa)."""
    return wall_law(Case().with_(wear={"law": "finnie", "cutting_fraction": 1.0}, plate={"hardness": flow_pressure}))


@pytest.fixture(scope="module")
def bend():
    wall = read_polymesh(OUTPUTS)
    return wall, wall_law(openfoam_finnie_case()), read_patch_post_processing(RECORDS, wall)


def _same_records(parts, whole):
    got = concat_records(parts)
    assert [got.files[i] for i in got.file_index] == [whole.files[i] for i in whole.file_index]
    assert np.array_equal(got.row, whole.row)
    for name in ("position", "velocity", "diameter", "density", "count", "time", "face"):
        assert np.array_equal(getattr(got, name), getattr(whole, name)), name


@pytest.mark.parametrize("chunk_rows", [1, 97, 1000, 10**6])
def test_the_plan_of_the_openfoam_folder_reads_every_row_once(bend, chunk_rows):
    wall, _, whole = bend
    chunks = plan_chunks(RECORDS, chunk_rows)
    assert sum(c.rows for c in chunks) == len(whole) == 4528  # the README's count of hits
    assert all(c.format == "openfoam" and c.serial for c in chunks)
    if chunk_rows > 1:
        _same_records([read_chunk(c, wall) for c in chunks], whole)
        normal = concat_records([read_chunk(c, wall) for c in chunks]).normal
        assert np.array_equal(normal, whole.normal)


def test_a_parallel_run_s_records_are_located_in_every_chunk(bend, tmp_path):
    """A record written by processor 1 anywhere in the run makes every chunk find its faces from the positions, as
    the whole-run reader does (wear.wall.openfoam)."""
    wall = bend[0]
    source = RECORDS / "0.04" / "bend.post.gz"
    lines = gzip.decompress(source.read_bytes()).decode().splitlines(keepends=True)
    tokens = lines[-1].split(" ", 2)
    lines[-1] = " ".join([tokens[0], "1", tokens[2]])  # currentProc of the last row
    (tmp_path / "0.04").mkdir()
    (tmp_path / "0.04" / "bend.post").write_text("".join(lines))
    (tmp_path / "0.02").mkdir()
    (tmp_path / "0.02" / "bend.post.gz").write_bytes((RECORDS / "0.02" / "bend.post.gz").read_bytes())
    chunks = plan_chunks(tmp_path, 100)
    assert chunks[0].path.endswith("bend.post.gz") and not any(c.serial for c in chunks)
    _same_records([read_chunk(c, wall) for c in chunks], read_patch_post_processing(tmp_path, wall))
    assert (read_chunk(chunks[0], wall).face == -1).all()


def test_formats_are_found_by_suffix_or_content(tmp_path):
    values = _table_rows(5, np.random.default_rng(8))
    pq.write_table(pa.table({h: values[:, j] for j, h in enumerate(HEADER)}), tmp_path / "records")
    write_csv(tmp_path / "records.txt", HEADER, [[repr(float(v)) for v in r] for r in values])
    assert [c.format for c in plan_chunks([tmp_path / "records", tmp_path / "records.txt"], 10)] == ["parquet", "csv"]
    assert plan_chunks(RECORDS / "0.02" / "bend.post.gz", 10)[0].format == "openfoam"
    assert np.array_equal(read_chunk(plan_chunks(tmp_path / "records", 10)[0], None).velocity, values[:, 3:6])


def _table_rows(n, rng):
    """n records on the flat wall of flat_mesh (z = 0, fluid above), falling at random angles."""
    position = np.column_stack([rng.random(n) * 0.04, rng.random(n) * 0.03, np.zeros(n)])
    velocity = np.column_stack([rng.normal(size=n), rng.normal(size=n), -1.0 - rng.random(n)]) * 10.0
    d = 1e-4 * (1.0 + rng.random(n))
    return np.column_stack([position, velocity, d, np.full(n, 2650.0), 1.0 + rng.integers(0, 5, n)])


HEADER = ["x_m", "y_m", "z_m", "u_m_s", "v_m_s", "w_m_s", "diameter_m", "density_kg_m3", "particles"]


@pytest.mark.parametrize("gz", [False, True])
@pytest.mark.parametrize("chunk_rows", [1, 3, 7, 100])
def test_the_plan_of_a_csv_file_reads_every_row_once(tmp_path, gz, chunk_rows):
    rows = [[repr(float(v)) for v in r] for r in _table_rows(23, np.random.default_rng(1))]
    rows.insert(9, [""] * 0)  # an empty row: counted, skipped
    path = write_csv(tmp_path / "r.csv", HEADER, rows)
    if gz:
        path = tmp_path / "r.csv.gz"
        path.write_bytes(gzip.compress((tmp_path / "r.csv").read_bytes()))
    chunks = plan_chunks(path, chunk_rows)
    assert [c.start_row for c in chunks] == list(range(0, 24, chunk_rows))
    assert sum(c.rows for c in chunks) == 24
    assert all((c.offset is None) == gz for c in chunks)
    whole = read_table(path)
    assert whole.row.tolist() == [*range(1, 10), *range(11, 25)]
    _same_records([read_chunk(c, None) for c in chunks], whole)


def test_the_plan_of_a_parquet_file_is_its_row_groups(tmp_path):
    values = _table_rows(50, np.random.default_rng(2))
    path = tmp_path / "r.parquet"
    pq.write_table(pa.table({h: values[:, j] for j, h in enumerate(HEADER)}), path, row_group_size=12)
    chunks = plan_chunks(path, 1000)
    assert [(c.start_row, c.rows) for c in chunks] == [(0, 12), (12, 12), (24, 12), (36, 12), (48, 2)]
    _same_records([read_chunk(c, None) for c in chunks], read_table(path))
    assert np.array_equal(read_table(path).position, values[:, :3])


def test_the_engine_reproduces_the_single_read_sums_and_openfoam_s_q(bend):
    wall, law, records = bend
    hits = hits_on_wall(records, wall)
    volume = record_volumes(law, records, hits)
    single = face_sum(len(wall), hits, volume)
    q = read_patch_field(OUTPUTS / "kinematicCloudQ", wall)
    sums = erode_wall(plan_chunks(RECORDS, 500), wall, law, progress=False)
    assert np.allclose(sums.volume_m3, single, rtol=1e-12, atol=1e-12 * single.max())
    assert np.allclose(sums.volume_m3, q, rtol=1e-12, atol=1e-12 * q.max())
    assert (sums.volume_m3 > 0).sum() == 756  # the faces OpenFOAM's Q is non-zero on (README)
    assert sums.records.sum() == sums.records_read == 4528 and sums.skipped == {}


def test_mass_and_particles_are_conserved(bend):
    """Σ over faces of the delivered mass = Σ over records of nParticle ρ π d³ / 6 (closed form, from the records)."""
    wall, law, records = bend
    sums = erode_wall(plan_chunks(RECORDS, 333), wall, law, progress=False)
    mass = records.count * records.density * math.pi * records.diameter**3 / 6.0
    assert sums.mass_kg.sum() == pytest.approx(mass.sum(), rel=1e-13)
    assert sums.mass_read_kg == pytest.approx(mass.sum(), rel=1e-13)
    assert sums.particles.sum() == pytest.approx(records.count.sum(), rel=1e-14)
    assert sums.angle_histogram.sum() == pytest.approx(records.count.sum(), rel=1e-14)
    # the README: 5e-4 kg of sand injected, and every one of the 1000 parcels hit a wall at least once
    assert sums.mass_kg.sum() > 0.999 * 5e-4


def test_pool_and_dask_give_the_serial_sums(bend):
    wall, law, _ = bend
    serial = erode_wall(plan_chunks(RECORDS, 400), wall, law, progress=False)
    pool = erode_wall(plan_chunks(RECORDS, 400), wall, law, WallOptions(workers=2), progress=False)
    other = erode_wall(plan_chunks(RECORDS, 1777), wall, law, WallOptions(workers=2), progress=False)
    dask = erode_wall(plan_chunks(RECORDS, 700), wall, law, WallOptions(workers=2, scheduler="local"), progress=False)
    for name in ("volume_m3", "mass_kg", "records", "particles", "speed_sum_m_s", "angle_histogram"):
        assert np.array_equal(getattr(pool, name), getattr(serial, name)), name  # the same chunks, added in order
        for result in (other, dask):
            assert np.allclose(getattr(result, name), getattr(serial, name), rtol=1e-13, atol=0), name


def test_speed_and_angle_statistics_against_the_given_records(tmp_path):
    """Records of known speed and angle on one face of a flat wall: the face's mean speed is the particle-weighted
    mean of the given speeds, its histogram the particles at the given angles."""
    wall = read_surface(_write_flat(tmp_path))
    centre = wall.centre[5]
    rows = []
    for theta, speed, n in ((5.0, 10.0, 1.0), (35.0, 20.0, 3.0), (89.0, 30.0, 2.0), (35.0, 40.0, 4.0)):
        t = math.radians(theta)
        rows.append([*centre, speed * math.sin(t), 0.0, -speed * math.cos(t), 1e-4, 2650.0, n])
    chunks = plan_chunks(write_csv(tmp_path / "r.csv", HEADER, rows), 2)
    sums = erode_wall(chunks, wall, _finnie(1e9), progress=False, histogram_bins_deg=[0, 30, 60, 90])
    assert sums.records[5] == 4 and sums.records.sum() == 4
    assert sums.mean_speed_m_s[5] == pytest.approx((10 + 60 + 60 + 160) / 10, rel=1e-14)
    assert sums.angle_histogram[5].tolist() == [1.0, 7.0, 2.0]
    assert np.isnan(sums.mean_speed_m_s[0])


def _write_flat(tmp_path):
    import meshio

    path = tmp_path / "flat.vtu"
    meshio.write(path, flat_mesh())
    return path


def test_a_bad_row_in_a_later_chunk_names_the_file_and_its_row(tmp_path):
    rows = [[repr(float(v)) for v in r] for r in _table_rows(20, np.random.default_rng(3))]
    rows[12][6] = "-1e-4"  # row 13: a negative diameter, in the third chunk of 5 rows
    path = write_csv(tmp_path / "r.csv", HEADER, rows)
    wall = read_surface(_write_flat(tmp_path))
    for workers in (1, 2):
        with pytest.raises(ValueError, match=rf"^{re.escape(str(path))}, row 13, column diameter_m: -0\.0001 is out"):
            erode_wall(plan_chunks(path, 5), wall, _finnie(1e9), WallOptions(workers=workers), progress=False)


def test_a_bad_value_in_a_parquet_row_group_names_its_row(tmp_path):
    values = _table_rows(30, np.random.default_rng(4))
    values[17, 4] = np.nan
    path = tmp_path / "r.parquet"
    pq.write_table(pa.table({h: values[:, j] for j, h in enumerate(HEADER)}), path, row_group_size=10)
    wall = read_surface(_write_flat(tmp_path))
    with pytest.raises(ValueError, match=r"r\.parquet, row 18, columns u_m_s v_m_s w_m_s: .* is not a finite number"):
        erode_wall(plan_chunks(path, 10), wall, _finnie(1e9), progress=False)


def test_skipped_records_are_counted_not_summed(tmp_path):
    values = _table_rows(10, np.random.default_rng(5))
    values[4, 5] = 7.0  # row 5 leaves the wall (w > 0 with the fluid above)
    path = write_csv(tmp_path / "r.csv", HEADER, [[repr(float(v)) for v in r] for r in values])
    wall = read_surface(_write_flat(tmp_path))
    sums = erode_wall(plan_chunks(path, 3), wall, _finnie(1e9), WallOptions(skip_bad=True), progress=False)
    mass = values[:, 8] * 2650.0 * math.pi * values[:, 6] ** 3 / 6.0
    assert sums.skipped == {"leaving_wall": 1} and sums.records.sum() == 9 and sums.records_read == 10
    assert sums.mass_kg.sum() == pytest.approx(mass.sum() - mass[4], rel=1e-13)


def test_chunks_too_large_for_the_memory_budget_are_refused_before_any_work(bend):
    wall, law, _ = bend
    huge = [Chunk("missing.csv", "csv", 0, 10**9), Chunk("missing.csv", "csv", 10**9, 10**9)]
    fits = chunk_rows_for(wall, min(2, machine_cores()), "csv")  # the pool: a worker per chunk and per core
    with pytest.raises(ValueError, match=rf"^missing\.csv: chunk_rows=1e\+09 needs .* give chunk_rows <= {fits}$"):
        erode_wall(huge, wall, law, WallOptions(workers=2), progress=False)


@pytest.mark.parametrize("bad", [0, 1.5, -3])
def test_chunk_rows_and_workers_are_checked(bend, bad):
    with pytest.raises(ValueError, match=rf"^chunk_rows={bad!r} is out of range"):
        plan_chunks(RECORDS, bad)
    with pytest.raises(ValueError, match=rf"^workers={bad!r} is out of range"):
        erode_wall([], bend[0], bend[1], WallOptions(workers=bad), progress=False)


def test_the_grid_finds_the_exact_nearest_face(bend):
    """Random points near the bend's wall, anywhere around it and at its vertices: the grid's distance is the k-d
    tree search's and the exact distance (wear.wall.locate.distance_to_faces) to both searches' faces, which are
    the same face but at ties (a point as near to two faces: at a shared edge or vertex)."""
    wall = bend[0]
    grid = face_grid(wall)
    rng = np.random.default_rng(6)
    low, high = wall.points.min(axis=0), wall.points.max(axis=0)
    anywhere = low - 0.2 * (high - low) + rng.random((3000, 3)) * 1.4 * (high - low)
    faces = rng.integers(0, len(wall), 3000)
    near = wall.centre[faces] + 1e-3 * rng.normal(size=(3000, 3))
    vertices = wall.points[rng.integers(0, len(wall.points), 200)]  # ties between every face at a vertex
    for points in (anywhere, near, vertices):
        face, distance = grid.nearest(points)
        exact_face, exact = nearest_faces(wall, points)
        assert np.array_equal(distance, exact)
        assert np.array_equal(distance, distance_to_faces(wall, points, face))
        assert np.array_equal(distance_to_faces(wall, points, exact_face), distance)  # where the faces differ: a tie
        assert np.array_equal(grid.distance(points, exact_face), distance)


def test_the_grid_is_used_for_records_without_a_face(tmp_path):
    values = _table_rows(200, np.random.default_rng(7))
    path = write_csv(tmp_path / "r.csv", HEADER, [[repr(float(v)) for v in r] for r in values])
    wall = read_surface(_write_flat(tmp_path))
    records = read_table(path)
    reference = hits_on_wall(records, wall)
    with_grid = hits_on_wall(records, wall, locator=face_grid(wall))
    assert np.array_equal(with_grid.distance, reference.distance)
    assert np.array_equal(distance_to_faces(wall, records.position, with_grid.face), reference.distance)
    assert np.array_equal(with_grid.angle, reference.angle)
