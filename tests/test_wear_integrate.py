"""Wear integration over the moving contact patch (issue 4, acceptance tests 1-4).

Impacts come from two independent sources: ``contact.simulate_impact`` (the project's H-DD engine) and a
small reference model integrated here with scipy (Hertz normal force with an optional dashpot, rigid-body
Coulomb sliding until the contact point sticks; errata Eqs. 3-4 and Johnson 1985 §11.4).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
from scipy.integrate import quad, solve_ivp
from scipy.special import gamma

from contact import simulate_impact
from contact.materials import Material, effective_modulus
from contact.theory import sphere_mass
from wear import (
    WearLaw,
    axisymmetric_wear_depth,
    fe_pressure_history,
    hertz_pressure_history,
    integrate_volume,
    integrate_wear,
    pressure_history,
    sliding_speed,
    wear_from_impact,
)
from wear.integrate import integrate_wear_numpy
from wear.slip import SlidingSpeed

BALL = Material(E=380e9, nu=0.23, density=4000.0, name="alumina")
PLATE = Material(E=70e9, nu=0.25, density=2700.0, yield_strength=100e6, name="aluminium")
RADIUS = 2.5e-3


def reference_impact(speed=3.9, angle=0.0, damping=0.0, friction=0.092, samples=1501):
    """Oblique impact integrated with scipy: m δ'' = −F, F = max(k δ^{3/2} + c √δ δ', 0) (Hertz + dashpot),
    rigid-body Coulomb sliding (I = 2/5 mR²): with the normal impulse J(t) = ∫F dt, the contact-point slip is
    s = v_t − 3.5 μ J/m until it reaches 0, then the ball rolls (s = 0, v_t constant).
    Returns an ImpactResult-like namespace with a History."""
    e_star = effective_modulus(BALL, PLATE)
    mass = sphere_mass(RADIUS, BALL.density)
    v_n, v_t = speed * math.cos(math.radians(angle)), speed * math.sin(math.radians(angle))
    k = 4.0 / 3.0 * e_star * math.sqrt(RADIUS)
    j_stick = mass * v_t / (3.5 * friction)

    def force(d, dd):
        d = np.maximum(d, 0.0)
        return np.maximum(k * d**1.5 + damping * np.sqrt(d) * dd, 0.0)

    def rhs(t, y):
        d, dd, impulse, _x = y
        f = force(d, dd)
        return [dd, -f / mass, f, v_t - friction * min(impulse, j_stick) / mass]

    def separate(t, y):
        return y[0] if t > 0 else 1.0

    separate.terminal, separate.direction = True, -1
    sol = solve_ivp(
        rhs,
        (0.0, 1e-3),
        [0.0, v_n, 0.0, 0.0],
        events=[separate],
        rtol=1e-11,
        atol=1e-18,
        dense_output=True,
        max_step=1e-8,
    )
    t_c = sol.t_events[0][0]
    t = np.linspace(0.0, t_c, samples)
    d, dd, impulse, x = sol.sol(t)
    d[-1] = 0.0
    slip = np.maximum(v_t - 3.5 * friction * impulse / mass, 0.0)
    f = force(d, dd)
    hist = SimpleNamespace(
        t=t,
        overlap=d,
        normal_force=f,
        contact_radius=np.sqrt(RADIUS * np.maximum(d, 0.0)),
        slip_velocity=slip,
        sliding=slip > 0.0,
        contact_x=x,
        center_x=x,
    )
    e = -sol.sol(t_c)[1] / v_n
    return SimpleNamespace(
        history=hist, radius=RADIUS, ball=BALL, plate=PLATE, mass=mass, normal_restitution=e, speed=speed, angle=angle
    )


def engine_impact(speed=3.9, angle=0.0, restitution=1.0, friction=0.092, normal_model="hertz"):
    return simulate_impact(
        radius=RADIUS,
        ball=BALL,
        plate=PLATE,
        speed=speed,
        angle=angle,
        friction=friction,
        restitution=restitution,
        normal_model=normal_model,
    )


# ------------------------------------------------------------------------------- acceptance 1: steady track
@pytest.mark.parametrize("alpha, beta", [(1.0, 0.0), (1.0, 0.3), (2.0, 1.0), (0.5, 0.0)])
def test_steady_sliding_hertz_track_matches_closed_form(alpha, beta):
    """A Hertz contact (a, p0) sliding at speed v along x at constant load: integrating Eq. 15 along the
    track, h(y) = K v^(β−1) p0^α a (1 − y²/a²)^((α+1)/2) √π Γ(α/2+1)/Γ(α/2+3/2) (issue 4, acceptance 1;
    for α = 1: K v^(β−1) p0 (πa/2)(1 − y²/a²)). Tolerance 1% of the maximum depth."""
    a, p0, v, K = 1e-4, 1.2e9, 2.0, 1e-13
    force = 2.0 / 3.0 * math.pi * a * a * p0
    t = np.linspace(0.0, 8 * a / v, 9)  # coarse samples: the sub-steps do the motion
    ph = hertz_pressure_history(t, v * t, np.full(t.size, a), np.full(t.size, force))
    law = WearLaw(K, alpha, beta)
    wm = integrate_wear(ph, SlidingSpeed(t, np.full(t.size, v)), law, density=7800.0)
    mid = np.argmin(np.abs(wm.x - 4 * a))  # every point of this column saw the whole patch pass
    h = wm.depth[:, mid]
    y = wm.y
    shape = math.sqrt(math.pi) * gamma(alpha / 2 + 1) / gamma(alpha / 2 + 1.5)
    exact = K * v ** (beta - 1) * p0**alpha * a * np.clip(1 - (y / a) ** 2, 0, None) ** ((alpha + 1) / 2) * shape
    err = np.max(np.abs(h - exact)) / exact.max()
    assert err < 0.01, f"max error {err:.2e} of max depth"
    # the scar is 2a wide at its 1% depth threshold (depth ∝ (1 − y²/a²)^((α+1)/2) across)
    width = 2 * a * math.sqrt(1 - 0.01 ** (2 / (alpha + 1)))
    assert wm.scar_width_m == pytest.approx(width, rel=0.01)


# ----------------------------------------------------------------------------- acceptance 2: impulse identity
def _impulse_cases():
    cases = [
        pytest.param(lambda: reference_impact(angle=0.0), "hertz", id="ref-normal"),
        pytest.param(lambda: reference_impact(angle=45.0), "hertz", id="ref-45deg"),
        pytest.param(lambda: reference_impact(angle=60.0, damping=2e4), "hertz", id="ref-60deg-damped"),
        pytest.param(lambda: reference_impact(angle=30.0, speed=8.0), "thornton", id="ref-thornton"),
        pytest.param(lambda: reference_impact(angle=30.0, speed=8.0), "paper", id="ref-paper"),
    ]
    for angle, e, source, model in [
        (0.0, 1.0, "hertz", "hertz"),
        (50.0, 0.8, "hertz", "hertz"),
        (70.0, 0.98, "paper", "hertz"),
        (30.0, 1.0, "thornton", "thornton"),
    ]:
        cases.append(
            pytest.param(
                lambda angle=angle, e=e, model=model: engine_impact(
                    speed=5.0, angle=angle, restitution=e, normal_model=model
                ),
                source,
                id=f"engine-{angle:g}deg-e{e:g}-{source}",
            )
        )
    return cases


@pytest.mark.parametrize("make, source", _impulse_cases())
def test_worn_volume_is_K_times_normal_impulse(make, source):
    """α = 1, β = 0: ∫∫ K p dA dt = K ∫F dt = K m V_n (1 + e) by conservation of momentum (issue 4,
    acceptance 2), whatever the pressure shape, as long as it carries the impact's force. Within 0.5%."""
    impact = make()
    law = WearLaw(2e-13, 1.0, 0.0)
    wm = integrate_wear(pressure_history(impact, source), sliding_speed(impact), law, density=PLATE.density)
    speed_n = impact.speed * math.cos(math.radians(impact.angle))
    expected = law.K * impact.mass * speed_n * (1.0 + impact.normal_restitution)
    assert wm.volume_m3 == pytest.approx(expected, rel=5e-3)
    assert wm.mass_kg == pytest.approx(PLATE.density * wm.volume_m3, rel=1e-12)


# --------------------------------------------------------------------------- acceptance 3: normal Hertz profile
TABLE_RHO = np.array([0.0, 0.25, 0.5, 0.75, 0.9, 1.0])
TABLE_H = np.array([1.0, 0.930, 0.727, 0.409, 0.173, 0.0])  # issue 4, acceptance 3


def _hertz_impact_profile(rho):
    """Independent quadrature: for a Hertz impact p0 ∝ a and a² = Rδ, so h(r) ∝ ∫ √(a² − r²) dt; with
    dt = dδ / δ', δ'² ∝ 1 − (δ/δmax)^{5/2} (energy), u = δ/δmax: h(ρ) ∝ ∫_{ρ²}^1 √(u − ρ²) / √(1 − u^{5/2}) du."""

    def smooth(u):  # √((1 − u)/(1 − u^{5/2})), → √(2/5) at u = 1
        return math.sqrt(0.4) if u >= 1.0 else math.sqrt((1 - u) / (1 - u**2.5))

    def h(r):
        if r >= 1.0:
            return 0.0
        return quad(smooth, r * r, 1.0, weight="alg", wvar=(0.5, -0.5), epsabs=0, epsrel=1e-12)[0]

    return np.array([h(r) for r in rho]) / h(0.0)


def test_hertz_impact_profile_table_by_quadrature():
    np.testing.assert_allclose(_hertz_impact_profile(TABLE_RHO), TABLE_H, atol=1e-3)


@pytest.mark.parametrize(
    "make",
    [
        pytest.param(lambda: reference_impact(), id="ref"),
        pytest.param(lambda: engine_impact(), id="engine"),
    ],
)
def test_normal_hertz_impact_depth_profile(make):
    """h(r)/h(0) of a normal Hertz impact with α = 1, β = 0 equals the table of issue 4 (acceptance 3)
    within 0.01, on the 2-D map and on the axisymmetric profile."""
    impact = make()
    ph, v = pressure_history(impact, "hertz"), sliding_speed(impact, "kinematic")
    law = WearLaw(1e-12, 1.0, 0.0)
    a_max = ph.max_extent
    h = axisymmetric_wear_depth(ph, v, law, TABLE_RHO * a_max)
    np.testing.assert_allclose(h / h[0], TABLE_H, atol=0.01)
    wm = integrate_wear(ph, v, law, density=PLATE.density)
    line = wm.centreline()
    x = wm.x - ph.contact_x[0]
    h2 = np.interp(TABLE_RHO * a_max, x, line)
    np.testing.assert_allclose(h2 / line.max(), TABLE_H, atol=0.01)
    assert wm.max_depth_m == pytest.approx(h[0], rel=1e-3)


# ----------------------------------------------------------------------- acceptance 4: no slip, N impacts
@pytest.mark.parametrize(
    "make",
    [
        pytest.param(lambda: reference_impact(angle=0.0), id="ref"),
        pytest.param(lambda: engine_impact(angle=0.0), id="engine"),
    ],
)
def test_normal_impact_with_sliding_speed_wears_nothing(make):
    """θ = 0: the contact point never slides, so with β > 0 and the "sliding" speed Eq. 15 gives no wear
    (issue 4, acceptance 4)."""
    impact = make()
    ph = pressure_history(impact, "hertz")
    wm = integrate_wear(ph, sliding_speed(impact, "sliding"), WearLaw(1e-12, 1.0, 0.3), density=PLATE.density)
    assert wm.volume_m3 == 0.0 and wm.max_depth_m == 0.0 and not np.any(wm.depth)


@pytest.mark.parametrize(
    "make",
    [
        pytest.param(lambda: reference_impact(angle=55.0), id="ref"),
        pytest.param(lambda: engine_impact(angle=55.0), id="engine"),
    ],
)
def test_n_identical_impacts_wear_n_times_one(make):
    """Without geometry update Eq. 15 is additive over impacts: N impacts give N × one (acceptance 4)."""
    impact = make()
    ph, v = pressure_history(impact, "hertz"), sliding_speed(impact, "sliding")
    law = WearLaw(1e-12, 1.0, 0.3)
    one = integrate_wear(ph, v, law, density=PLATE.density)
    assert one.volume_m3 > 0.0
    many = one
    for _ in range(4):
        many = integrate_wear(ph, v, law, density=PLATE.density, on=many)
    np.testing.assert_allclose(many.depth, 5 * one.depth, rtol=1e-12, atol=0)
    assert many.volume_m3 == pytest.approx(5 * one.volume_m3, rel=1e-12)
    assert many.scar_length_m == pytest.approx(one.scar_length_m, rel=1e-12)


# ----------------------------------------------------------------------------------------- other checks
def test_fe_table_of_hertz_reproduces_hertz_source():
    """An FE-like table (Hertz, Eq. 16, sampled on 80 graded surface nodes at 60 steps) gives the wear of the
    "hertz" source: volume and maximum depth within 1% (linear interpolation in time and on the nodes)."""
    impact = reference_impact(angle=40.0)
    h = impact.history
    hertz = pressure_history(impact, "hertz")
    steps = np.linspace(0.0, h.t[-1], 60)
    a = np.interp(steps, h.t, h.contact_radius)
    force = np.interp(steps, h.t, h.normal_force)
    nodes = 1.5 * hertz.max_extent * np.linspace(0.0, 1.0, 80) ** 1.3
    p0 = np.where(a > 0, 1.5 * force / (math.pi * np.maximum(a, 1e-30) ** 2), 0.0)
    table = p0[:, None] * np.sqrt(np.clip(1 - (nodes[None, :] / np.maximum(a[:, None], 1e-30)) ** 2, 0, None))
    fe = pressure_history(impact, "fe", fe=(steps, nodes, table))
    law = WearLaw(1e-12, 1.0, 0.3)
    v = sliding_speed(impact, "kinematic")
    ref = integrate_wear(hertz, v, law, density=PLATE.density)
    got = integrate_wear(fe, v, law, density=PLATE.density)
    assert got.volume_m3 == pytest.approx(ref.volume_m3, rel=0.01)
    assert got.max_depth_m == pytest.approx(ref.max_depth_m, rel=0.01)
    direct = fe_pressure_history(steps, nodes, table, np.interp(steps, h.t, h.contact_x))
    np.testing.assert_array_equal(direct.pressure, fe.pressure)


def test_numba_kernel_equals_numpy_reference():
    """The parallel kernel and the plain numpy implementation of the same quadrature agree to rounding."""
    impact = reference_impact(angle=65.0, samples=301)
    ph, v = pressure_history(impact, "paper", yield_force=50.0), sliding_speed(impact, "kinematic")
    law = WearLaw(1e-12, 1.7, 0.3)
    fast = integrate_wear(ph, v, law, density=PLATE.density)
    slow = integrate_wear_numpy(ph, v, law, density=PLATE.density)
    np.testing.assert_allclose(fast.depth, slow.depth, rtol=1e-9, atol=1e-12 * fast.max_depth_m)


def test_integrate_volume_of_a_paraboloid():
    """∫ h0 (1 − r²/c²) dA over r < c = π c² h0 / 2 (closed form), trapezoidal rule on a 201² grid."""
    c, h0 = 1e-4, 1e-7
    x = np.linspace(-1.2 * c, 1.2 * c, 201)
    depth = h0 * np.clip(1 - (x[None, :] ** 2 + x[:, None] ** 2) / c**2, 0, None)
    assert integrate_volume(x, x, depth) == pytest.approx(math.pi * c * c * h0 / 2, rel=1e-3)


def test_bad_inputs_name_the_parameter():
    impact = reference_impact(samples=101)
    ph, v, law = pressure_history(impact, "hertz"), sliding_speed(impact), WearLaw(1e-12)
    with pytest.raises(ValueError, match="^points_across="):
        integrate_wear(ph, v, law, density=2700.0, points_across=20)
    with pytest.raises(ValueError, match="^density="):
        integrate_wear(ph, v, law, density=-1.0)
    with pytest.raises(ValueError, match="^source="):
        pressure_history(impact, "johnson")
    with pytest.raises(ValueError, match="^fe=None"):
        pressure_history(impact, "fe")
    with pytest.raises(ValueError, match="^impact.history=None"):
        wear_from_impact(SimpleNamespace(history=None), law, pressure="hertz")
    oblique = reference_impact(angle=60.0, samples=101)
    with pytest.raises(ValueError, match="^contact_x moves"):
        axisymmetric_wear_depth(pressure_history(oblique, "hertz"), v, law, [0.0])


def test_archard_volume_equals_friction_work_over_mu():
    """α = 1, β = 1 in full gross sliding: V = K ∫∫ p |v_s| dA dt = K ∫ F |v_s| dt = K W_f / μ, with W_f the
    friction work −∫F_t (v_t − Rω) dt that the engine accounts in its energy balance (Archard's law; at 70°,
    μ = 0.092 the contact slides throughout: Ψ = tanθ/μ = 30 > 5.8, Maw, Barber & Fawcett 1976). Within 0.5%."""
    impact = engine_impact(speed=5.0, angle=70.0, restitution=0.9)
    assert np.mean(impact.history.sliding) > 0.99  # stuck only while the spring first loads and at separation
    law = WearLaw(1e-12, 1.0, 1.0)
    wm = wear_from_impact(impact, law, pressure="hertz", speed="sliding")
    assert wm.volume_m3 == pytest.approx(law.K * impact.friction_work / impact.friction, rel=5e-3)
    manual = integrate_wear(pressure_history(impact, "hertz"), sliding_speed(impact), law, density=PLATE.density)
    np.testing.assert_array_equal(wm.depth, manual.depth)
    assert wm.mass_kg == pytest.approx(PLATE.density * wm.volume_m3, rel=1e-12)
