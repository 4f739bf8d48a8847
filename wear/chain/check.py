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

On a long-worn seat the peak is not a resolved number (measured on the default case after 10⁴ impacts: contact area
within 0.3% and approach within 0.1% of the half-space solution, FE peak 2.05–2.07 GPa against 1.72 GPa on the P2
surface and 1.79 GPa on a cubic-spline one): the pressure sits on the worn scar's shoulder at r ≈ 0.94a and drops to
zero within two FE elements, where the FE nodal pressure, an L2 projection of the nodal reactions, overshoots (the
reaction over its tributary area gives 1.93 GPa). The surface is read as the FE's P2 elements carry it
(:func:`fem.surface_profile`).

Not done: the same check on the 2-D worn scar. The cumulative 2-D map of a cycle-jumped run multiplies single
impacts' maps by the block sizes (hundreds), which magnifies their time-sampling streaks into ±30% ripples that the
half-space solution turns into meaningless peaks (16–19 GPa measured); the FE surface takes the filtered azimuthal
average and is not affected.
"""

from __future__ import annotations

import math

from contact.halfspace import sphere_on_axisymmetric_surface
from fem import surface_profile

__all__ = ["halfspace_check"]


def halfspace_check(result, cells: int = 192) -> dict:
    """Peak pressures (Pa) of the last computed impact of ``result`` (:class:`wear.chain.records.RepeatResult`) at its
    max force: the FE's, and the half-space solution's on the surface that impact met (``result.met_surface``);
    grid of ``cells`` × ``cells`` over ±2.5 contact radii about the FE axis."""
    last = [r for r in result.records if r.kind == "computed"][-1]
    plate = result.plate
    r = plate.surface_r
    dent_depth, wear_depth = result.met_surface

    def met(rho):
        return surface_profile(r, dent_depth + wear_depth, rho)

    solution, _ = sphere_on_axisymmetric_surface(
        plate.radius, met, last.max_force, plate.effective_modulus, 2.5 * last.contact_radius, cells
    )
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
        "grid_spacing_m": solution.spacing,
    }
