"""Where a hit lies on the wall: the closest point of a triangle and the nearest face.

Reference: an independent construction of the distance from a point to a triangle, the least of the distances to
the three edges (segments, the parameter clamped to [0, 1]) and, when the point's projection on the plane falls
inside (non-negative barycentric coordinates), the height above the plane; and brute force over every triangle
for the nearest face (the k-d tree search must be exact, also on sliver triangles).
"""

from __future__ import annotations

import meshio
import numpy as np
from scipy.spatial import Delaunay

from wear.wall import read_surface
from wear.wall.locate import closest_on_triangles, nearest_faces


def _distance(p, a, b, c) -> float:
    def segment(u, v):
        t = np.clip(np.dot(p - u, v - u) / np.dot(v - u, v - u), 0.0, 1.0)
        return np.linalg.norm(p - (u + t * (v - u)))

    best = min(segment(a, b), segment(b, c), segment(c, a))
    n = np.cross(b - a, c - a)
    n /= np.linalg.norm(n)
    foot = p - np.dot(p - a, n) * n
    area = np.dot(np.cross(b - a, c - a), n)
    weights = [np.dot(np.cross(v - foot, w - foot), n) / area for v, w in ((b, c), (c, a), (a, b))]
    if min(weights) >= 0.0:
        best = min(best, abs(np.dot(p - a, n)))
    return best


def test_the_closest_point_of_a_triangle_is_at_the_independent_distance():
    rng = np.random.default_rng(3)
    a, b, c = (rng.normal(size=(400, 3)) for _ in range(3))
    p = 2.0 * rng.normal(size=(400, 3))
    q = closest_on_triangles(p, a, b, c)
    expected = [_distance(*args) for args in zip(p, a, b, c, strict=True)]
    assert np.allclose(np.linalg.norm(p - q, axis=1), expected, rtol=1e-12, atol=1e-14)


def test_the_nearest_face_is_exact_on_sliver_triangles(tmp_path):
    """400 random points of a 1 m × 1 cm strip, Delaunay-triangulated (slivers), 800 hits up to a few mm off it."""
    rng = np.random.default_rng(5)
    points = np.column_stack([rng.random(400), 0.01 * rng.random(400), np.zeros(400)])
    meshio.write(tmp_path / "strip.vtu", meshio.Mesh(points, [("triangle", Delaunay(points[:, :2]).simplices)]))
    wall = read_surface(tmp_path / "strip.vtu")
    hits = np.column_stack([rng.random(800), 0.012 * rng.random(800) - 0.001, 0.002 * rng.normal(size=800)])
    face, distance = nearest_faces(wall, hits, chunk=512)
    tri, face_of = wall.triangles
    assert np.array_equal(face_of, np.arange(len(wall)))  # a surface of triangles: one triangle a face
    corners = wall.points[tri]
    # brute force with the kernel checked above: every hit against every triangle
    every = np.linalg.norm(
        hits[:, None, :] - closest_on_triangles(hits[:, None, :], corners[:, 0], corners[:, 1], corners[:, 2]), axis=2
    )
    assert np.array_equal(distance, every.min(axis=1))
    assert np.all(every[np.arange(len(hits)), face] == distance)
