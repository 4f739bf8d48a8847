r"""Frictionless contact of a rigid sphere with the plate surface z = 0 (SI units).

The sphere's lower surface at overlap δ is exact (no paraboloid approximation):

.. math:: z_s(r) = -\delta + R - \sqrt{R^2 - r^2},

and the surface nodes obey u_z(r_i) ≤ z_s(r_i) (small strain: gaps measured at the reference
radius). The contact set of a sphere pressed into a flat is a disc, so the active set is the
first ``n`` surface nodes from the axis: the semi-smooth Newton of :mod:`fem.solver` moves ``n``
outwards where an inactive node penetrates and inwards where an active node pulls (negative
reaction). No penalty parameter.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse.linalg as spla

__all__ = ["sphere_surface", "update_active_count", "contact_radius", "pressure_from_reactions"]


def sphere_surface(r: np.ndarray, overlap: float, radius: float) -> np.ndarray:
    """z_s(r) (m) of the sphere's lower surface; +inf beyond r = R (never in contact)."""
    r = np.asarray(r, dtype=float)
    inside = r < radius
    z = np.full(r.shape, np.inf)
    z[inside] = -overlap + radius - np.sqrt(radius**2 - r[inside] ** 2)
    return z


def update_active_count(n_active: int, reactions: np.ndarray, gap: np.ndarray, gap_tol: float) -> int:
    """New number of active surface nodes (sorted by r).

    ``reactions`` (N, positive = compressive) of all surface nodes, ``gap`` = z_s − u_z (m,
    negative = penetration). Penetration beyond the current set extends it to the outermost
    penetrating node; otherwise pulling active nodes at the edge of the set are released.
    """
    outside = np.flatnonzero(gap[n_active:] < -gap_tol)
    if outside.size:
        return int(n_active + outside[-1] + 1)
    # release from the edge inwards only: inside the disc a pulling node of an unconverged iterate
    # is not a separation (and a P2 vertex may carry a small negative share of a positive pressure)
    n = n_active
    while n > 0 and reactions[n - 1] < 0.0:
        n -= 1
    return n


def contact_radius(surface_r: np.ndarray, n_active: int, gap: np.ndarray) -> float:
    """Contact radius (m) located between the last active and the first free node.

    Outside a smooth frictionless contact edge the gap opens like (r − a)^{3/2}; a is found by
    extrapolating g^{2/3} linearly from the first two free nodes, and clamped to the interval
    between the last active and the first free node.
    """
    if n_active == 0:
        return 0.0
    r = surface_r
    if n_active + 1 >= r.size:
        return float(r[n_active - 1])
    lo, hi = r[n_active - 1], r[n_active]
    g1, g2 = max(gap[n_active], 0.0) ** (2.0 / 3.0), max(gap[n_active + 1], 0.0) ** (2.0 / 3.0)
    if g2 <= g1:
        return float(0.5 * (lo + hi))
    a = hi - g1 * (r[n_active + 1] - hi) / (g2 - g1)
    return float(np.clip(a, lo, hi))


def pressure_from_reactions(surface_mass_lu: spla.SuperLU, reactions: np.ndarray) -> np.ndarray:
    """Nodal pressure (Pa) p solving M p = P with the 2πr-weighted surface mass matrix M (m²)."""
    return surface_mass_lu.solve(reactions)
