"""The backtracking of a Newton step of the 3-D plate (:mod:`fem.solid.solver`).

With a perfectly plastic surface layer under a follower slip traction the consistent tangent can overshoot into a
spreading plastic mechanism (the yielding points grow tenfold and the residual by 10⁷ within ten full steps) where a
fraction of the step converges: the step is halved until the out-of-balance norm falls (Armijo). A function of its
own: it needs of the solver only the state at a displacement (``balance``), not its sets or its linear systems.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

__all__ = ["backtrack"]


def backtrack(
    balance: Callable[[np.ndarray, np.ndarray], tuple],
    free: np.ndarray,
    u: np.ndarray,
    step: np.ndarray,
    du: np.ndarray,
    multipliers: np.ndarray,
    new_multipliers: np.ndarray,
    residual: float,
) -> tuple[np.ndarray, np.ndarray, tuple, bool] | None:
    """Backtrack the Newton step ``du`` (m) from ``u`` (m), Armijo on the out-of-balance norm over the ``free`` DOFs.

    ``balance(u, λ)`` is the solver's state at a displacement and stick multipliers, its item 4 the out-of-balance
    force (N). The contact's gap closure ``step`` (m, on the constrained DOFs) is taken whole and the fraction
    applies to the rest of ``du`` (and to the multipliers' change to ``new_multipliers``); the reference is the
    residual after the gap closure (``residual``, N, when the step closes no gap). Halves up to 5 times. Returns
    (u, λ, the ``balance`` of u, whether the step was shortened), or None where no fraction lowers the residual: the
    tangent does not point downhill and the increment falls back to the elastic stiffness."""
    if step.any():
        residual = float(np.linalg.norm(balance(u + step, multipliers)[4][free]))
    rest = du - step
    fraction = 1.0
    for _ in range(6):
        trial_u = u + step + fraction * rest
        trial_multipliers = multipliers + fraction * (new_multipliers - multipliers)
        trial = balance(trial_u, trial_multipliers)
        if np.linalg.norm(trial[4][free]) <= (1.0 - 1e-4 * fraction) * residual:
            return trial_u, trial_multipliers, trial, fraction < 1.0
        fraction *= 0.5
    return None
