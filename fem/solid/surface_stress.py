r"""The 3-D plate's stress on its surface z = 0, recovered from the element stresses and the contact tractions.

The surface stresses decide where a sliding contact first yields once μ ≳ 0.3 (Hamilton 1983: at the surface, at
the trailing edge) and where a brittle or coated plate cracks (the radial tension at the contact edge, Johnson 1985
Eq. 3.45), but the quadrature points of the surface elements lie below the surface (a quarter of an element deep on
average), where those stresses have already decayed: under a sliding Hertz contact with μ = 0.5 the von Mises
stress at the trailing edge falls from 0.957 p0 at the surface to 0.75 p0 at a depth of 0.01a. The recovery reads
the field on the surface itself:

1. each element's stress — linear on a P2 tetrahedron of an elastic field, its strain being the gradient of a
   quadratic displacement — is taken through its four quadrature points and evaluated at its corners, and the
   corner values are averaged over the elements that share a vertex;
2. at a surface vertex the out-of-plane components are those the surface carries, σ_zz = −p, σ_xz = τ_x,
   σ_yz = τ_y (the contact tractions on the plate, zero outside the contact); the in-plane components are step 1's.

Adjusting the in-plane stresses to step 2's σ_zz at fixed in-plane strain (by ν Δσ_zz / (1 − ν)) was measured and left
out: against Johnson's Hertz surface stresses it moved σ_r and σ_θ away from the closed form by up to 0.007 p0, where
the vertex pressure is itself an approximation. Stresses in Mandel notation (σ_xx, σ_yy, σ_zz, √2 σ_yz, √2 σ_xz, √2
σ_xy), Pa, as in :mod:`fem.solid.forms`. Accuracy (``tests/test_fem_surface_stress.py``, ``docs/fem-record.md``), with
16 elements across a in a band at the contact edge (:func:`fem.solid.mesh.generate_block`): Johnson's Hertz surface
stresses within 0.013 p0 but at the edge vertex; Hamilton's under a sliding contact, μ = 0.5, within 2% along the
trailing half but within an element of the edge, where his √-cusp (0.957 p0 at the edge, under 0.93 p0 beyond 0.02a of
it) is smeared over the element: the edge vertex 20% low, its neighbour 5% high, and the largest value 1% from
Hamilton's, an element inside the edge.
"""

from __future__ import annotations

import math

import numpy as np

from fem.solid.forms import SolidDiscretisation

__all__ = ["vertex_stress", "surface_stress"]

SQRT2 = math.sqrt(2.0)


def vertex_stress(disc: SolidDiscretisation, stress: np.ndarray) -> np.ndarray:
    """Stress (mesh vertices, 6) in Pa, Mandel, at the vertices of ``disc``'s mesh: each element's linear field
    through its quadrature-point ``stress`` (elements, 4, 6), evaluated at its corners and averaged over the
    elements that share the vertex."""
    mesh = disc.mesh
    nqp = disc.qp.shape[2]
    if stress.shape != (mesh.t.shape[1], nqp, 6) or nqp != 4:
        raise ValueError(f"stress: shape {stress.shape}, expected (elements, 4, 6) = ({mesh.t.shape[1]}, 4, 6) (Pa)")
    # coordinates from each element's centre, so that a small element far from the origin stays well conditioned
    centre = disc.qp.mean(axis=2)  # (3, elements)
    points = disc.qp - centre[:, :, None]
    at_points = np.concatenate([np.ones((1, *points.shape[1:])), points], axis=0).transpose(1, 2, 0)
    coefficients = np.linalg.solve(at_points, stress)  # (elements, 4 = 1, x, y, z, 6)
    corners = mesh.p[:, mesh.t] - centre[:, None, :]  # (3, 4, elements)
    at_corners = np.concatenate([np.ones((1, *corners.shape[1:])), corners], axis=0).transpose(2, 1, 0)
    values = np.einsum("eck,eks->ecs", at_corners, coefficients)
    total = np.zeros((mesh.p.shape[1], 6))
    count = np.zeros(mesh.p.shape[1])
    np.add.at(total, mesh.t.T, values)
    np.add.at(count, mesh.t.T, 1.0)
    return total / count[:, None]


def surface_stress(
    disc: SolidDiscretisation, stress: np.ndarray, pressure: np.ndarray, shear: np.ndarray
) -> np.ndarray:
    r"""Stress (surface vertices, 6) in Pa, Mandel, on the surface z = 0 at ``disc.surface_vertex_nodes``.

    ``stress`` (elements, 4, 6) the quadrature-point stresses (Pa); ``pressure`` (surface vertices) the contact
    pressure p on the plate (Pa, positive pressing, zero outside the contact) and ``shear`` (surface vertices, 2) its
    shear traction (τ_x, τ_y) (Pa):

    .. math::
        \sigma_{zz} = -p, \quad \sigma_{xz} = \tau_x, \quad \sigma_{yz} = \tau_y,

    the in-plane components those of :func:`vertex_stress`.
    """
    nv = disc.surface_vertex_nodes.size
    pressure = np.asarray(pressure, dtype=float)
    shear = np.asarray(shear, dtype=float)
    if pressure.shape != (nv,) or shear.shape != (nv, 2):
        raise ValueError(
            f"pressure, shear: shapes {pressure.shape}, {shear.shape}, expected ({nv},) and ({nv}, 2): one value "
            "(Pa) per surface vertex"
        )
    recovered = vertex_stress(disc, stress)[disc.surface_vertex_nodes]
    recovered[:, 2] = -pressure
    recovered[:, 3] = SQRT2 * shear[:, 1]
    recovered[:, 4] = SQRT2 * shear[:, 0]
    return recovered
