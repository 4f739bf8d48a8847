"""Acceptance 3 and 4 of issue 3: elastic-plastic loading and unloading.

References
- Kogut & Etsion (2002), J. Appl. Mech. 69:657, Eqs. 11-14: P/P_c = 1.03 w^1.425 (1 ≤ w ≤ 6),
  1.40 w^1.263 (6 ≤ w ≤ 110); A/A_c = 0.93 w^1.136 (1 ≤ w ≤ 6), 0.94 w^1.146 (6 ≤ w ≤ 110), w = δ/δ_c;
  the plastic zone reaches the surface between w ≈ 6 (their finding); the issue accepts 4 to 10.
  Their case is a deformable sphere on a rigid flat, ours a rigid sphere on a deformable flat:
  identical while elastic and close in early plasticity (the flattened sphere and the dented flat
  share the contact geometry to first order), hence the 15% tolerance.
- Any elastic unloading: dF/dδ = 2E*a (Johnson 1985 Eq. 3.22; errata, end of the yield section).
- Mesarovic & Johnson (2000), errata Eq. 19: elastic unloading from a uniform p* over a*.

Meshes: reduced case meshes (16 P2 elements across the largest contact radius, 10 across the first
yield contact radius) — the mesh convergence test shows F changes by < 2% between this and the
default mesh, far inside the 15% tolerance, while a wrong return map (no plasticity, or yield at
√3 Y) moves P/P_c at w = 20 by > 30%.
"""

import math

import numpy as np
import pytest

import fem
from contact.materials import Material, effective_modulus
from contact.theory import first_yield, mesarovic_johnson_pressure

R = 10e-3
PLATE = Material(E=210e9, nu=0.3, density=7850.0, yield_strength=210e6)
E_STAR = effective_modulus(Material.rigid(), PLATE)
FY = first_yield(R, E_STAR, 210e6, 0.3)


def kogut_etsion(w):
    if w <= 6.0:
        return 1.03 * w**1.425, 0.93 * w**1.136
    return 1.40 * w**1.263, 0.94 * w**1.146


@pytest.fixture(scope="module")
def cycle_w20():
    w_load = np.r_[np.linspace(0.5, 2.0, 4), np.linspace(2.5, 6.0, 8), np.linspace(7.0, 20.0, 9)]
    d_max = 20.0 * FY.overlap
    # a small first unloading step for the unloading stiffness, then down to zero
    w_unload = np.r_[20.0 * 0.995, np.linspace(19.0, 0.0, 12)]
    path = np.r_[w_load, w_unload] * FY.overlap
    mesh = fem.plate_mesh(R, PLATE, d_max, contact_elements=16, yield_elements=10)
    return fem.indent(R, PLATE, path, mesh=mesh, keep_states=True)


@pytest.mark.parametrize("w", [2.0, 6.0, 20.0])
def test_kogut_etsion_loading(cycle_w20, w):
    k = int(np.argmin(np.abs(cycle_w20.overlap / FY.overlap - w)))
    assert abs(cycle_w20.overlap[k] / FY.overlap - w) < 1e-9
    p_ref, a_ref = kogut_etsion(w)
    p = cycle_w20.force[k] / FY.force
    area = (cycle_w20.contact_radius[k] / FY.contact_radius) ** 2
    print(
        f"w={w}: P/Pc FE {p:.3f} vs KE {p_ref:.3f} ({p / p_ref - 1:+.1%}); A/Ac FE {area:.3f} vs {a_ref:.3f} "
        f"({area / a_ref - 1:+.1%})"
    )
    assert abs(p / p_ref - 1.0) < 0.15
    assert abs(area / a_ref - 1.0) < 0.15


def test_plastic_zone_reaches_surface_between_w4_and_w10(cycle_w20):
    w = cycle_w20.overlap / FY.overlap
    regimes = np.array(cycle_w20.regime)
    first_surface = w[np.flatnonzero(regimes == "surface-plastic")[0]]
    last_contained = w[np.flatnonzero(regimes == "contained")[-1]]
    print(f"plastic zone reaches the surface between w = {last_contained:.2f} and {first_surface:.2f}")
    assert 4.0 <= first_surface <= 10.0
    assert last_contained < first_surface


def test_unloading_stiffness_is_2_estar_a(cycle_w20):
    # Elastic unloading: dF/dδ = 2E*a at the start of unloading (a = contact radius at δ_max).
    k = int(np.argmax(cycle_w20.overlap))
    dF = cycle_w20.force[k] - cycle_w20.force[k + 1]
    dd = cycle_w20.overlap[k] - cycle_w20.overlap[k + 1]
    a = 0.5 * (cycle_w20.contact_radius[k] + cycle_w20.contact_radius[k + 1])
    ratio = (dF / dd) / (2.0 * E_STAR * a)
    print(f"unloading stiffness / 2E*a = {ratio:.4f}")
    assert abs(ratio - 1.0) < 0.03


def test_unloading_leaves_a_dent_and_force_law(cycle_w20):
    assert cycle_w20.force[-1] == 0.0
    assert cycle_w20.residual_depth[0] > 0.0  # a permanent dent on the axis
    law = cycle_w20.force_law()
    assert law.unloading_max_overlap.size == 1
    assert 0.0 < law.residual_overlap[0] < law.unloading_max_overlap[0]


def test_unload_from_kept_state_reproduces_the_unloading(cycle_w20):
    # the restart from kept states reproduces the run's own unloading: the loading branch is path independent
    # and the unloading elastic, so 20 equal steps from w = 20 (through w = 19) meet the run's own 19.9 → 19 →
    # 17.3 → … → 0 at w = 19 and at the end (residual dent), whatever the step sizes (12 large steps stalled
    # Newton at the contact loss before the contact set could take any shape)
    again = cycle_w20.unload_from(cycle_w20.overlap.max(), steps=20)
    k = int(np.argmax(cycle_w20.overlap))
    assert abs(cycle_w20.overlap[k + 2] / FY.overlap - 19.0) < 1e-9
    j = int(np.argmin(np.abs(again.overlap - cycle_w20.overlap[k + 2])))
    assert abs(again.overlap[j] / cycle_w20.overlap[k + 2] - 1.0) < 1e-12
    assert abs(again.force[j] / cycle_w20.force[k + 2] - 1.0) < 1e-3
    assert again.force[-1] == 0.0
    assert abs(again.residual_depth[0] / cycle_w20.residual_depth[0] - 1.0) < 1e-3
    # a second unloading from a lower maximum adds a curve to the family
    cycle_w20.unload_from(10.0 * FY.overlap, steps=8)
    law = cycle_w20.force_law()
    assert law.unloading_max_overlap.size == 2
    assert law.residual_overlap[0] < law.residual_overlap[1]


def test_mesarovic_johnson_unloading_profile():
    # Deep plastic load (w = 50) then unloading: FE pressure vs Mesarovic & Johnson (2000), Eq. 19,
    # built from the FE's own p* (mean pressure at the maximum) and a*. Reduced mesh (16 elements over a*).
    w_path = np.r_[np.geomspace(1.0, 50.0, 14), np.linspace(50.0, 40.0, 11)[1:], np.linspace(39.0, 30.0, 10)]
    path = w_path * FY.overlap
    mesh = fem.plate_mesh(R, PLATE, path.max(), contact_elements=16, yield_elements=0)
    res = fem.indent(R, PLATE, path, mesh=mesh)
    k = int(np.argmax(res.overlap))
    a_star = res.contact_radius[k]
    p_star = res.mean_pressure[k]
    r = res.surface_r
    for target in (0.75, 0.5):
        ratios = res.contact_radius[k:] / a_star
        j = k + int(np.argmin(np.abs(ratios - target)))
        a = res.contact_radius[j]
        inside = r <= a_star
        ref = mesarovic_johnson_pressure(r[inside], a, a_star, p_star)
        rms = math.sqrt(np.mean((res.pressure[j][inside] - ref) ** 2)) / p_star
        print(f"a/a* = {a / a_star:.3f}: RMS(FE − MJ)/p* = {rms:.3f}")
        assert abs(a / a_star - target) < 0.06
        # measured 0.071 / 0.044 (Eq. 19 is itself an approximation of the unloading profile); the node-to-node
        # mode of a pressure read off the quadratic nodes (p = M⁻¹P) gave 0.14 / 0.10
        assert rms < 0.10
