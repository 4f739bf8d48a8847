"""The half-space contact solver (contact.halfspace) against Hertz's closed form.

Reference: Hertz (1882) as given by Johnson, Contact Mechanics (1985), §4.2: for a sphere of radius R pressed with
force W on a half-space of effective modulus E*, a = (3WR/4E*)^(1/3), p0 = 3W/(2πa²), δ = a²/R.
"""

import math

import numpy as np
import pytest

from contact.halfspace import halfspace_contact, influence_coefficients
from contact.theory import hertz_contact_radius_from_force, hertz_overlap, hertz_peak_pressure

R = 2.5e-3
E_STAR = 1.5e11
W = 200.0


def sphere_gap(cells: int, half_width: float, offset: float = 0.0):
    spacing = 2.0 * half_width / cells
    x = (np.arange(cells) - (cells - 1) / 2) * spacing
    xx, yy = np.meshgrid(x, x)
    return (xx**2 + yy**2) / (2.0 * R) + offset, spacing


@pytest.mark.parametrize("cells", [48, 96])
def test_hertz_sphere(cells):
    a = hertz_contact_radius_from_force(W, R, E_STAR)
    gap, spacing = sphere_gap(cells, 2.0 * a)
    sol = halfspace_contact(gap, spacing, W, E_STAR)
    # 12 and 24 cells across a: the cell-averaged peak and the approach within 1%, the area within a ring of cells
    assert sol.max_pressure == pytest.approx(hertz_peak_pressure(W, R, E_STAR), rel=0.01)
    assert sol.approach == pytest.approx(hertz_overlap(W, R, E_STAR), rel=0.01)
    ring = 2.0 * math.pi * a * spacing
    assert abs(sol.contact_area - math.pi * a * a) < ring
    assert sol.pressure.sum() * spacing**2 == pytest.approx(W, rel=1e-12)
    assert np.all(sol.gap >= 0.0)


def test_error_falls_with_refinement():
    a = hertz_contact_radius_from_force(W, R, E_STAR)
    errors = []
    for cells in (24, 48, 96):
        gap, spacing = sphere_gap(cells, 2.0 * a)
        errors.append(abs(halfspace_contact(gap, spacing, W, E_STAR).approach / hertz_overlap(W, R, E_STAR) - 1))
    assert errors[0] > errors[1] > errors[2]


def test_offset_gap_shifts_the_approach_only():
    # a gap raised everywhere by c is the same contact with the approach larger by c
    a = hertz_contact_radius_from_force(W, R, E_STAR)
    gap, spacing = sphere_gap(48, 2.0 * a)
    base = halfspace_contact(gap, spacing, W, E_STAR)
    raised = halfspace_contact(gap + 1e-6, spacing, W, E_STAR)
    assert raised.approach - base.approach == pytest.approx(1e-6, rel=1e-6)
    np.testing.assert_allclose(raised.pressure, base.pressure, rtol=1e-9, atol=1e-9 * base.max_pressure)


def test_influence_of_a_cell_far_away_is_a_point_load():
    # Boussinesq: a point load P at distance s displaces the surface by P / (π E* s) (Johnson 1985, eq. 3.22a); a
    # unit pressure on a cell is the load spacing² (N), so k (m/Pa) = spacing² / (π E* s) far away
    spacing = 1e-6
    k = influence_coefficients((64, 64), spacing, E_STAR)
    s = 40 * spacing
    assert k[0, 40] == pytest.approx(spacing**2 / (math.pi * E_STAR * s), rel=1e-3)


def test_bad_input():
    gap, spacing = sphere_gap(16, 1e-3)
    with pytest.raises(ValueError, match="force"):
        halfspace_contact(gap, spacing, -1.0, E_STAR)
    with pytest.raises(ValueError, match="effective_modulus"):
        halfspace_contact(gap, spacing, W, 150.0)
    with pytest.raises(ValueError, match="gap"):
        halfspace_contact(gap[0], spacing, W, E_STAR)
    with pytest.raises(ValueError, match="edge of the grid"):
        small, h = sphere_gap(16, 0.3 * hertz_contact_radius_from_force(W, R, E_STAR))
        halfspace_contact(small, h, W, E_STAR)


def test_sphere_on_a_flat_axisymmetric_surface_is_hertz():
    """sphere_on_axisymmetric_surface with depth 0: Hertz (exact sphere; (a/R)² = 4e-3 from the paraboloid)."""
    from contact.halfspace import sphere_on_axisymmetric_surface

    a = hertz_contact_radius_from_force(W, R, E_STAR)
    sol, rho = sphere_on_axisymmetric_surface(R, np.zeros_like, W, E_STAR, 2.0 * a, 96)
    assert rho.shape == (96, 96) and rho.min() > 0.0
    assert sol.max_pressure == pytest.approx(hertz_peak_pressure(W, R, E_STAR), rel=0.01)
    assert sol.approach == pytest.approx(hertz_overlap(W, R, E_STAR), rel=0.01)
    assert sol.contact_area == pytest.approx(math.pi * a * a, rel=0.03)
    with pytest.raises(ValueError, match=r"half_width=0\.01 .*m"):
        sphere_on_axisymmetric_surface(R, np.zeros_like, W, E_STAR, 0.01)
