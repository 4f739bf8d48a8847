"""The normal impact (angle 0°) with friction on the 3-D plate (``fem.model = "3d"``) against two independent
references: the symmetry of a normal impact (no tangential force, spin or tangential velocity) and the
axisymmetric plate's chain of the same case.

Friction μ = 0.3 (the default case's): the plate's slip zone slips radially and its slip turns as the dent
unloads, which used to end the run ("Newton did not converge ... residual nan N"). Reduced path (CI): 3 elements
across the contact radius (``mesh_scale`` 2.6), 5 + 3 increments.
"""

import numpy as np
import pytest
from solid_cases import REDUCED_3D

from wear import run
from wear.case import JOBS

#: 3 elements across the contact radius.
REDUCED = {**REDUCED_3D, "mesh_scale": 2.6}


@pytest.fixture(scope="module")
def normal():
    case = (
        JOBS["run"].default_case().with_(impact={"angle": 0.0, "friction": 0.3}, fem=REDUCED, output={"render": False})
    )
    return run(case)


def test_normal_impact_with_friction_converges_and_stays_symmetric(normal):
    """Reference: the mirror symmetry of a normal impact about the plate normal. The plate's radial friction
    tractions cancel: its tangential force stays below 10 % of μP at every step (a sliding traction would carry μP;
    after lift-off, of 1 % of the peak P; the coarse mesh is not mirror-symmetric in x: measured 6.7 % of μP at the
    first step, 6 contact nodes, and at most 3.3 % after), and the ball leaves with no spin and no tangential
    velocity. Friction acts through radial shear tractions in the contact. (Whether part of
    the contact slips depends on the mesh: Spence's (1975) slip annulus narrows as the materials' |β|/μ falls; on
    this reduced mesh, 3 elements across the contact, the whole contact sticks since the stick test reads the
    vertices' hat moments; before, its edge vertices were released by the L² projection's overshoot and slid.)"""
    r = normal
    assert r.solid.converged
    solid = r.solid.solid
    mu = r.case.impact.friction
    load = np.maximum(solid.normal_force, 0.01 * np.max(solid.normal_force))  # lift-off: P = 0
    assert np.all(np.abs(solid.tangential_force) <= 0.1 * mu * load), solid.tangential_force / load
    # friction acted: the contact carries shear tractions (radial, so that they cancel in the force above)
    shear = np.linalg.norm(solid.shear, axis=2)
    assert np.max(shear) > 0.05 * mu * np.max(solid.pressure), np.max(shear) / (mu * np.max(solid.pressure))
    assert r.impact.spin == 0.0
    assert r.impact.rebound_tangential_velocity == 0.0
    assert r.impact.max_tangential_force == 0.0


def test_normal_impact_with_friction_matches_the_axisymmetric_chain(normal):
    """Reference: the axisymmetric plate's chain of the same case (the (r, z) frictionless model, its own mesh and
    solver), which the 3-D run starts from and keeps in ``coupling``/``fe``. Friction changes the normal response of
    a normal contact little (Spence 1975: a few per cent on P(δ) for a Hertz contact): the peak force and the normal
    restitution within 3 % and the residual dent within 5 %, the tolerances of the 3-D plate against the
    axisymmetric one in ``tests/test_fem_solid.py``."""
    r = normal
    axisymmetric = r.coupling.impact
    assert r.impact.max_force == pytest.approx(axisymmetric.max_force, rel=0.03)
    assert r.impact.normal_restitution == pytest.approx(axisymmetric.normal_restitution, rel=0.03)
    assert r.surface.max_dent_depth == pytest.approx(float(np.max(r.fe.residual_depth)), rel=0.05)


@pytest.fixture(scope="module")
def frictionless_normal():
    # the default increments (10 + 6): on the reduced path's 5 + 3 the fields, linear in time at fixed points, lose
    # the growing contact edge's wear (measured −9.5% of the volume against the axisymmetric plate)
    fem = {**REDUCED_3D, "solid_load_steps": 10, "solid_unload_steps": 6}
    case = JOBS["run"].default_case().with_(impact={"angle": 0.0, "friction": 0.0}, fem=fem)
    return run(case.with_(output={"render": False}))


def test_frictionless_normal_impact_wears_as_the_axisymmetric_plate(frictionless_normal):
    """Reference: the axisymmetric plate's chain of the same case (its own (r, z) mesh of 32 elements across the
    contact, its increments and its wear read-out in the contact's frame). At normal incidence without friction both
    plates wear only through the surface's radial slip under the ball (``wear.speed = "local"``; the contact-point
    slip of the paper is 0 there): the worn volume and the deepest wear within 5% of each other, both non-zero, and
    the dent within 3% (the 3-D plate's default mesh, 4 elements across the contact, read at its quadratic surface
    nodes; measured: volume −1.1%, deepest wear −2.6%, dent −0.4%; read at the vertices alone the volume was −10%)."""
    from wear.chain.axisymmetric_run import impact_wear

    r = frictionless_normal
    c = r.coupling
    wm = impact_wear(r.case, c.impact, c.pressure_table, c.plastic_work, c.radial_table)[1]
    print(
        f"3-D / axisymmetric: volume {r.wear.volume_m3:.4e} / {wm.volume_m3:.4e} m^3, deepest {r.wear.max_depth_m:.4e}"
        f" / {wm.max_depth_m:.4e} m, dent {r.surface.max_dent_depth:.4e} / {np.max(r.fe.residual_depth):.4e} m"
    )
    assert wm.volume_m3 > 0.0 and r.wear.volume_m3 > 0.0
    assert r.wear.volume_m3 == pytest.approx(wm.volume_m3, rel=0.05)
    assert r.wear.max_depth_m == pytest.approx(wm.max_depth_m, rel=0.05)
    assert r.surface.max_dent_depth == pytest.approx(float(np.max(r.fe.residual_depth)), rel=0.03)
