"""Sparse direct solves of the symmetric positive-definite systems of the 3-D plate.

MKL PARDISO (through pypardiso) in its SPD mode factorises the upper triangle: on 2 cores it is the fastest of the
direct solvers measured here at 30k–300k unknowns (3 s at 33k, 7–12 s at 118k, 62 s and 4 GB at 286k: about 7×
faster than SuperLU at 33k) and installs from wheels. Where its wheels do not exist (MKL is x86-64 only), SciPy's
SuperLU with a symmetric ordering is the fallback: correct, several times slower. A factorisation is kept and
re-used for many right-hand sides (the modified-Newton iterations and the preconditioned CG of
:mod:`fem.solid.solver`).

PARDISO's OpenMP threads and the OpenBLAS threads of numpy and SciPy (the Krylov method's dot products between two
solves) take turns at the same cores, and each pool spins a while after its work before it sleeps: on 2 cores a
solve followed by a dot product of 42,000 numbers took 25 ms where the solve alone takes 14. Within
:func:`pardiso_threads` OpenBLAS runs on one thread and PARDISO has the cores (the default 3-D impact 161 → 121 s,
benchmarks/bench_solid.py).
"""

from __future__ import annotations

import os
from contextlib import AbstractContextManager, nullcontext
from functools import cache

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from threadpoolctl import ThreadpoolController

try:
    import pypardiso
except ImportError:  # pragma: no cover - platforms without MKL wheels
    pypardiso = None

__all__ = ["BACKEND", "Factorisation", "SingularMatrixError", "factorise", "pardiso_threads"]

#: The direct solver in use: "pardiso" or "superlu".
BACKEND = "pardiso" if pypardiso is not None else "superlu"


def _pardiso_solver(mtype: int) -> pypardiso.PyPardisoSolver:
    """A PARDISO handle of matrix type ``mtype``. pypardiso looks for MKL's library on every handle (ctypes'
    find_library, then a recursive glob of the environment: 0.7–1.0 s here, as long as a factorisation of the
    default 3-D plate); once found, its path goes into pypardiso's own ``PYPARDISO_MKL_RT`` setting so that later
    handles load it directly."""
    solver = pypardiso.PyPardisoSolver(mtype=mtype)
    os.environ.setdefault("PYPARDISO_MKL_RT", solver.libmkl._name)
    return solver


#: OpenBLAS's thread count within :func:`pardiso_threads`; None: left as it is (before; benchmarks/bench_solid.py's
#: reference).
OPENBLAS_THREADS_BESIDE_PARDISO: int | None = 1


@cache
def _openblas() -> ThreadpoolController:
    """The OpenBLAS libraries loaded (numpy's and SciPy's: both are, once this module's imports ran)."""
    return ThreadpoolController().select(internal_api="openblas")


def pardiso_threads() -> AbstractContextManager:
    """A context (``with pardiso_threads(): ...``) in which OpenBLAS runs on :data:`OPENBLAS_THREADS_BESIDE_PARDISO`
    threads (one), so that PARDISO's threads have the cores between the vector operations of a Krylov method (module
    docstring); OpenBLAS's thread count is restored after it."""
    if OPENBLAS_THREADS_BESIDE_PARDISO is None:
        return nullcontext()
    return _openblas().limit(limits=OPENBLAS_THREADS_BESIDE_PARDISO)


class SingularMatrixError(np.linalg.LinAlgError):
    """The matrix is not positive definite (a zero or negative pivot)."""


class Factorisation:
    """The factor of a symmetric positive-(semi)definite ``matrix`` (CSR); :meth:`solve` applies its inverse,
    :meth:`refactor` factorises another matrix of the same sparsity pattern.

    PARDISO's three phases are called one by one: the analysis (11: the fill-reducing ordering and the symbolic
    factorisation, a quarter of a factorisation's time on the 3-D plate), the numerical factorisation (22) and the
    solve (33). A matrix of the pattern already analysed is factorised by phase 22 alone (:meth:`refactor`): the
    ordering depends on the pattern only.

    A solve is one forward and backward substitution: MKL's defaults add two steps of iterative refinement to every
    solve (``iparm[7]`` = 2: three substitutions and two products with the matrix, 37–66 ms against 16–18 ms on the
    default 3-D plate), which the Krylov method the factor preconditions does anyway (:mod:`fem.core.kept_factor`);
    refinement is then left to the indefinite mode, whose perturbed pivots MKL refines (``iparm[7]`` = 0)."""

    #: MKL PARDISO's ``iparm[7]``: the iterative refinement steps of a solve; 0: only after perturbed pivots (the
    #: indefinite fallback), 2: MKL's default, two on every solve (before; benchmarks/bench_solid.py's reference).
    refinement_steps = 0

    def __init__(self, matrix: sp.csr_matrix) -> None:
        self.shape = matrix.shape
        self.analyses = 0
        if pypardiso is not None:
            self._pattern, self._upper_entries, self._upper = _upper(matrix)
            self._pardiso = None
            self._mtype = 2
            self._factorise_pardiso(analyse=True)
        else:  # pragma: no cover
            try:
                self._lu = spla.splu(
                    matrix.tocsc(), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True}
                )
            except RuntimeError as exc:
                raise SingularMatrixError(f"SuperLU could not factorise the matrix: {exc}") from None

    def _factorise_pardiso(self, analyse: bool) -> None:
        """Phases 11 (if ``analyse``) and 22 on ``self._upper``: SPD first; a consistent tangent of a perfectly
        plastic zone can be singular to working precision (zero pivot, PARDISO error -4): the symmetric-indefinite
        mode with pivot perturbation takes it (analysed anew)."""
        rhs = np.zeros((self.shape[0], 1))
        error = None
        for mtype in (self._mtype, -2) if self._mtype == 2 else (-2,):
            if analyse or self._pardiso is None or mtype != self._mtype:
                if self._pardiso is not None:
                    self._pardiso.free_memory(everything=True)
                self._pardiso = _pardiso_solver(mtype)
                self._mtype = mtype
                phases = (11, 22)
            else:
                phases = (22,)
            try:
                for phase in phases:
                    self._pardiso.set_phase(phase)
                    self._pardiso._call_pardiso(self._upper, rhs)
                    if phase == 11:
                        # the analysis filled in MKL's defaults (iparm[0] = 1 from now on): the solves' refinement
                        self._pardiso.iparm[7] = self.refinement_steps
                self.analyses += int(11 in phases)
                return
            except pypardiso.pardiso_wrapper.PyPardisoError as exc:
                error = exc
                analyse = True
        self._pardiso.free_memory(everything=True)
        self._pardiso = None
        raise SingularMatrixError(f"PARDISO could not factorise the matrix: {error}") from None

    def same_pattern(self, matrix: sp.csr_matrix) -> bool:
        """Whether ``matrix``'s upper triangle has this factor's sparsity pattern (PARDISO only)."""
        if pypardiso is None or self._pardiso is None:
            return False
        indptr, indices = self._pattern
        return np.array_equal(matrix.indptr, indptr) and np.array_equal(matrix.indices, indices)

    def refactor(self, matrix: sp.csr_matrix) -> None:
        """Factorise ``matrix``, of this factor's pattern (:meth:`same_pattern`), reusing the analysis."""
        self._upper = sp.csr_matrix((matrix.data[self._upper_entries], self._upper.indices, self._upper.indptr))
        self._factorise_pardiso(analyse=False)

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        """x = A⁻¹ rhs (rhs: one vector or columns)."""
        if pypardiso is not None:
            self._pardiso.set_phase(33)
            return self._pardiso._call_pardiso(self._upper, np.asfortranarray(rhs, dtype=float))
        return self._lu.solve(np.asarray(rhs, dtype=float))  # pragma: no cover

    def free(self) -> None:
        """Release the factor's memory (PARDISO keeps it outside Python's reach until told)."""
        if pypardiso is not None and self._pardiso is not None:
            self._pardiso.free_memory(everything=True)


def _upper(matrix: sp.csr_matrix) -> tuple[tuple[np.ndarray, np.ndarray], np.ndarray, sp.csr_matrix]:
    """The upper triangle of ``matrix`` (CSR, sorted indices), as PARDISO's symmetric modes read it, and what a
    matrix of the same pattern needs to be cut the same way without sorting: ``matrix``'s pattern (indptr, indices)
    and the positions in its ``data`` of the upper triangle's entries, in order."""
    if not matrix.has_sorted_indices:
        matrix = matrix.sorted_indices()
    rows = np.repeat(np.arange(matrix.shape[0]), np.diff(matrix.indptr))
    entries = np.flatnonzero(matrix.indices >= rows)
    indptr = np.r_[0, np.cumsum(np.bincount(rows[entries], minlength=matrix.shape[0]))]
    upper = sp.csr_matrix((matrix.data[entries], matrix.indices[entries], indptr), shape=matrix.shape)
    return (matrix.indptr.copy(), matrix.indices.copy()), entries, upper


def factorise(matrix: sp.csr_matrix) -> Factorisation:
    """Factorise the SPD ``matrix`` (CSR)."""
    return Factorisation(matrix)
