"""Deformed surface meshes (wear/surface.py) against closed-form volumes and the z = −(dent + wear) rule."""

import math

import meshio
import numpy as np
import pytest

from wear.surface import DeformedSurface, deform_plate_mesh, integrate_point_data, plate_block_mesh, surface_mesh


def _paraboloid_surface(n=161, half=2e-4, a=1e-4, h0=2e-6, dent_depth=5e-6, centre=(2e-5, -1e-5)):
    x = np.linspace(-half, half, n)
    y = np.linspace(-half, half, n + 10)
    gx, gy = np.meshgrid(x, y, indexing="ij")
    wear = h0 * np.maximum(1.0 - (gx**2 + gy**2) / a**2, 0.0)
    # dent: spherical-cap-like residual profile h(r) = d (1 - r²/b²) for r < b
    r = np.linspace(0.0, 1.5 * a, 400)
    dent = dent_depth * np.maximum(1.0 - (r / a) ** 2, 0.0)
    return DeformedSurface(x, y, wear, r, dent, centre), (a, h0, dent_depth)


def test_surface_volume_matches_paraboloid_closed_form():
    """∫ w dA of a paraboloid cap w = h0 (1 − r²/a²) is π a² h0 / 2 (elementary calculus);
    the mesh integral of ``wear_depth`` over surface.vtu must match within 0.5% on a 161² grid."""
    surf, (a, h0, d) = _paraboloid_surface()
    mesh = surface_mesh(surf)
    exact = math.pi * a**2 * h0 / 2.0
    assert integrate_point_data(mesh, "wear_depth") == pytest.approx(exact, rel=5e-3)
    # the dent is the same shape: π a² d / 2
    assert integrate_point_data(mesh, "dent_depth") == pytest.approx(math.pi * a**2 * d / 2.0, rel=5e-3)


def test_surface_node_z_is_minus_dent_plus_wear(tmp_path):
    """Issue 4 acceptance 6: node z = −(dent + wear), checked after a meshio write/read round trip;
    the dent is centred at ``dent_centre`` (its deepest node is the nearest grid node to it)."""
    surf, _ = _paraboloid_surface()
    path = tmp_path / "surface.vtu"
    surface_mesh(surf).write(path)
    back = meshio.read(path)
    z = back.points[:, 2]
    np.testing.assert_allclose(z, -(back.point_data["dent_depth"] + back.point_data["wear_depth"]), rtol=0, atol=1e-15)
    dent = back.point_data["dent_depth"]
    deepest = back.points[np.argmax(dent), :2]
    dx = surf.x[1] - surf.x[0]
    assert np.all(np.abs(deepest - np.array(surf.dent_centre)) <= dx)
    # independent evaluation of the dent at the nodes: h(r) = d (1 − r²/a²), linear interpolation error O(dr²)
    r = np.hypot(back.points[:, 0] - surf.dent_centre[0], back.points[:, 1] - surf.dent_centre[1])
    np.testing.assert_allclose(dent, 5e-6 * np.maximum(1 - (r / 1e-4) ** 2, 0), atol=5e-6 * 1e-3)


def test_integrate_triangles_and_quads_agree_on_bilinear_field():
    """A bilinear field f = 1 + x + 2y + 3xy on [0,1]² integrates to 1 + 1/2 + 1 + 3/4 = 3.25 exactly with quads;
    the triangulated field (linear per triangle) on a fine grid converges to the same value."""
    x = np.linspace(0, 1, 3)
    gx, gy = np.meshgrid(x, x, indexing="ij")
    f = 1 + gx + 2 * gy + 3 * gx * gy
    pts = np.column_stack([gx.ravel(), gy.ravel(), np.zeros(gx.size)])
    quads = np.array([[0, 3, 4, 1], [1, 4, 5, 2], [3, 6, 7, 4], [4, 7, 8, 5]])
    mesh = meshio.Mesh(pts, [("quad", quads)], point_data={"f": f.ravel()})
    assert integrate_point_data(mesh, "f") == pytest.approx(3.25, rel=1e-12)
    tris = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    mesh_t = meshio.Mesh(pts, [("triangle", tris)], point_data={"f": f.ravel()})
    assert integrate_point_data(mesh_t, "f") == pytest.approx(3.25, rel=0.02)


def test_plate_block_top_nodes_and_cell_volumes(tmp_path):
    """plate.vtu: top nodes at −(dent + wear) (same rule as surface.vtu); every hexahedron is ordered as VTK wants
    (a negative orientation renders inside-out in ParaView) and the block's undeformed span is L_x × L_y × t."""
    surf, _ = _paraboloid_surface(n=61)
    t = 1e-3
    mesh = plate_block_mesh(surf, t, n_layers=5)
    path = tmp_path / "plate.vtu"
    mesh.write(path)
    back = meshio.read(path)
    undeformed_z = back.points[:, 2] - back.point_data["displacement"][:, 2]
    top = undeformed_z == 0.0
    np.testing.assert_allclose(
        back.points[top, 2], -(back.point_data["dent_depth"][top] + back.point_data["wear_depth"][top]), atol=1e-15
    )
    assert top.sum() == 61 * 71
    hexes = back.cells_dict["hexahedron"]
    p = back.points[hexes]
    # VTK ordering (bottom face counter-clockwise seen from the top face): body diagonal · (x-edge × y-edge) > 0
    vol = np.einsum("ij,ij->i", p[:, 6] - p[:, 0], np.cross(p[:, 1] - p[:, 0] + p[:, 2] - p[:, 3], p[:, 3] - p[:, 0]))
    assert np.all(vol > 0)
    undeformed = back.points.copy()
    undeformed[:, 2] -= back.point_data["displacement"][:, 2]
    span = np.ptp(undeformed, axis=0)
    assert span == pytest.approx([4e-4, 4e-4, t], rel=1e-12)


def test_user_plate_mesh_is_moved_at_its_top():
    """A user's meshio block (tetrahedra, top at z = 0.002 m) gets its top nodes moved by −(dent + wear)
    evaluated independently from the closed-form paraboloids; nodes at the bottom do not move."""
    surf, (a, h0, d) = _paraboloid_surface()
    rng = np.random.default_rng(1)
    pts = np.column_stack([rng.uniform(-1.5e-4, 1.5e-4, (200, 2)), rng.choice([0.0, 0.001, 0.002], 200)])
    mesh = meshio.Mesh(pts, [("vertex", np.arange(200)[:, None])])
    moved = deform_plate_mesh(mesh, surf)
    top = pts[:, 2] == 0.002
    r_w = np.hypot(pts[:, 0], pts[:, 1])
    r_d = np.hypot(pts[:, 0] - surf.dent_centre[0], pts[:, 1] - surf.dent_centre[1])
    expected = h0 * np.maximum(1 - (r_w / a) ** 2, 0) + d * np.maximum(1 - (r_d / a) ** 2, 0)
    # bilinear interpolation of the smooth paraboloid on a 2.5 µm grid: error ≤ h0 (dx/a)² / 4 ≈ 3e-10 m;
    # within two cells of the kink at r = a the error is bounded by slope × dx / 4 = (2 h0 / a) dx / 4 = 2.5e-8 m
    dx = surf.x[1] - surf.x[0]
    tol = np.where(np.abs(r_w - a) < 2 * dx, 3e-8, 1e-9)
    assert np.all(np.abs(moved.points[top, 2] - (0.002 - expected[top])) <= tol[top])
    bottom = pts[:, 2] == 0.0
    np.testing.assert_array_equal(moved.points[bottom], pts[bottom])
    mid = ~top & ~bottom
    assert np.all(np.abs(moved.points[mid, 2] - (0.001 - expected[mid] / 2)) <= tol[mid])


@pytest.mark.parametrize(
    "kwargs, key",
    [
        ({"wear_depth": -np.ones((3, 4))}, "wear_depth"),
        ({"wear_depth": np.ones((4, 3))}, "wear_depth"),
        ({"dent_radius": np.array([0.0, -1.0])}, "dent_radius"),
        ({"x": np.array([0.0, 0.0, 1.0])}, "x"),
    ],
)
def test_bad_surface_inputs_name_the_parameter(kwargs, key):
    args = dict(
        x=np.linspace(0, 1, 3),
        y=np.linspace(0, 1, 4),
        wear_depth=np.zeros((3, 4)),
        dent_radius=np.array([0.0, 1.0]),
        dent_depth=np.zeros(2),
    )
    args.update(kwargs)
    with pytest.raises(ValueError, match=key):
        DeformedSurface(**args)
