"""A tabulated normal force law: what a finite-element plate (``fem``) hands to the impact model.

The loading branch is one curve F(δ), a(δ) from δ = 0. Unloading is a family of curves, one per
maximum overlap δ_max reached before unloading starts; each runs from δ_max down to the residual
overlap δ_p where the force vanishes. Between tabulated δ_max the impact model interpolates the
unloading curves in the normalised coordinate s = (δ − δ_p)/(δ_max − δ_p).

SI units: overlaps and radii in m, forces in N.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact.checks import check_array

__all__ = ["TabulatedLaw"]


@dataclass(frozen=True, eq=False)
class TabulatedLaw:
    """Loading curve and a family of unloading curves of a normal contact.

    Attributes
    ----------
    loading_overlap : (n,) array, m
        Strictly increasing overlaps, starting at 0.
    loading_force : (n,) array, N
        Force on the loading branch, non-negative, starting at 0.
    loading_contact_radius : (n,) array, m
        Contact radius on the loading branch.
    unloading_max_overlap : (k,) array, m
        Strictly increasing δ_max at which each unloading curve starts (k ≥ 1).
    unloading_overlap : (k, m) array, m
        Row j: overlaps strictly decreasing from ``unloading_max_overlap[j]`` to the residual
        overlap δ_p, j (where the force has fallen to zero).
    unloading_force : (k, m) array, N
        Row j: force along unloading curve j, from the loading force at δ_max down to 0.
    unloading_contact_radius : (k, m) array, m
        Row j: contact radius along unloading curve j.
    shear_strength : float, Pa
        The largest shear traction the plate's surface carries, k (Orowan's friction τ = min(μp, k) in the
        ``mindlin_deresiewicz`` tangential law, :func:`contact.laws.memory_tangential_law`); ∞ (default): Coulomb's
        τ = μp. A perfectly plastic plate's surface layer yields in shear at k = Y/√3.
    """

    loading_overlap: np.ndarray
    loading_force: np.ndarray
    loading_contact_radius: np.ndarray
    unloading_max_overlap: np.ndarray
    unloading_overlap: np.ndarray
    unloading_force: np.ndarray
    unloading_contact_radius: np.ndarray
    shear_strength: float = math.inf

    def __post_init__(self) -> None:
        lo = check_array("loading_overlap", self.loading_overlap, low=0.0, units="m", min_size=2)
        lf = check_array("loading_force", self.loading_force, low=0.0, units="N", min_size=2)
        la = check_array("loading_contact_radius", self.loading_contact_radius, low=0.0, units="m", min_size=2)
        if not (lo.shape == lf.shape == la.shape):
            raise ValueError(
                f"loading_overlap, loading_force, loading_contact_radius have shapes {lo.shape}, {lf.shape}, "
                f"{la.shape}: must be equal"
            )
        if lo[0] != 0.0 or np.any(np.diff(lo) <= 0.0):
            raise ValueError("loading_overlap must start at 0 and increase strictly (m)")
        um = check_array("unloading_max_overlap", self.unloading_max_overlap, low=0.0, low_open=True, units="m")
        uo = check_array("unloading_overlap", self.unloading_overlap, low=0.0, units="m", ndim=2)
        uf = check_array("unloading_force", self.unloading_force, low=0.0, units="N", ndim=2)
        ua = check_array("unloading_contact_radius", self.unloading_contact_radius, low=0.0, units="m", ndim=2)
        if not (uo.shape == uf.shape == ua.shape) or uo.shape[0] != um.size or uo.shape[1] < 2:
            raise ValueError(
                f"unloading_overlap, unloading_force, unloading_contact_radius have shapes {uo.shape}, "
                f"{uf.shape}, {ua.shape}: must all be (len(unloading_max_overlap)={um.size}, m >= 2)"
            )
        if not self.shear_strength > 0.0:
            raise ValueError(f"shear_strength={self.shear_strength!r} must be > 0 (Pa; inf for Coulomb friction)")
        if np.any(np.diff(um) <= 0.0):
            raise ValueError("unloading_max_overlap must increase strictly (m)")
        if np.any(np.diff(uo, axis=1) >= 0.0):
            raise ValueError("each row of unloading_overlap must decrease strictly from its δ_max (m)")
        if not np.allclose(uo[:, 0], um, rtol=1e-9, atol=0.0):
            raise ValueError("unloading_overlap[:, 0] must equal unloading_max_overlap (m)")
        for name, arr in (
            ("loading_overlap", lo),
            ("loading_force", lf),
            ("loading_contact_radius", la),
            ("unloading_max_overlap", um),
            ("unloading_overlap", uo),
            ("unloading_force", uf),
            ("unloading_contact_radius", ua),
        ):
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)

    @property
    def residual_overlap(self) -> np.ndarray:
        """δ_p (m) of each unloading curve: the overlap where its force reaches zero."""
        return self.unloading_overlap[:, -1]
