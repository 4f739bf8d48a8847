r"""Cross-check of a repeated-impact run's last pressure by the elastic half-space solution (SI units).

After many impacts the plate responds (nearly) elastically, so the peak pressure of the last computed impact
should be the elastic contact pressure of the surface the previous impacts left at the same force, independent of
the FE: :func:`contact.halfspace.halfspace_contact` (Love 1929 influence coefficients, Polonsky & Keer 1999) with
the gap

.. math::

    g(x, y) = R - \sqrt{R^2 - \rho^2} + d(\rho) + w(x, y), \qquad \rho = \sqrt{(x - x_a)^2 + y^2}

(sphere about the FE axis x_a, d the FE dent, w the wear). It holds for a shaken-down impact; an impact that
still yields has its FE pressure capped by plasticity (the fully plastic limit is about 2.8 Y), so there the
half-space value is the elastic pressure the surface *would* carry, an upper bound. Two versions of w: the
axisymmetric average the FE plate carries (the same surface: the difference measures the FE's own error, and any
plastic flow in the last impact), and the 2-D worn scar (elongated along the impact for an oblique impact: the
difference measures what the axisymmetric FE misses).
"""

from __future__ import annotations

import math

import numpy as np

from contact.halfspace import halfspace_contact

__all__ = ["halfspace_check"]


def halfspace_check(result, cells: int = 96) -> dict:
    """Peak pressures (Pa) of the last computed impact of ``result`` (:class:`wear.repeat.RepeatResult`) at its
    max force: the FE's, and the half-space solution's on the surface that impact met (``result.met_surface``)
    with the axisymmetric wear profile and with the 2-D worn scar; grid of ``cells``² over ±2.5 contact radii
    about the FE axis."""
    from scipy.interpolate import RegularGridInterpolator

    last = [r for r in result.records if r.kind == "computed"][-1]
    plate = result.plate
    radius = plate.radius
    r = plate.surface_r
    half_width = 2.5 * last.contact_radius
    spacing = 2.0 * half_width / cells
    x = (np.arange(cells) - (cells - 1) / 2) * spacing
    xx, yy = np.meshgrid(x, x)
    rho = np.hypot(xx, yy)
    sphere = radius - np.sqrt(radius * radius - rho * rho)
    dent_depth, wear_depth, wm = result.met_surface
    dent = np.interp(rho, r, dent_depth)
    axisymmetric = np.interp(rho, r, wear_depth)
    if wm is None:
        worn = np.zeros_like(rho)
    else:
        scar = RegularGridInterpolator((wm.y, wm.x), wm.depth, bounds_error=False, fill_value=0.0)
        worn = scar(np.stack([yy.ravel(), (xx + result.axis_x).ravel()], axis=1)).reshape(xx.shape)
    e_star = plate.effective_modulus
    axi = halfspace_contact(sphere + dent + axisymmetric, spacing, last.max_force, e_star)
    two_d = halfspace_contact(sphere + dent + worn, spacing, last.max_force, e_star)
    return {
        "impact": last.first,
        # the check holds for an elastic (shaken-down) impact; with new plastic strain the FE pressure is capped by
        # yielding (≈ 2.8 Y when fully plastic) where the elastic half-space pressure is not
        "plastic_strain_increment": last.plastic_strain_increment,
        "shaken_down": last.shaken_down,
        "force_N": last.max_force,
        "fe_max_pressure_Pa": last.max_pressure,
        "halfspace_axisymmetric_max_pressure_Pa": axi.max_pressure,
        "halfspace_2d_scar_max_pressure_Pa": two_d.max_pressure,
        "halfspace_2d_scar_contact_area_m2": two_d.contact_area,
        "halfspace_axisymmetric_contact_area_m2": axi.contact_area,
        "fe_contact_area_m2": math.pi * last.contact_radius**2,
        "grid_spacing_m": spacing,
    }
