r"""The force law of a plate's indentation: its loading branch and the unloading curve from its top, overlaps from first
contact (SI units); the impact on a plate (:mod:`fem.coupling`, :mod:`fem.solid_coupling`) runs on it. Two laws
derived from one: a second unloading curve from a deeper overlap (:func:`with_unloading_from`), and the law of the
dented plate reloaded at the same site (:func:`reloading_law`), the start of the next impact's coupling.
"""

from __future__ import annotations

import math

import numpy as np

from contact import TabulatedLaw
from fem.axisymmetric.result import IndentationResult, loading_branch, unloading_curve

__all__ = ["force_law", "reloading_law", "with_unloading_from"]

#: Relative difference below which two overlaps of a law are the same point (round-off of sums of overlaps in m).
_SAME_OVERLAP = 1e-9


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


def with_unloading_from(law: TabulatedLaw, overlap: float, force: float, radius: float) -> TabulatedLaw:
    """``law`` with one more unloading curve, from ``overlap`` (m, beyond its last δ_max): its last curve moved up by
    the extra overlap and scaled to ``force`` (N) and ``radius`` (m) at its top. An impact that goes past the last
    δ_max unloads between the two curves, where the engine interpolates (:func:`contact.laws.tabulated_arrays`)."""
    top = float(law.unloading_max_overlap[-1])
    grid, f, a = law.unloading_overlap[-1], law.unloading_force[-1], law.unloading_contact_radius[-1]
    return TabulatedLaw(
        law.loading_overlap,
        law.loading_force,
        law.loading_contact_radius,
        np.r_[law.unloading_max_overlap, overlap],
        np.vstack([law.unloading_overlap, grid + (overlap - top)]),
        np.vstack([law.unloading_force, f * (force / f[0])]),
        np.vstack([law.unloading_contact_radius, a * (radius / max(a[0], 1e-300))]),
        law.shear_strength,
    )


def reloading_law(law: TabulatedLaw, reach: float = 3.0) -> TabulatedLaw:
    r"""The law of the plate that ``law``'s impact has dented, for the next impact at the same site: overlaps from the
    new first contact, at the old residual overlap δ_p (m; the dent the ball meets).

    Up to the old δ_max the plate reloads elastically along its last unloading curve (the first curve of ``law``,
    from δ_max to δ_p, reversed): :math:`F_{\mathrm{re}}(\delta') = F_{\mathrm{un}}(\delta_p + \delta')`. Beyond
    it the plate yields again on its loading branch (the points of ``law`` past δ_max), continued at that branch's
    last slope dF/dδ and da/dδ to ``reach`` × the reloading curve's length (the ball brings more energy than the
    elastic reloading stores: by the rebound's e_n², it goes past the old δ_max). Unloading from the old δ_max is
    the reloading curve itself (elastic); from the end of the table the last unloading curve of ``law`` moved there
    (:func:`with_unloading_from`), and between the two the engine interpolates. An approximation of the dented
    plate's law, not the plate's answer: the coupling's first cycle presses the plate along the impact run on it,
    nearer the dented plate's path than the previous impact's (docs/repeat.md)."""
    down, force, radius = law.unloading_overlap[0], law.unloading_force[0], law.unloading_contact_radius[0]
    top, residual = float(down[0]), float(down[-1])
    # the loading points past the top; one within round-off of it is the top itself, where the curve starts (the
    # plate's δ* reached by two sums), and kept twice it would repeat an overlap of the reloading branch
    past = law.loading_overlap > top * (1.0 + _SAME_OVERLAP)
    overlap = np.r_[down[::-1] - residual, law.loading_overlap[past] - residual]
    f = np.r_[force[::-1], law.loading_force[past]]
    a = np.r_[radius[::-1], law.loading_contact_radius[past]]
    step = law.loading_overlap[-1] - law.loading_overlap[-2]
    slope_f = (law.loading_force[-1] - law.loading_force[-2]) / step
    slope_a = (law.loading_contact_radius[-1] - law.loading_contact_radius[-2]) / step
    further = np.linspace(0.0, (reach - 1.0) * overlap[-1], 41)[1:]
    overlap = np.r_[overlap, overlap[-1] + further]
    f = np.r_[f, f[-1] + slope_f * further]
    a = np.r_[a, a[-1] + slope_a * further]
    f[0] = 0.0  # first contact: the engine's Hertz-like start needs an exact zero
    elastic = TabulatedLaw(
        overlap,
        f,
        a,
        np.array([top - residual]),
        (down - residual)[None, :],
        force[None, :],
        radius[None, :],
        law.shear_strength,
    )
    return with_unloading_from(elastic, float(overlap[-1]), float(f[-1]), float(a[-1]))
