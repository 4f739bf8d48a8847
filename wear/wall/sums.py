r"""Per-face sums of per-impact quantities, and the eroded volume of each impact by a wear law.

A quantity :math:`q_i` of each record i (kept on face :math:`f_i`) sums per face as

.. math:: Q_f = \sum_{i:\ f_i = f} q_i,

one ``np.bincount`` pass; the sum over the faces equals the sum over the kept records (no record counted twice or
lost). Sums of chunks of records add face by face, which is how a large table is summed in parts.

The eroded volume of record i by a wear law of :mod:`wear.wall.per_record` (:func:`record_volumes`): the law's
volume of one particle at the record's angle and speed, times the particles it stands for, and 0 for a record left
out of the sums (its face −1). OpenFOAM's ``particleErosion`` is Finnie's law with c = 1 (it has no cutting
fraction; its ``p``, ``psi`` = ψ and ``K`` are ``plate.hardness``, ``wear.depth_ratio`` and ``wear.force_ratio``).
"""

from __future__ import annotations

import numpy as np

from wear.wall.hits import Hits
from wear.wall.records import ImpactRecords

__all__ = ["face_sum", "record_volumes", "refuse_records"]


def face_sum(n_faces: int, hits: Hits, values: np.ndarray) -> np.ndarray:
    """Sum of ``values`` (one per record) over the records kept on each of the ``n_faces`` faces (f,)."""
    kept = hits.kept
    return np.bincount(hits.face[kept], weights=np.asarray(values, float)[kept], minlength=n_faces)


def refuse_records(refused, records: ImpactRecords, hits: Hits) -> None:
    """Raise a ``ValueError`` naming the file, row and column of the first record kept on the wall that
    ``refused(speed_m_s, density_kg_m3)`` (a law's ``refused``, e.g. :meth:`wear.wall.per_record.TableLaw.refused`;
    None: every record taken) gives as (index among the kept, field, why)."""
    if refused is None:
        return
    kept = np.flatnonzero(hits.kept)
    bad = refused(hits.speed[kept], records.density[kept])
    if bad is not None:
        i, field_name, why = bad
        raise ValueError(f"{records.where(int(kept[i]), field_name)}: {why}")


def record_volumes(law, records: ImpactRecords, hits: Hits) -> np.ndarray:
    """The eroded volume (m³) of each record by ``law`` (:func:`wear.wall.per_record.wall_law`, or any object with its
    ``volume(angle_deg, speed_m_s, diameter_m, density_kg_m3, count)``); 0 for a skipped record. A record the law
    cannot take (a law's ``refused``, e.g. a speed outside a response table) is a ``ValueError`` naming its file, row
    and column, and so is a volume that is not finite and >= 0 (a law's bug or its constants)."""
    kept = hits.kept
    refuse_records(getattr(law, "refused", None), records, hits)
    volume = np.zeros(len(records))
    if kept.any():
        volume[kept] = law.volume(
            hits.angle[kept], hits.speed[kept], records.diameter[kept], records.density[kept], records.count[kept]
        )
    wrong = np.flatnonzero(kept & ~(np.isfinite(volume) & (volume >= 0.0)))
    if len(wrong):
        i = wrong[0]
        raise ValueError(
            f"{records.where(i, 'velocity')}: the law {getattr(law, 'name', type(law).__name__)} gives the "
            f"eroded volume {volume[i]!r} m^3 (speed {hits.speed[i]:.6g} m/s, angle {hits.angle[i]:.6g} deg): "
            "a volume is finite and >= 0"
        )
    return volume
