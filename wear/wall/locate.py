r"""Where a hit lies on the wall: the distance from points to the wall's faces and the face nearest to a point.

A face is the union of its fan triangles (:attr:`wear.wall.mesh.Wall.triangles`). The distance from a point p
to a triangle (a, b, c) is :math:`|p - q|` with q the triangle's closest point, found by the Voronoi regions of
its vertices, edges and interior (Ericson, *Real-Time Collision Detection*, 2005, §5.1.5), vectorised over
points. The nearest face of a point is the face of its nearest triangle, searched among the triangles whose
centroids are nearest to it (a k-d tree, scipy's ``cKDTree``) and proven nearest (:func:`nearest_faces`).
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from wear.wall.mesh import Wall

__all__ = ["closest_on_triangles", "distance_to_faces", "nearest_faces", "default_tolerance"]


def _dot(u: np.ndarray, v: np.ndarray) -> np.ndarray:
    # three products and two sums: several times faster than einsum on (n, k, 3) arrays
    return u[..., 0] * v[..., 0] + u[..., 1] * v[..., 1] + u[..., 2] * v[..., 2]


def closest_on_triangles(p: np.ndarray, a: np.ndarray, b: np.ndarray, c: np.ndarray) -> np.ndarray:
    """The point of each triangle (a, b, c) closest to p (all (..., 3), m)."""
    ab, ac, ap, bp, cp = b - a, c - a, p - a, p - b, p - c
    d1, d2, d3, d4, d5, d6 = _dot(ab, ap), _dot(ac, ap), _dot(ab, bp), _dot(ac, bp), _dot(ab, cp), _dot(ac, cp)
    va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
    with np.errstate(divide="ignore", invalid="ignore"):  # each region's formula is used only inside it
        on_ab = d1 / (d1 - d3)
        on_ac = d2 / (d2 - d6)
        on_bc = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        total = va + vb + vc
        v, w = vb / total, vc / total
    regions = [
        (d1 <= 0) & (d2 <= 0),
        (d3 >= 0) & (d4 <= d3),
        (vc <= 0) & (d1 >= 0) & (d3 <= 0),
        (d6 >= 0) & (d5 <= d6),
        (vb <= 0) & (d2 >= 0) & (d6 <= 0),
        (va <= 0) & (d4 - d3 >= 0) & (d5 - d6 >= 0),
    ]
    points = [a, b, a + on_ab[..., None] * ab, c, a + on_ac[..., None] * ac, b + on_bc[..., None] * (c - b)]
    inside = a + v[..., None] * ab + w[..., None] * ac
    out = inside
    for region, point in zip(reversed(regions), reversed(points), strict=True):  # the first region that holds wins
        out = np.where(region[..., None], point, out)
    return out


def distance_to_faces(wall: Wall, points: np.ndarray, faces: np.ndarray) -> np.ndarray:
    """Distance (m) from each point (n, 3) to the face ``faces[i]`` of the wall (the nearest of its triangles)."""
    tri, _ = wall.triangles
    first = np.concatenate([[0], np.cumsum(wall.sizes - 2)])[faces]
    best = np.full(len(faces), np.inf)
    for j in range(int(wall.sizes[faces].max(initial=3)) - 2):
        has = wall.sizes[faces] - 2 > j
        t = tri[first[has] + j]
        q = closest_on_triangles(points[has], *(wall.points[t[:, k]] for k in range(3)))
        best[has] = np.minimum(best[has], np.linalg.norm(points[has] - q, axis=1))
    return best


def nearest_faces(
    wall: Wall, points: np.ndarray, candidates: int = 8, chunk: int = 1 << 14
) -> tuple[np.ndarray, np.ndarray]:
    """The wall face nearest to each point (n, 3) and its distance (m), ``chunk`` points at a time (bounded
    memory). Exact: a triangle of centroid c and circumradius about c at most R is no nearer to p than
    ``|p − c| − R``, so when the ``candidates``-th nearest centroid is farther than the best distance + R_max the
    nearest triangle is among the candidates; otherwise the search is repeated with 4 times more candidates."""
    tri, face_of = wall.triangles
    corners = wall.points[tri]
    centroid = corners.mean(axis=1)
    reach = float(np.linalg.norm(corners - centroid[:, None, :], axis=2).max())
    tree = cKDTree(centroid)
    best_tri = np.empty(len(points), np.int64)
    distance = np.full(len(points), np.inf)
    for start in range(0, len(points), chunk):
        todo = np.arange(start, min(start + chunk, len(points)))
        k = candidates
        while len(todo):
            k = min(k, len(tri))
            p = points[todo]
            gap, near = (a.reshape(len(p), k) for a in tree.query(p, k=k))
            d = np.linalg.norm(p[:, None, :] - _closest(p[:, None, :], corners, near), axis=2)
            best = np.argmin(d, axis=1)
            rows = np.arange(len(p))
            best_tri[todo], distance[todo] = near[rows, best], d[rows, best]
            # the candidates may miss the nearest triangle while a centroid beyond them is within reach
            todo = todo[(gap[:, -1] <= d[rows, best] + reach) & (k < len(tri))]
            k *= 4
    return face_of[best_tri], distance


def _closest(p: np.ndarray, corners: np.ndarray, which: np.ndarray) -> np.ndarray:
    """The closest points to p of the triangles ``which`` (corners (t, 3, 3))."""
    return closest_on_triangles(p, corners[which, 0], corners[which, 1], corners[which, 2])


def default_tolerance(wall: Wall) -> float:
    """The largest distance (m) of a hit from its face by default: a quarter of the median face size
    √(median area); CFD codes record the hit on the face (to round-off), so a hit farther off is another mesh,
    other units or a wrong file."""
    return 0.25 * float(np.sqrt(np.median(wall.area)))
