r"""Frictionless contact of a rigid sphere with the plate surface z = 0 (SI units).

The sphere's lower surface at overlap δ is exact (no paraboloid approximation):

.. math:: z_s(r) = -\delta + R - \sqrt{R^2 - r^2},

and the surface nodes obey u_z(r_i) ≤ z_s(r_i) (small strain: gaps measured at the reference
radius, and to the node's own reference height: a worn node sits below z = 0). The contact set is
found by :mod:`fem.axisymmetric.solver` (nodes that penetrate join, nodes that pull leave). No penalty parameter.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from scipy.linalg import solve_banded

__all__ = ["sphere_surface", "contact_radius", "contact_radius_around", "pressure_from_reactions"]


def sphere_surface(r: np.ndarray, overlap: float, radius: float) -> np.ndarray:
    """z_s(r) (m) of the sphere's lower surface; +inf beyond r = R (never in contact)."""
    r = np.asarray(r, dtype=float)
    inside = r < radius
    z = np.full(r.shape, np.inf)
    z[inside] = -overlap + radius - np.sqrt(radius**2 - r[inside] ** 2)
    return z


def contact_radius(surface_r: np.ndarray, active: np.ndarray, gap: np.ndarray) -> float:
    """Contact radius (m) located between the outermost active node and the next node.

    Outside a smooth frictionless contact edge the gap opens like (r − a)^{3/2}; a is found by
    extrapolating g^{2/3} linearly from the first two free nodes, and clamped to the interval
    between the last active and the first free node.
    """
    if not active.any():
        return 0.0
    n_active = int(np.flatnonzero(active)[-1]) + 1
    r = surface_r
    if n_active + 1 >= r.size:
        return float(r[n_active - 1])
    lo, hi = r[n_active - 1], r[n_active]
    g1, g2 = max(gap[n_active], 0.0) ** (2.0 / 3.0), max(gap[n_active + 1], 0.0) ** (2.0 / 3.0)
    if g2 <= g1:
        return float(0.5 * (lo + hi))
    a = hi - g1 * (r[n_active + 1] - hi) / (g2 - g1)
    return float(np.clip(a, lo, hi))


def contact_radius_around(distance: np.ndarray, active: np.ndarray, gap: np.ndarray, band: float) -> float:
    r"""Contact radius (m) of a patch around the sphere's axis from nodes in any layout (the 3-D plate's surface
    nodes at ``distance`` ρ from the axis, m; ``active`` in contact; ``gap`` m).

    The edge asymptote of :func:`contact_radius`, on scattered nodes: outside a smooth contact edge the gap opens
    like (ρ − a)^{3/2}, so g^{2/3} is fitted linear in ρ by least squares over the free nodes within ``band`` (m)
    of the nearest free node and extrapolated to g = 0. The area of the nodes in contact would give a staircase
    in δ, one step per ring of nodes (a quarter of a at four elements across the contact radius); the fit moves
    with the edge between the rings. Where the free nodes do not open outward (a fit whose g^{2/3} falls with ρ),
    the midpoint of the outermost node in contact and the nearest free node.

    >>> rho = np.array([0.0, 1.0, 2.0, 3.0, 4.0])
    >>> round(contact_radius_around(rho, rho < 1.5, np.maximum(rho - 1.8, 0.0) ** 1.5, band=2.0), 6)
    1.8
    """
    if not active.any():
        return 0.0
    inside = float(distance[active].max())
    free = ~active
    if not free.any():
        return inside
    rho, free_gap = distance[free], gap[free]
    nearest = float(rho.min())
    near = rho <= nearest + band
    if np.count_nonzero(near) < 2:
        near = np.argsort(rho)[:2]  # a single free node gives no slope: the midpoint below
    x, y = rho[near], np.maximum(free_gap[near], 0.0) ** (2.0 / 3.0)
    dx = x - x.mean()
    slope = float(dx @ (y - y.mean())) / max(float(dx @ dx), 1e-300)
    if slope <= 0.0:
        return 0.5 * (inside + nearest)
    return float(x.mean() - y.mean() / slope)


def pressure_from_reactions(
    hats: sp.csr_matrix, hat_mass: np.ndarray, reactions: np.ndarray, surface_r: np.ndarray, radius: float
) -> np.ndarray:
    r"""The contact pressure (Pa) at the surface nodes, a field linear between the surface vertices, from the
    contact reactions P_i (N) of the quadratic surface nodes.

    The reactions are the pressure's moments against the quadratic shape functions, P_i = ∫ p φ_i 2πr ds; a
    vertex's piecewise-linear hat ψ_j = Σ_i ψ_j(x_i) φ_i is one of their combinations, so its moment is exact,
    and the pressure is the L2 projection of the contact traction on the hats (``hats`` ψ_j(x_i), ``hat_mass``
    M_jk = ∫ ψ_j ψ_k 2πr ds in m², banded):

    .. math:: \sum_k M_{jk} p_k = \sum_i \psi_j(x_i) P_i .

    Node-by-node contact on quadratic elements is an equal-order pairing of displacement and pressure that is
    not inf-sup stable (Hild & Laborde 2002; Wohlmuth 2011, Acta Numerica 20:569, §3): the reactions carry an
    alternation between corner and mid-side nodes that the quadratic field p = M⁻¹P magnifies; a vertex hat's
    moment cancels it (½ + ½ of the mid-side nodes against the corner), which is the linear multiplier space
    the mortar methods use for quadratic displacements. Outside the contact radius ``radius`` (m; ``surface_r``
    the nodes' radii, m) the pressure is zero: the projection of the edge's √(a − r) fall rings slightly below
    zero over the next element.
    """
    at_vertices = solve_banded((1, 1), hat_mass, hats @ reactions)
    pressure = hats.T @ at_vertices
    pressure[surface_r > radius] = 0.0
    return pressure
