r"""Small-strain J2 (von Mises) plasticity with linear isotropic hardening: radial return.

Vectorised over quadrature points, Mandel notation: 4 components (r, z, θ, √2 rz) on the axisymmetric plate
(:mod:`fem.axisymmetric.forms`) or 6 (x, y, z, √2 yz, √2 xz, √2 xy) on the 3-D plate (:mod:`fem.solid.forms`); the first
three are the normal components in both. With the trial
deviatoric stress s_tr = 2G dev(ε − ε_p,n), q_tr = √(3/2)‖s_tr‖ and the yield function
f = q_tr − (Y + H ᾱ_n):

.. math::
    \Delta\bar\alpha = \frac{\langle f\rangle}{3G + H},\qquad
    s = \Bigl(1 - \frac{3G\Delta\bar\alpha}{q_{tr}}\Bigr) s_{tr},\qquad
    \varepsilon_p = \varepsilon_{p,n} + \sqrt{\tfrac32}\,\Delta\bar\alpha\,\hat n,

and the consistent (algorithmic) tangent (Simo & Hughes 1998, Box 3.2)

.. math::
    D = 3K P_{vol} + 2G\theta P_{dev} - 2G\bar\theta\, \hat n\otimes\hat n,\quad
    \theta = 1 - \frac{3G\Delta\bar\alpha}{q_{tr}},\quad
    \bar\theta = \frac{3G}{3G + H} - (1 - \theta),

with n̂ = s_tr/‖s_tr‖. ᾱ is the equivalent plastic strain (dimensionless), stresses in Pa.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["J2Material", "StressUpdate", "plastic_work", "radial_return", "von_mises"]


def _identity(components: int) -> np.ndarray:
    """The unit tensor in Mandel notation with ``components`` (4 or 6) entries."""
    one = np.zeros(components)
    one[:3] = 1.0
    return one


def _projectors(components: int) -> tuple[np.ndarray, np.ndarray]:
    """Volumetric and deviatoric projectors (components × components)."""
    one = _identity(components)
    p_vol = np.outer(one, one) / 3.0
    return p_vol, np.eye(components) - p_vol


@dataclass(frozen=True)
class J2Material:
    """Plate constitutive parameters: ``E`` (Pa), ``nu``, ``yield_strength`` (Pa or None = elastic),
    ``hardening`` H (Pa, linear isotropic; 0 = perfectly plastic)."""

    E: float
    nu: float
    yield_strength: float | None = None
    hardening: float = 0.0

    @property
    def shear(self) -> float:
        return self.E / (2.0 * (1.0 + self.nu))

    @property
    def surface_shear_strength(self) -> float:
        """The largest shear traction (Pa) the surface of a perfectly plastic plate carries, k = Y/√3 (von Mises
        in pure shear; the limit of the contact's slip traction, :mod:`fem.solid.friction`); ∞ for an elastic or a
        hardening plate, whose surface hardens as it flows."""
        if self.yield_strength is None or self.hardening > 0.0:
            return math.inf
        return self.yield_strength / math.sqrt(3.0)

    @property
    def bulk(self) -> float:
        return self.E / (3.0 * (1.0 - 2.0 * self.nu))

    @property
    def elastic_tangent(self) -> np.ndarray:
        """The axisymmetric 4 × 4 Mandel elastic tangent (Pa)."""
        return self.elastic_tangent_of(4)

    def elastic_tangent_of(self, components: int) -> np.ndarray:
        """The Mandel elastic tangent (Pa) with ``components`` (4: axisymmetric, 6: 3-D) entries."""
        p_vol, p_dev = _projectors(components)
        return 3.0 * self.bulk * p_vol + 2.0 * self.shear * p_dev


@dataclass(frozen=True, eq=False)
class StressUpdate:
    """Result of :func:`radial_return`: ``stress`` (…, c) Pa, ``plastic_strain`` (…, c) (c = 4 or 6 Mandel components),
    ``alpha`` (…) equivalent plastic strain, ``yielding`` (…) bool mask of points on the yield
    surface in this increment, ``trial_ratio`` (…) q_tr / (Y + Hᾱ_n), ``tangent`` (n_yielding, 4, 4)
    consistent tangent at the yielding points only (Pa)."""

    stress: np.ndarray
    plastic_strain: np.ndarray
    alpha: np.ndarray
    yielding: np.ndarray
    trial_ratio: np.ndarray
    tangent: np.ndarray


def von_mises(stress: np.ndarray) -> np.ndarray:
    """Von Mises equivalent stress (Pa) of Mandel stresses (…, 4) or (…, 6)."""
    s = stress - (stress[..., :3].sum(axis=-1) / 3.0)[..., None] * _identity(stress.shape[-1])
    return np.sqrt(1.5 * np.einsum("...i,...i->...", s, s))


def radial_return(
    material: J2Material, total_strain: np.ndarray, plastic_strain: np.ndarray, alpha: np.ndarray
) -> StressUpdate:
    """Return-map the total Mandel strain (…, 4) or (…, 6) from the converged state (ε_p,n, ᾱ_n)."""
    G = material.shear
    components = total_strain.shape[-1]
    one = _identity(components)
    elastic_strain = total_strain - plastic_strain
    trace = elastic_strain[..., :3].sum(axis=-1)
    dev = elastic_strain - (trace / 3.0)[..., None] * one
    s_trial = 2.0 * G * dev
    pressure_part = (material.bulk * trace)[..., None] * one
    norm = np.sqrt(np.einsum("...i,...i->...", s_trial, s_trial))
    q_trial = np.sqrt(1.5) * norm
    if material.yield_strength is None:
        stress = s_trial + pressure_part
        empty = np.zeros(alpha.shape, dtype=bool)
        no_tangent = np.zeros((0, components, components))
        return StressUpdate(stress, plastic_strain, alpha, empty, np.zeros_like(alpha), no_tangent)
    H = material.hardening
    flow_stress = material.yield_strength + H * alpha
    ratio = q_trial / flow_stress
    yielding = ratio > 1.0 + 1e-10  # points left exactly on the surface by the last return unload elastically
    stress = s_trial + pressure_part
    new_plastic = plastic_strain.copy()
    new_alpha = alpha.copy()
    if not yielding.any():
        return StressUpdate(stress, new_plastic, new_alpha, yielding, ratio, np.zeros((0, components, components)))
    qy = q_trial[yielding]
    ny = s_trial[yielding] / norm[yielding][:, None]
    d_alpha = (qy - flow_stress[yielding]) / (3.0 * G + H)
    theta = 1.0 - 3.0 * G * d_alpha / qy
    stress[yielding] = theta[:, None] * s_trial[yielding] + pressure_part[yielding]
    new_plastic[yielding] += np.sqrt(1.5) * d_alpha[:, None] * ny
    new_alpha[yielding] += d_alpha
    theta_bar = 3.0 * G / (3.0 * G + H) - (1.0 - theta)
    p_vol, p_dev = _projectors(components)
    tangent = (
        3.0 * material.bulk * p_vol[None]
        + 2.0 * G * theta[:, None, None] * p_dev[None]
        - 2.0 * G * theta_bar[:, None, None] * ny[:, :, None] * ny[:, None, :]
    )
    return StressUpdate(stress, new_plastic, new_alpha, yielding, ratio, tangent)


def plastic_work(material: J2Material, weight: np.ndarray, alpha_before: np.ndarray, alpha_after: np.ndarray) -> float:
    r"""Plastic work (J) dissipated between two states: :math:`\int \int_{\bar\alpha_0}^{\bar\alpha_1} (Y + H\bar\alpha)
    \,d\bar\alpha\,dV = \sum_q w_q \left[Y \Delta\bar\alpha + \tfrac{H}{2}\Delta(\bar\alpha^2)\right]` (J2 with
    linear hardening: the dissipation rate σ : ε̇_p is σ_y(ᾱ) ᾱ̇). ``weight`` (m³) and the equivalent plastic strains
    are per quadrature point; 0 for an elastic material."""
    if material.yield_strength is None:
        return 0.0
    a0, a1 = np.asarray(alpha_before, float), np.asarray(alpha_after, float)
    density = material.yield_strength * (a1 - a0) + 0.5 * material.hardening * (a1**2 - a0**2)
    return float(np.sum(weight * density))
