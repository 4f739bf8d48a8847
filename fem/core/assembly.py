r"""Batched assembly on a fixed CSR pattern, for any discretisation that carries its strain operators.

A discretisation (the axisymmetric plate's :class:`fem.axisymmetric.forms.Discretisation`, the 3-D plate's
:class:`fem.solid.forms.SolidDiscretisation`) provides ``B`` (elements, qp, c, k): the Mandel strain operators
at the quadrature points (c = 4 axisymmetric, 6 in 3-D; k element DOFs), ``weight`` (elements, qp): the
integration weights (m³), ``element_dofs`` (elements, k), ``ndofs``, and the fixed CSR pattern (``indices``,
``indptr``, ``entry_index`` from :func:`csr_pattern`, ``matrix(data)``). Then

.. math:: K = \sum_e \sum_q B_q^T D_q B_q \, w_q, \qquad f_{int} = \sum_e \sum_q B_q^T \sigma_q \, w_q .

The element matrices are formed with numpy batched products and summed into the fixed pattern (computed once) with
:func:`numpy.bincount`; scikit-fem's generic form assembly would re-evaluate the basis at every Newton iteration.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np
import scipy.sparse as sp

__all__ = [
    "Discretised",
    "assemble",
    "csr_pattern",
    "element_matrices",
    "internal_force",
    "strain",
    "tangent_stiffness",
]


class Discretised(Protocol):
    """What the assembly needs of a discretisation (see the module docstring)."""

    B: np.ndarray
    weight: np.ndarray
    element_dofs: np.ndarray
    entry_index: np.ndarray
    indices: np.ndarray
    ndofs: int

    def matrix(self, data: np.ndarray) -> sp.csr_matrix: ...


def csr_pattern(element_dofs: np.ndarray, ndofs: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The fixed CSR pattern (``indptr``, ``indices``) of the global matrix of elements with DOFs ``element_dofs``
    (elements, n), and ``entry_index`` mapping each element entry (elements · n · n, row-major) to it."""
    n = element_dofs.shape[1]
    rows = np.repeat(element_dofs[:, :, None], n, axis=2).ravel()
    cols = np.repeat(element_dofs[:, None, :], n, axis=1).ravel()
    unique, entry_index = np.unique(rows * ndofs + cols, return_inverse=True)
    indices = (unique % ndofs).astype(np.int32)
    indptr = np.zeros(ndofs + 1, dtype=np.int64)
    np.add.at(indptr, unique // ndofs + 1, 1)
    return np.cumsum(indptr), indices, entry_index


def strain(disc: Discretised, u: np.ndarray) -> np.ndarray:
    """Mandel strain (elements, qp, c) of the displacement ``u`` (m); c = 4 here, 6 for :mod:`fem.solid.forms`, whose
    discretisation carries the same operators (``B``, ``weight``, ``element_dofs``, the CSR pattern)."""
    ue = u[disc.element_dofs]  # (elements, k)
    return np.einsum("eqij,ej->eqi", disc.B, ue, optimize=True)


def internal_force(disc: Discretised, stress: np.ndarray) -> np.ndarray:
    """f_int (N) of the Mandel ``stress`` (elements, qp, c) in Pa."""
    fe = np.einsum("eqij,eqi,eq->ej", disc.B, stress, disc.weight, optimize=True)
    return np.bincount(disc.element_dofs.ravel(), weights=fe.ravel(), minlength=disc.ndofs)


def element_matrices(disc: Discretised, tangent: np.ndarray, elements: np.ndarray | None = None) -> np.ndarray:
    """Element stiffness matrices (n, k, k) in N/m (k element DOFs) for the c × c ``tangent`` per
    (element, qp).

    ``tangent`` is (n, qp, c, c) for the n elements selected by ``elements`` (all if None), or
    (c, c) for a uniform elastic tangent.
    """
    B = disc.B if elements is None else disc.B[elements]
    w = disc.weight if elements is None else disc.weight[elements]
    DB = np.matmul(tangent, B)
    BT = np.swapaxes(B, 2, 3) * w[:, :, None, None]
    return np.matmul(BT, DB).sum(axis=1)


def assemble(disc: Discretised, element_data: np.ndarray) -> sp.csr_matrix:
    """Sum element matrices (elements, k, k) into the fixed CSR pattern."""
    data = np.bincount(disc.entry_index, weights=element_data.ravel(), minlength=disc.indices.size)
    return disc.matrix(data)


def tangent_stiffness(
    disc: Discretised, elastic: sp.csr_matrix, elastic_element_matrices: np.ndarray, elastic_tangent: np.ndarray, upd
) -> sp.csr_matrix:
    """The consistent tangent (N/m) of the stress update ``upd`` (:class:`fem.core.plasticity.StressUpdate`): the
    ``elastic`` stiffness (assembled from ``elastic_element_matrices``, the Mandel ``elastic_tangent`` in Pa) with
    the change of the elements that have a yielding point, their points' consistent tangents in place of the
    elastic one; summed into the fixed pattern on those elements only (a new matrix)."""
    if not upd.yielding.any():
        return disc.matrix(elastic.data.copy())
    elements = np.flatnonzero(upd.yielding.any(axis=1))
    components = elastic_tangent.shape[0]
    D = np.broadcast_to(elastic_tangent, (elements.size, disc.weight.shape[1], components, components)).copy()
    D[upd.yielding[elements]] = upd.tangent
    change = element_matrices(disc, D, elements) - elastic_element_matrices[elements]
    entries = disc.entry_index.reshape(disc.element_dofs.shape[0], -1)[elements].ravel()
    return disc.matrix(elastic.data + np.bincount(entries, change.ravel(), elastic.data.size))
