"""A uniform stream on a flat wall of triangles: Finnie's closed form per impact × the impacts on each face.

Reference: Finnie (1960), Wear 3: 87–103, the volume cut by one particle (``wall_cases.finnie_1960``, coded from
the paper, not taken from impactwear). Every face receives the same number of identical impacts at
random points inside it, so its volume is exactly that number × W; the sum over faces is the sum over impacts; the
wall read as two files gives each face the same volume as the wall read as one.
"""

from __future__ import annotations

import math

import meshio
import numpy as np
import pytest
from wall_cases import PSI, C, K, P, finnie_1960, flat_mesh, write_csv

from wear.case import Case
from wear.wall import (
    ImpactRecords,
    concat_walls,
    face_sum,
    hits_on_wall,
    read_surface,
    read_table,
    record_volumes,
    wall_law,
)

SPEED, DIAMETER, DENSITY, PER_FACE, PARTICLES = 25.0, 300e-6, 2650.0, 7, 40.0


def _stream(wall, theta: float, seed: int = 1) -> ImpactRecords:
    """PER_FACE hits at random points inside every face, velocity at θ from the wall normal (−z) in the x–z
    plane."""
    rng = np.random.default_rng(seed)
    tri, face = wall.triangles
    w = rng.dirichlet(np.ones(3), size=(len(tri), PER_FACE))
    position = np.einsum("tkj,tjx->tkx", w, wall.points[tri]).reshape(-1, 3)
    n = len(position)
    t = math.radians(theta)
    return ImpactRecords(
        position=position,
        velocity=np.tile([SPEED * math.sin(t), 0.0, -SPEED * math.cos(t)], (n, 1)),
        diameter=np.full(n, DIAMETER),
        density=np.full(n, DENSITY),
        count=np.full(n, PARTICLES),
        time=np.zeros(n),
        face=np.full(n, -1),
    )


def _per_face(wall, records):
    hits = hits_on_wall(records, wall)
    case = Case().with_(
        wear={"law": "finnie", "cutting_fraction": C, "force_ratio": K, "depth_ratio": PSI}, plate={"hardness": P}
    )
    v = record_volumes(wall_law(case), records, hits)
    return hits, v, face_sum(len(wall), hits, v)


@pytest.fixture
def wall(tmp_path):
    path = tmp_path / "plate.vtu"
    meshio.write(path, flat_mesh())
    return read_surface(path)


def test_the_flat_wall_s_normals_point_into_the_wall_and_its_area_is_the_rectangle_s(wall):
    assert np.allclose(wall.normal, [0.0, 0.0, -1.0], atol=1e-15)
    assert wall.area.sum() == pytest.approx(0.04 * 0.03, rel=1e-14)


@pytest.mark.parametrize("theta", [80.0, 30.0])  # α = 10° (tan α < K/6) and α = 60° (the other branch)
def test_a_uniform_stream_gives_finnie_s_volume_times_the_impacts_on_every_face(wall, theta):
    records = _stream(wall, theta)
    hits, v, q = _per_face(wall, records)
    assert np.array_equal(np.bincount(hits.face, minlength=len(wall)), np.full(len(wall), PER_FACE))
    assert np.allclose(hits.angle, theta, rtol=0, atol=1e-12)
    mass = DENSITY * math.pi * DIAMETER**3 / 6.0
    expected = PER_FACE * PARTICLES * finnie_1960(mass, SPEED, 90.0 - theta)
    assert q == pytest.approx(np.full(len(wall), expected), rel=1e-12)
    assert q.sum() == pytest.approx(v.sum(), rel=1e-14) == pytest.approx(len(records) / PER_FACE * expected)


def test_the_plain_table_gives_the_same_answer(wall, tmp_path):
    records = _stream(wall, 80.0)
    header = ["x_m", "y_m", "z_m", "u_m_s", "v_m_s", "w_m_s", "diameter_m", "density_kg_m3", "particles"]
    rows = [
        [*(repr(float(x)) for x in p), *(repr(float(x)) for x in u), repr(DIAMETER), repr(DENSITY), repr(PARTICLES)]
        for p, u in zip(records.position, records.velocity, strict=True)
    ]
    table = read_table(write_csv(tmp_path / "hits.csv", header, rows))
    assert np.array_equal(table.position, records.position) and np.all(table.time == 0.0)
    assert np.array_equal(_per_face(wall, table)[2], _per_face(wall, records)[2])


def test_a_wall_split_into_two_files_gives_each_face_the_same_volume(wall, tmp_path):
    mesh = flat_mesh()
    triangles = mesh.cells[0].data
    half = len(triangles) // 2
    meshio.write(tmp_path / "left.vtu", meshio.Mesh(mesh.points, [("triangle", triangles[:half])]))
    meshio.write(tmp_path / "right.obj", meshio.Mesh(mesh.points, [("triangle", triangles[half:])]))
    split = concat_walls([read_surface(tmp_path / "left.vtu"), read_surface(tmp_path / "right.obj")])
    assert split.patch_names == ("left", "right") and len(split) == len(wall)
    records = _stream(wall, 30.0)
    one = _per_face(wall, records)[2]
    two = _per_face(split, records)[2]
    # the same faces in the same order (the split keeps the file order), each with the same volume
    assert np.allclose(split.centre, wall.centre, rtol=0, atol=1e-15)
    assert two == pytest.approx(one, rel=1e-14)


def test_a_table_of_faces_without_positions_and_with_the_source_s_normals(wall, tmp_path):
    """Faces given (0-based) and no positions: each record sits at its face's centre; a recorded normal equal to
    the face normal (−z) gives the face normal's answer, one tilted by 10° about y gives Finnie at θ ± 10°."""
    theta = 30.0
    t = math.radians(theta)
    velocity = [repr(SPEED * math.sin(t)), "0", repr(-SPEED * math.cos(t))]
    header = ["face", "u_m_s", "v_m_s", "w_m_s", "diameter_m", "density_kg_m3", "nx", "ny", "nz"]
    mass = DENSITY * math.pi * DIAMETER**3 / 6.0
    for tilt in (0.0, 10.0):
        s = math.radians(tilt)
        normal = [repr(-math.sin(s)), "0", repr(-math.cos(s))]  # (0, 0, -1) turned by +tilt about y
        rows = [[str(f), *velocity, repr(DIAMETER), repr(DENSITY), *normal] for f in range(len(wall))]
        table = read_table(write_csv(tmp_path / "faces.csv", header, rows), wall)
        assert np.array_equal(table.position, wall.centre)
        hits, _, q = _per_face(wall, table)
        assert np.allclose(hits.angle, theta + tilt, rtol=0, atol=1e-12)
        assert q == pytest.approx(np.full(len(wall), finnie_1960(mass, SPEED, 90.0 - theta - tilt)), rel=1e-12)
