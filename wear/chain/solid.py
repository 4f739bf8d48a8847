"""The 3-D plate in the chain (``fem.model = "3d"``): its checks, its coupling, and the wear and residual surface
from its fields (SI units, angles in degrees from the plate normal).

The oblique impact, first coupled to the axisymmetric plate (its normal law is the 3-D one's within about 1 % at
μ = 0, a cheap start), is coupled to the 3-D half plate with friction (:func:`fem.solid_coupling.couple_solid`);
the 3-D pressure and stick/slip fields then drive the local wear law (:mod:`wear.solid_wear`) and the 3-D residual
surface is the dent.

The impact's tangential law is the plate's: partial slip with memory, Mindlin–Deresiewicz
(:data:`SOLID_TANGENTIAL_MODEL`, :func:`contact.laws.memory_tangential_law`), which the 3-D plate reproduces at
constant load (Cattaneo–Mindlin, ``tests/test_fem_solid.py``); :func:`solid_case` sets it for the whole chain, the
axisymmetric start included.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from contact import ImpactResult
from fem.solid_coupling import SolidCoupledImpact, SolidCouplingSettings, couple_solid
from wear.case import Case
from wear.chain.plate import impact_on_law, wear_constants
from wear.integrate import WearMap, wear_map
from wear.laws import local
from wear.laws.impact import ImpactWear, impact_wear, wear_of_impact
from wear.pressure import PressureHistory, fe_pressure_history
from wear.slip import sliding_speed
from wear.solid_wear import on_half_surface, solid_dent_depth, solid_grid, solid_wear_depth
from wear.surface import DeformedSurface

__all__ = [
    "MIN_CONTACT_ELEMENTS",
    "SOLID_TANGENTIAL_MODEL",
    "check_solid_case",
    "solid_case",
    "solid_settings",
    "solid_impact",
    "solid_wear",
    "solid_surface",
]

#: Fewest 3-D elements across the largest contact radius that resolve the contact (the Hertz force is within 2 %
#: with 4; below 3 the contact edge falls between two element vertices over much of the impact).
MIN_CONTACT_ELEMENTS = 3
#: 3-D elements across the largest contact radius at ``fem.mesh_scale`` = 1.
CONTACT_ELEMENTS_AT_SCALE_1 = 8


#: The impact's tangential law on the 3-D plate: the plate's own partial slip with memory.
SOLID_TANGENTIAL_MODEL = "mindlin_deresiewicz"


def solid_case(case: Case) -> Case:
    """``case`` with the impact's tangential law the 3-D plate's (:data:`SOLID_TANGENTIAL_MODEL`): the H-DD spring
    slides where the plate sticks and reverses at 2/3 of its stiffness (``docs/fem.md``)."""
    return case.with_(impact={"tangential_model": SOLID_TANGENTIAL_MODEL})


def solid_settings(case: Case) -> SolidCouplingSettings:
    """The 3-D coupling's numbers from the case's ``[fem]`` table (its own ``solid_load_steps`` and
    ``solid_unload_steps``; elements across the contact radius 8/``mesh_scale``)."""
    f = case.fem
    return SolidCouplingSettings(
        tolerance=f.tolerance,
        max_iterations=f.solid_iterations,
        load_steps=f.solid_load_steps,
        unload_steps=f.solid_unload_steps,
        overshoot=f.overshoot,
        contact_elements=round(CONTACT_ELEMENTS_AT_SCALE_1 / f.mesh_scale),
    )


def check_solid_case(case: Case) -> None:
    """One-line ``ValueError`` for a case the 3-D plate cannot run: a coupling other than two-way, or a mesh too
    coarse to resolve the contact (``impact.friction`` has one range for every plate, the case schema's)."""
    if case.fem.coupling != "two-way":
        raise ValueError(
            f"fem.model='3d' needs fem.coupling='two-way' (got {case.fem.coupling!r}): the 3-D plate "
            "is coupled to the impact"
        )
    elements = solid_settings(case).contact_elements
    if elements < MIN_CONTACT_ELEMENTS:
        raise ValueError(
            f"fem.mesh_scale={case.fem.mesh_scale!r}: the 3-D plate would have {elements} elements across the "
            f"contact radius and cannot resolve the contact; it needs at least {MIN_CONTACT_ELEMENTS} "
            f"(mesh_scale <= {CONTACT_ELEMENTS_AT_SCALE_1 / (MIN_CONTACT_ELEMENTS - 0.5):.3g})"
        )


def solid_impact(case: Case, start: ImpactResult, progress: Callable[[int], None] | None = None) -> SolidCoupledImpact:
    """The case's impact coupled to the 3-D plate from the impact ``start`` (m, s; the axisymmetric coupled one);
    ``progress(cycle)`` is called as each 3-D plate cycle starts."""
    ball, plate = case.ball.material(), case.plate.material()
    return couple_solid(
        impact_on_law(case),
        start,
        case.ball.radius,
        plate,
        case.impact.friction,
        None if ball.is_rigid else ball,
        0.0,
        solid_settings(case),
        progress,
    )


def _across_profile(coupled: SolidCoupledImpact, samples: int = 81) -> PressureHistory:
    """The 3-D pressure across the track through each step's contact centre as a p(r, t) table (the wear stage's
    pressure history for the summary, ``pressure.npz`` and the figures)."""
    field = coupled.field
    radii = np.linspace(0.0, 1.5 * float(np.max(field.contact_radius)), samples)
    across = on_half_surface(field.points, field.pressure.T, field.centre[:, None], radii, field.triangles)
    rows = np.array([across[k, :, k] for k in range(field.centre.size)])
    ph = fe_pressure_history(field.time, radii, rows, field.centre)
    return PressureHistory(ph.time, ph.contact_x, ph.extent, ph.pressure, source="fe-3d (across the track)")


def solid_wear(case: Case, coupled: SolidCoupledImpact) -> tuple[PressureHistory, WearMap, ImpactWear]:
    """Stage ``wear`` on the 3-D plate: the local law integrated with the 3-D pressure and stick/slip fields
    (:func:`wear.solid_wear.solid_wear_depth`) on the 3-D grid; another law's volumes as on the axisymmetric plate,
    laid out by the across-track pressure profile. Returns (pressure history, wear map, worn volumes)."""
    w, impact = case.wear, coupled.impact
    ph = _across_profile(coupled)
    # the local slip is the plate's own, vertex by vertex (:mod:`wear.solid_wear`); the contact-point slips are the
    # impact's
    speed = None if w.speed == "local" else sliding_speed(impact, w.speed)
    constants = wear_constants(case)
    density = case.plate.material().density
    if w.law != local.LAW.name:
        contact_point = speed or sliding_speed(impact, "sliding")
        wm, worn = wear_of_impact(
            w.law, constants, w.wear_law(), impact, ph, contact_point, density=density, points_across=w.points_across
        )
        return ph, wm, worn
    field = coupled.field
    x, y = solid_grid(field, w.points_across)
    depth = solid_wear_depth(field, speed, w.wear_law(), x, y, float(impact.history.t[0]))
    wm = wear_map(x, y, depth, density)
    return ph, wm, impact_wear(local.LAW.name, constants, impact, local=wm.volume_m3)


def solid_surface(coupled: SolidCoupledImpact, wm: WearMap) -> DeformedSurface:
    """The 3-D plate's residual surface on the wear grid (m) with the wear map ``wm``; its profile across the
    track through the deepest point as ``dent_radius``/``dent_depth``."""
    dent = solid_dent_depth(coupled.field, wm.x, wm.y)
    wear = wm.depth.T
    i, j = np.unravel_index(int(np.argmax(dent)), dent.shape)
    across = wm.y >= wm.y[j]
    return DeformedSurface(
        wm.x, wm.y, wear, wm.y[across] - wm.y[j], dent[i, across], (float(wm.x[i]), 0.0), dent_grid=dent
    )
