"""Point location over a plane mesh's own triangles (SI units): which triangle holds each query point.

A uniform grid of squares is laid over the query points, :data:`CELLS_ACROSS` of them across the smallest triangle
there (fewer where that would give more than about three cells per query point and triangle), its lines offset from
the points' box by a golden fraction of a side (off a structured mesh's lines). Each triangle is listed in every cell
it overlaps (the separating axes of a square and a triangle: their sides), so that a cell holds a triangle or two; a
cell that lies in the one triangle it holds is that triangle's. A point in such a cell is in its triangle; any other
point is tested against each triangle of its cell, which include every triangle holding it (a cell is tested 10⁻⁶ of
its side larger than it is, against the same tolerance as a point, and a point's cell is found by the same rounded
operations that placed the cells). Exact for any triangle shape, skinny ones included, and over the mesh's own
triangles, never a triangulation of its points.
"""

from __future__ import annotations

import numpy as np

__all__ = ["find_triangles", "ROUND_OFF", "CELLS_ACROSS"]

#: Relative round-off tolerance: a point is in a triangle when its barycentric coordinates λ are all ≥ −ROUND_OFF L²/2A
#: (L the triangle's longest side, A its area).
ROUND_OFF = 1e-12
#: Query points located at once (bounds the memory of the point–candidate pairs).
CHUNK = 1 << 14
#: Cells across the smallest triangle near the query points (finer: fewer candidates per point, more cells to fill).
CELLS_ACROSS = 4


def find_triangles(points: np.ndarray, triangles: np.ndarray, qx: np.ndarray, qy: np.ndarray) -> np.ndarray:
    """The row of ``triangles`` ((t, 3) rows of ``points`` (m, (n, 2))) holding each query point (``qx``, ``qy``) (m,
    any shapes that broadcast), -1 where none does: its barycentric coordinates λ in the triangle all
    ≥ −:data:`ROUND_OFF` L²/2A (L the triangle's longest side, A its area: within round-off of its sides); one of
    them for a point on a shared side or vertex. Shape of the broadcast query; int."""
    qx, qy = np.broadcast_arrays(np.asarray(qx, float), np.asarray(qy, float))
    x, y = qx.ravel(), qy.ravel()
    corners = np.asarray(points, float)[np.asarray(triangles, int)]
    sides = np.roll(corners, -1, axis=1) - corners  # side k from corner k to corner k + 1
    area2 = sides[:, 0, 0] * sides[:, 1, 1] - sides[:, 0, 1] * sides[:, 1, 0]  # 2A, + anticlockwise
    scale = np.sign(area2) / np.max(np.sum(sides**2, axis=2), axis=1)  # orientation / L²
    # (side k, [corner k's x, y, side k's x, y × scale], triangle): λ_k 2A/L² = scaled side × (point − corner)
    table = np.concatenate([corners, sides * scale[:, None, None]], axis=2).transpose(1, 2, 0).copy()
    finite = np.isfinite(x) & np.isfinite(y)
    found = np.full(x.size, -1)
    if not finite.any() or not np.any(area2):
        return found.reshape(qx.shape)
    origin, side, shape, start, items, owner = _grid(table, np.flatnonzero(area2), x[finite], y[finite])
    for begin in range(0, x.size, CHUNK):
        px, py = x[begin : begin + CHUNK], y[begin : begin + CHUNK]
        i, j = np.floor((px - origin[0]) / side), np.floor((py - origin[1]) / side)
        point = np.flatnonzero((i >= 0) & (i < shape[0]) & (j >= 0) & (j < shape[1]))  # NaN: in no cell
        cell = (j[point] * shape[0] + i[point]).astype(int)
        own = owner[cell]
        found[begin + point[own >= 0]] = own[own >= 0]
        point, cell = point[own < 0], cell[own < 0]
        n = start[cell + 1] - start[cell]
        tri = items[np.repeat(start[cell] - np.cumsum(n) + n, n) + np.arange(int(n.sum()))]
        point = np.repeat(point, n)
        hit = np.min(_signed(np.take(table, tri, axis=2), px[point], py[point]), axis=0) >= -ROUND_OFF
        found[begin + point[hit]] = tri[hit]
    return found.reshape(qx.shape)


def _signed(rows: np.ndarray, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """λ_k 2A/L² ((3, p), ≥ 0 inside) of the points (``x``, ``y``) (m) in the triangles ``rows`` (their columns of
    the table of :func:`find_triangles`): to each side k, the signed distance over L²/|side k|."""
    vx, vy, sx, sy = rows.transpose(1, 0, 2)
    return sx * (y - vy) - sy * (x - vx)


def _grid(table: np.ndarray, used: np.ndarray, x: np.ndarray, y: np.ndarray) -> tuple:
    """The grid (module docstring) of the triangles ``used`` of the ``table`` of :func:`find_triangles` over the
    points (``x``, ``y``) (m): its origin (m, (2,)), side (m), shape (nx, ny); the triangles of cell k (numbered x
    fastest) ``items[start[k]:start[k + 1]]`` and the triangle the whole cell lies in, alone in it, ``owner[k]`` (-1:
    none)."""
    low, high = table[:, :2, used].min(axis=0).T, table[:, :2, used].max(axis=0).T
    box = np.array([[x.min(), y.min()], [x.max(), y.max()]])
    there = np.all((low <= box[1]) & (high >= box[0]), axis=1)
    width = np.max(high - low, axis=1)
    side = float(np.min(width[there], initial=np.max(width))) / CELLS_ACROSS
    extent, cells = box[1] - box[0], x.size + used.size  # at most about 3 cells per point and triangle
    side = max(side, float(np.sqrt(np.prod(extent) / cells)), float(np.max(extent)) / cells)
    origin = box[0] - 0.3819660112501051 * side
    shape = np.floor((box[1] - origin) / side).astype(int) + 1
    first = np.maximum(np.floor((low - origin) / side).astype(int), 0)
    span = np.maximum(np.minimum(np.floor((high - origin) / side).astype(int), shape - 1) - first + 1, 0)
    count = span[:, 0] * span[:, 1]
    listed = np.repeat(np.arange(used.size), count)
    k = np.arange(listed.size) - np.repeat(np.cumsum(count) - count, count)
    col, row = first[listed, 0] + k % span[listed, 0], first[listed, 1] + k // span[listed, 0]
    centre = origin + (np.column_stack([col, row]) + 0.5) * side
    rows = np.take(table, used[listed], axis=2)
    signed = _signed(rows, centre[:, 0], centre[:, 1])
    reach = (0.5 + 1e-6) * side * (np.abs(rows[:, 2]) + np.abs(rows[:, 3]))  # to a square's corner, most and least
    overlap = np.min(signed + reach, axis=0) >= -ROUND_OFF
    within = np.min(signed - reach, axis=0)[overlap] >= 0.0
    cell, tri = (row * shape[0] + col)[overlap], used[listed[overlap]]
    held = np.bincount(cell, minlength=int(np.prod(shape)))
    owner = np.full(held.size, -1)
    alone = within & (held[cell] == 1)
    owner[cell[alone]] = tri[alone]
    return origin, side, shape, np.concatenate([[0], np.cumsum(held)]), tri[np.argsort(cell, kind="stable")], owner
