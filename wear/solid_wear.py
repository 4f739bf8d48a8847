r"""Wear and dent of the 3-D plate: equation 15 integrated with the 3-D plate's own pressure and stick/slip fields, and
its residual surface on the wear grid (SI units: m, s, Pa).

The 3-D plate (:func:`fem.indent_solid`, :func:`fem.couple_solid`) gives, at each of its steps k placed at impact
time t_k, the contact pressure p_k at its quadratic surface nodes (linear between the vertices) and the ball's slip
s_k over each of them in the step (the quadratic displacement's own; zero where the node sticks; half plate,
mirrored about the plane of incidence y = 0). With the local slip
(``wear.speed = "local"``, the default; :mod:`wear.slip`) each point wears at its own slip rate, the plate's:

.. math::

    w(\mathbf{x}) = \int K\, p(\mathbf{x}, t)^{\alpha}\, v(\mathbf{x}, t)^{\beta}\, dt
    \approx \sum_k K\, \frac{p_{k-1}^{\alpha} + p_k^{\alpha}}{2}\,\Delta t_k
    \left(\frac{\lVert s_k(\mathbf{x})\rVert}{\Delta t_k}\right)^{\beta},

p^α linear in time over a step and the slip at a constant rate through it (t before the first step: the impact's
first contact, p = 0). A point in the stick zone does not slide and does not wear (β > 0); where the whole contact
slides the slip rate is the ball's slip speed less the rate of the plate's own shear displacement
(``tests/test_fem_solid.py`` checks the slip against Cerruti's). With the impact's contact-point slip
(``"sliding"``, the paper's, or ``"kinematic"``) every point in contact moves at its speed ``|v_t − Rω|``
(:func:`wear.sliding_speed`) instead, stuck or not:

.. math::

    w(\mathbf{x}) \approx \sum_k W_k\, p_k(\mathbf{x})^{\alpha},
    \qquad W_k = \int K\, v(t)^{\beta}\, \phi_k(t)\, dt,

φ_k the piecewise-linear hat of step k in time. Either way the fields are linear in time between the plate's steps
at fixed points of the plate (not in the moving frame of the contact, as the axisymmetric p(r/a, t) table is),
which underestimates p^α where the contact edge grows between two steps; the error falls with the number of loading
steps.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import Delaunay

from contact.fields import SurfaceField
from wear.law import WearLaw
from wear.slip import SlidingSpeed
from wear.triangle_finder import find_triangles

__all__ = ["on_half_surface", "solid_grid", "step_weights", "solid_wear_depth", "solid_dent_depth"]


def on_half_surface(
    points: np.ndarray, values: np.ndarray, px: np.ndarray, py: np.ndarray, triangles: np.ndarray | None = None
) -> np.ndarray:
    """The whole plate's field at (``px``, ``py``) (m, any shape) from its ``values`` (n, ...) at the half plate's
    surface ``points`` (m, (n, 2), y ≥ 0): linear over the half plate's ``triangles`` ((t, 3) rows of ``points``: the
    mesh's own, over which its fields are linear; default a Delaunay triangulation of the points), evaluated at
    :math:`(x, |y|)`, so that the field is symmetric about the plane of incidence y = 0 by construction; 0 outside
    the surface. The mesh's triangles, not Delaunay's: a structured mesh's cocircular points leave Delaunay a choice
    of diagonal, which round-off then makes (the default 3-D impact's worn volume on the grid changed by 2.3% between
    two runs whose meshes differed by 10⁻¹¹ m, with its vertex values the same to 10⁻⁶), and a triangulation of the
    points and their mirror images makes it differently on each side. Shape ``px.shape + values.shape[1:]``."""
    px, py = np.broadcast_arrays(np.asarray(px, float), np.asarray(py, float))
    query = np.column_stack([px.ravel(), np.abs(py.ravel())])
    if triangles is None:
        found_in = Delaunay(points)
        triangles, found = found_in.simplices, found_in.find_simplex(query)
    else:
        found = find_triangles(points, triangles, query[:, 0], query[:, 1])
    inside = found >= 0
    corners = triangles[found[inside]]
    origin = points[corners[:, 0]]
    sides = np.stack([points[corners[:, 1]] - origin, points[corners[:, 2]] - origin], axis=2)
    local = np.linalg.solve(sides, (query[inside] - origin)[..., None])[..., 0]
    weights = np.column_stack([1.0 - local.sum(axis=1), local])
    values = np.asarray(values, float)
    out = np.zeros((query.shape[0], *values.shape[1:]))
    out[inside] = np.einsum("mk,mk...->m...", weights, values[corners])
    return out.reshape(px.shape + values.shape[1:])


def solid_grid(field: SurfaceField, points_across: int, reach: float = 2.0) -> tuple[np.ndarray, np.ndarray]:
    """The wear grid (x, y in m) of a plate's surface ``field``: spacing 2 a_max/``points_across`` (a_max the largest
    contact radius), x over the contact centres' track ± ``reach`` a_max, y over ± ``reach`` a_max (the pile-up lip of a
    plastic dent lies outside the contact), y = 0 a grid line."""
    a_max = float(np.max(field.contact_radius))
    if a_max <= 0.0:
        raise ValueError("the 3-D plate never came into contact (contact radius 0 m): nothing to integrate")
    dx = 2.0 * a_max / points_across
    half = int(np.ceil(reach * a_max / dx))
    lo, hi = float(np.min(field.centre)), float(np.max(field.centre))
    x = lo + dx * np.arange(-half, int(np.ceil((hi - lo) / dx)) + half + 1)
    return x, dx * np.arange(-half, half + 1)


def step_weights(times: np.ndarray, speed: SlidingSpeed, law: WearLaw) -> np.ndarray:
    r"""W_k = ∫ K v^β φ_k dt (units of K × s × (m/s)^β) of the steps at ``times`` (s, increasing), by the trapezoid
    rule on the union of the steps' and the sliding speed's samples."""
    t = np.union1d(times, speed.time[(speed.time > times[0]) & (speed.time < times[-1])])
    rate = law.K * np.interp(t, speed.time, speed.speed, left=0.0, right=0.0) ** law.beta
    weights = np.zeros(times.size)
    for k in range(times.size):
        hat = np.interp(t, times, np.eye(times.size)[k])
        weights[k] = np.trapezoid(rate * hat, t)
    return weights


def _on_grid(
    points: np.ndarray, values: np.ndarray, x: np.ndarray, y: np.ndarray, triangles: np.ndarray | None
) -> np.ndarray:
    """Vertex ``values`` (m, ...) of the half plate at ``points`` (m) on the grid ``x``, ``y`` (m): (..., ny, nx),
    linear over ``triangles`` and symmetric about y = 0 (:func:`on_half_surface`), 0 outside the surface."""
    gx, gy = np.meshgrid(x, y)
    return np.moveaxis(on_half_surface(points, values, gx, gy, triangles), (0, 1), (-2, -1))


def solid_wear_depth(
    field: SurfaceField, speed: SlidingSpeed | None, law: WearLaw, x: np.ndarray, y: np.ndarray, start: float = 0.0
) -> np.ndarray:
    """Wear depth (m, (ny, nx), positive into the plate) on the grid ``x``, ``y`` (m) of a plate's surface
    ``field`` (its steps placed at impact times, the impact's first contact at ``start``, s), with the local wear
    ``law``: at each point's own slip rate on the plate (the local slip) where ``speed`` is None, else at the
    impact's contact-point slip ``speed`` (m/s; module docstring)."""
    times = np.asarray(field.time, float)
    pressed = np.maximum(field.pressure, 0.0) ** law.alpha
    if speed is None:
        start = min(start, float(times[0]))
        step = np.diff(np.r_[start, times])
        before = np.vstack([np.zeros_like(pressed[:1]), pressed[:-1]])
        rate = np.linalg.norm(field.slip, axis=2) / np.maximum(step, 1e-300)[:, None]
        worn = law.K * 0.5 * (before + pressed) * step[:, None] * rate**law.beta
    else:
        worn = pressed * step_weights(times, speed, law)[:, None]
    return np.maximum(_on_grid(field.points, worn.sum(axis=0), x, y, field.triangles), 0.0)


def solid_dent_depth(field: SurfaceField, x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """A plate's residual surface (m, (nx, ny), positive into the plate, pile-up negative) on the grid: its
    ``field.dent`` at ``field.dent_points`` interpolated linearly (on the 3-D plate its quadratic surface nodes,
    vertices and mid-edge nodes, which halves the distance over which the curved dent bottom is cut short against
    the vertices alone)."""
    return _on_grid(field.dent_points, field.dent, x, y, field.dent_triangles).T
