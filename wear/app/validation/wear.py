"""Validation checks of ``wear`` (equation 15 integrated over the moving contact patch), for ``impactwear validate``.

References: closed forms evaluated here (the steady Hertz track; the impulse identity V = K m V_n (1 + e) from
conservation of momentum; Archard's V = K W_f/μ), an independent quadrature of the normal Hertz impact's depth
profile (and its tabulated values), and the additivity of Eq. 15 without geometry update.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad
from scipy.special import gamma

from contact import Material, simulate_impact
from contact.materials import effective_modulus as e_star_of
from contact.theory import hertz_impact, speed_components, sphere_mass
from wear import (
    WearLaw,
    axisymmetric_wear_depth,
    hertz_pressure_history,
    integrate_wear,
    pressure_history,
    sliding_speed,
    wear_from_impact,
)
from wear.app.validation.checks import Check, absolute, relative
from wear.case import Case
from wear.chain.restitution import restitution_sweep
from wear.chain.single import run
from wear.erosion import ImpactResponse, Stream, build_response_table, erode, table_axes
from wear.slip import SlidingSpeed

BALL = Material(E=380e9, nu=0.23, density=4000.0, name="alumina")
PLATE = Material(E=70e9, nu=0.25, density=2700.0, yield_strength=100e6, name="aluminium")
RADIUS = 2.5e-3
CASE = "alumina R 2.5 mm on aluminium (Y 100 MPa)"


def _impact(speed=5.0, angle=0.0, restitution=1.0, friction=0.092, normal_model="hertz"):
    return simulate_impact(
        RADIUS, BALL, PLATE, speed, angle, friction, restitution=restitution, normal_model=normal_model
    )


def steady_track(quick: bool) -> list[Check]:
    """A Hertz contact (a, p0) sliding at constant speed v and load: across the track
    h(y) = K v^(β−1) p0^α a (1 − y²/a²)^((α+1)/2) √π Γ(α/2+1)/Γ(α/2+3/2) (closed form; 1% of the max depth)."""
    a, p0, v = 1e-4, 1.2e9, 2.0
    force = 2.0 / 3.0 * math.pi * a * a * p0
    out = []
    for alpha, beta in ((1.0, 0.3), (2.0, 1.0), (0.5, 0.0)):
        K = 1e-13 * 1e9 ** (1.0 - alpha)  # depths of ~10 nm whatever α (K in m^(1-β) s^(β-1) Pa^(-α))
        t = np.linspace(0.0, 8 * a / v, 9)
        ph = hertz_pressure_history(t, v * t, np.full(t.size, a), np.full(t.size, force))
        wm = integrate_wear(
            ph,
            SlidingSpeed(t, np.full(t.size, v)),
            WearLaw(K, alpha, beta),
            density=7800.0,
            points_across=64 if quick else 160,
        )
        h = wm.depth[:, np.argmin(np.abs(wm.x - 4 * a))]
        shape = math.sqrt(math.pi) * gamma(alpha / 2 + 1) / gamma(alpha / 2 + 1.5)
        exact = K * v ** (beta - 1) * p0**alpha * a * np.clip(1 - (wm.y / a) ** 2, 0, None) ** ((alpha + 1) / 2)
        exact *= shape
        err = float(np.max(np.abs(h - exact)) / exact.max())
        out.append(
            Check(
                "wear",
                f"track depth h(y), α = {alpha:g}, β = {beta:g}",
                "a 0.1 mm, p0 1.2 GPa, v 2 m/s",
                float(exact.max()),
                "closed form",
                float(h.max()),
                err,
                0.01,
                "max |Δh| / max h",
                "m",
            )
        )
    return out


def impulse_identity(quick: bool) -> list[Check]:
    """α = 1, β = 0: the worn volume is K ∫F dt = K m V_n (1 + e) (conservation of momentum), whatever the pressure
    shape that carries the force (0.5%)."""
    law = WearLaw(2e-13, 1.0, 0.0)
    out = []
    for angle, e, source, model in (
        (0.0, 1.0, "hertz", "hertz"),
        (50.0, 0.8, "hertz", "hertz"),
        (70.0, 0.98, "paper", "hertz"),
        (30.0, 1.0, "thornton", "thornton"),
    ):
        imp = _impact(angle=angle, restitution=e, normal_model=model)
        wm = integrate_wear(pressure_history(imp, source), sliding_speed(imp), law, density=PLATE.density)
        vn, _ = speed_components(imp.speed, angle)
        expected = law.K * imp.mass * vn * (1.0 + imp.normal_restitution)
        out.append(
            relative(
                "wear",
                f"worn volume = K m V_n (1+e), {source} pressure",
                f"{CASE}, 5 m/s, {angle:g}°, {model} impact" + (f", e {e:g}" if model == "hertz" else ""),
                expected,
                "conservation of momentum",
                wm.volume_m3,
                5e-3,
                "m³",
            )
        )
    return out


def _hertz_impact_profile(rho) -> np.ndarray:
    """h(r)/h(0) of a normal Hertz impact (α = 1, β = 0) by quadrature: p0 ∝ a, a² = Rδ, dt = dδ/δ',
    δ'² ∝ 1 − (δ/δmax)^(5/2): h(ρ) ∝ ∫_{ρ²}^1 √(u − ρ²)/√(1 − u^(5/2)) du."""

    def smooth(u):  # √((1 − u)/(1 − u^{5/2})) → √(2/5) at u = 1
        return math.sqrt(0.4) if u >= 1.0 else math.sqrt((1 - u) / (1 - u**2.5))

    def h(r):
        if r >= 1.0:
            return 0.0
        return quad(smooth, r * r, 1.0, weight="alg", wvar=(0.5, -0.5), epsabs=0, epsrel=1e-12)[0]

    return np.array([h(r) for r in rho]) / h(0.0)


def hertz_impact_profile(quick: bool) -> list[Check]:
    """Normal Hertz impact, α = 1, β = 0: the depth profile h(r)/h(0) at r/a_max = 0, 0.25, 0.5, 0.75, 0.9, 1 equals
    1, 0.930, 0.727, 0.409, 0.173, 0 (tabulated; reproduced here by quadrature) within 0.01."""
    rho = np.array([0.0, 0.25, 0.5, 0.75, 0.9, 1.0])
    table = np.array([1.0, 0.930, 0.727, 0.409, 0.173, 0.0])
    quadrature = _hertz_impact_profile(rho)
    imp = _impact(speed=3.9)
    ph, v = pressure_history(imp, "hertz"), sliding_speed(imp, "kinematic")
    law = WearLaw(1e-12, 1.0, 0.0)
    a_max = ph.max_extent
    h = axisymmetric_wear_depth(ph, v, law, rho * a_max)
    wm = integrate_wear(ph, v, law, density=PLATE.density, points_across=64 if quick else 200)
    line = np.interp(rho * a_max, wm.x - ph.contact_x[0], wm.centreline())
    case = f"{CASE}, 3.9 m/s, normal"
    measure = "max |Δ| over r/a_max = 0, 0.25, 0.5, 0.75, 0.9, 1"
    rows = (
        ("quadrature of a closed-form Hertz impact", "closed form", quadrature, table, "tabulated h(r)/h(0)", 1e-3),
        ("axisymmetric profile", case, h / h[0], quadrature, "quadrature (this module)", 0.01),
        ("2-D depth map centreline", case, line / wm.centreline().max(), quadrature, "quadrature (this module)", 0.01),
    )
    return [
        Check(
            "wear",
            f"h(0.75 a_max)/h(0), {label}",
            where,
            float(ref[3]),
            src,
            float(got[3]),
            float(np.max(np.abs(got - ref))),
            tol,
            measure,
        )
        for label, where, got, ref, src, tol in rows
    ]


def sliding_and_additivity(quick: bool) -> list[Check]:
    """A normal impact with β > 0 and the gross-sliding speed wears nothing (the contact point never slides);
    without geometry update equation 15 is additive (5 impacts = 5 × one); α = 1, β = 1 in gross sliding gives
    Archard's V = K W_f/μ with W_f the friction work of the impact engine (0.5%)."""
    law = WearLaw(1e-12, 1.0, 0.3)
    normal = _impact(angle=0.0)
    wm0 = integrate_wear(pressure_history(normal, "hertz"), sliding_speed(normal), law, density=PLATE.density)
    oblique = _impact(angle=55.0)
    ph, v = pressure_history(oblique, "hertz"), sliding_speed(oblique)
    one = integrate_wear(ph, v, law, density=PLATE.density)
    many = one
    for _ in range(4):
        many = integrate_wear(ph, v, law, density=PLATE.density, on=many)
    archard = _impact(speed=5.0, angle=70.0, restitution=0.9)
    law1 = WearLaw(1e-12, 1.0, 1.0)
    wm1 = wear_from_impact(archard, law1, pressure="hertz", speed="sliding")
    return [
        absolute(
            "wear",
            "worn volume, normal impact, β = 0.3, sliding speed",
            f"{CASE}, 5 m/s, 0°",
            0.0,
            "no slip at normal incidence",
            wm0.volume_m3,
            0.0,
            "m³",
        ),
        relative(
            "wear",
            "worn volume of 5 identical impacts",
            f"{CASE}, 5 m/s, 55°",
            5 * one.volume_m3,
            "additivity of Eq. 15",
            many.volume_m3,
            1e-12,
            "m³",
        ),
        relative(
            "wear",
            "worn volume, α = 1, β = 1, sliding throughout",
            f"{CASE}, 5 m/s, 70°, e 0.9",
            law1.K * archard.friction_work / archard.friction,
            "Archard: V = K W_f / μ",
            wm1.volume_m3,
            5e-3,
            "m³",
        ),
    ]


def fe_table_source(quick: bool) -> list[Check]:
    """The ``"fe"`` pressure source fed with a nodal table of the Hertz profile (equation 16 sampled on 80 graded
    surface nodes at 60 steps, as an FE result would be) gives the wear of the ``"hertz"`` source (1%)."""
    imp = _impact(speed=3.9, angle=40.0)
    h = imp.history
    hertz = pressure_history(imp, "hertz")
    steps = np.linspace(0.0, h.t[-1], 60)
    a = np.interp(steps, h.t, h.contact_radius)
    force = np.interp(steps, h.t, h.normal_force)
    nodes = 1.5 * hertz.max_extent * np.linspace(0.0, 1.0, 80) ** 1.3
    p0 = np.where(a > 0, 1.5 * force / (math.pi * np.maximum(a, 1e-30) ** 2), 0.0)
    table = p0[:, None] * np.sqrt(np.clip(1 - (nodes[None, :] / np.maximum(a[:, None], 1e-30)) ** 2, 0, None))
    law = WearLaw(1e-12, 1.0, 0.3)
    v = sliding_speed(imp, "kinematic")
    ref = integrate_wear(hertz, v, law, density=PLATE.density)
    got = integrate_wear(pressure_history(imp, "fe", fe=(steps, nodes, table)), v, law, density=PLATE.density)
    case = f"{CASE}, 3.9 m/s, 40°, Hertz table on 80 nodes × 60 steps"
    src = '"hertz" source (Eq. 16 from the impact history)'
    return [
        relative("wear", 'worn volume, "fe" source', case, ref.volume_m3, src, got.volume_m3, 0.01, "m³"),
        relative("wear", 'max wear depth, "fe" source', case, ref.max_depth_m, src, got.max_depth_m, 0.01, "m"),
    ]


def erosion_flux_balance(quick: bool) -> list[Check]:
    """Particle-stream erosion on a still-flat plate: the number of impacts is the flux balance
    N = c V cos θ A T / m_p, and the mass loss is N × (one impact's worn volume from the single-impact chain
    contact.simulate_impact → wear.wear_from_impact, not the response table) × plate density (0.5%)."""

    sand = Material(E=94e9, nu=0.17, density=2650.0, name="silica")
    steel = Material(E=200e9, nu=0.3, density=7850.0, yield_strength=350e6, name="steel")
    radius, speed, angle, mu, conc, exposure = 100e-6, 20.0, 45.0, 0.3, 0.464, 20.0
    law = WearLaw(K=1e-11, alpha=1.0, beta=0.3)
    response = ImpactResponse(radius, sand, steel, mu, law, pressure="hertz", points_across=48)
    vn, angles = table_axes(speed, angle, angle_margin=10.0, angle_step=5.0, speeds=3)
    table = build_response_table(response, vn, angles, points_per_length=8)
    single = wear_from_impact(simulate_impact(radius, sand, steel, speed, angle, mu), law, pressure="hertz")
    result = erode(table, Stream(speed, angle, exposure, concentration=conc), grid=64 if quick else 128, seed=3)
    m_p = 4.0 / 3.0 * math.pi * radius**3 * sand.density
    n_expected = conc * speed * math.cos(math.radians(angle)) * result.patch_size**2 * exposure / m_p
    case = "silica R 100 µm on steel, 20 m/s, 45°, c 0.464 kg/m³, 20 s"
    return [
        absolute(
            "wear",
            "number of impacts on the patch",
            case,
            round(n_expected),
            "flux balance c V cos θ A T / m_p",
            result.n_impacts,
            0.0,
        ),
        relative(
            "wear",
            "eroded mass (flat plate)",
            case,
            result.n_impacts * single.volume_m3 * steel.density,
            "N × single-impact chain × density",
            float(result.mass_loss_kg[-1]),
            5e-3,
            "kg",
        ),
    ]


def coupling(quick: bool) -> list[Check]:
    """Two-way impact-FE coupling (wear.run, fem.couple): on an elastic plate the
    coupled normal impact has the Hertz closed-form max force and contact time (errata equations 10-11, 1%); on a
    plastic plate its normal restitution is within 5% of Thornton (1997) for V/V_y ≤ 2 (both near-Hertz there)."""

    fem_options = dict(mesh_scale=4.0, load_steps=8, unload_steps=4) if quick else {}
    base = Case.default().with_(fem=fem_options, output={"figures": False, "render": False})
    elastic = base.with_(plate={"yield_strength": None}, impact={"angle": 0.0})
    res = run(elastic)
    ball, plate = elastic.ball.material(), elastic.plate.material()
    ref = hertz_impact(
        sphere_mass(elastic.ball.radius, ball.density),
        elastic.ball.radius,
        e_star_of(ball, plate),
        elastic.impact.speed,
    )
    case = f"{ball.name} R {elastic.ball.radius * 1e3:g} mm on elastic {plate.name}, {elastic.impact.speed:g} m/s"
    src = "Hertz impact closed form (errata Eqs. 10-11)"
    out = [
        relative("wear", "coupled FE impact: max force", case, ref.max_force, src, res.impact.max_force, 0.01, "N"),
        relative(
            "wear", "coupled FE impact: contact time", case, ref.contact_time, src, res.impact.contact_time, 0.01, "s"
        ),
    ]
    sweep = restitution_sweep(base, [1.5, 2.0])
    for x, e, e_t in zip(sweep.speed_ratio, sweep.restitution, sweep.thornton, strict=True):
        out.append(
            relative(
                "wear",
                f"coupled FE normal restitution at V/V_y = {x:g}",
                f"{base.ball.name} on {base.plate.name} (Y {base.plate.yield_strength / 1e6:g} MPa), normal",
                e_t,
                "Thornton 1997, J. Appl. Mech. 64:383",
                e,
                0.05,
            )
        )
    return out
