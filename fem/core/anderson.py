r"""Anderson acceleration of a fixed-point iteration (type II, Walker & Ni 2011), for the 3-D plate's
initial-stiffness iteration u ← u + K_e⁻¹ r(u) (:mod:`fem.solid.solver`; displacements in m)."""

from __future__ import annotations

import numpy as np

__all__ = ["anderson_step"]


def anderson_step(
    history: list[tuple[np.ndarray, np.ndarray]], u: np.ndarray, du: np.ndarray, depth: int = 6
) -> np.ndarray:
    r"""The next iterate after ``u`` with the plain step ``du``, mixed over the last ``depth`` iterates kept in
    ``history`` (appended to here; pairs of u and du): with their differences ΔU, ΔG of u and of du,

    .. math:: \gamma = \arg\min \lVert du - \Delta G\,\gamma \rVert,\qquad
              u \leftarrow u + du - (\Delta U + \Delta G)\,\gamma .

    The plain iteration converges linearly, at the rate of the plastic zone's softening (tens of iterations when a
    dent unloads with reverse yield); the mixing recovers a Krylov-like rate from the same solves. On a linear map
    it reaches the solution in n + 1 steps, as GMRES does:

    >>> A = np.array([[1.5, 0.2], [0.1, 0.7]]); b = np.array([1.0, 2.0])
    >>> history, u = [], np.zeros(2)
    >>> for _ in range(3):
    ...     u = anderson_step(history, u, b - A @ u)
    >>> bool(np.allclose(u, np.linalg.solve(A, b)))
    True
    """
    history.append((u, du))
    del history[: -(depth + 1)]
    if len(history) < 2:
        return u + du
    dU = np.stack([b[0] - a[0] for a, b in zip(history[:-1], history[1:], strict=True)], axis=1)
    dG = np.stack([b[1] - a[1] for a, b in zip(history[:-1], history[1:], strict=True)], axis=1)
    gamma = np.linalg.lstsq(dG, du, rcond=None)[0]
    return u + du - (dU + dG) @ gamma
