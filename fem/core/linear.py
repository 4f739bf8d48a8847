"""Sparse direct solves of the symmetric positive-definite systems of the 3-D plate.

MKL PARDISO (through pypardiso) in its SPD mode factorises the upper triangle: on 2 cores it is the fastest of the
direct solvers measured here at 30k–300k unknowns (3 s at 33k, 7–12 s at 118k, 62 s and 4 GB at 286k: about 7×
faster than SuperLU at 33k) and installs from wheels. Where its wheels do not exist (MKL is x86-64 only), SciPy's
SuperLU with a symmetric ordering is the fallback: correct, several times slower. A factorisation is kept and
re-used for many right-hand sides (the modified-Newton iterations and the preconditioned CG of
:mod:`fem.solid.solver`).
"""

from __future__ import annotations

import os

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

try:
    import pypardiso
except ImportError:  # pragma: no cover - platforms without MKL wheels
    pypardiso = None

__all__ = ["BACKEND", "Factorisation", "SingularMatrixError", "factorise"]

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


class SingularMatrixError(np.linalg.LinAlgError):
    """The matrix is not positive definite (a zero or negative pivot)."""


class Factorisation:
    """The factor of a symmetric positive-(semi)definite ``matrix`` (CSR); :meth:`solve` applies its inverse."""

    def __init__(self, matrix: sp.csr_matrix) -> None:
        self.shape = matrix.shape
        if pypardiso is not None:
            self._upper = sp.triu(matrix, format="csr")
            self._upper.sort_indices()
            # SPD first; a consistent tangent of a perfectly plastic zone can be singular to working precision
            # (zero pivot, PARDISO error -4): the symmetric-indefinite mode with pivot perturbation takes it
            for mtype in (2, -2):
                self._pardiso = _pardiso_solver(mtype)
                try:
                    self._pardiso.factorize(self._upper)
                    break
                except pypardiso.pardiso_wrapper.PyPardisoError as exc:
                    self._pardiso.free_memory(everything=True)
                    error = exc
            else:
                raise SingularMatrixError(f"PARDISO could not factorise the matrix: {error}") from None
        else:  # pragma: no cover
            try:
                self._lu = spla.splu(
                    matrix.tocsc(), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True}
                )
            except RuntimeError as exc:
                raise SingularMatrixError(f"SuperLU could not factorise the matrix: {exc}") from None

    def solve(self, rhs: np.ndarray) -> np.ndarray:
        """x = A⁻¹ rhs (rhs: one vector or columns)."""
        if pypardiso is not None:
            return self._pardiso.solve(self._upper, np.ascontiguousarray(rhs, dtype=float))
        return self._lu.solve(np.asarray(rhs, dtype=float))  # pragma: no cover

    def free(self) -> None:
        """Release the factor's memory (PARDISO keeps it outside Python's reach until told)."""
        if pypardiso is not None:
            self._pardiso.free_memory(everything=True)


def factorise(matrix: sp.csr_matrix) -> Factorisation:
    """Factorise the SPD ``matrix`` (CSR)."""
    return Factorisation(matrix)
