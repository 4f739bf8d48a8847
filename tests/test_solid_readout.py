"""The 3-D plate's surface fields read on the wear grid (wear.solid_wear.on_half_surface over the mesh's own surface
triangles, fem.solid.forms): linear between the mesh's points, symmetric about the plane of incidence, and continuous
in round-off. References: a field linear in x and |y| is reproduced exactly by linear interpolation (closed form);
a field's grid integral over the whole plate is the FE's own, 2 Σ v_j A_j over the half plate's hats (A_j = ∫ψ_j dA,
fem.solid.forms; the default 3-D impact's worn volume on its grid is within 0.02% of it, a Delaunay reading of the
same vertex values was 3.6–7.4% above it);
the same field on a mesh moved by 10⁻⁹ of its size integrates to the same number to round-off (a Delaunay
triangulation of this structured mesh's cocircular points changes its diagonals there: the grid integral of the
Hertz-like peak below moved by 1.3% with it, the default 3-D impact's worn volume by 2.3% between two runs).
The point location over the mesh's triangles (wear.triangle_finder.find_triangles) against matplotlib's trifinder
(matplotlib.tri.Triangulation.get_trifinder, the reference, which the read-out used before), on random, structured,
graded and skinny triangles."""

from __future__ import annotations

import numpy as np
import pytest
from matplotlib.tri import Triangulation
from scipy.spatial import Delaunay

from fem.solid.forms import discretise_solid
from fem.solid.mesh import generate_block, scale_block
from wear.solid_wear import on_half_surface
from wear.triangle_finder import find_triangles

SIZE = 1e-4  # m, the block's unit length (the largest contact radius)


@pytest.fixture(scope="module")
def disc():
    return discretise_solid(scale_block(generate_block(4, track=(0.0, 0.5)), SIZE))


def _vertices(disc) -> np.ndarray:
    return disc.nodes[:2, disc.surface_vertex_nodes].T


def _linear(points: np.ndarray) -> np.ndarray:
    return 2.0 + 3.0 * points[:, 0] / SIZE - 5.0 * np.abs(points[:, 1]) / SIZE


def test_a_linear_field_is_read_exactly_and_symmetrically(disc):
    rng = np.random.default_rng(3)
    px, py = rng.uniform(-2 * SIZE, 2 * SIZE, 500), rng.uniform(-2 * SIZE, 2 * SIZE, 500)
    expected = _linear(np.column_stack([px, py]))
    vertices = _vertices(disc)
    at_vertices = on_half_surface(vertices, _linear(vertices), px, py, disc.surface_triangles)
    np.testing.assert_allclose(at_vertices, expected, rtol=1e-12)
    nodes = disc.surface_xy
    at_nodes = on_half_surface(nodes, _linear(nodes), px, py, disc.surface_node_triangles)
    np.testing.assert_allclose(at_nodes, expected, rtol=1e-12)
    # several columns at once, and 0 off the plate's surface
    both = on_half_surface(
        vertices, np.column_stack([_linear(vertices), -_linear(vertices)]), px, py, disc.surface_triangles
    )
    np.testing.assert_allclose(both, np.column_stack([expected, -expected]), rtol=1e-12)
    assert on_half_surface(vertices, _linear(vertices), 1.0, 0.0, disc.surface_triangles) == 0.0


def test_the_grid_reading_is_continuous_in_round_off(disc):
    gx, gy = np.meshgrid(np.linspace(-2 * SIZE, 2.5 * SIZE, 301), np.linspace(-2 * SIZE, 2 * SIZE, 251))

    def integral(scale: float) -> float:
        points = _vertices(disc) * scale
        peak = np.sqrt(np.maximum(1.0 - ((points[:, 0] - 0.3 * SIZE) ** 2 + points[:, 1] ** 2) / SIZE**2, 0.0))
        return float(on_half_surface(points, peak, gx, gy, disc.surface_triangles).sum())

    reference = integral(1.0)
    for scale in (1.0 + 1.5e-9, 1.0 - 2.3e-9, 1.0 + 7e-10):
        assert integral(scale) == pytest.approx(reference, rel=1e-7)


def test_the_grid_integral_is_the_meshs_own(disc):
    # the whole plate's integral of the vertex values' linear field is 2 Σ v_j A_j (mirrored half plate)
    vertices = _vertices(disc)
    peak = np.sqrt(np.maximum(1.0 - ((vertices[:, 0] - 0.3 * SIZE) ** 2 + vertices[:, 1] ** 2) / SIZE**2, 0.0))
    x, y = np.linspace(-2 * SIZE, 2.5 * SIZE, 451), np.linspace(-2 * SIZE, 2 * SIZE, 401)
    gx, gy = np.meshgrid(x, y)
    on_grid = on_half_surface(vertices, peak, gx, gy, disc.surface_triangles).sum() * (x[1] - x[0]) * (y[1] - y[0])
    assert on_grid == pytest.approx(2.0 * peak @ disc.surface_area, rel=2e-4)  # a Delaunay reading: 1.2e-3 off


def _least_barycentric(points: np.ndarray, triangles: np.ndarray, qx: np.ndarray, qy: np.ndarray) -> np.ndarray:
    """The least barycentric coordinate of each query point in each triangle ((q, t)): ≥ 0 inside."""
    corners = points[triangles]
    inverse = np.linalg.inv(np.stack([corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]], axis=2))
    out = np.empty((qx.size, len(triangles)))
    for at in range(0, qx.size, 256):
        query = np.column_stack([qx[at : at + 256], qy[at : at + 256]])
        local = np.einsum("tij,qtj->qti", inverse, query[:, None, :] - corners[None, :, 0])
        out[at : at + 256] = np.minimum(1.0 - local.sum(axis=2), local.min(axis=2))
    return out


def _against_matplotlib(points: np.ndarray, triangles: np.ndarray, qx: np.ndarray, qy: np.ndarray) -> dict:
    """find_triangles against matplotlib's trifinder (the reference): the same triangle where the point is strictly
    inside matplotlib's; a triangle that holds the point (to round-off) wherever it finds one, which on a shared side
    or vertex may be either neighbour; every point matplotlib finds found; -1 where matplotlib gives -1 away from the
    mesh's boundary. Returns how many points were of each kind."""
    ours = find_triangles(points, triangles, qx, qy)
    theirs = Triangulation(points[:, 0], points[:, 1], triangles).get_trifinder()(qx, qy)
    least = _least_barycentric(points, triangles, qx, qy)
    rows = np.arange(qx.size)
    assert np.all(least[rows[ours >= 0], ours[ours >= 0]] >= -1e-9)
    strict = np.flatnonzero(theirs >= 0)
    strict = strict[least[strict, theirs[strict]] > 1e-9]
    np.testing.assert_array_equal(ours[strict], theirs[strict])
    assert np.all(ours[theirs >= 0] >= 0)
    away = (theirs < 0) & (least.max(axis=1) < -1e-9)
    np.testing.assert_array_equal(ours[away], -1)
    edges = np.abs(least.max(axis=1)) <= 1e-9
    return {"strict": strict.size, "on sides": int(np.sum(edges)), "outside": int(np.sum(away))}


def _on_the_sides(points: np.ndarray, triangles: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """The vertices, and points along every side (its middle and a random place): on shared sides and vertices."""
    a, b = points[triangles], points[np.roll(triangles, -1, axis=1)]
    f = np.concatenate([np.full(triangles.size, 0.5), rng.uniform(size=triangles.size)])[:, None]
    return np.vstack([points, np.tile(a.reshape(-1, 2), (2, 1)) + f * np.tile((b - a).reshape(-1, 2), (2, 1))])


def _structured(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The grid of points x × y, each cell cut along a diagonal that alternates from cell to cell."""
    gx, gy = np.meshgrid(x, y, indexing="ij")
    points = np.column_stack([gx.ravel(), gy.ravel()])
    i, j = np.meshgrid(np.arange(x.size - 1), np.arange(y.size - 1), indexing="ij")
    i, j = i.ravel(), j.ravel()
    p00, p10, p01, p11 = i * y.size + j, (i + 1) * y.size + j, i * y.size + j + 1, (i + 1) * y.size + j + 1
    up = (i + j) % 2 == 0
    first = np.where(up[:, None], np.column_stack([p00, p10, p11]), np.column_stack([p00, p10, p01]))
    second = np.where(up[:, None], np.column_stack([p00, p11, p01]), np.column_stack([p10, p11, p01]))
    return points, np.vstack([first, second])


@pytest.mark.parametrize("case", ["random", "structured, graded", "skinny", "sliver fan", "far from the origin"])
def test_triangle_found_is_matplotlibs(case):
    rng = np.random.default_rng(7)
    if case == "random":
        points = rng.uniform(size=(150, 2))
        triangles = Delaunay(points).simplices
    elif case == "structured, graded":
        points, triangles = _structured(np.sinh(np.linspace(-2.0, 2.0, 17)), np.linspace(0.0, 1.0, 9) ** 2)
    elif case == "skinny":  # aspect ratio 10⁴
        points, triangles = _structured(np.linspace(0.0, 1e-4, 9), np.linspace(0.0, 10.0, 7))
    elif case == "sliver fan":  # a nearest-centroid guess misses: slivers 0.4° wide about the centre
        angle = np.linspace(0.0, np.pi, 451)
        points = np.vstack([[0.0, 0.0], np.column_stack([np.cos(angle), np.sin(angle)])])
        triangles = np.column_stack([np.zeros(450, int), np.arange(1, 451), np.arange(2, 452)])
    else:
        points, triangles = _structured(1e3 + np.linspace(0.0, 1e-3, 13), -5.0 + np.linspace(0.0, 1e-3, 11))
    low, high = points.min(axis=0), points.max(axis=0)
    scattered = low + (high - low) * rng.uniform(-0.2, 1.2, size=(1500, 2))
    query = np.vstack([scattered, _on_the_sides(points, triangles, rng)])
    counts = _against_matplotlib(points, triangles, query[:, 0], query[:, 1])
    assert min(counts.values()) > 50, counts


def test_triangle_found_on_the_plates_surface_is_matplotlibs(disc):
    """The plate's own surface meshes (vertices, and quadratic nodes' triangles) read on a wear grid whose line y = 0
    is the half plate's boundary, and on the sides and vertices."""
    rng = np.random.default_rng(11)
    gx, gy = np.meshgrid(np.linspace(-2 * SIZE, 2.5 * SIZE, 61), np.linspace(0.0, 2 * SIZE, 27))
    for points, triangles in (
        (_vertices(disc), disc.surface_triangles),
        (disc.surface_xy, disc.surface_node_triangles),
    ):
        near = np.flatnonzero(np.all(np.abs(points[triangles]).max(axis=1) < 3 * SIZE, axis=1))
        on_sides = _on_the_sides(points, triangles[rng.choice(near, min(near.size, 300), replace=False)], rng)
        query = np.vstack([np.column_stack([gx.ravel(), gy.ravel()]), on_sides])
        counts = _against_matplotlib(points, triangles, query[:, 0], query[:, 1])
        assert counts["strict"] > 1000 and counts["on sides"] > 1500, counts
        assert np.all(find_triangles(points, triangles, gx, gy) >= 0)  # y = 0 included


def test_triangle_finder_gives_minus_one_off_the_mesh_for_nan_and_in_a_degenerate_triangle():
    points = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [2.0, 0.0]])
    triangles = np.array([[0, 1, 2], [0, 1, 3]])  # the second has no area: it holds no point
    found = find_triangles(points, triangles, [[0.2, np.nan], [1.5, 5.0]], [[0.2, 0.1], [0.0, 5.0]])
    assert found.tolist() == [[0, -1], [-1, -1]]
    assert find_triangles(points, triangles, np.zeros(0), np.zeros(0)).shape == (0,)
