"""The FE plate of a case: its mesh, the :class:`fem.Plate`, the coupling's settings, the impact run on a force
law, the sliding speed on its surface and the wear law's constants (SI units). Every chain that couples an impact
to the plate builds them here."""

from __future__ import annotations

from collections.abc import Callable

from skfem import MeshTri

import fem
from contact import ImpactResult, TabulatedLaw, simulate_impact
from fem.axisymmetric.mesh import DEFAULT_PARAMETERS
from wear.case import Case
from wear.slip import RadialSlip, SlidingSpeed, sliding_speed

__all__ = [
    "case_mesh",
    "case_plate",
    "check_impact_overlap",
    "coupling_settings",
    "impact_on_law",
    "plate_sliding_speed",
    "wear_constants",
]

#: Hertz's maximum overlap grows as the normal speed to the power 4/5 (Johnson 1985, Eq. 11.24); a yielding plate's
#: grows faster, so the speed scaled by this power's inverse is one the FE plate can take.
HERTZ_OVERLAP_SPEED_POWER = 0.8


def case_mesh(case: Case, max_overlap: float, growth: float = 1.0) -> MeshTri:
    """The FE mesh for a path reaching ``max_overlap`` (m): fem's default mesh scaled to it, or with
    ``fem.mesh_scale`` ≠ 1 a generated mesh with fem's default element counts across the contact and first-yield
    radii divided by ``mesh_scale``; ``growth``: the contact will widen to that × its first radius
    (:func:`fem.axisymmetric.mesh.generate_mesh`)."""
    ball, plate = case.ball.material(), case.plate.material()
    ball_arg = None if ball.is_rigid else ball
    scale = case.fem.mesh_scale
    if scale == 1.0:
        return fem.plate_mesh(case.ball.radius, plate, max_overlap, ball_arg, growth=growth)
    return fem.plate_mesh(
        case.ball.radius,
        plate,
        max_overlap,
        ball_arg,
        contact_elements=max(6, round(DEFAULT_PARAMETERS["contact_elements"] / scale)),
        yield_elements=max(4, round(DEFAULT_PARAMETERS["yield_elements"] / scale)),
        growth=growth,
    )


def check_impact_overlap(case: Case, max_overlap: float) -> None:
    """A one-line ``ValueError`` naming ``impact.speed`` when ``max_overlap`` (m), the FE plate's loading that the
    case's impact asks for, is beyond the ball radius the FE plate is built for, with the largest speed that fits:
    the speed scaled by (R / max_overlap)^(1/0.8) (:data:`HERTZ_OVERLAP_SPEED_POWER`)."""
    radius = case.ball.radius
    if max_overlap <= radius:
        return
    speed = case.impact.speed
    largest = speed * (radius / max_overlap) ** (1.0 / HERTZ_OVERLAP_SPEED_POWER)
    raise ValueError(
        f"impact.speed={speed:g} m/s drives the ball {max_overlap:.3g} m into the FE plate, beyond the ball radius "
        f"{radius:g} m that the plate is built for: give impact.speed <= {largest:.3g} m/s"
    )


def case_plate(case: Case, max_overlap: float, growth: float = 1.0, taper_depth: float | None = None) -> fem.Plate:
    """A virgin :class:`fem.Plate` of the case's plate (an elastic ball enters through E*) on :func:`case_mesh`,
    sized for ``max_overlap`` (m), the loading its impact asks for (:func:`check_impact_overlap`)."""
    ball, plate = case.ball.material(), case.plate.material()
    if plate.is_rigid:
        raise ValueError("plate.rigid=true: the FE plate needs a deformable plate (set plate.rigid = false)")
    check_impact_overlap(case, max_overlap)
    mesh = case_mesh(case, max_overlap, growth)
    return fem.Plate(
        case.ball.radius, plate, max_overlap, ball=None if ball.is_rigid else ball, mesh=mesh, taper_depth=taper_depth
    )


def coupling_settings(case: Case) -> fem.CouplingSettings:
    """The coupling's numbers from the case's ``[fem]`` table."""
    f = case.fem
    return fem.CouplingSettings(
        tolerance=f.tolerance,
        max_iterations=f.max_iterations,
        load_steps=f.load_steps,
        unload_steps=f.unload_steps,
        overshoot=f.overshoot,
    )


def impact_on_law(case: Case) -> Callable[[TabulatedLaw], ImpactResult]:
    """The case's impact (with histories) run on a tabulated force law (overlaps from first contact)."""
    args = case.impact_arguments(normal_model="tabulated", history=True)
    for unused in ("restitution", "limiting_pressure"):  # the tabulated law carries its own unloading
        del args[unused]

    def run(law: TabulatedLaw) -> ImpactResult:
        return simulate_impact(**args, force_law=law)

    return run


def wear_constants(case: Case) -> dict[str, float | str | None]:
    """The constants of the case's wear law (:mod:`wear.laws`): the ``[wear]`` table and the plate's hardness."""
    return {**case.wear.values(), "hardness": case.plate.hardness}


def plate_sliding_speed(case: Case, impact: ImpactResult, radial_table=None) -> SlidingSpeed:
    """The sliding speed of ``case.wear.speed`` along ``impact``; the local slip with the FE surface's
    ``radial_table`` (time s, r m, u_r m)."""
    radial = None if radial_table is None or case.wear.speed != "local" else RadialSlip(*radial_table)
    return sliding_speed(impact, case.wear.speed, radial)
