"""The plate's cycle of a coupled impact: the kept loading steps below the unloading overlap δ* followed by the
unloading from δ* (SI units).
"""

from __future__ import annotations

from dataclasses import dataclass

import meshio
import numpy as np

from fem.axisymmetric.result import FirstYieldPoint, IndentationResult, join

__all__ = ["PlateCycle"]


@dataclass(frozen=True, eq=False)
class PlateCycle:
    """The plate's cycle of a coupled impact: the kept loading steps below δ* followed by the unloading from δ*
    (per step: ``overlap`` m from first contact, ``force`` N, ``contact_radius`` m, ``pressure`` Pa (steps, surface
    nodes), ``radial_displacement`` m (steps, surface nodes: u_r), ``regime``, ``max_equivalent_plastic_strain``),
    ``surface_r`` (m), ``residual_depth`` (m, after the
    unloading, positive into the plate), ``first_yield`` (reached in this cycle, or None), ``loading`` and
    ``unloading`` (the plate's results, overlaps from the original plane)."""

    overlap: np.ndarray
    force: np.ndarray
    contact_radius: np.ndarray
    pressure: np.ndarray
    radial_displacement: np.ndarray
    regime: list[str]
    max_equivalent_plastic_strain: np.ndarray
    surface_r: np.ndarray
    residual_depth: np.ndarray
    first_yield: FirstYieldPoint | None
    loading: IndentationResult
    unloading: IndentationResult

    def to_meshio(self) -> meshio.Mesh:
        """The plate after the unloading (:meth:`fem.IndentationResult.to_meshio`)."""
        return self.unloading.to_meshio()

    @classmethod
    def join(
        cls, loading: IndentationResult, unloading: IndentationResult, first_contact: float, max_overlap: float
    ) -> PlateCycle:
        """The loading steps strictly below ``max_overlap`` δ* (m, from the original plane; the loading may be a
        whole cycle: stop at its peak) and the unloading."""
        c = join(loading, unloading, below=max_overlap)
        return cls(
            overlap=c.overlap - first_contact,
            force=c.force,
            contact_radius=c.contact_radius,
            pressure=c.pressure,
            radial_displacement=c.radial_displacement,
            regime=c.regime,
            max_equivalent_plastic_strain=c.max_equivalent_plastic_strain,
            surface_r=c.surface_r,
            residual_depth=c.residual_depth,
            first_yield=c.first_yield,
            loading=loading,
            unloading=unloading,
        )
