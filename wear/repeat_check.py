r"""Cross-check of a repeated-impact run's last pressure by the elastic half-space solution (SI units).

After many impacts the plate responds (nearly) elastically, so the peak pressure of the last computed impact
should be the elastic contact pressure of the surface the previous impacts left at the same force, independent of
the FE: :func:`contact.halfspace.halfspace_contact` (Love 1929 influence coefficients, Polonsky & Keer 1999) with
the gap

.. math::

    g(x, y) = R - \sqrt{R^2 - \rho^2} + d(\rho) + w(x, y), \qquad \rho = \sqrt{(x - x_a)^2 + y^2}

(sphere about the FE axis x_a, d the FE dent, w the FE plate's axisymmetric wear profile). It holds for a
shaken-down impact; an impact that still yields has its FE pressure capped by plasticity (the fully plastic limit is
about 2.8 Y), so there the half-space value is the elastic pressure the surface *would* carry, an upper bound.

Not done: the same check on the 2-D worn scar. The cumulative 2-D map of a cycle-jumped run multiplies single
impacts' maps by the block sizes (hundreds), which magnifies their time-sampling streaks into ±30% ripples that the
half-space solution turns into meaningless peaks (16–19 GPa measured); the FE surface takes the filtered azimuthal
average and is not affected.
"""

from __future__ import annotations

import math

import numpy as np

from contact.halfspace import halfspace_contact

__all__ = ["halfspace_check"]


def halfspace_check(result, cells: int = 96) -> dict:
    """Peak pressures (Pa) of the last computed impact of ``result`` (:class:`wear.repeat.RepeatResult`) at its
    max force: the FE's, and the half-space solution's on the surface that impact met (``result.met_surface``);
    grid of ``cells``² over ±2.5 contact radii about the FE axis."""
    last = [r for r in result.records if r.kind == "computed"][-1]
    plate = result.plate
    radius = plate.radius
    r = plate.surface_r
    half_width = 2.5 * last.contact_radius
    spacing = 2.0 * half_width / cells
    x = (np.arange(cells) - (cells - 1) / 2) * spacing
    rho = np.hypot(*np.meshgrid(x, x))
    dent_depth, wear_depth = result.met_surface
    gap = radius - np.sqrt(radius * radius - rho * rho) + np.interp(rho, r, dent_depth) + np.interp(rho, r, wear_depth)
    solution = halfspace_contact(gap, spacing, last.max_force, plate.effective_modulus)
    return {
        "impact": last.first,
        # the check holds for an elastic (shaken-down) impact; with new plastic strain the FE pressure is capped by
        # yielding (≈ 2.8 Y when fully plastic) where the elastic half-space pressure is not
        "plastic_strain_increment": last.plastic_strain_increment,
        "shaken_down": last.shaken_down,
        "force_N": last.max_force,
        "fe_max_pressure_Pa": last.max_pressure,
        "halfspace_max_pressure_Pa": solution.max_pressure,
        "fe_contact_area_m2": math.pi * last.contact_radius**2,
        "halfspace_contact_area_m2": solution.contact_area,
        "grid_spacing_m": spacing,
    }
