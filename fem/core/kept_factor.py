"""Linear solves on a kept factorisation: the modified-Newton linear algebra of the 3-D plate.

A Newton iteration of the 3-D plate solves K x = r with K the tangent whose constrained rows are s·I. Factorising K
(PARDISO, :mod:`fem.core.linear`) costs as much as 25–40 solves with its factor (0.55–0.7 s against 17–24 ms on the
default 3-D plate); the tangent changes little from one iteration to the next (a few plastic points, the slip
tractions), so the factor of an earlier K preconditions a Krylov method on the new one, and K is factorised again
only when the constrained DOFs changed (``key``: a new contact or stick node changes K by a rank of a few dozen,
which the old factor resolves only in as many iterations: tried with the old factor first, the default impact took
1000 more solves for 5 fewer factorisations) or when the Krylov method is slow (rare: 30 iterations instead of 15
saved 2 of 107). A new factor of a matrix of the old one's sparsity pattern (the 3-D plate keeps the tangent's
pattern whatever the constrained DOFs) reuses the old one's analysis: PARDISO's numerical factorisation only.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from fem.core.increments import WorkCounters
from fem.core.linear import Factorisation, factorise

__all__ = ["KeptFactor"]


class KeptFactor:
    """The factor of one symmetric positive-definite matrix, kept for the solves of later matrices with the same
    constrained DOFs; counts its work in ``counters``. ``max_krylov`` Krylov iterations at most before it
    refactorises."""

    #: Whether a new factor of a matrix of the kept factor's sparsity pattern reuses its analysis (PARDISO's ordering
    #: and symbolic factorisation, :meth:`fem.core.linear.Factorisation.refactor`); False: every factorisation
    #: analyses its matrix anew, as before (benchmarks/bench_solid.py's reference).
    reuse_analysis = True

    def __init__(self, counters: WorkCounters, max_krylov: int = 15) -> None:
        self.counters = counters
        self.max_krylov = max_krylov
        self._factor: Factorisation | None = None
        self._key = b""
        self._data = np.zeros(0)

    def solve(
        self,
        matrix: sp.csr_matrix,
        rhs: np.ndarray,
        tolerance: float,
        key: bytes,
        coupling: Callable[[np.ndarray], np.ndarray] | None = None,
    ) -> np.ndarray:
        """x with (matrix − coupling) x = rhs to a residual of ``tolerance`` (N): CG (GMRES with the nonsymmetric
        ``coupling``, a function of x) preconditioned with the kept factor when ``key`` (the constrained DOFs) is
        the kept one, else (or when the Krylov method is slow) on a new factor of ``matrix``. The factor of the
        very same matrix is applied directly: CG on a stiff penalty system cannot reach a tight tolerance in
        floating point."""
        kept = self._factor is not None and key == self._key
        if kept and coupling is None and self._same(matrix):
            self.counters.solves += 1
            return self._factor.solve(rhs)
        if kept:
            x, converged = self._krylov(matrix, rhs, tolerance, coupling)
            if converged or self._same(matrix):
                return x
        self._refactor(matrix, key)
        if coupling is None:
            self.counters.solves += 1
            return self._factor.solve(rhs)
        return self._krylov(matrix, rhs, tolerance, coupling)[0]

    def _krylov(self, matrix, rhs, tolerance: float, coupling) -> tuple[np.ndarray, bool]:
        count = [0]

        def apply(v: np.ndarray) -> np.ndarray:
            count[0] += 1
            return self._factor.solve(v)

        M = spla.LinearOperator(matrix.shape, matvec=apply, dtype=float)
        x0 = apply(rhs)
        if coupling is None:
            x, info = spla.cg(matrix, rhs, x0=x0, rtol=1e-12, atol=tolerance, maxiter=self.max_krylov, M=M)
        else:
            A = spla.LinearOperator(matrix.shape, matvec=lambda v: matrix @ v - coupling(v), dtype=float)
            x, info = spla.gmres(A, rhs, x0=x0, rtol=1e-12, atol=tolerance, restart=self.max_krylov, maxiter=1, M=M)
        self.counters.solves += count[0]
        return x, info == 0

    def _refactor(self, matrix: sp.csr_matrix, key: bytes) -> None:
        t0 = time.perf_counter()
        if self.reuse_analysis and self._factor is not None and self._factor.same_pattern(matrix):
            self._factor.refactor(matrix)  # the pattern's analysis kept: the numerical factorisation only
        else:
            if self._factor is not None:
                self._factor.free()
            self._factor = factorise(matrix)
            self.counters.analyses += 1
        self._key = key
        self._data = matrix.data.copy()
        self.counters.factorisations += 1
        self.counters.factor_time += time.perf_counter() - t0

    def _same(self, matrix: sp.csr_matrix) -> bool:
        # the same key means the same sparsity pattern: compare the values
        return matrix.data.shape == self._data.shape and np.array_equal(matrix.data, self._data)
