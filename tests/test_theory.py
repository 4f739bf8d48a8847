"""Closed-form contact mechanics against published numbers (sources named per test)."""

import math

import numpy as np
import pytest

from contact import Material, effective_modulus, effective_shear_modulus, theory, yield_velocity


def test_hertz_impact_chung_ooi_test2_alumina():
    # Chung & Ooi (2011), Granular Matter 13:643-656, test 2: Al oxide sphere R 2.5 mm on a rigid plane at 3.9 m/s.
    ball = Material(E=380e9, nu=0.23, density=4000.0)
    e_star = effective_modulus(ball, Material.rigid())
    h = theory.hertz_impact(theory.sphere_mass(2.5e-3, 4000.0), 2.5e-3, e_star, 3.9)
    assert h.max_overlap == pytest.approx(8.0888e-6, rel=1e-4)
    assert h.max_force == pytest.approx(615.35, rel=1e-4)
    assert h.contact_time == pytest.approx(6.1045e-6, rel=1e-4)


def test_hertz_relations_consistent_with_johnson():
    # Johnson (1985), Contact Mechanics, Ch. 4: a^3 = 3FR/(4E*), p0 = 3F/(2 pi a^2), delta = a^2/R.
    R, e_star, F = 0.01, 115e9, 250.0
    a = theory.hertz_contact_radius_from_force(F, R, e_star)
    assert a**3 == pytest.approx(3 * F * R / (4 * e_star), rel=1e-12)
    assert theory.hertz_peak_pressure(F, R, e_star) == pytest.approx(3 * F / (2 * math.pi * a**2), rel=1e-12)
    assert theory.hertz_overlap(F, R, e_star) == pytest.approx(a**2 / R, rel=1e-12)
    assert theory.hertz_force(a**2 / R, R, e_star) == pytest.approx(F, rel=1e-12)


def test_moose_hertz_benchmark():
    # MOOSE contact module Hertz benchmark: E* = 7.5e6 Pa, R = 1 m, F = 1e4 N -> a = 0.1 m, delta = 0.01 m.
    assert theory.hertz_contact_radius_from_force(1e4, 1.0, 7.5e6) == pytest.approx(0.1, rel=1e-9)
    assert theory.hertz_overlap(1e4, 1.0, 7.5e6) == pytest.approx(0.01, rel=1e-9)


@pytest.mark.parametrize("nu, c_ref, depth_ref", [(0.3, 1.6128, 0.481)])
def test_yield_coefficient_exact(nu, c_ref, depth_ref):
    # Johnson (1985) Sec. 6.2: first yield at p0 = 1.60 Y (nu = 0.3) at z = 0.48a; exact C(0.3) = 1.6128
    # (errata Eq. 18), and Green (2005) fit C = 1.30075 + 0.87825 nu + 0.54373 nu^2 within 0.1%.
    assert theory.yield_coefficient(nu) == pytest.approx(c_ref, abs=1e-4)
    assert theory.yield_depth_ratio(nu) == pytest.approx(depth_ref, abs=1e-3)


@pytest.mark.parametrize("nu", [0.2, 0.25, 0.3, 0.35, 0.4])
def test_yield_coefficient_matches_green_fit(nu):
    # Green (2005), Proc. IMechE J 219:J04104: fit of the exact C(nu), accurate to 0.1%.
    assert theory.yield_coefficient(nu) == pytest.approx(float(theory.green_yield_coefficient(nu)), rel=1e-3)


def test_first_yield_force_formula():
    # Errata Eq. 18: F_y = pi^3 (C Y)^3 R^2 / (6 E*^2); check the paper's C = 1.6 and the exact C.
    R, Y, e_star = 10e-3, 210e6, 210e9 / (1 - 0.09)
    fy = theory.first_yield(R, e_star, Y, 0.3, coefficient=theory.PAPER_YIELD_COEFFICIENT)
    assert fy.force == pytest.approx(math.pi**3 * (1.6 * Y) ** 3 * R**2 / (6 * e_star**2), rel=1e-12)
    exact = theory.first_yield(R, e_star, Y, 0.3)
    assert exact.force / fy.force == pytest.approx((1.6128 / 1.6) ** 3, rel=3e-4)
    assert exact.depth == pytest.approx(0.481 * exact.contact_radius, rel=2e-3)


def test_yield_velocity_thornton_form():
    # Thornton (1997), J. Appl. Mech. 64:383: V_y = 1.56 sqrt(p_y^5 / (E*^4 rho)).
    ball = Material(E=210e9, nu=0.3, density=7850.0)
    plate = Material(E=210e9, nu=0.3, density=7850.0, yield_strength=500e6)
    e_star = effective_modulus(ball, plate)
    p_y = 1.6128 * 500e6
    assert yield_velocity(radius=5e-3, ball=ball, plate=plate) == pytest.approx(
        1.56 * math.sqrt(p_y**5 / (e_star**4 * 7850.0)), rel=2e-3
    )


def test_thornton_restitution_published():
    # Thornton (1997), Eq. 39, values quoted in the issue: e at V_i/V_y = 1.5, 2, 5, 10, 100.
    ref = [0.97124, 0.93063, 0.77334, 0.65856, 0.37430]
    got = theory.thornton_restitution([1.5, 2, 5, 10, 100])
    np.testing.assert_allclose(got, ref, atol=1e-5)


def test_effective_moduli_kharaz_pair():
    # Errata Eqs. 5, 9 for alumina on soda-lime glass (Kharaz, Gorham & Salman 2001 materials).
    b, p = Material(380e9, 0.23, 4000.0), Material(70e9, 0.25, 2500.0)
    assert effective_modulus(b, p) == pytest.approx(1 / ((1 - 0.23**2) / 380e9 + (1 - 0.25**2) / 70e9), rel=1e-12)
    gb, gp = 380e9 / 2.46, 70e9 / 2.5
    assert effective_shear_modulus(b, p) == pytest.approx(1 / ((2 - 0.23) / gb + (2 - 0.25) / gp), rel=1e-12)


def test_hertz_pressure_integrates_to_force():
    # Errata Eq. 16: the corrected profile integrates to F = 2/3 pi a^2 p0.
    a, p0 = 1e-4, 2e9
    r = np.linspace(0, a, 200001)
    f = np.trapezoid(2 * np.pi * r * theory.hertz_pressure(r, a, p0), r)
    assert f == pytest.approx(2 / 3 * np.pi * a**2 * p0, rel=1e-5)


def test_mesarovic_johnson_profile_integrates_to_its_force():
    # Mesarovic & Johnson (2000): F/F* = (2/pi)[asin x - x sqrt(1-x^2)] is the integral of Eq. 19.
    a_star, p_star = 2e-4, 1.5e9
    for x in (0.3, 0.6, 0.9):
        r = np.linspace(0, x * a_star, 400001)
        f = np.trapezoid(2 * np.pi * r * theory.mesarovic_johnson_pressure(r, x * a_star, a_star, p_star), r)
        assert f == pytest.approx(float(theory.mesarovic_johnson_force(x * a_star, a_star, p_star)), rel=1e-4)


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(E=210.0, nu=0.3, density=7850.0), "E"),
        (dict(E=-1e9, nu=0.3, density=7850.0), "E"),
        (dict(E=210e9, nu=0.5, density=7850.0), "nu"),
        (dict(E=210e9, nu=-0.1, density=7850.0), "nu"),
        (dict(E=210e9, nu=0.3, density=0.0), "density"),
        (dict(E=210e9, nu=0.3, density=float("nan")), "density"),
        (dict(E=210e9, nu=0.3, density=7850.0, yield_strength=210.0), "yield_strength"),
        (dict(E="steel", nu=0.3, density=7850.0), "E"),
    ],
)
def test_material_rejects_bad_values(kwargs, name):
    with pytest.raises(ValueError, match=rf"^{name}="):
        Material(**kwargs)
