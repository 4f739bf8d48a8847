"""The 3-D plate's surface fields read on the wear grid (wear.solid_wear.on_half_surface over the mesh's own surface
triangles, fem.solid.forms): linear between the mesh's points, symmetric about the plane of incidence, and continuous
in round-off. References: a field linear in x and |y| is reproduced exactly by linear interpolation (closed form);
a field's grid integral over the whole plate is the FE's own, 2 Σ v_j A_j over the half plate's hats (A_j = ∫ψ_j dA,
fem.solid.forms; the default 3-D impact's worn volume on its grid is within 0.02% of it, a Delaunay reading of the
same vertex values was 3.6–7.4% above it);
the same field on a mesh moved by 10⁻⁹ of its size integrates to the same number to round-off (a Delaunay
triangulation of this structured mesh's cocircular points changes its diagonals there: the grid integral of the
Hertz-like peak below moved by 1.3% with it, the default 3-D impact's worn volume by 2.3% between two runs)."""

from __future__ import annotations

import numpy as np
import pytest

from fem.solid.forms import discretise_solid
from fem.solid.mesh import generate_block, scale_block
from wear.solid_wear import on_half_surface

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
