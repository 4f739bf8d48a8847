r"""Per-face sums of per-impact quantities, and the eroded volume of each impact by a closed-form law.

A quantity :math:`q_i` of each record i (kept on face :math:`f_i`) sums per face as

.. math:: Q_f = \sum_{i:\ f_i = f} q_i,

one ``np.bincount`` pass; the sum over the faces equals the sum over the kept records (no record counted twice or
lost). Sums of chunks of records add face by face, which is how a large table is summed in parts.

Finnie's (1960) cutting volume of record i, with :math:`N_i` particles of mass :math:`m_i = \rho_i \pi d_i^3 / 6`
at speed :math:`V_i` and angle :math:`\alpha_i = 90° - \theta_i` from the surface (:func:`wear.laws.finnie_volume`):

.. math:: W_i = N_i \frac{c\, m_i V_i^2}{p\, \psi K}\, f(\alpha_i), \qquad
          f(\alpha) = \sin 2\alpha - \frac{6}{K}\sin^2\alpha \ \ (\tan\alpha \le K/6), \qquad
          \frac{K\cos^2\alpha}{6} \ \ \text{otherwise}.

OpenFOAM's ``particleErosion`` is this with c = 1 (it has no cutting fraction; ``p``, ``psi`` = ψ and ``K`` are its
coefficients, defaults ψ = K = 2).
"""

from __future__ import annotations

import numpy as np

from wear.laws import finnie_volume
from wear.wall.hits import Hits
from wear.wall.records import ImpactRecords

__all__ = ["face_sum", "finnie_volumes"]


def face_sum(n_faces: int, hits: Hits, values: np.ndarray) -> np.ndarray:
    """Sum of ``values`` (one per record) over the records kept on each of the ``n_faces`` faces (f,)."""
    kept = hits.kept
    return np.bincount(hits.face[kept], weights=np.asarray(values, float)[kept], minlength=n_faces)


def finnie_volumes(
    records: ImpactRecords,
    hits: Hits,
    *,
    flow_pressure: float,
    force_ratio: float,
    depth_ratio: float,
    cutting_fraction: float,
) -> np.ndarray:
    """Finnie's eroded volume of each record (m³; 0 for a skipped one): ``flow_pressure`` p (Pa), ``force_ratio``
    K, ``depth_ratio`` ψ, ``cutting_fraction`` c (see the module docstring)."""
    volume = records.count * finnie_volume(
        records.mass, hits.speed, hits.angle, flow_pressure, force_ratio, depth_ratio, cutting_fraction
    )
    return np.where(hits.kept, volume, 0.0)
