r"""The force law of a plate's indentation: its loading branch and the unloading curve from its top, overlaps from first
contact (SI units); the impact on a plate (:mod:`fem.coupling`, :mod:`fem.solid_coupling`) runs on it.
"""

from __future__ import annotations

import math

import numpy as np

from contact import TabulatedLaw
from fem.axisymmetric.result import IndentationResult, loading_branch, unloading_curve

__all__ = ["force_law"]


def force_law(
    loading: IndentationResult,
    unloading: IndentationResult | None = None,
    first_contact: float = 0.0,
    effective_modulus: float | None = None,
    points: int = 41,
    shear_strength: float = math.inf,
) -> TabulatedLaw:
    r"""The plate's force law from first contact (δ' = δ − ``first_contact``, m): the loading branch and the
    unloading curve from its top (``unloading``), or, without one, a provisional elastic curve of Hertz form
    :math:`F = F^*\left(\frac{\delta - \delta_p}{\delta^* - \delta_p}\right)^{3/2}`, with
    :math:`\delta^* - \delta_p = 3F^*/(4E^*a^*)` so that dF/dδ = 2E*a* at the start (exact for elastic unloading;
    ``effective_modulus`` E*, Pa), which cannot change δ_max. The law carries the plate surface's
    ``shear_strength`` (Pa, the limit of the impact's slip traction: :attr:`contact.TabulatedLaw.shear_strength`;
    the 3-D plate's, :mod:`fem.solid_coupling`; ∞ here by default: the axisymmetric plate is frictionless)."""
    d, f, a = loading_branch(loading.overlap, loading.force, loading.contact_radius, first_contact)
    if unloading is None:
        d_star, f_star, a_star = d[-1], f[-1], a[-1]
        drop = min(3.0 * f_star / (4.0 * effective_modulus * max(a_star, 1e-300)), d_star)
        s = np.linspace(1.0, 0.0, points)
        return TabulatedLaw(
            d,
            f,
            a,
            np.array([d_star]),
            (d_star - drop + s * drop)[None, :],
            (f_star * s**1.5)[None, :],
            (a_star * np.sqrt(s))[None, :],
            shear_strength,
        )
    top, grid, force, radius = unloading_curve(unloading.overlap, unloading.force, unloading.contact_radius, points)
    top, grid = top - first_contact, grid - first_contact
    if grid[-1] < 0.0:
        # a residual overlap below first contact (numerical noise of a shaken-down plate) closes the curve at
        # δ' = 0, F^(2/3) linear in δ near separation (Hertz-like)
        new = np.linspace(top, 0.0, points)
        force = np.interp(new[::-1], grid[::-1], force[::-1] ** (2.0 / 3.0))[::-1] ** 1.5
        radius = np.interp(new[::-1], grid[::-1], radius[::-1])[::-1]
        grid, force[-1], radius[-1] = new, 0.0, 0.0
    return TabulatedLaw(d, f, a, np.array([top]), grid[None, :], force[None, :], radius[None, :], shear_strength)
