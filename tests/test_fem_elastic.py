"""Acceptance 1 of issue 3: elastic indentation against Hertz (Johnson 1985, Contact Mechanics, §4.2)
and the MOOSE Hertz contact benchmark (E* = 7.5e6 Pa, R = 1 m, F = 1e4 N → a = 0.1 m, δ = 0.01 m).

Mesh: the generated case mesh with 32 P2 elements across the largest contact radius and no extra
first-yield box (purely elastic). Discretisation error at this size is ~0.5% in F (finite block
L = 128 a and the mesh); a wrong axisymmetric weight or a missing hoop strain changes F by tens of
per cent, a paraboloid-vs-sphere or E*-vs-E mix-up by ≥ 9%, so the 1% / 2% tolerances catch them.
"""

import math
import warnings

import numpy as np
import pytest

import fem
from contact.materials import Material, effective_modulus
from contact.theory import hertz_force, hertz_pressure

R = 10e-3
PLATE = Material(E=210e9, nu=0.3, density=7850.0)
E_STAR = effective_modulus(Material.rigid(), PLATE)


@pytest.fixture(scope="module")
def hertz_run():
    d_max = (0.05 * R) ** 2 / R  # a = 0.05 R
    path = d_max * np.array([0.25, 0.5, 0.75, 1.0])
    mesh = fem.plate_mesh(R, PLATE, d_max, contact_elements=32, yield_elements=0)
    return fem.indent(R, PLATE, path, mesh=mesh)


def test_hertz_force_within_1_percent(hertz_run):
    # Johnson (1985) Eq. 4.23: F = 4/3 E* √R δ^{3/2}
    expected = hertz_force(hertz_run.overlap, R, E_STAR)
    err = np.abs(hertz_run.force / expected - 1.0)
    assert err.max() < 0.01, f"Hertz force errors {err}"


def test_hertz_contact_radius_within_3_percent(hertz_run):
    # Johnson (1985) Eq. 4.22: a = √(Rδ)
    expected = np.sqrt(R * hertz_run.overlap)
    err = np.abs(hertz_run.contact_radius / expected - 1.0)
    assert err.max() < 0.03, f"contact radius errors {err}"


def test_hertz_pressure_profile_within_5_percent_rms(hertz_run):
    # Johnson (1985) Eq. 4.21 / errata Eq. 16: p = p0 √(1 − r²/a²), p0 = 2E*a/(πR)
    for k, d in enumerate(hertz_run.overlap):
        a = math.sqrt(R * d)
        p0 = 2.0 * E_STAR * a / (math.pi * R)
        r = hertz_run.surface_r
        inside = r <= 1.2 * a
        diff = hertz_run.pressure[k][inside] - hertz_pressure(r[inside], a, p0)
        rms = math.sqrt(np.mean(diff**2)) / p0
        assert rms < 0.05, f"step {k}: pressure RMS error {rms:.3%} of p0"
        assert abs(hertz_run.max_pressure[k] / p0 - 1.0) < 0.05


def test_hertz_pressure_profile_within_1_percent_rms_inside_the_contact(hertz_run):
    # Johnson (1985) Eq. 4.21 / errata Eq. 16 over r < 0.95 a, where the field is smooth (the edge's square-root
    # singularity of dp/dr is left out): 0.2-0.7% of p0 on this mesh (32 P2 elements across the largest contact
    # radius, the default density); a corner/mid-side alternation of ±1.5% of p0 alone fails it, and the
    # quadratic nodes' reactions divided by the row sums of their P2 surface mass are off by orders of magnitude
    for k, d in enumerate(hertz_run.overlap):
        a = math.sqrt(R * d)
        p0 = 2.0 * E_STAR * a / (math.pi * R)
        r = hertz_run.surface_r
        inside = r < 0.95 * a
        diff = hertz_run.pressure[k][inside] - hertz_pressure(r[inside], a, p0)
        rms = math.sqrt(np.mean(diff**2)) / p0
        assert rms < 0.01, f"step {k}: pressure RMS error {rms:.3%} of p0 inside 0.95 a"


def test_moose_hertz_benchmark():
    # MOOSE contact module Hertz benchmark: E* = 7.5e6 Pa, R = 1 m, F = 1e4 N → a = 0.1 m, δ = 0.01 m.
    nu = 0.3
    plate = Material(E=7.5e6 * (1.0 - nu**2), nu=nu, density=1000.0)
    mesh = fem.plate_mesh(1.0, plate, 0.01, contact_elements=24, yield_elements=0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # a/R = 0.1 sits on the small-strain warning threshold
        res = fem.indent(1.0, plate, [0.005, 0.01], mesh=mesh)
    assert abs(res.force[-1] / 1e4 - 1.0) < 0.02, res.force[-1]
    assert abs(res.contact_radius[-1] / 0.1 - 1.0) < 0.02, res.contact_radius[-1]


def test_elastic_ball_uses_effective_modulus():
    # An elastic ball enters only through E* (Johnson 1985 §4.2): two balls giving the same E* agree.
    ball = Material(E=210e9, nu=0.3, density=7850.0)
    d = 1e-6
    mesh = fem.plate_mesh(R, PLATE, d, ball=ball, contact_elements=12, yield_elements=0)
    res = fem.indent(R, PLATE, [d], ball=ball, mesh=mesh)
    e_star = effective_modulus(ball, PLATE)
    assert abs(res.force[0] / hertz_force(d, R, e_star) - 1.0) < 0.02
