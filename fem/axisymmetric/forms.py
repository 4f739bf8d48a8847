r"""Axisymmetric P2 kinematics: the strain operators of the (r, z) plate and its surface operators.

Displacement u = (u_r, u_z) on P2 triangles (scikit-fem's :class:`~skfem.ElementTriP2` basis,
our own interleaved numbering: global DOF 2·n + c for scalar node n and component c = 0 (r),
1 (z)). Strains in Mandel notation, so a 4 × 4 tangent acts as a plain matrix:

.. math::
    \varepsilon = \left(\partial_r u_r,\; \partial_z u_z,\; u_r / r,\;
    \tfrac{1}{\sqrt2}(\partial_z u_r + \partial_r u_z)\right),

and every integral carries the axisymmetric weight 2πr:

.. math:: K = \sum_e \sum_q B_q^T D_q B_q \, 2\pi r_q\, w_q |J_e|, \qquad
          f_{int} = \sum_e \sum_q B_q^T \sigma_q \, 2\pi r_q\, w_q |J_e| .

The operators are computed once; :mod:`fem.core.assembly` forms the element matrices and the internal force
from them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from skfem import Basis, ElementTriP2, MeshTri

from fem.core.assembly import csr_pattern

__all__ = ["Discretisation", "discretise", "elastic_tangent"]

SQRT2 = math.sqrt(2.0)


@dataclass(frozen=True, eq=False)
class Discretisation:
    """Everything the solver needs about the mesh, precomputed once.

    ``B`` (elements, qp, 4, 12) strain operators, ``weight`` (elements, qp) = 2πr w det J (m³),
    ``element_dofs`` (elements, 12), ``qp_r``/``qp_z`` (elements, qp) quadrature coordinates (m),
    CSR pattern (``indptr``, ``indices``) with ``entry_index`` mapping element entries to it,
    ``axis_dofs``/``bottom_dofs`` (constrained), ``surface_nodes`` (scalar node ids sorted by r),
    ``surface_r``/``surface_z`` (m) their reference coordinates (z = 0 on a flat plate, below 0 where the surface
    was worn), ``surface_hats`` (surface vertices × surface nodes) the values of each surface vertex's piecewise-
    linear hat function at the surface nodes, ``surface_hat_mass`` the hats' 2πr-weighted mass matrix (m², banded:
    rows super-, main and sub-diagonal, as :func:`scipy.linalg.solve_banded` takes it),
    ``node_r``/``node_z`` (m) of every scalar node.
    """

    mesh: MeshTri
    basis: Basis
    B: np.ndarray
    weight: np.ndarray
    element_dofs: np.ndarray
    qp_r: np.ndarray
    qp_z: np.ndarray
    indptr: np.ndarray
    indices: np.ndarray
    entry_index: np.ndarray
    ndofs: int
    axis_dofs: np.ndarray
    bottom_dofs: np.ndarray
    surface_nodes: np.ndarray
    surface_r: np.ndarray
    surface_z: np.ndarray
    surface_hats: sp.csr_matrix
    surface_hat_mass: np.ndarray
    node_r: np.ndarray
    node_z: np.ndarray
    surface_layer: np.ndarray  # (elements, qp) bool: top-row quadrature points (depth < 0.2 h) at z = 0

    def matrix(self, data: np.ndarray) -> sp.csr_matrix:
        """CSR matrix with the fixed pattern and the given ``data``."""
        return sp.csr_matrix((data, self.indices, self.indptr), shape=(self.ndofs, self.ndofs))


def elastic_tangent(E: float, nu: float) -> np.ndarray:
    """Isotropic elastic 4 × 4 Mandel tangent (Pa): D = 3K·P_vol + 2G·P_dev."""
    bulk = E / (3.0 * (1.0 - 2.0 * nu))
    shear = E / (2.0 * (1.0 + nu))
    one = np.array([1.0, 1.0, 1.0, 0.0])
    p_vol = np.outer(one, one) / 3.0
    return 3.0 * bulk * p_vol + 2.0 * shear * (np.eye(4) - p_vol)


def _surface_hats(mesh: MeshTri, surface_nodes: np.ndarray) -> tuple[sp.csr_matrix, np.ndarray]:
    """The piecewise-linear hat functions of the surface vertices: their values at the surface nodes (a vertex's own
    node 1, the mid-side nodes of its two surface facets ½, exact on the straight facets), and their mass matrix
    ∫ ψ_i ψ_j 2πr ds (m², exact: on a facet of length L from r_0 to r_1, L/12 · 2π (3r_0 + r_1, r_0 + r_1;
    r_0 + r_1, r_0 + 3r_1)), banded. The vertices are numbered by radius, so a facet joins neighbours."""
    nvert = mesh.p.shape[1]
    is_vertex = surface_nodes < nvert
    nv = int(is_vertex.sum())
    vertex_rows = np.full(nvert, -1, dtype=np.int64)
    vertex_rows[surface_nodes[is_vertex]] = np.arange(nv)
    entries = []  # (vertex row, surface node, hat value)
    mass = np.zeros((3, nv))  # banded: mass[1 + i - j, j] = M[i, j]
    for i, node in enumerate(surface_nodes):
        if is_vertex[i]:
            entries.append((vertex_rows[node], i, 1.0))
            continue
        # a P2 facet node: scikit-fem numbers them after the vertices, in facet order
        ends = mesh.facets[:, node - nvert]
        length = float(np.hypot(*(mesh.p[:, ends[1]] - mesh.p[:, ends[0]])))
        (j0, r0), (j1, r1) = sorted((vertex_rows[e], mesh.p[0, e]) for e in ends)
        if j1 != j0 + 1:
            raise ValueError(
                f"mesh surface: facet {node - nvert} joins vertices that are not neighbours in r (the "
                "surface must be a graph z(r), each facet between consecutive vertices)"
            )
        scale = 2.0 * np.pi * length / 12.0
        mass[1, j0] += scale * (3.0 * r0 + r1)
        mass[1, j1] += scale * (r0 + 3.0 * r1)
        mass[0, j1] += scale * (r0 + r1)
        mass[2, j0] += scale * (r0 + r1)
        entries += [(j0, i, 0.5), (j1, i, 0.5)]
    rows, cols, values = np.array(entries).T
    hats = sp.csr_matrix((values, (rows.astype(np.int64), cols.astype(np.int64))), shape=(nv, surface_nodes.size))
    return hats, mass


def discretise(mesh: MeshTri, intorder: int = 4) -> Discretisation:
    """Precompute the P2 axisymmetric operators of ``mesh`` (r, z in m; named boundaries required)."""
    basis = Basis(mesh, ElementTriP2(), intorder=intorder)
    nel = mesh.t.shape[1]
    nq = basis.dx.shape[1]
    nloc = len(basis.basis)  # 6 scalar functions
    phi = np.stack([np.asarray(basis.basis[i][0]) for i in range(nloc)])  # (6, el, qp)
    grad = np.stack([basis.basis[i][0].grad for i in range(nloc)])  # (6, 2, el, qp)
    x = np.asarray(basis.global_coordinates())  # (2, el, qp)
    r = x[0]
    B = np.zeros((nel, nq, 4, 2 * nloc))
    dr = np.moveaxis(grad[:, 0], 0, -1)  # (el, qp, 6)
    dz = np.moveaxis(grad[:, 1], 0, -1)
    ph = np.moveaxis(phi, 0, -1)
    B[:, :, 0, 0::2] = dr
    B[:, :, 1, 1::2] = dz
    B[:, :, 2, 0::2] = ph / r[:, :, None]
    B[:, :, 3, 0::2] = dz / SQRT2
    B[:, :, 3, 1::2] = dr / SQRT2
    weight = 2.0 * np.pi * r * basis.dx

    scalar_dofs = basis.element_dofs.T  # (el, 6)
    element_dofs = np.empty((nel, 2 * nloc), dtype=np.int64)
    element_dofs[:, 0::2] = 2 * scalar_dofs
    element_dofs[:, 1::2] = 2 * scalar_dofs + 1
    ndofs = 2 * basis.N

    indptr, indices, entry_index = csr_pattern(element_dofs, ndofs)

    axis_nodes = basis.get_dofs(mesh.boundaries["axis"]).flatten()
    bottom_nodes = basis.get_dofs(mesh.boundaries["bottom"]).flatten()
    surface_facets = mesh.boundaries["surface"]
    surf = basis.get_dofs(surface_facets).flatten()
    node_r, node_z = basis.doflocs
    surf = surf[np.argsort(node_r[surf])]

    surface_hats, surface_hat_mass = _surface_hats(mesh, surf)

    # the top row of quadrature points: depth below 0.2 × the element size, in elements touching the surface
    # (found by the boundary's vertices, not by z = 0: a worn surface has moved its nodes)
    on_surface = np.zeros(mesh.p.shape[1], dtype=bool)
    on_surface[mesh.facets[:, surface_facets].ravel()] = True
    touches = on_surface[mesh.t].any(axis=0)
    top = float(mesh.p[1, on_surface].max())
    e1 = mesh.p[:, mesh.t[1]] - mesh.p[:, mesh.t[0]]
    e2 = mesh.p[:, mesh.t[2]] - mesh.p[:, mesh.t[0]]
    size = np.sqrt(np.abs(e1[0] * e2[1] - e1[1] * e2[0]))
    surface_layer = touches[:, None] & (top - x[1] < 0.2 * size[:, None])

    return Discretisation(
        mesh=mesh,
        basis=basis,
        B=B,
        weight=weight,
        element_dofs=element_dofs,
        qp_r=r,
        qp_z=x[1],
        indptr=indptr,
        indices=indices,
        entry_index=entry_index,
        ndofs=ndofs,
        axis_dofs=2 * axis_nodes,
        bottom_dofs=2 * bottom_nodes + 1,
        surface_nodes=surf,
        surface_r=node_r[surf],
        surface_z=node_z[surf],
        surface_hats=surface_hats,
        surface_hat_mass=surface_hat_mass,
        node_r=node_r,
        node_z=node_z,
        surface_layer=surface_layer,
    )
