r"""The plate's material as the FE plates model it, and the size of the contact they are meshed for (SI units).

An elastic ball is represented by a rigid sphere and a plate of modulus E_p' = E*(1 − ν_p²), so that the effective
modulus E* (errata Eq. 5) is unchanged: exact for the Hertz (elastic) solution, an approximation once the plate
yields (the ball's own deformation is then not resolved). Both plates are small-strain models: the contact radius
they are asked for is bounded by :data:`SMALL_STRAIN_LIMIT` × the ball radius.
"""

from __future__ import annotations

import math
import warnings

from contact.materials import Material, effective_modulus
from contact.theory import first_yield as hertz_first_yield
from fem.core.plasticity import J2Material

__all__ = ["SMALL_STRAIN_LIMIT", "SMALL_STRAIN_WARNING", "check_small_strain", "estimate_contact_radius", "plate_model"]

#: Largest a/R accepted (small strain); a warning is given above SMALL_STRAIN_WARNING.
SMALL_STRAIN_LIMIT = 0.3
SMALL_STRAIN_WARNING = 0.1


def plate_model(plate: Material, ball: Material | None, hardening: float) -> tuple[J2Material, float]:
    """The FE plate's material and the effective modulus E* (Pa) of ``ball`` (None: rigid) on ``plate``: the
    ball is a rigid sphere and the plate a J2 solid of modulus E_p' = E*(1 − ν_p²), Poisson's ratio ν_p, yield
    strength Y and linear hardening modulus ``hardening`` H (Pa), so that E* is unchanged (module docstring;
    warns when an elastic ball meets a plate that can yield). One-line ``ValueError`` for a rigid plate."""
    if not isinstance(plate, Material):
        raise ValueError(f"plate={plate!r} is not a contact.Material")
    if plate.is_rigid:
        raise ValueError("plate.E=inf: the plate must be deformable (finite E in Pa)")
    e_star = effective_modulus(ball if ball is not None else Material.rigid(), plate)
    E = e_star * (1.0 - plate.nu**2)
    if ball is not None and not ball.is_rigid and plate.yield_strength is not None:
        warnings.warn(
            "elastic ball: represented by a rigid sphere and a plate with the same E*; exact while elastic, "
            "approximate once the plate yields",
            stacklevel=3,
        )
    return J2Material(E, plate.nu, plate.yield_strength, hardening), e_star


def estimate_contact_radius(radius: float, e_star: float, plate: Material, overlap: float) -> float:
    """Contact radius (m) expected at ``overlap`` (m): Hertz √(Rδ) while elastic, Kogut & Etsion's
    (2002) A/A_c = 0.93 w^1.136 (w ≤ 6), 0.94 w^1.146 (w > 6), w = δ/δ_c, once yielded."""
    a = math.sqrt(radius * overlap)
    if plate.yield_strength is None:
        return a
    fy = hertz_first_yield(radius, e_star, plate.yield_strength, plate.nu)
    w = overlap / fy.overlap
    if w <= 1.0:
        return a
    area_ratio = 0.93 * w**1.136 if w <= 6.0 else 0.94 * w**1.146
    return max(a, fy.contact_radius * math.sqrt(area_ratio))


def check_small_strain(radius: float, e_star: float, plate: Material, max_overlap: float) -> None:
    """A one-line ``ValueError`` if the contact radius expected at ``max_overlap`` (m) exceeds
    :data:`SMALL_STRAIN_LIMIT` × the ball radius (m), a warning above :data:`SMALL_STRAIN_WARNING` × it."""
    a_max = estimate_contact_radius(radius, e_star, plate, max_overlap)
    if a_max / radius > SMALL_STRAIN_LIMIT:
        raise ValueError(
            f"overlaps: max overlap {max_overlap:.6g} m gives a contact radius ≈ {a_max:.3g} m "
            f"= {a_max / radius:.3g} R: "
            f"small strain needs a/R <= {SMALL_STRAIN_LIMIT} (overlap <= ~{SMALL_STRAIN_LIMIT**2 * radius:.3g} m)"
        )
    if a_max / radius > SMALL_STRAIN_WARNING * (1.0 + 1e-6):
        warnings.warn(
            f"contact radius ≈ {a_max / radius:.3g} R > {SMALL_STRAIN_WARNING} R: "
            "the small-strain assumption is strained",
            stacklevel=3,
        )
