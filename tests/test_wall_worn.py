"""The rates, remaining life and worn wall of wear.wall.worn against closed forms: a flat wall (rates, depth and
swept volume exact), a cylinder's inner wall (the moved points on the cylinder of radius R + depth; the swept volume
of two coaxial prisms), life = thickness / rate."""

from __future__ import annotations

import math

import meshio
import numpy as np
import pytest
from wall_cases import OUTPUTS, flat_mesh

from wear.wall.foam import read_polymesh
from wear.wall.mesh import Wall, read_surface
from wear.wall.worn import (
    SECONDS_PER_YEAR,
    hot_spots,
    remaining_life,
    swept_volume,
    vertex_depth,
    vertex_normals,
    wall_wear,
    worn_mesh,
    worn_wall,
)

STEEL = 7800.0  # kg/m^3
EXPOSURE = 0.05  # s


@pytest.fixture
def flat(tmp_path) -> Wall:
    path = tmp_path / "flat.vtu"
    meshio.write(path, flat_mesh(nx=5, ny=4))
    return read_surface(path)


def cylinder(radius: float, length: float, n_theta: int, n_z: int, triangles: bool = False) -> Wall:
    """The inner wall of a cylinder about z (fluid inside, normals pointing out, into the material): a regular grid of
    quads (or each cut into two triangles), points exactly on the radius."""
    theta = np.arange(n_theta) * 2 * math.pi / n_theta
    z = np.linspace(0.0, length, n_z + 1)
    t, zz = np.meshgrid(theta, z, indexing="ij")
    points = np.column_stack([radius * np.cos(t).ravel(), radius * np.sin(t).ravel(), zz.ravel()])
    node = np.arange(n_theta * (n_z + 1)).reshape(n_theta, n_z + 1)
    nxt = np.roll(node, -1, axis=0)
    a, b, c, d = node[:, :-1].ravel(), nxt[:, :-1].ravel(), nxt[:, 1:].ravel(), node[:, 1:].ravel()
    # (a, b, c, d) runs +theta then +z: its right-hand normal is e_theta x e_z = e_r, out of the fluid
    faces = np.column_stack([a, b, c, d]) if not triangles else np.concatenate([np.c_[a, b, c], np.c_[a, c, d]])
    k = faces.shape[1]
    return Wall(
        points, faces.ravel(), np.arange(len(faces) + 1) * k, np.zeros(len(faces)), ("pipe",), np.arange(len(faces))
    )


def test_flat_wall_uniform_depth_gives_the_closed_form_rates_and_moves_every_point_by_it(flat):
    """Volume V_f = c A_f on every face (c = 2e-9 m over T): E = rho c / T, h' = c / T, depth c t_s / T on every face
    and every point (interior and boundary), along -z (the wall's normal), and the volume between the wall and the
    worn wall (a slab) equals the eroded volume scaled to t_s."""
    c = 2e-9
    wear = wall_wear(flat, c * flat.area, EXPOSURE, STEEL)
    np.testing.assert_allclose(wear.mass_kg, STEEL * c * flat.area, rtol=1e-15)
    np.testing.assert_allclose(wear.erosion_rate_kg_m2_s, STEEL * c / EXPOSURE, rtol=1e-14)
    np.testing.assert_allclose(wear.thickness_loss_rate_m_s, c / EXPOSURE, rtol=1e-14)
    np.testing.assert_allclose(wear.thickness_loss_mm_year, c / EXPOSURE * 1e3 * 365.25 * 86400, rtol=1e-14)
    service = 3600.0
    depth = c * service / EXPOSURE
    np.testing.assert_allclose(wear.depth_m(service), depth, rtol=1e-14)
    worn = worn_wall(flat, wear, service)
    np.testing.assert_allclose(
        worn.points - flat.points, np.tile([0.0, 0.0, -depth], (len(flat.points), 1)), rtol=1e-13
    )
    eroded = wear.volume_m3.sum() * service / EXPOSURE
    np.testing.assert_allclose(swept_volume(flat, worn), eroded, rtol=1e-12)
    np.testing.assert_allclose(eroded, 0.04 * 0.03 * depth, rtol=1e-12)  # area x depth


def test_flat_wall_of_triangles_conserves_the_volume_for_any_depths(flat):
    """On a flat wall of triangles the swept prism of a face is its area times the mean depth of its points, and the
    area-weighted point depths make their sum the eroded volume (module docstring): exact for random depths, on
    triangles of unequal areas (the interior points moved in the plane), where an unweighted mean would not be."""
    rng = np.random.default_rng(3)
    points = flat.points.copy()
    inner = (points[:, 0] > 0) & (points[:, 0] < 0.04) & (points[:, 1] > 0) & (points[:, 1] < 0.03)
    points[inner, :2] += rng.uniform(-0.002, 0.002, (inner.sum(), 2))
    wall = Wall(points, flat.face_points, flat.face_offsets, flat.patch, flat.patch_names, flat.labels)
    assert wall.area.max() > 1.3 * wall.area.min() and np.allclose(wall.normal, [0.0, 0.0, -1.0])
    volume = rng.uniform(0.0, 1e-12, len(wall)) * (rng.uniform(size=len(wall)) > 0.3)
    wear = wall_wear(wall, volume, EXPOSURE, STEEL)
    service = 1e4
    np.testing.assert_allclose(
        swept_volume(wall, worn_wall(wall, wear, service)), volume.sum() * service / EXPOSURE, rtol=1e-11
    )


def test_cylinder_moved_points_lie_on_the_larger_cylinder():
    """The inner wall of a pipe (R = 25 mm, N = 64 faces round) losing the shell pi ((R + h)^2 - R^2) L, shared by
    area: every moved point lies at radius R + h to the discretisation's accuracy. A face is a chord of the circle,
    so its depth is V_f / A_f = h' = h (1 + h / (2R)) (pi / N) / sin(pi / N), relative error h / (2R) + (pi / N)^2 / 6.
    The point normals are radial by the mesh's mirror symmetry, except at the open ends of the triangulated pipe,
    where one triangle of one column meets two of the next: there they lean by delta = pi / (3N) and the radius
    falls short by h delta^2 / 2 more. The volume between the faceted walls (prisms of N sides) is the shell's times
    cos(pi / N) (1 + h' / (2R)): the area grows with depth (curvature) and the chords cut the circle."""
    radius, length, n_theta, n_z, h = 0.025, 0.1, 64, 10, 2e-4
    shell = math.pi * ((radius + h) ** 2 - radius**2) * length
    lean = math.pi / (3 * n_theta)
    for triangles in (False, True):
        wall = cylinder(radius, length, n_theta, n_z, triangles)
        normal = vertex_normals(wall)
        angle = np.arccos(np.clip(np.einsum("ij,ij->i", normal[:, :2], wall.points[:, :2] / radius), -1.0, 1.0))
        ends = (wall.points[:, 2] == 0.0) | (wall.points[:, 2] == length)
        assert np.all(angle[~ends] < 1e-7) and np.all(normal[:, 2] == 0.0)
        assert np.all(angle[ends] < 1e-7) if not triangles else np.allclose(angle[ends], lean, rtol=1e-3)
        wear = wall_wear(wall, shell * wall.area / wall.area.sum(), EXPOSURE, STEEL)
        worn = worn_wall(wall, wear, EXPOSURE)
        r = np.hypot(worn.points[:, 0], worn.points[:, 1])
        bound = h / (2 * radius) + (math.pi / n_theta) ** 2 / 6 + (lean**2 / 2 if triangles else 0.0)
        assert np.all(np.abs(r - radius - h) <= 1.01 * bound * h), np.abs(r - radius - h).max() / h
        np.testing.assert_array_equal(worn.points[:, 2], wall.points[:, 2])
        depth = shell / wall.area.sum()
        expected = shell * math.cos(math.pi / n_theta) * (1 + depth / (2 * radius))
        # quads: exact; triangles: the leaning end normals shift the ends' points sideways (measured 1.4e-5)
        np.testing.assert_allclose(swept_volume(wall, worn), expected, rtol=1e-4 if triangles else 1e-10)


def test_life_is_thickness_over_rate_and_inf_without_wear(flat):
    volume = np.zeros(len(flat))
    volume[[2, 7]] = [3e-12, 1e-12]
    wear = wall_wear(flat, volume, EXPOSURE, STEEL)
    rate = volume / (flat.area * EXPOSURE)
    life = remaining_life(wear, 0.01)
    assert life[2] == 0.01 / rate[2] and life[7] == 0.01 / rate[7]
    assert np.all(np.isinf(np.delete(life, [2, 7])))
    thickness = np.linspace(0.005, 0.02, len(flat))
    np.testing.assert_array_equal(remaining_life(wear, thickness)[[2, 7]], thickness[[2, 7]] / rate[[2, 7]])
    unknown = thickness.copy()
    unknown[[2, 3]] = np.nan  # a face of unknown thickness has an unknown life, worn (2) or not (3)
    life_unknown = remaining_life(wear, unknown)
    assert np.isnan(life_unknown[[2, 3]]).all() and life_unknown[7] == thickness[7] / rate[7]
    spots = hot_spots(flat, wear, 0.01, n=5)
    np.testing.assert_array_equal(spots.face, [2, 7] if rate[2] > rate[7] else [7, 2])
    np.testing.assert_array_equal(spots.remaining_life_year, life[spots.face] / (365.25 * 86400))
    np.testing.assert_array_equal(spots.position_m, flat.centre[spots.face])
    assert spots.patch == ("flat", "flat")
    assert SECONDS_PER_YEAR == 31_557_600.0


def test_worn_mesh_carries_the_named_fields_and_writes_stl_and_vtu(flat, tmp_path):
    """The mesh written as VTU reads back with every per-face field in face order and the moved points; as STL with
    the moved points."""
    rng = np.random.default_rng(5)
    wear = wall_wear(flat, rng.uniform(0.0, 1e-12, len(flat)), EXPOSURE, STEEL)
    mesh = worn_mesh(flat, wear, 1e3, 0.01)
    meshio.write(tmp_path / "worn.vtu", mesh)
    back = meshio.read(tmp_path / "worn.vtu")
    worn = worn_wall(flat, wear, 1e3)
    np.testing.assert_allclose(back.points, worn.points, rtol=1e-15)
    np.testing.assert_allclose(back.cell_data["erosion_rate_kg_m2_s"][0], wear.erosion_rate_kg_m2_s, rtol=1e-15)
    np.testing.assert_allclose(back.cell_data["thickness_loss_mm_year"][0], wear.thickness_loss_mm_year, rtol=1e-15)
    np.testing.assert_allclose(back.cell_data["remaining_life_s"][0], remaining_life(wear, 0.01), rtol=1e-15)
    np.testing.assert_allclose(back.point_data["wear_depth_m"], vertex_depth(flat, wear.depth_m(1e3)), rtol=1e-15)
    meshio.write(tmp_path / "worn.stl", meshio.Mesh(mesh.points, mesh.cells))
    np.testing.assert_allclose(
        read_surface(tmp_path / "worn.stl").points.min(axis=0), worn.points.min(axis=0), atol=1e-7
    )


@pytest.mark.parametrize(
    ("volume", "exposure", "density", "message"),
    [
        (-1.0, EXPOSURE, STEEL, r"volume_m3\[0\]=-1.0 is out of range"),
        (1e-12, 0.0, STEEL, "exposure_s=0.0 is out of range"),
        (1e-12, EXPOSURE, float("nan"), "density_kg_m3=nan is out of range"),
    ],
)
def test_bad_input_names_the_parameter(flat, volume, exposure, density, message):
    volumes = np.full(len(flat), 1e-12)
    volumes[0] = volume
    with pytest.raises(ValueError, match=message):
        wall_wear(flat, volumes, exposure, density)


def test_bad_thickness_service_time_and_count_name_the_parameter(flat):
    wear = wall_wear(flat, np.full(len(flat), 1e-12), EXPOSURE, STEEL)
    with pytest.raises(ValueError, match="thickness_m=0.0 .* out of range"):
        remaining_life(wear, 0.0)
    with pytest.raises(ValueError, match="thickness_m has shape"):
        remaining_life(wear, np.ones(3))
    with pytest.raises(ValueError, match="service_s=-1.0 is out of range"):
        worn_wall(flat, wear, -1.0)
    with pytest.raises(ValueError, match="n=0 is out of range"):
        hot_spots(flat, wear, 0.01, n=0)
    other = cylinder(0.025, 0.1, 8, 2)
    with pytest.raises(ValueError, match="the wear has 40 faces: the wall has 16"):
        worn_wall(other, wear, 1.0)
    with pytest.raises(ValueError, match="worn is not the wall's faces on moved points"):
        swept_volume(flat, other)


def test_lumped_volume_is_the_eroded_volume_on_a_wall_of_quads():
    """The module docstring's identity sum_v A_v h_v = sum_f A_f h_f (A_v: each face's area shared equally by its
    k points) on a wall whose faces all have k = 4, for any depths: the OpenFOAM bend's three wall patches (quads),
    random depths."""
    wall = read_polymesh(OUTPUTS)
    assert set(wall.sizes.tolist()) == {4}
    rng = np.random.default_rng(7)
    wear = wall_wear(wall, rng.uniform(0.0, 1e-12, len(wall)) * wall.area, EXPOSURE, STEEL)
    depth = wear.depth_m(1e4)
    owner = np.repeat(np.arange(len(wall)), wall.sizes)
    lumped = np.bincount(wall.face_points, weights=(wall.area / wall.sizes)[owner], minlength=len(wall.points))
    np.testing.assert_allclose((lumped * vertex_depth(wall, depth)).sum(), (wall.area * depth).sum(), rtol=1e-12)
