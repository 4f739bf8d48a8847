r"""The 3-D plate's linear systems on the tangent's fixed sparsity pattern (N/m).

A Newton iteration of :mod:`fem.solid.solver` factorises (or preconditions with an earlier factor) one of two
matrices built from the consistent tangent K (:func:`fem.core.assembly.tangent_stiffness`):

* the **constrained** tangent, K with the rows and columns of the constrained DOFs (the clamped ones and the contact
  nodes' u_z) zeroed and a scale s on their diagonal;
* the **stick system** K_mod + ρ CᵀC of the augmented Lagrangian of the stick rows C, and the Newton step solved
  with it (:meth:`TangentSystems.augmented_step`: the Uzawa update of the stick rows' multipliers).

Both keep every entry of the tangent's pattern, zeros included, so that every constrained tangent has one pattern
and every stick system of the same stick rows another: PARDISO analyses each pattern once
(:meth:`fem.core.linear.Factorisation.refactor`). What locates the entries (the row of each stored entry, each
row's diagonal, the union with the stick rows' entries) is found once — per mesh, per set of constrained DOFs, per
set of stick rows — not in every Newton iteration.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from fem.core.assembly import Discretised
from fem.core.kept_factor import KeptFactor

__all__ = ["TangentSystems", "union_pattern"]


def union_pattern(
    tangent_keys: np.ndarray, stick_keys: np.ndarray, n: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The CSR pattern (indptr, indices) of the n × n union of the tangent's entries and the stick rows' CᵀC
    entries, both given as row-major positions (row · n + column; ``tangent_keys`` ascending), and where each goes
    in it: (indptr, indices, the tangent's entries, the stick entries). The few stick entries outside the tangent's
    pattern (nodes of one stick vertex's dual function in no common element) are merged in, each shifting the
    tangent's entries after it by one: O(nnz), without sorting the tangent's entries."""
    where = np.searchsorted(tangent_keys, stick_keys)
    inside = tangent_keys[np.minimum(where, tangent_keys.size - 1)] == stick_keys
    extra = np.unique(stick_keys[~inside])
    before_extra = np.searchsorted(tangent_keys, extra)
    shift = np.zeros(tangent_keys.size + 1, np.int64)
    np.add.at(shift, before_extra, 1)
    tangent_entries = np.arange(tangent_keys.size) + np.cumsum(shift)[:-1]
    extra_entries = before_extra + np.arange(extra.size)
    keys = np.empty(tangent_keys.size + extra.size, np.int64)
    keys[tangent_entries] = tangent_keys
    keys[extra_entries] = extra
    indptr = np.r_[0, np.cumsum(np.bincount(keys // n, minlength=n))]
    stick_entries = np.empty(stick_keys.size, np.int64)
    stick_entries[inside] = tangent_entries[where[inside]]
    stick_entries[~inside] = extra_entries[np.searchsorted(extra, stick_keys[~inside])]
    return indptr, (keys % n).astype(np.int32), tangent_entries, stick_entries


class TangentSystems:
    """The constrained tangents and stick systems of the discretisation ``disc`` (its fixed CSR pattern: ``indptr``,
    ``indices``, ``ndofs``)."""

    def __init__(self, disc: Discretised) -> None:
        self.ndofs = disc.ndofs
        self.indices = disc.indices
        #: the row of each stored entry of the pattern, and the position of each row's diagonal entry
        self.entry_rows = np.repeat(np.arange(disc.ndofs), np.diff(disc.indptr))
        self.diagonal_entries = np.flatnonzero(self.entry_rows == disc.indices)
        self._keys = self.entry_rows * disc.ndofs + disc.indices  # row-major positions: ascending
        self._stick_pattern: tuple | None = None

    def diagonal(self, K: sp.csr_matrix) -> np.ndarray:
        """The diagonal of a matrix ``K`` of the pattern (N/m)."""
        return K.data[self.diagonal_entries]

    def constraint(self, free: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """What :meth:`constrained` needs of the DOFs ``free`` (false: constrained), found once for a set: the mask
        of the stored entries in free rows and columns, and the constrained rows' diagonal entries."""
        return free[self.entry_rows] & free[self.indices], self.diagonal_entries[~free]

    @staticmethod
    def constrained(K: sp.csr_matrix, constraint: tuple[np.ndarray, np.ndarray], scale: float) -> sp.csr_matrix:
        """``K`` with the rows and columns of the constrained DOFs (``constraint``, :meth:`constraint`) zeroed and
        ``scale`` (N/m) on their diagonal, every stored entry kept."""
        kept_entries, constrained_diagonals = constraint
        data = np.where(kept_entries, K.data, 0.0)
        data[constrained_diagonals] = scale
        return sp.csr_matrix((data, K.indices, K.indptr), shape=K.shape)

    def stick_system(self, K_mod: sp.csr_matrix, CtC: sp.coo_matrix, rho: float, key: bytes) -> sp.csr_matrix:
        """K_mod + ρ CᵀC with K_mod's stored zeros kept (a sparse "+" drops them): on the union of the tangent's
        pattern and the stick rows' (named by ``key``; :func:`union_pattern`), found once for a set of rows."""
        n = self.ndofs
        stick_keys = CtC.row.astype(np.int64) * n + CtC.col
        pattern = self._stick_pattern
        if pattern is None or pattern[0] != key or not np.array_equal(pattern[1], stick_keys):
            pattern = (key, stick_keys, *union_pattern(self._keys, stick_keys, n))
            self._stick_pattern = pattern
        _, _, indptr, indices, tangent_entries, stick_entries = pattern
        data = np.zeros(indices.size)
        data[tangent_entries] = K_mod.data
        np.add.at(data, stick_entries, rho * CtC.data)
        return sp.csr_matrix((data, indices, indptr), shape=K_mod.shape)

    def augmented_step(
        self,
        linear: KeptFactor,
        K_mod: sp.csr_matrix,
        rhs: np.ndarray,
        rows: sp.csr_matrix,
        row_ids: np.ndarray,
        defect: np.ndarray,
        multipliers: np.ndarray,
        key: bytes,
        tolerance: float,
        coupling,
    ) -> tuple[np.ndarray, np.ndarray]:
        r"""One Newton step of the stuck system [[K_mod, Cᵀ], [C, 0]] [du; λ] = [rhs; defect] as an augmented
        Lagrangian (Uzawa) update from the multipliers λ_k of the step before:

        .. math:: (K + \rho C^T C)\,du = r - C^T\lambda_k + \rho C^T d,\qquad
                  \lambda_{k+1} = \lambda_k + \rho\,(C\,du - d).

        ρ is 10⁴ × the stiffness of a DOF over the rows' own scale (the rows are scaled to unit sums, so the
        constraint error is a length): each update gains about four digits on the multipliers, so they converge
        alongside Newton, one solve a step. The solve (``linear``) is preconditioned by
        the kept factor of an earlier K + ρCᵀC with the same constrained DOFs and stick rows (the penalty part is
        then exact in the preconditioner and the Krylov method sees only the plastic points' change of tangent and
        the slip tractions' ``coupling``), within ``tolerance`` (N). A saddle-point factorisation (PARDISO's
        symmetric-indefinite mode) perturbed the multipliers' zero pivots into a residual of 1e12 here; the
        multipliers' exact Schur complement needs a solve per stick row for every new factor. ``row_ids`` name the
        rows (2·vertex + component). Returns (du, λ_{k+1})."""
        diagonal = float(np.mean(self.diagonal(K_mod)))
        CtC = (rows.T @ rows).tocsr()
        rho = 1e4 * diagonal / max(float(np.mean(CtC.diagonal()[CtC.diagonal() > 0.0])), 1e-300)
        full_key = key + row_ids.tobytes() + rows.indices.tobytes()
        augmented = self.stick_system(K_mod, CtC.tocoo(), rho, full_key)
        du = linear.solve(
            augmented, rhs - rows.T @ multipliers + rho * (rows.T @ defect), tolerance, full_key, coupling
        )
        return du, multipliers + rho * (rows @ du - defect)
