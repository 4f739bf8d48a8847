"""The sparse direct solves of the 3-D plate (fem.core.linear, fem.core.kept_factor, and the stick system's pattern of
fem.solid.systems): a factor solves its system, a refactorisation of a matrix of the same sparsity pattern (PARDISO's
analysis reused) solves the new one to the same round-off as a fresh factor, a singular SPD matrix falls back to the
indefinite mode, the kept factor analyses a pattern once, the stick system on its union pattern sums as SciPy does,
and OpenBLAS runs on one thread beside PARDISO (threadpoolctl's own count). Reference: the residual ‖A x − b‖ of each
solve, a dense solve (numpy), SciPy's sparse sum."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
from threadpoolctl import threadpool_info

from fem.core.increments import WorkCounters
from fem.core.kept_factor import KeptFactor
from fem.core.linear import BACKEND, factorise, pardiso_threads
from fem.solid.systems import union_pattern


def _laplacian(n: int, shift: float = 1.0) -> sp.csr_matrix:
    """The 2-D five-point Laplacian on an n × n grid plus ``shift`` on the diagonal (SPD for shift > 0)."""
    one = sp.diags([-1.0, 2.0, -1.0], [-1, 0, 1], shape=(n, n))
    return (sp.kron(one, sp.eye(n)) + sp.kron(sp.eye(n), one) + shift * sp.eye(n * n)).tocsr()


def test_a_refactorisation_solves_the_new_matrix_as_a_fresh_factor_does():
    rng = np.random.default_rng(3)
    a = _laplacian(20)
    b = rng.normal(size=a.shape[0])
    factor = factorise(a)
    assert np.linalg.norm(a @ factor.solve(b) - b) < 1e-12 * np.linalg.norm(b)
    changed = a.copy()
    changed.data *= rng.uniform(0.5, 2.0, size=changed.data.size)
    changed = ((changed + changed.T) * 0.5 + 10.0 * sp.eye(a.shape[0])).tocsr()
    if BACKEND != "pardiso":
        pytest.skip("the analysis is PARDISO's")
    assert factor.same_pattern(changed)
    factor.refactor(changed)
    x = factor.solve(b)
    assert factor.analyses == 1
    assert np.allclose(x, np.linalg.solve(changed.toarray(), b), rtol=1e-12, atol=1e-14)
    columns = np.column_stack([b, 2.0 * b])
    assert np.allclose(factor.solve(columns), np.column_stack([x, 2.0 * x]), rtol=1e-12, atol=1e-14)
    assert not factor.same_pattern(_laplacian(21))


def test_a_singular_matrix_is_factorised_in_the_indefinite_mode():
    """The pure Neumann Laplacian (shift 0, zero row sums) is singular; a compatible right-hand side (zero mean) has
    solutions, and the fallback's is one of them."""
    if BACKEND != "pardiso":
        pytest.skip("the fallback is PARDISO's")
    a = _laplacian(10, shift=0.0)
    a = (a - sp.diags(np.asarray(a.sum(axis=1)).ravel())).tocsr()  # zero row sums: singular
    b = np.random.default_rng(4).normal(size=a.shape[0])
    b -= b.mean()
    x = factorise(a).solve(b)
    assert np.linalg.norm(a @ x - b) < 1e-8 * np.linalg.norm(b)


def test_the_kept_factor_analyses_a_pattern_once():
    counters = WorkCounters()
    kept = KeptFactor(counters)
    a = _laplacian(15)
    b = np.ones(a.shape[0])
    for k, key in enumerate((b"one", b"two", b"three")):  # a new key: a new factor, of the same pattern
        m = (a + (1.0 + k) * sp.eye(a.shape[0])).tocsr()
        x = kept.solve(m, b, 1e-12, key)
        assert np.linalg.norm(m @ x - b) < 1e-10
    assert counters.factorisations == 3
    assert counters.analyses == (1 if BACKEND == "pardiso" else 3)


def test_the_augmented_pattern_sums_as_scipy_does():
    """The stick system K + ρCᵀC on the union of the two patterns (fem.solid.systems.union_pattern, found once per
    set of stick rows) against SciPy's sparse sum, on random patterns with entries in and out of K's and a stick
    entry past K's last one."""
    n = 60
    for seed in range(10):
        K = (sp.random(n, n, density=0.1, random_state=seed, format="csr") + sp.eye(n)).tocsr()
        K.sort_indices()
        C = sp.random(n, n, density=0.05, random_state=seed + 100).tocoo()
        C = sp.coo_matrix((np.r_[C.data, 1.0], (np.r_[C.row, n - 1], np.r_[C.col, n - 1])), shape=(n, n))
        rows = np.repeat(np.arange(n), np.diff(K.indptr))
        indptr, indices, tangent, stick = union_pattern(rows * n + K.indices, C.row.astype(np.int64) * n + C.col, n)
        data = np.zeros(indices.size)
        data[tangent] = K.data
        np.add.at(data, stick, 2.0 * C.data)
        union = sp.csr_matrix((data, indices, indptr), shape=(n, n))
        assert union.has_sorted_indices
        assert union.nnz == (abs(K) + abs(C)).nnz
        assert abs(union - (K + 2.0 * C)).max() == 0.0


def test_openblas_runs_on_one_thread_beside_pardiso_and_gets_its_threads_back():
    # pardiso_threads leaves PARDISO's cores to it between the Krylov method's vector operations; a user's numpy
    # gets its threads back after the 3-D plate's increment
    def openblas_threads() -> list[int]:
        return [lib["num_threads"] for lib in threadpool_info() if lib["internal_api"] == "openblas"]

    before = openblas_threads()
    with pardiso_threads():
        inside = openblas_threads()
    assert inside and all(n == 1 for n in inside)
    assert openblas_threads() == before
