"""The 3-D plate (fem.solid.indentation, fem.solid.solver) against independent references: Hertz, the axisymmetric FE
plate, and Hamilton's (1983) closed-form stresses under a sliding sphere.

The meshes are the default 3-D block (4 elements across the largest contact radius, quadratic nodes at a/8).
"""

import math

import numpy as np
import pytest
from reference_tables import read_table

import fem
from contact.materials import Material
from contact.theory import first_yield
from fem.core.plasticity import J2Material, von_mises
from fem.solid.forms import discretise_solid
from fem.solid.indentation import indent_solid
from fem.solid.mesh import generate_block, scale_block
from fem.solid.solver import SolidSolver

R, E, NU, Y = 0.01, 210e9, 0.3, 210e6
E_STAR = E / (1.0 - NU**2)


def hertz_force(overlap):
    return 4.0 / 3.0 * E_STAR * math.sqrt(R) * overlap**1.5


def test_normal_contact_matches_hertz():
    """Hertz (Johnson 1985, Eqs. 4.22-4.23): P = 4/3 E* R^1/2 δ^3/2 within 2%, a = √(Rδ) within 3%."""
    plate = Material(E=E, nu=NU, density=7800.0)
    delta = (1e-4) ** 2 / R
    result = indent_solid(R, plate, [0.5 * delta, delta])
    force_error = result.normal_force / hertz_force(result.overlap) - 1.0
    radius_error = result.contact_radius / np.sqrt(R * result.overlap) - 1.0
    assert np.all(np.abs(force_error) < 0.02), force_error
    assert abs(radius_error[-1]) < 0.03, radius_error
    assert np.all(result.tangential_force == pytest.approx(0.0, abs=1e-9 * result.normal_force.max()))


def test_contact_radius_follows_hertz_between_the_rings_of_nodes():
    """Hertz (Johnson 1985, Eq. 4.22): a = √(Rδ) within 3% at every step of a press whose contact edge passes the
    vertex rings (4 elements across the largest contact radius; measured: within 2.1%). The area of the vertices in
    contact gives a staircase in δ, up to 15% above √(Rδ) on this path (20% below and 17% above on 16 steps); the
    edge found from the free nodes' gaps (:func:`fem.core.sphere.contact_radius_around`) moves between the rings."""
    plate = Material(E=E, nu=NU, density=7800.0)
    delta = (1e-4) ** 2 / R
    overlaps = delta * (np.arange(3, 11) / 10) ** 1.5
    result = indent_solid(R, plate, overlaps, contact_elements=4)
    radius_error = result.contact_radius / np.sqrt(R * result.overlap) - 1.0
    assert np.all(np.abs(radius_error) < 0.03), radius_error


@pytest.mark.slow
@pytest.mark.parametrize(
    ("interference", "loading", "contact_elements"),
    [(6.0, np.linspace(0.0, 1.0, 7)[1:], 4), (20.0, (np.arange(1, 9) / 8) ** 1.5, 3)],
    ids=["w6-default-mesh", "w20-reduced-mesh"],
)
def test_plastic_normal_contact_matches_axisymmetric_plate(interference, loading, contact_elements):
    """A normal press to w = δ/δ_c = 6 (default mesh) and 20 (3 elements across the contact, the suite's reduced
    mesh; 4 give +0.5% / −0.1%) and back: the 3-D plate's peak force within 3% and residual dent within 5% of the
    axisymmetric FE plate (itself validated against Kogut & Etsion 2002 and Mesarovic & Johnson 2000)."""
    plate = Material(E=E, nu=NU, density=7800.0, yield_strength=Y)
    critical = first_yield(R, E_STAR, Y, NU).overlap
    peak = interference * critical
    path = np.r_[peak * loading, [0.6 * peak, 0.3 * peak, 0.0]]
    solid = indent_solid(R, plate, path, contact_elements=contact_elements)
    axisymmetric = fem.indent(R, plate, path)
    top = int(np.argmax(path))
    assert solid.normal_force[top] / axisymmetric.force[top] - 1.0 == pytest.approx(0.0, abs=0.03)
    centre = int(np.argmin(np.linalg.norm(solid.surface_vertices[:, :2], axis=1)))
    dent = solid.residual_depth[centre]
    assert dent / float(np.max(axisymmetric.residual_depth)) - 1.0 == pytest.approx(0.0, abs=0.05)


@pytest.mark.slow
def test_first_yield_under_a_sliding_sphere_matches_hamilton():
    """Elastic plate, Hertz load applied without friction, then slid to gross sliding (Q = μP): the largest von
    Mises stress gives the critical p0/Y of first yield, against Hamilton's (1983) closed-form stresses
    (tests/data/hamilton_first_yield.csv, ν = 0.3): within 3%, below the surface at z ≈ 0.48a for μ = 0 and 0.2.
    For μ = 0.5 yield starts at the surface on the trailing half (Hamilton: at the trailing edge x = −a); its value
    needs the stress on the surface itself (tests/test_fem_surface_stress.py): the quadrature points lie below it."""
    reference = read_table("hamilton_first_yield.csv")
    a_max = 1e-4
    delta = a_max**2 / R
    mesh = scale_block(generate_block(4), a_max)
    solver = SolidSolver(mesh, J2Material(E, NU), R, 0.5, hertz_force(delta), delta)
    loaded = solver.advance(solver.initial_state(), None, (delta, 0.0, 0.0), friction=0.0)
    shear_modulus = E / (2.0 * (1.0 + NU))
    for mu in (0.0, 0.2, 0.5):
        normal, _ = solver.surface_forces(loaded)
        P = 2.0 * normal.sum()
        a = (3.0 * P * R / (4.0 * E_STAR)) ** (1.0 / 3.0)
        p0 = 3.0 * P / (2.0 * math.pi * a**2)
        # twice the Cattaneo-Mindlin slide of gross sliding, 3μP(2 − ν)/(16 G a)
        slide = 2.0 * 3.0 * mu * P * (2.0 - NU) / (16.0 * shear_modulus * a)
        state = solver.advance(loaded, None, (delta, 0.0, slide), friction=mu)
        normal, shear = solver.surface_forces(state)
        if mu > 0.0:
            assert not state.stick.any()
            assert 2.0 * shear[:, 0].sum() / (mu * 2.0 * normal.sum()) == pytest.approx(1.0, abs=0.01)
        stress = von_mises(solver.stress_update(state).stress)
        worst = np.unravel_index(np.argmax(stress), stress.shape)
        x, _, z = solver.disc.qp[:, worst[0], worst[1]] / a
        ratio = p0 / stress.max()
        row = {name: column[reference["mu"] == mu][0] for name, column in reference.items()}
        if mu < 0.3:
            assert ratio / row["p0_over_Y"] - 1.0 == pytest.approx(0.0, abs=0.03), (mu, ratio)
            assert -z == pytest.approx(row["z_over_a"], abs=0.06), (mu, z)
        else:
            assert row["z_over_a"] == 0.0
            assert -z < 0.1 and x < 0.0, (mu, x, z)


def test_bad_friction_and_path_lengths_name_the_parameter():
    plate = Material(E=E, nu=NU, density=7800.0)
    with pytest.raises(ValueError, match="friction"):
        indent_solid(R, plate, [1e-6], friction=1.5)
    with pytest.raises(ValueError, match="slides: 1 entries, but the overlap path has 2"):
        indent_solid(R, plate, [1e-6, 2e-6], slides=[0.0])


MU_SLIDE = 0.3  # the friction coefficient of the constant-load slides


def _slid_at_constant_load(fractions, contact_elements):
    """A rigid sphere pressed into the steel plate without friction to a Hertz contact of radius 0.1 mm, then slid at
    that load with μ = 0.3 by ``fractions`` of Mindlin's gross slide ξ_max = 3μP(2 − ν)/(16 G a) (Johnson 1985 §7.2;
    the path's slides from the Hertz contact), over a shallow box (the tractions need the surface resolved). Returns
    (the result, ξ_max (m) and a (m) of the FE's own normal force)."""
    plate = Material(E=E, nu=NU, density=7800.0)
    a_max = 1e-4
    delta = a_max**2 / R
    shear_modulus = E / (2.0 * (1.0 + NU))

    def gross_slide(P, a):
        return 3.0 * MU_SLIDE * P * (2.0 - NU) / (16.0 * shear_modulus * a)

    result = indent_solid(
        R,
        plate,
        np.full(fractions.size + 1, delta),
        slides=np.r_[0.0, fractions * gross_slide(hertz_force(delta), math.sqrt(R * delta))],
        friction=np.r_[0.0, np.full(fractions.size, MU_SLIDE)],
        contact_elements=contact_elements,
        box_depth=0.3,
    )
    P = result.normal_force[0]
    a = (3.0 * P * R / (4.0 * E_STAR)) ** (1.0 / 3.0)
    return result, gross_slide(P, a), a


@pytest.mark.slow
def test_partial_slip_matches_cattaneo_mindlin():
    """Normal load applied without friction, then the ball's surface slid by ξ with μ = 0.3 (Johnson 1985 §7.2,
    Eqs. 7.42-7.43, rigid ball): Q/μP = 1 − (1 − ξ/ξ_max)^{3/2}, ξ_max = 3μP(2 − ν)/(16 G a), stick radius
    c/a = (1 − Q/μP)^{1/3}. The slide each Q takes within 5%; the stick edge within half an element (a/16) of
    Mindlin's c: the stick set is a set of vertices (measured 0.17–0.41 of an element outside c, at c/a 0.90, 0.71
    and 0.45: the Coulomb law on each vertex's hat moments keeps a vertex stuck while its hat's mean traction is
    inside the cone); gross sliding (Q = μP within 1%) beyond ξ_max. A mesh with 8 elements across a over a shallow
    box (the tractions need the surface resolved)."""
    mu = MU_SLIDE
    result, slide_max, a = _slid_at_constant_load(np.array([0.2, 0.5, 0.8, 1.2]), contact_elements=8)
    fractions = result.slide[1:] / slide_max
    ratio = result.tangential_force[1:] / (mu * result.normal_force[1:])
    partial = fractions < 1.0
    slide_for_q = slide_max * (1.0 - (1.0 - ratio[partial]) ** (2.0 / 3.0))
    np.testing.assert_allclose(slide_for_q / (fractions[partial] * slide_max), 1.0, atol=0.05)
    stick = a * (1.0 - ratio[partial]) ** (1.0 / 3.0)
    np.testing.assert_allclose(result.stick_radius[1:][partial] - stick, 0.0, atol=0.5 * a / 8)
    np.testing.assert_allclose(ratio[~partial], 1.0, atol=0.01)
    assert np.all(result.stick_radius[1:][~partial] == 0.0)


def test_proportional_oblique_loading_sticks_whatever_the_increments():
    """Mindlin & Deresiewicz (1953; Johnson 1985 §7.4): a sphere pressed and dragged together, its slide growing in
    proportion to its overlap, ξ = λ δ (2 − ν)/(2(1 − ν)) with λ < μ, slips nowhere: each increment adds the stuck
    circle's tangential load dQ = 8Ga/(2 − ν) dξ to the normal dP = 4Ga/(1 − ν) dδ, so Q/P = λ and the whole contact
    sticks, in any number of increments. λ = 0.15, μ = 0.3, elastic steel, 16 increments to a = 0.1 mm on the
    default mesh (4 elements across a; its edge ring of vertices is a quarter of a). Measured: Q/P 0.134–0.142 from
    the 4th increment (2 elements across a and more; 0.19 on the first), the stick radius at least 0.70 a. A stick
    test on the L² projection of the tractions, which overshoots the cone at a stick edge, released a ring of
    vertices every few increments: the stick radius fell to 0 by the 12th increment and Q/P to 0.10 (0.46–0.83 a
    and Q/P 0.132 in 4 increments)."""
    plate = Material(E=E, nu=NU, density=7800.0)
    lam = 0.15
    overlaps = (1e-4) ** 2 / R * np.arange(1, 17) / 16
    result = indent_solid(
        R,
        plate,
        overlaps,
        slides=lam * overlaps * (2.0 - NU) / (2.0 * (1.0 - NU)),
        friction=MU_SLIDE,
        contact_elements=4,
        box_depth=0.3,
    )
    ratio = result.tangential_force / result.normal_force
    # from the 4th increment on (2 elements across a and more), the FE's tangential and normal stiffness in Q/P
    assert np.all(np.abs(ratio[3:] / lam - 1.0) <= 0.12), ratio
    assert np.all(result.stick_radius >= 0.65 * result.contact_radius), result.stick_radius / result.contact_radius


def test_reversed_gross_slip_follows_mindlin_deresiewicz_unloading():
    """Normal load applied without friction, the ball slid to gross slip (1.2 ξ_max, μ = 0.3) and the slide then
    taken back by 2.4 ξ_max at the same load: Mindlin & Deresiewicz's (1953) unloading (Johnson 1985 §7.3, with
    Q* = μP), Q = Q* − 2μP[1 − (1 − Δξ/(2ξ_max))^{3/2}] for a slide Δξ back from the turn, then gross slip the other
    way (Q = −μP) once Δξ ≥ 2ξ_max. The whole contact sticks where the slide turns and slips back from its edge: a
    plate whose tractions lag the reversed slide (or that slides back at once) misses it by tenths of μP.
    Measured 0.012, 0.024, 0.016 μP off on the default mesh (4 elements across a; 0.02 μP in 8 steps on 6)."""
    mu = MU_SLIDE
    fractions = np.r_[0.6, 1.2, 1.2 - np.array([0.6, 1.2, 1.8, 2.4])]
    result, slide_max, _ = _slid_at_constant_load(fractions, contact_elements=4)
    ratio = result.tangential_force[1:] / (mu * result.normal_force[1:])
    assert ratio[1] == pytest.approx(1.0, abs=0.01)
    back = (result.slide[2] - result.slide[3:]) / slide_max
    expected = 1.0 - 2.0 * (1.0 - (1.0 - np.minimum(back, 2.0) / 2.0) ** 1.5)
    print("Q/muP", ratio[2:], "Mindlin-Deresiewicz", expected)
    np.testing.assert_allclose(ratio[2:], expected, atol=0.03)
    assert ratio[-1] == pytest.approx(-1.0, abs=0.01)


def test_surface_operators_integrate_exactly():
    """The surface operators against exact integrals (fem.solid.forms): the hats' mass sums to the surface area
    (Σ_jk ∫ψ_j ψ_k = ∫1), the consistent loads of a linear traction have the hat mass as moments (H G = M, both
    ∫ψ_j ψ_k), and the dual functions' loads have each vertex's own hat integral only (H G̃ = diag ∫ψ_k;
    Wohlmuth 2000)."""
    d = discretise_solid(scale_block(generate_block(3), 1e-4))
    x, y = d.nodes[0, d.surface_nodes], d.nodes[1, d.surface_nodes]
    width = float(np.ptp(x)) * float(np.ptp(y))
    assert d.surface_hat_mass.sum() == pytest.approx(width, rel=1e-12)
    hats = d.surface_hats
    np.testing.assert_allclose((hats @ d.surface_loads).toarray(), d.surface_hat_mass.toarray(), atol=1e-12 * width)
    np.testing.assert_allclose((hats @ d.surface_dual_loads).toarray(), np.diag(d.surface_area), atol=1e-12 * width)


def test_mesh_generation_is_quiet(caplog):
    """No scikit-fem log lines reach the user while the block is refined (a performance note per refined mesh)."""
    with caplog.at_level("INFO"):
        mesh = generate_block(4)
    assert mesh.nelements > 1000
    assert not [r for r in caplog.records if r.name.startswith("skfem")]


@pytest.mark.slow
def test_gross_slip_field_matches_cerruti():
    """Hertz load applied without friction, then the ball slid by ξ = 2 ξ_max at μ = 0.3 in one step: the whole
    contact slides (Q = μP) under q = μp0 √(1 − r²/a²), whose surface displacement is Cerruti's (Johnson 1985 §3.6
    and Eq. 7.39): u_x = πq0/(32Ga) [4(2 − ν)a² − (4 − 3ν)x² − (4 − ν)y²], u_y = πq0/(32Ga) 2ν x y. The plate's slip
    over each vertex in the step, ξ e_x − Δu, within 5% of ξ_max of that (r < 0.8a; the wear's slip field), the
    bound of the Cattaneo–Mindlin check (measured: 3.9%)."""
    mu = 0.3
    plate = Material(E=E, nu=NU, density=7800.0)
    a_max = 1e-4
    delta = a_max**2 / R
    shear_modulus = E / (2.0 * (1.0 + NU))
    xi_max = 3.0 * mu * hertz_force(delta) * (2.0 - NU) / (16.0 * shear_modulus * math.sqrt(R * delta))
    result = indent_solid(R, plate, [delta, delta], slides=[0.0, 2.0 * xi_max], friction=[0.0, mu])
    P = result.normal_force[1]
    assert result.tangential_force[1] / (mu * P) == pytest.approx(1.0, abs=0.01)
    a = (3.0 * P * R / (4.0 * E_STAR)) ** (1.0 / 3.0)
    q0 = 3.0 * mu * P / (2.0 * math.pi * a**2)
    x, y = result.surface_vertices[:, 0], result.surface_vertices[:, 1]
    inside = np.hypot(x, y) < 0.8 * a
    scale = math.pi * q0 / (32.0 * shear_modulus * a)
    u_x = scale * (4.0 * (2.0 - NU) * a**2 - (4.0 - 3.0 * NU) * x**2 - (4.0 - NU) * y**2)
    u_y = scale * 2.0 * NU * x * y
    expected = np.column_stack([result.slide[1] - u_x, -u_y])[inside]
    error = np.abs(result.slip[1][inside] - expected).max() / xi_max
    assert inside.sum() > 20 and error < 0.05, error


def test_shear_limited_gross_slip_carries_orowans_force():
    """Orowan's friction τ = min(μp, k) (fem.solid.friction): Hertz load applied without friction, then slid by
    2 ξ_max at μ = 0.3 with the surface's shear strength k = 0.6 μp0. The whole contact slides at ∫min(μp, k) dA
    = kπc² + (2π/3) μp0 a² (1 − c²/a²)^{3/2}, c² = a²(1 − (k/μp0)²) (Hertz's pressure, integrated by hand; 0.792 μP)
    within 3.5% (measured +2.7%; +1.2% with 6 elements across a: the hats across r = c average the kink of
    min(μp, k), an O(h²) excess)."""
    mu = 0.3
    a_max = 1e-4
    delta = a_max**2 / R
    p0_hertz = 2.0 * E_STAR * a_max / (math.pi * R)
    k = 0.6 * mu * p0_hertz
    mesh = scale_block(generate_block(4), a_max)
    solver = SolidSolver(mesh, J2Material(E, NU), R, mu, hertz_force(delta), delta, shear_strength=k)
    loaded = solver.advance(solver.initial_state(), None, (delta, 0.0, 0.0), friction=0.0)
    shear_modulus = E / (2.0 * (1.0 + NU))
    xi_max = 3.0 * mu * hertz_force(delta) * (2.0 - NU) / (16.0 * shear_modulus * a_max)
    state = solver.advance(loaded, None, (delta, 0.0, 2.0 * xi_max), friction=mu)
    normal, shear = solver.surface_forces(state)
    P, Q = 2.0 * normal.sum(), 2.0 * shear[:, 0].sum()
    a = (3.0 * P * R / (4.0 * E_STAR)) ** (1.0 / 3.0)
    p0 = 3.0 * P / (2.0 * math.pi * a**2)
    c2 = a**2 * (1.0 - (k / (mu * p0)) ** 2)
    orowan = k * math.pi * c2 + 2.0 * math.pi / 3.0 * mu * p0 * a**2 * (1.0 - c2 / a**2) ** 1.5
    assert not state.stick.any()
    assert Q / orowan == pytest.approx(1.0, abs=0.035), (Q / orowan, Q / (mu * P))
