"""The converged state of the 3-D plate after an increment (SI units)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["SolidState"]


@dataclass(frozen=True, eq=False)
class SolidState:
    """Converged state: ``overlap`` δ (m), ``centre`` c (m), ``slide`` ξ (m), ``u`` nodal displacements (m,
    interleaved x, y, z), ``plastic_strain`` (elements, qp, 6) Mandel, ``alpha`` (elements, qp) equivalent plastic
    strain, ``contact`` and ``stick`` bool masks of the surface nodes, ``direction`` (surface vertices, 2) the unit
    slip directions of the slipping vertices, ``iterations`` Newton iterations spent, ``friction`` the Coulomb
    coefficient it was solved with."""

    overlap: float
    centre: float
    slide: float
    u: np.ndarray
    plastic_strain: np.ndarray
    alpha: np.ndarray
    contact: np.ndarray
    stick: np.ndarray
    direction: np.ndarray
    iterations: int = 0
    friction: float = 0.0
