"""The wear law (errata Eq. 15), its units, and the pressure and sliding-speed sources along an impact.

References named in each test: errata Eqs. 15-19, Thornton (1997), Mesarovic & Johnson (2000), Johnson
(1985) Contact Mechanics.
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from contact.theory import mesarovic_johnson_force, mesarovic_johnson_pressure
from wear import (
    WearLaw,
    fe_pressure_history,
    hertz_pressure_history,
    paper_pressure_history,
    sliding_speed,
    wear_coefficient_units,
)


# ---------------------------------------------------------------------------------------------- wear law
def test_units_of_K_follow_errata_eq15():
    # errata "Wear": [K] = m^(1-β) s^(β-1) Pa^(-α); the paper's fit α = 1, β = 0.3
    assert wear_coefficient_units(1.0, 0.3) == "m^(0.7) s^(-0.7) Pa^(-1)"
    assert wear_coefficient_units(1.0, 0.0) == "m^(1) s^(-1) Pa^(-1)"
    assert WearLaw(1e-12, 2.0, 1.0).units == "m^(0) s^(0) Pa^(-2)"


def test_rate_is_K_p_alpha_v_beta():
    law = WearLaw(K=2e-12, alpha=1.5, beta=0.3)
    p, v = np.array([1e8, 3e9, 0.0, -5.0]), np.array([2.0, -0.5, 1.0, 1.0])
    expected = 2e-12 * np.array([1e8**1.5 * 2.0**0.3, 3e9**1.5 * 0.5**0.3, 0.0, 0.0])
    np.testing.assert_allclose(law.rate(p, v), expected, rtol=1e-14)
    # β = 0: speed does not enter, even a stuck point wears (0⁰ = 1)
    assert WearLaw(1e-12, 1.0, 0.0).rate(1e9, 0.0) == pytest.approx(1e-3)
    # β > 0: a stuck point does not wear
    assert WearLaw(1e-12, 1.0, 0.3).rate(1e9, 0.0) == 0.0


def test_K_units_are_checked_against_the_exponents():
    WearLaw(1e-12, 1.0, 0.3, K_units="m^(0.7) s^(-0.7) Pa^(-1)")
    WearLaw(1e-12, 1.0, 0.0, K_units="m s^-1 Pa^-1")
    with pytest.raises(ValueError, match="K_units"):
        WearLaw(1e-12, 1.0, 0.3, K_units="m s^-1 Pa^-1")  # the β = 0 unit given with β = 0.3
    with pytest.raises(ValueError, match="K_units"):
        WearLaw(1e-12, 1.0, 0.3, K_units="mm^3/(N m)")  # an Archard volume coefficient: not this law


@pytest.mark.parametrize(
    "kwargs, name",
    [
        ({"K": -1e-12}, "K"),
        ({"K": math.nan}, "K"),
        ({"K": math.inf}, "K"),
        ({"K": "1e-12"}, "K"),
        ({"K": 1e-12, "alpha": -0.5}, "alpha"),
        ({"K": 1e-12, "alpha": 5.0}, "alpha"),
        ({"K": 1e-12, "beta": -1.0}, "beta"),
        ({"K": 1e-12, "beta": math.nan}, "beta"),
    ],
)
def test_bad_wear_law_names_the_parameter(kwargs, name):
    with pytest.raises(ValueError, match=rf"^{name}="):
        WearLaw(**kwargs)


# ---------------------------------------------------------------------------------------------- pressure
def _elastic_loading(n=50):
    """Hertz loading branch of steel on steel (E* = 115.4 GPa), R = 5 mm."""
    R, E = 5e-3, 115.4e9
    overlap = np.linspace(0.0, 4e-6, n)
    a = np.sqrt(R * overlap)
    force = 4.0 / 3.0 * E * math.sqrt(R) * overlap**1.5
    return R, E, np.linspace(0.0, 1e-6, n), a, force, overlap


def test_hertz_source_is_eq16_with_hertz_peak_pressure():
    # errata Eqs. 16-17: p = p0 √(1 − r²/a²), p0 = 2E*a/(πR) = 3F/(2πa²) on the Hertz branch
    R, E, t, a, f, _ = _elastic_loading()
    ph = hertz_pressure_history(t, np.zeros_like(t), a, f)
    k = 37
    r = np.linspace(0.0, 1.2 * a[k], 50)
    p0 = 2.0 * E * a[k] / (math.pi * R)
    np.testing.assert_allclose(ph.at(k, r), p0 * np.sqrt(np.clip(1 - (r / a[k]) ** 2, 0, None)), atol=1e-3 * p0)
    # its force is the impact's force (trapezoid in r on 257 points: < 0.05%)
    np.testing.assert_allclose(ph.force()[1:], f[1:], rtol=5e-4)


def test_thornton_source_reproduces_thornton_1997_loading():
    # Thornton (1997): Hertz truncated at p_y with a = √(Rδ) and p0 = 2E*a/(πR) carries
    # F = F_y + π p_y R (δ − δ_y), F_y = π³p_y³R²/(6E*²), δ_y = (π p_y / (2E*))² R.
    R, E, p_y = 5e-3, 115.4e9, 1.6 * 400e6
    delta_y = (math.pi * p_y / (2 * E)) ** 2 * R
    f_y = math.pi**3 * p_y**3 * R**2 / (6 * E**2)
    overlap = np.linspace(1.5, 20.0, 8) * delta_y
    a = np.sqrt(R * overlap)
    force = f_y + math.pi * p_y * R * (overlap - delta_y)
    t = np.arange(overlap.size) * 1e-7
    ph = hertz_pressure_history(t, np.zeros_like(t), a, force, limiting_pressure=p_y)
    assert ph.source == "thornton"
    for k in range(overlap.size):
        r = np.linspace(0.0, a[k], 200, endpoint=False)
        p0 = 2.0 * E * a[k] / (math.pi * R)
        expected = np.minimum(p0 * np.sqrt(1 - (r / a[k]) ** 2), p_y)
        np.testing.assert_allclose(ph.at(k, r), expected, atol=2e-3 * p_y)
    np.testing.assert_allclose(ph.force(), force, rtol=5e-4)


def test_paper_source_follows_mesarovic_johnson_on_unloading():
    # Loading past the paper's F_y, then elastic unloading: Eq. 19 with a*, p* of maximum overlap and the
    # force law F/F* = (2/π)[asin x − x√(1−x²)] (Mesarovic & Johnson 2000; contact.theory closed forms).
    R, E = 5e-3, 115.4e9
    a_load = np.linspace(0.0, 2e-4, 40)
    f_load = 4 * E * a_load**3 / (3 * R)
    a_star, f_star = a_load[-1], f_load[-1]
    p_star = f_star / (math.pi * a_star**2)
    x = np.linspace(0.98, 0.0, 30)[1:]
    f_unload = mesarovic_johnson_force(x * a_star, a_star, p_star)
    a = np.concatenate([a_load, 1.1 * a_star * x])  # the impact's own a(t) on unloading is not used
    f = np.concatenate([f_load, f_unload])
    overlap = np.concatenate([a_load**2 / R, a_star**2 / R - 1e-7 * (1 + np.arange(x.size))])
    t = np.arange(a.size) * 1e-7
    f_y = f_load[10]
    ph = paper_pressure_history(t, np.zeros_like(t), a, f, overlap, yield_force=f_y)
    r = np.linspace(0.0, a_star, 300)
    # before yield: Hertz (Eq. 16)
    k = 8
    np.testing.assert_allclose(
        ph.at(k, r),
        1.5 * f[k] / (math.pi * a[k] ** 2) * np.sqrt(np.clip(1 - (r / a[k]) ** 2, 0, None)),
        atol=1e-3 * p_star,
    )
    # after yield on loading: flat F/(πa²); at the maximum: uniform p*
    k = 25
    np.testing.assert_allclose(ph.at(k, r[r < 0.99 * a[k]]), f[k] / (math.pi * a[k] ** 2), rtol=1e-9)
    # unloading: Eq. 19 at the radius implied by the force
    for j in (3, 12, 25):
        k = a_load.size + j
        assert ph.extent[k] == pytest.approx(x[j] * a_star, rel=1e-9)
        expected = mesarovic_johnson_pressure(r, x[j] * a_star, a_star, p_star)
        np.testing.assert_allclose(ph.at(k, r), expected, atol=5e-3 * p_star)
    np.testing.assert_allclose(ph.force()[1:], f[1:], rtol=5e-4, atol=1e-9 * f_star)


def test_paper_source_is_hertz_below_first_yield():
    R, E, t, a, f, overlap = _elastic_loading()
    paper = paper_pressure_history(t, np.zeros_like(t), a, f, overlap, yield_force=2 * f.max())
    hertz = hertz_pressure_history(t, np.zeros_like(t), a, f)
    np.testing.assert_array_equal(paper.pressure, hertz.pressure)


def test_fe_source_resamples_a_nodal_table():
    # An FE-like table: Hertz sampled on graded surface nodes must come back as Hertz (Eq. 16) to within
    # the linear interpolation error of the nodal field.
    R, E, t, a, f, _ = _elastic_loading(30)
    nodes = 1.5 * a[-1] * np.linspace(0.0, 1.0, 121) ** 1.2
    p0 = 2 * E * a / (math.pi * R)
    table = p0[:, None] * np.sqrt(np.clip(1 - (nodes[None, :] / np.maximum(a[:, None], 1e-30)) ** 2, 0, None))
    ph = fe_pressure_history(t, nodes, table - 1e-3, np.zeros_like(t))  # small negative FE noise is dropped
    k = 20
    r = np.linspace(0.0, a[k], 100)
    exact = p0[k] * np.sqrt(1 - (r / a[k]) ** 2)
    np.testing.assert_allclose(ph.at(k, r[:-3]), exact[:-3], atol=0.01 * p0[k])  # FE nodal data: linear in r
    assert np.all(ph.extent >= a) and np.all(ph.extent[1:] <= a[1:] + 2 * np.diff(nodes).max())
    np.testing.assert_allclose(ph.force()[5:], f[5:], rtol=0.01)


def test_sliding_speed_models():
    # "sliding": |v_t − Rω| only while in gross sliding; "kinematic": always
    hist = SimpleNamespace(
        t=np.arange(5) * 1e-6,
        slip_velocity=np.array([-1.0, -0.5, 0.2, 0.3, -2.0]),
        sliding=np.array([True, False, False, True, True]),
    )
    np.testing.assert_array_equal(sliding_speed(hist, "sliding").speed, [1.0, 0.0, 0.0, 0.3, 2.0])
    np.testing.assert_array_equal(sliding_speed(hist, "kinematic").speed, [1.0, 0.5, 0.2, 0.3, 2.0])
    with pytest.raises(ValueError, match="^model="):
        sliding_speed(hist, "slip")
