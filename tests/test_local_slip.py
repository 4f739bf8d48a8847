"""The local slip of the wear law on the axisymmetric plate (``wear.speed = "local"``, :mod:`wear.slip`): the plate
surface's radial motion under the ball plus the impact's contact-point slip.

Reference: the elastic half-space under a Hertz pressure (Johnson 1985, *Contact Mechanics*, Eq. 3.41a): inside the
contact the surface moves radially by

    u_r(r) = −(1 − 2ν)(1 + ν)/(3E) · p0 a²/r · [1 − (1 − r²/a²)^{3/2}],

with a = √(Rδ), p0 = 2E*a/(πR). The FE plate is a rigid sphere on a plate of modulus E' = E*(1 − ν²) and ν, so
that in time, with ȧ = R δ̇/(2a), the plate surface slips under the ball at

    u̇_r(r) = −2(1 − 2ν)/(π R (1 − ν)) · (a/r) (a − √(a² − r²)) ȧ,

and a normal elastic impact wears w(r) = ∫ K p^α |u̇_r|^β dt, integrated here by a quadrature of our own.
"""

import math

import numpy as np
import pytest

import fem
from contact import Material, effective_modulus, simulate_impact
from wear import WearLaw, hertz_pressure_history, integrate_wear, sliding_speed
from wear.case import JOBS
from wear.chain.single import run
from wear.integrate import axisymmetric_wear_depth
from wear.slip import RadialSlip

STEEL = Material(E=210e9, nu=0.3, density=7850.0)
ALUMINA = Material(E=380e9, nu=0.23, density=4000.0)
RADIUS = 2.5e-3


def johnson_radial_displacement(r, a, radius, e_star, nu):
    """u_r (m) of the E*-plate's surface at radii ``r`` (m) under the Hertz pressure of contact radius ``a`` (m)."""
    r = np.asarray(r, float)
    e_plate = e_star * (1.0 - nu**2)
    p0 = 2.0 * e_star * a / (math.pi * radius)
    scale = -(1.0 - 2.0 * nu) * (1.0 + nu) / (3.0 * e_plate) * p0 * a**2
    with np.errstate(over="ignore"):  # (r/a)² → inf far outside a tiny contact: the clip takes it to 0
        inside = 1.0 - np.clip(1.0 - (r / a) ** 2, 0.0, None) ** 1.5
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(r > 0.0, scale * inside / r, 0.0)


def johnson_radial_rate(r, a, a_dot, radius, nu):
    """u̇_r (m/s) of the surface inside the contact (module docstring)."""
    r = np.asarray(r, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        shape = np.where(r > 0.0, (a / r) * (a - np.sqrt(np.maximum(a * a - r * r, 0.0))), 0.0)
    return -2.0 * (1.0 - 2.0 * nu) / (math.pi * radius * (1.0 - nu)) * shape * a_dot


def reference_depth(t, overlap, r, law, radius, e_star, nu):
    """w(r) (m) of a normal elastic impact of overlap history ``overlap`` (m) at ``t`` (s): Hertz's pressure and
    Johnson's radial slip, the trapezoidal rule on the impact's own (dense) time samples."""
    a = np.sqrt(radius * np.maximum(overlap, 0.0))
    a_dot = np.gradient(a, t)
    rr = np.asarray(r, float)[None, :]
    p0 = 2.0 * e_star * a / (math.pi * radius)
    inside = rr < a[:, None]
    with np.errstate(over="ignore"):  # (r/a)² → inf before first contact: the clip takes it to 0
        squared = (rr / np.maximum(a, 1e-300)[:, None]) ** 2
    p = np.where(inside, p0[:, None] * np.sqrt(np.clip(1.0 - squared, 0, None)), 0)
    rate = johnson_radial_rate(rr, a[:, None], a_dot[:, None], radius, nu)
    return np.trapezoid(law.K * p**law.alpha * np.abs(rate) ** law.beta * inside, t, axis=0)


def test_fe_surface_moves_radially_as_johnsons_half_space():
    """The axisymmetric FE plate pressed elastically by a rigid sphere (R 10 mm, δ 1 µm, the default mesh): the
    surface nodes' u_r within 1% of its largest value of Johnson's Eq. 3.41 everywhere within 2a (measured: 0.16% at
    the centre to 0.5% at the edge)."""
    radius, overlap = 10e-3, 1e-6
    mesh = fem.plate_mesh(radius, STEEL, overlap)
    result = fem.indent(radius=radius, plate=STEEL, overlaps=np.linspace(0.0, overlap, 5)[1:], mesh=mesh)
    a = math.sqrt(radius * overlap)
    r = result.surface_r
    near = r < 2.0 * a
    expected = johnson_radial_displacement(r[near], a, radius, STEEL.E / (1 - STEEL.nu**2), STEEL.nu)
    got = result.radial_displacement[-1][near]
    assert np.max(np.abs(got - expected)) < 0.01 * np.max(np.abs(expected))
    assert np.all(got[r[near] > 0.0] < 0.0)  # inwards, towards the axis


@pytest.fixture(scope="module")
def hertz_impact():
    return simulate_impact(RADIUS, ALUMINA, STEEL, 2.0, 0.0, 0.0, normal_model="hertz", history=True)


@pytest.mark.parametrize("engine", ["numba", "numpy"])
def test_local_slip_wear_of_a_normal_hertz_impact_is_the_quadrature(hertz_impact, engine):
    """A normal elastic Hertz impact, its pressure the Hertz source and its surface's radial motion Johnson's
    (sampled at 400 times): the wear map's radial profile within 1% of the largest depth of the quadrature of
    ∫ K p |u̇_r|^0.3 dt, and its volume within 1% (both engines). Without the radial motion the contact-point slip
    is 0 at normal incidence and nothing wears."""
    imp = hertz_impact
    h = imp.history
    e_star = effective_modulus(ALUMINA, STEEL)
    law = WearLaw(K=1e-11, alpha=1.0, beta=0.3)
    nu = STEEL.nu
    ph = hertz_pressure_history(h.t, h.contact_x, h.contact_radius, h.normal_force)
    times = np.linspace(h.t[0], h.t[-1], 400)
    radii = np.linspace(0.0, 1.2 * imp.max_contact_radius, 241)
    a_t = np.sqrt(RADIUS * np.interp(times, h.t, np.maximum(h.overlap, 0.0)))
    table = np.array([johnson_radial_displacement(radii, max(a, 1e-300), RADIUS, e_star, nu) for a in a_t])
    speed = sliding_speed(imp, "local", RadialSlip(times, radii, table))
    wm = integrate_wear(ph, speed, law, density=STEEL.density, engine=engine)
    r = wm.x - h.contact_x[0]  # the grid nodes along the centre line, from the centre out (w ∝ r^0.3 at r → 0)
    along = (r >= 0.0) & (r <= imp.max_contact_radius)
    r, got = r[along], wm.centreline()[along]
    expected = reference_depth(h.t, h.overlap, r, law, RADIUS, e_star, nu)
    print(f"max depth {wm.max_depth_m:.4e} (quadrature {expected.max():.4e}), volume {wm.volume_m3:.4e}")
    assert np.max(np.abs(got - expected)) < 0.01 * expected.max()
    volume = float(np.trapezoid(2.0 * math.pi * r * expected, r))
    assert wm.volume_m3 == pytest.approx(volume, rel=0.01)
    profile = axisymmetric_wear_depth(ph, speed, law, r)
    assert np.max(np.abs(profile - expected)) < 0.01 * expected.max()
    assert integrate_wear(ph, sliding_speed(imp, "sliding"), law, density=STEEL.density).volume_m3 == 0.0


def test_run_at_normal_incidence_wears_by_the_plates_radial_slip():
    """``impactwear run``'s chain at normal incidence on an elastic plate (the default alumina ball on a Ti-6Al-4V
    plate without yield, 1 m/s): the worn volume and deepest wear of the local slip against the quadrature of Hertz's
    pressure and Johnson's radial slip along the run's own overlap history, within 3% (the FE plate's pressure and
    u_r against the closed forms; measured: see the print)."""
    case = JOBS["run"].default_case()
    case = case.with_(
        impact={"angle": 0.0, "speed": 1.0},
        plate={"yield_strength": None},
        output={"render": False, "figures": False},
    )
    result = run(case)
    imp, law = result.impact, case.wear.wear_law()
    e_star, nu = effective_modulus(case.ball.material(), case.plate.material()), case.plate.nu
    r = np.linspace(0.0, 1.02 * imp.max_contact_radius, 200)
    expected = reference_depth(imp.history.t, imp.history.overlap, r, law, case.ball.radius, e_star, nu)
    volume = float(np.trapezoid(2.0 * math.pi * r * expected, r))
    wm = result.wear
    print(f"volume {wm.volume_m3:.4e} / {volume:.4e}, deepest {wm.max_depth_m:.4e} / {expected.max():.4e}")
    assert wm.volume_m3 == pytest.approx(volume, rel=0.03)
    assert wm.max_depth_m == pytest.approx(expected.max(), rel=0.03)


def test_the_local_slip_needs_the_plates_pressure():
    """``wear.speed = "local"`` with a closed-form pressure is refused in one line naming both keys."""
    with pytest.raises(ValueError, match=r"^wear.speed='local' .* wear.pressure='fe' \(got 'hertz'\)"):
        JOBS["run"].default_case().with_(wear={"pressure": "hertz"})
