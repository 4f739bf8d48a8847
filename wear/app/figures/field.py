"""Quadrature-point fields of the axisymmetric FE plate made drawable as filled contours.

A scatter of quadrature values shows moiré holes where the mesh coarsens; a field on the FE triangles does not.
:func:`split_in_four` refines the mesh triangles at their edge midpoints (the P2 nodes of the plate's elements),
and :func:`project_to_nodes` turns quadrature values into nodal values on that triangulation (lumped L2
projection), ready for ``tricontourf``; :func:`cell_field_on_nodes` does the same for one value per triangle (a
section of the 3-D plate); :func:`refine_grid` resamples a field on a regular grid by a bicubic spline, for a
map without the cells' blocks. Plain numpy and scipy; coordinates in m (any consistent length unit works).
"""

from __future__ import annotations

import numpy as np
from scipy.interpolate import RectBivariateSpline

__all__ = [
    "split_in_four",
    "barycentric",
    "child_of",
    "project_to_nodes",
    "quadrature_field_on_mesh",
    "cell_field_on_nodes",
    "refine_grid",
]


def split_in_four(points: np.ndarray, triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each triangle split into four at its edge midpoints (a midpoint shared by two triangles is one point).

    ``points`` (n, 2), ``triangles`` (m, 3) vertex ids. Returns (points (n + edges, 2), triangles (4m, 3)) where
    triangle 4e + k is child k of triangle e: the corner triangles at vertices 0, 1, 2 (k = 0, 1, 2) and the
    centre triangle (k = 3).
    """
    points = np.asarray(points, dtype=float)
    triangles = np.asarray(triangles, dtype=np.int64)
    n = points.shape[0]
    edges = np.sort(np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [0, 2]]]), axis=1)
    unique, inverse = np.unique(edges, axis=0, return_inverse=True)
    m = triangles.shape[0]
    mid = n + inverse.reshape(3, m)  # midpoint ids of the edges 01, 12, 02 of each triangle
    m01, m12, m02 = mid
    v0, v1, v2 = triangles.T
    children = np.stack(
        [
            np.column_stack([v0, m01, m02]),
            np.column_stack([m01, v1, m12]),
            np.column_stack([m02, m12, v2]),
            np.column_stack([m01, m12, m02]),
        ],
        axis=1,
    ).reshape(4 * m, 3)
    midpoints = 0.5 * (points[unique[:, 0]] + points[unique[:, 1]])
    return np.vstack([points, midpoints]), children


def barycentric(points: np.ndarray, triangles: np.ndarray, owner: np.ndarray, xy: np.ndarray) -> np.ndarray:
    """Barycentric coordinates (k, 3) of the points ``xy`` (k, 2) in their triangles ``triangles[owner]``."""
    corners = np.asarray(points, dtype=float)[np.asarray(triangles)[np.asarray(owner)]]  # (k, 3, 2)
    d1 = corners[:, 1] - corners[:, 0]
    d2 = corners[:, 2] - corners[:, 0]
    rel = np.asarray(xy, dtype=float) - corners[:, 0]
    det = d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0]
    l1 = (rel[:, 0] * d2[:, 1] - rel[:, 1] * d2[:, 0]) / det
    l2 = (d1[:, 0] * rel[:, 1] - d1[:, 1] * rel[:, 0]) / det
    return np.column_stack([1.0 - l1 - l2, l1, l2])


def child_of(lam: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """For barycentric coordinates ``lam`` (k, 3) in a parent triangle: the child of :func:`split_in_four` that
    holds each point (k,) and the point's barycentric coordinates in that child (k, 3)."""
    lam = np.asarray(lam, dtype=float)
    corner = np.argmax(lam, axis=1)
    child = np.where(lam[np.arange(lam.shape[0]), corner] >= 0.5, corner, 3)
    l0, l1, l2 = lam.T
    # child vertex order as in split_in_four; the linear maps follow from the midpoints having λ = ½, ½
    local = np.select(
        [child[:, None] == 0, child[:, None] == 1, child[:, None] == 2],
        [
            np.column_stack([2 * l0 - 1, 2 * l1, 2 * l2]),
            np.column_stack([2 * l0, 2 * l1 - 1, 2 * l2]),
            np.column_stack([2 * l0, 2 * l1, 2 * l2 - 1]),
        ],
        np.column_stack([1 - 2 * l2, 1 - 2 * l0, 1 - 2 * l1]),
    )
    return child, local


def project_to_nodes(
    n_nodes: int, triangles: np.ndarray, owner: np.ndarray, lam: np.ndarray, values: np.ndarray
) -> np.ndarray:
    """Nodal values (n_nodes,) from point values: the lumped L2 projection onto linear triangles.

    Each value (k,) at barycentric coordinates ``lam`` (k, 3) in triangle ``triangles[owner]`` adds to the three
    nodes with its hat-function weights λ; a node then holds the λ-weighted mean of the values around it.
    Lumping keeps the result inside the range of the values (no over- or undershoot, so a strain stays ≥ 0) at
    the price of smoothing over about one triangle.
    """
    triangles = np.asarray(triangles)
    lam = np.clip(np.asarray(lam, dtype=float), 0.0, 1.0)
    nodes = triangles[np.asarray(owner)]  # (k, 3)
    num = np.bincount(
        nodes.ravel(), weights=(lam * np.asarray(values, dtype=float)[:, None]).ravel(), minlength=n_nodes
    )
    den = np.bincount(nodes.ravel(), weights=lam.ravel(), minlength=n_nodes)
    out = np.zeros(n_nodes)
    np.divide(num, den, out=out, where=den > 0)
    return out


def quadrature_field_on_mesh(
    points: np.ndarray, triangles: np.ndarray, qp_r: np.ndarray, qp_z: np.ndarray, *fields: np.ndarray
) -> tuple[np.ndarray, np.ndarray, list[np.ndarray]]:
    """Quadrature fields (elements, qp) of a linear-triangle mesh as nodal fields on its four-fold refinement.

    ``points`` (n, 2) (r, z) and ``triangles`` (elements, 3) of the FE mesh, ``qp_r``/``qp_z`` (elements, qp)
    the quadrature coordinates. Returns (refined points, refined triangles, one nodal array per field), for
    ``matplotlib.tri.Triangulation`` and ``tricontourf``.
    """
    qp_r, qp_z = np.asarray(qp_r, dtype=float), np.asarray(qp_z, dtype=float)
    elements, per = qp_r.shape
    parent = np.repeat(np.arange(elements), per)
    xy = np.column_stack([qp_r.ravel(), qp_z.ravel()])
    fine_points, fine_triangles = split_in_four(points, triangles)
    child, local = child_of(barycentric(points, triangles, parent, xy))
    owner = 4 * parent + child
    nodal = [project_to_nodes(fine_points.shape[0], fine_triangles, owner, local, np.ravel(f)) for f in fields]
    return fine_points, fine_triangles, nodal


def cell_field_on_nodes(points: np.ndarray, triangles: np.ndarray, values: np.ndarray) -> np.ndarray:
    r"""Nodal values (n,) from one value per triangle: the lumped L2 projection of the piecewise constant field,
    :math:`v_i = \sum_{e \ni i} |T_e| v_e / \sum_{e \ni i} |T_e|` (the area-weighted mean over the triangles
    round node i; within the range of the values, so a strain stays ≥ 0).

    ``points`` (n, 2), ``triangles`` (m, 3) vertex ids, ``values`` (m,); a node of no triangle gets 0.
    """
    points = np.asarray(points, dtype=float)
    triangles = np.asarray(triangles)
    d1 = points[triangles[:, 1]] - points[triangles[:, 0]]
    d2 = points[triangles[:, 2]] - points[triangles[:, 0]]
    area = 0.5 * np.abs(d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0])
    weight = np.repeat(area, 3)
    n = points.shape[0]
    num = np.bincount(triangles.ravel(), weights=weight * np.repeat(np.asarray(values, dtype=float), 3), minlength=n)
    den = np.bincount(triangles.ravel(), weights=weight, minlength=n)
    out = np.zeros(n)
    np.divide(num, den, out=out, where=den > 0)
    return out


def refine_grid(
    x: np.ndarray, y: np.ndarray, values: np.ndarray, factor: int = 4
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``values`` (ny, nx) on the regular grid ``x`` (nx,), ``y`` (ny,) resampled on a grid ``factor`` times finer
    (the old grid lines kept) by the interpolating bicubic spline (linear along an axis of fewer than 4 points),
    clipped to the values' range (the spline overshoots next to a kink). Returns (fine x, fine y, fine values).
    """
    x, y, values = np.asarray(x, dtype=float), np.asarray(y, dtype=float), np.asarray(values, dtype=float)
    fine_x = np.interp(np.arange((x.size - 1) * factor + 1) / factor, np.arange(x.size), x)
    fine_y = np.interp(np.arange((y.size - 1) * factor + 1) / factor, np.arange(y.size), y)
    kx, ky = (3 if n >= 4 else max(n - 1, 1) for n in (x.size, y.size))
    spline = RectBivariateSpline(y, x, values, kx=ky, ky=kx, s=0)
    return fine_x, fine_y, np.clip(spline(fine_y, fine_x), values.min(), values.max())
