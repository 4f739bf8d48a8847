r"""3-D quadratic-tetrahedron kinematics of the plate and its surface operators.

Displacement u = (u_x, u_y, u_z) on P2 tetrahedra (scikit-fem's :class:`~skfem.ElementTetP2` basis, interleaved
numbering: global DOF 3·n + c for scalar node n and component c). Strains in Mandel notation,

.. math::
    \varepsilon = \bigl(\varepsilon_{xx}, \varepsilon_{yy}, \varepsilon_{zz},
    \sqrt2\,\varepsilon_{yz}, \sqrt2\,\varepsilon_{xz}, \sqrt2\,\varepsilon_{xy}\bigr),

so the operators ``B`` (elements, qp, 6, 30) and weights (m³) plug into the same batched assembly as the
axisymmetric plate's (:mod:`fem.core.assembly`). Four quadrature points per element integrate the stiffness of a
straight P2 tetrahedron exactly.

The surface z = 0 carries the contact. Its quadratic nodes take the contact constraints; the tractions (pressure,
shear) are fields linear between the surface vertices, as on the axisymmetric plate (:mod:`fem.core.sphere`):
the vertex hats ψ_j (values ψ_j(x_i) at the surface nodes: 1 at the vertex, ½ at the mid-edge nodes of its edges),
their mass M_jk = ∫ ψ_j ψ_k dA, and the consistent loads G_ik = ∫ φ_i ψ_k dA of a linear traction on the quadratic
nodes (on a triangle of area A: A/30 and −A/60 at the vertices, 2A/15 and A/15 at the mid-edge nodes, for the own
and the opposite hat; Σ_i G_ik = ∫ ψ_k), and those of the hats' dual functions, G̃_ik = ∫ φ_i φ̃_k dA with
φ̃_k = 4ψ_k − 1 on each triangle of the vertex (Wohlmuth 2000: ∫ φ̃_k ψ_j = δ_kj ∫ ψ_j, so the hat moments of G̃'s
loads are the vertex's own only, Σ_i ψ_j(x_i) G̃_ik = δ_jk ∫ ψ_k; 2A/15 and −A/15 at the vertices, A/5 and −A/15 at
the mid-edge nodes).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from skfem import Basis, ElementTetP2, MeshTet

from fem.core.assembly import csr_pattern

__all__ = ["SolidDiscretisation", "discretise_solid"]

SQRT2 = math.sqrt(2.0)
#: Mandel components (row of B) and the two displacement components each shear strain couples.
_SHEARS = ((3, 1, 2), (4, 0, 2), (5, 0, 1))


@dataclass(frozen=True, eq=False)
class SolidDiscretisation:
    """The 3-D plate's operators, precomputed once.

    ``B`` (elements, qp, 6, 30) strain operators, ``weight`` (elements, qp) = w det J (m³), ``element_dofs``
    (elements, 30), ``qp`` (3, elements, qp) quadrature coordinates (m), CSR pattern (``indptr``, ``indices``,
    ``entry_index``), ``fixed_dofs`` (the clamped bottom and u_y on the symmetry plane), ``nodes`` (3, scalar nodes)
    node coordinates (m), ``surface_nodes`` the scalar nodes on z = 0, ``surface_vertex_nodes`` the surface
    vertices' scalar nodes, ``surface_hats`` (surface vertices × surface nodes) ψ_j(x_i), ``surface_hat_mass``
    (surface vertices²) M (m²), ``surface_loads`` (surface nodes × surface vertices) G (m²), ``surface_dual_loads``
    G̃ (m², the dual functions'), ``surface_area``
    (surface vertices) each hat's integral ∫ ψ_j dA over the half plate (m²), ``surface_triangles`` (triangles, 3)
    the surface triangles as rows of the surface vertices, ``surface_node_triangles`` (4 × triangles, 3) each split
    at its mid-edge nodes into four, as rows of the surface nodes.
    """

    mesh: MeshTet
    basis: Basis
    B: np.ndarray
    weight: np.ndarray
    element_dofs: np.ndarray
    qp: np.ndarray
    indptr: np.ndarray
    indices: np.ndarray
    entry_index: np.ndarray
    ndofs: int
    fixed_dofs: np.ndarray
    nodes: np.ndarray
    surface_nodes: np.ndarray
    surface_vertex_nodes: np.ndarray
    surface_hats: sp.csr_matrix
    surface_hat_mass: sp.csc_matrix
    surface_loads: sp.csr_matrix
    surface_dual_loads: sp.csr_matrix
    surface_area: np.ndarray
    surface_triangles: np.ndarray
    surface_node_triangles: np.ndarray

    def matrix(self, data: np.ndarray) -> sp.csr_matrix:
        """CSR matrix with the fixed pattern and the given ``data``."""
        return sp.csr_matrix((data, self.indices, self.indptr), shape=(self.ndofs, self.ndofs))

    @property
    def surface_xy(self) -> np.ndarray:
        """(surface nodes, 2) reference x, y of the surface nodes (m)."""
        return self.nodes[:2, self.surface_nodes].T

    def surface_dofs(self, component: int) -> np.ndarray:
        """Global DOFs of ``component`` (0 x, 1 y, 2 z) at the surface nodes."""
        return 3 * self.surface_nodes + component


def _strain_operator(basis: Basis) -> np.ndarray:
    nloc = len(basis.basis)
    grad = np.stack([np.asarray(basis.basis[i][0].grad) for i in range(nloc)])  # (10, 3, el, qp)
    grad = np.moveaxis(grad, 0, -1)  # (3, el, qp, 10)
    nel, nq = grad.shape[1:3]
    B = np.zeros((nel, nq, 6, 3 * nloc))
    for c in range(3):
        B[:, :, c, c::3] = grad[c]
    for row, i, j in _SHEARS:
        B[:, :, row, i::3] = grad[j] / SQRT2
        B[:, :, row, j::3] = grad[i] / SQRT2
    return B


def _surface_operators(mesh: MeshTet, basis: Basis, surface_nodes: np.ndarray):
    """Hats, hat mass and consistent loads of the surface triangles (see the module docstring), and the triangles
    as rows of the surface vertices and split into four as rows of the surface nodes."""
    nvert = mesh.p.shape[1]
    vertex_nodes = surface_nodes[surface_nodes < nvert]
    vertex_row = np.full(basis.N, -1, dtype=np.int64)
    vertex_row[vertex_nodes] = np.arange(vertex_nodes.size)
    node_row = np.full(basis.N, -1, dtype=np.int64)
    node_row[surface_nodes] = np.arange(surface_nodes.size)
    edge_of = {tuple(e): nvert + k for k, e in enumerate(np.sort(mesh.edges, axis=0).T.tolist())}
    triangles = np.sort(mesh.facets[:, mesh.boundaries["surface"]], axis=0)  # (3, triangles)
    p = mesh.p[:, triangles]
    area = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0], axis=0), axis=0)
    mass_rows, mass_cols, mass_values = [], [], []
    load_rows, load_cols, load_values, dual_values = [], [], [], []
    hat_entries = {(vertex_row[v], node_row[v]): 1.0 for v in vertex_nodes}
    for k in range(3):
        for m in range(3):
            mass_rows.append(vertex_row[triangles[k]])
            mass_cols.append(vertex_row[triangles[m]])
            mass_values.append(area * (2.0 if k == m else 1.0) / 12.0)
            load_rows.append(node_row[triangles[k]])
            load_cols.append(vertex_row[triangles[m]])
            load_values.append(area * (1.0 / 30.0 if k == m else -1.0 / 60.0))
            dual_values.append(area * (2.0 / 15.0 if k == m else -1.0 / 15.0))
    sides = ((0, 1), (1, 2), (0, 2))
    mid_nodes = [
        np.array([edge_of[(int(x), int(y))] for x, y in zip(triangles[a], triangles[b], strict=True)]) for a, b in sides
    ]
    for (a, b), edge_nodes in zip(sides, mid_nodes, strict=True):
        for m in range(3):
            load_rows.append(node_row[edge_nodes])
            load_cols.append(vertex_row[triangles[m]])
            load_values.append(area * (2.0 / 15.0 if m in (a, b) else 1.0 / 15.0))
            dual_values.append(area * (1.0 / 5.0 if m in (a, b) else -1.0 / 15.0))
        for end in (a, b):
            for node, vertex in zip(edge_nodes, triangles[end], strict=True):
                hat_entries[(vertex_row[vertex], node_row[node])] = 0.5
    # each triangle split at its mid-edge nodes (of the sides 0-1, 1-2, 0-2) into four, as rows of the surface nodes
    mids = [node_row[m] for m in mid_nodes]
    corners = [node_row[t] for t in triangles]
    quarters = [(corners[0], mids[0], mids[2]), (corners[1], mids[1], mids[0]), (corners[2], mids[2], mids[1])]
    node_triangles = np.vstack([np.column_stack(q) for q in (*quarters, tuple(mids))])
    nv, ns = vertex_nodes.size, surface_nodes.size
    if np.any(np.concatenate(load_rows) < 0) or np.any(np.concatenate(mass_rows) < 0):
        raise ValueError("mesh: a surface triangle has a node off the surface z = 0")
    mass = sp.csc_matrix(
        (np.concatenate(mass_values), (np.concatenate(mass_rows), np.concatenate(mass_cols))), shape=(nv, nv)
    )
    loads = sp.csr_matrix(
        (np.concatenate(load_values), (np.concatenate(load_rows), np.concatenate(load_cols))), shape=(ns, nv)
    )
    dual_loads = sp.csr_matrix(
        (np.concatenate(dual_values), (np.concatenate(load_rows), np.concatenate(load_cols))), shape=(ns, nv)
    )
    (rows, cols), values = zip(*hat_entries.keys(), strict=True), list(hat_entries.values())
    hats = sp.csr_matrix((values, (rows, cols)), shape=(nv, ns))
    return vertex_nodes, hats, mass, loads, dual_loads, vertex_row[triangles].T, node_triangles


def discretise_solid(mesh: MeshTet) -> SolidDiscretisation:
    """Precompute the P2 operators of the half block ``mesh`` (m; boundaries ``surface``, ``bottom``,
    ``symmetry`` named, as :func:`fem.solid.mesh.generate_block` makes them)."""
    missing = [b for b in ("surface", "bottom", "symmetry") if mesh.boundaries is None or b not in mesh.boundaries]
    if missing:
        raise ValueError(
            f"mesh has no boundary named {', '.join(repr(m) for m in missing)}: a 3-D plate mesh names its "
            "boundaries 'surface' (z = 0), 'bottom' (z = -L) and 'symmetry' (y = 0) (m)"
        )
    basis = Basis(mesh, ElementTetP2(), intorder=2)
    scalar_dofs = basis.element_dofs.T  # (el, 10)
    nel, nloc = scalar_dofs.shape
    element_dofs = (3 * scalar_dofs[:, :, None] + np.arange(3)).reshape(nel, 3 * nloc)
    ndofs = 3 * basis.N
    indptr, indices, entry_index = csr_pattern(element_dofs, ndofs)
    nodes = np.asarray(basis.doflocs)
    bottom = basis.get_dofs(mesh.boundaries["bottom"]).flatten()
    symmetry = basis.get_dofs(mesh.boundaries["symmetry"]).flatten()
    fixed = np.unique(np.concatenate([3 * bottom, 3 * bottom + 1, 3 * bottom + 2, 3 * symmetry + 1]))
    surface_nodes = np.unique(basis.get_dofs(mesh.boundaries["surface"]).flatten())
    vertex_nodes, hats, mass, loads, dual_loads, triangles, node_triangles = _surface_operators(
        mesh, basis, surface_nodes
    )
    return SolidDiscretisation(
        mesh=mesh,
        basis=basis,
        B=_strain_operator(basis),
        weight=np.asarray(basis.dx),
        element_dofs=element_dofs,
        qp=np.asarray(basis.global_coordinates()),
        indptr=indptr,
        indices=indices,
        entry_index=entry_index,
        ndofs=ndofs,
        fixed_dofs=fixed,
        nodes=nodes,
        surface_nodes=surface_nodes,
        surface_vertex_nodes=vertex_nodes,
        surface_hats=hats,
        surface_hat_mass=mass,
        surface_loads=loads,
        surface_dual_loads=dual_loads,
        surface_area=np.asarray(mass.sum(axis=0)).ravel(),
        surface_triangles=triangles,
        surface_node_triangles=node_triangles,
    )
