"""Validation checks of ``contact`` (the H-DD impact engine and the closed forms), for ``impactwear validate``;
Chung & Ooi's benchmark tests run in :mod:`wear.app.validation.chung_ooi`.

Every reference is independent of the code it checks: numbers published by Thornton (1997), Kharaz, Gorham &
Salman (2001), Johnson (1985), Green (2005), Mesarovic & Johnson (2000), the MOOSE contact benchmark; the
conservation of energy and the order of the integrator; and numerical quadrature of the closed-form pressure
profiles.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad

from contact import Material, TabulatedLaw, simulate_impact, simulate_impacts, theory, yield_velocity
from contact.halfspace import halfspace_contact
from contact.materials import effective_modulus
from wear.app.validation.checks import Check, absolute, relative
from wear.app.validation.chung_ooi import AL_OXIDE, RIGID
from wear.app.validation.references import kharaz_data, kharaz_rms


def thornton_1997(quick: bool) -> list[Check]:
    """Restitution of elastic-perfectly plastic impacts against Thornton (1997), Journal of Applied Mechanics 64:383
    (engine, 0.2%)."""
    ball = Material(E=70e9, nu=0.3, density=2700.0, yield_strength=100e6)
    vy = yield_velocity(5e-3, ball, RIGID)
    ratios = np.array([1.5, 2.0, 5.0, 10.0, 100.0])
    ref = [0.97124, 0.93063, 0.77334, 0.65856, 0.37430]
    b = simulate_impacts(5e-3, ball, RIGID, ratios * vy, 0.0, 0.0, normal_model="thornton")
    case = "Al ball R 5 mm, Y 100 MPa, on rigid"
    return [
        relative("contact", f"normal restitution at V/V_y = {x:g}", case, e, "Thornton 1997, Eq. 39", got, 2e-3)
        for x, e, got in zip(ratios, ref, b.normal_restitution, strict=True)
    ]


def kharaz_2001(quick: bool) -> list[Check]:
    """The H-DD and the Mindlin–Deresiewicz tangential laws against the Kharaz, Gorham & Salman (2001) measurements
    (alumina on glass, 3.9 m/s, μ 0.092, e 0.98): RMS difference at the measured angles. The tolerances are about
    the scatter of the digitised points about a smooth curve (not a published uncertainty): 1°, 40 rad/s (~7% of
    the peak spin), 0.06 in e_t."""
    data = kharaz_data()
    src = "Kharaz, Gorham & Salman 2001 (digitised points)"
    rows = (
        ("centre_rebound_angle_deg", "centre rebound angle", 1.0, "deg"),
        ("spin_rad_per_s", "spin after impact", 40.0, "rad/s"),
        ("tangential_restitution", "tangential restitution", 0.06, ""),
    )
    checks = []
    for model, case in (
        ("hdd", "alumina R 2.5 mm on soda-lime glass, 3.9 m/s"),
        ("mindlin_deresiewicz", "the same, Mindlin–Deresiewicz tangential law"),
    ):
        rms = kharaz_rms(model)
        checks += [
            Check(
                "contact",
                f"RMS model − measured {label} ({data[key][0].size} points)",
                case,
                "measured points",
                src,
                rms[key],
                rms[key],
                tol,
                "RMS",
                unit,
                error_units=unit,
            )
            for key, label, tol, unit in rows
        ]
    return checks


def integration_and_energy(quick: bool) -> list[Check]:
    """Velocity Verlet converges at order 2 (errata equations 12-14 note) and the reported works close the energy
    balance E_in − E_out = W_normal + W_friction (conservation of energy)."""
    ball = Material(E=210e9, nu=0.3, density=7800.0)
    e_star = effective_modulus(ball, RIGID)
    tc = theory.hertz_impact(
        theory.sphere_mass(5e-3, 7800.0), 5e-3, e_star, 2.0 * math.cos(math.radians(20))
    ).contact_time

    def state(n):
        r = simulate_impact(5e-3, ball, RIGID, 2.0, 20.0, 0.3, time_step=tc / n)
        h, k = r.history, n // 2
        return np.array([h.normal_velocity[k], h.tangential_velocity[k], 5e-3 * h.omega[k], h.overlap[k] / tc])

    ref = state(12800 if quick else 51200)
    errors = [np.max(np.abs(state(n) - ref)) for n in (200, 400, 800)]
    order = float(np.mean(np.log2(np.array(errors[:-1]) / np.array(errors[1:]))))
    r = simulate_impact(2.5e-3, AL_OXIDE, RIGID, 3.9, 30.0, 0.3, restitution=0.7, history=False)
    return [
        absolute(
            "contact",
            "observed order of convergence (velocity Verlet)",
            "steel R 5 mm, 2 m/s, 20°, μ 0.3",
            2.0,
            "second-order scheme (state at t_c/2, Δt = t_c/200-800)",
            order,
            0.15,
        ),
        relative(
            "contact",
            "energy lost = normal work + friction work",
            "Al oxide, 3.9 m/s, 30°, μ 0.3, e 0.7",
            r.normal_work + r.friction_work,
            "conservation of energy",
            r.energy_in - r.energy_out,
            1e-4,
            "J",
        ),
    ]


def closed_forms(quick: bool) -> list[Check]:
    """Closed forms against published numbers and against quadrature: MOOSE Hertz benchmark, exact first-yield
    coefficient C(0.3) = 1.6128 at z = 0.481a (Johnson 1985 §6.2; errata equation 18), Green's (2005) fit, and the
    force carried by the equation 16 and equation 19 profiles (scipy quadrature)."""
    return [*_hertz_benchmark(), *_first_yield(), _green_fit(), _hertz_profile_force(), _mesarovic_johnson_force()]


def _hertz_benchmark() -> list[Check]:
    """Contact radius (m) and overlap (m) of the MOOSE contact module's Hertz benchmark: E* = 7.5 MPa, R = 1 m,
    F = 1e4 N."""
    return [
        relative(
            "contact",
            "Hertz contact radius",
            "E* 7.5 MPa, R 1 m, F 1e4 N",
            0.1,
            "MOOSE contact Hertz benchmark",
            theory.hertz_contact_radius_from_force(1e4, 1.0, 7.5e6),
            1e-6,
            "m",
        ),
        relative(
            "contact",
            "Hertz overlap",
            "E* 7.5 MPa, R 1 m, F 1e4 N",
            0.01,
            "MOOSE contact Hertz benchmark",
            theory.hertz_overlap(1e4, 1.0, 7.5e6),
            1e-6,
            "m",
        ),
    ]


def _first_yield() -> list[Check]:
    """The exact first-yield coefficient C(0.3) = p0/Y and its depth z/a at ν = 0.3 (Johnson 1985 §6.2)."""
    return [
        absolute(
            "contact",
            "first-yield coefficient C(ν) = p0/Y",
            "ν = 0.3",
            1.6128,
            "Johnson 1985 §6.2; errata Eq. 18",
            theory.yield_coefficient(0.3),
            1e-4,
        ),
        absolute(
            "contact",
            "first-yield depth z/a",
            "ν = 0.3",
            0.481,
            "Johnson 1985 §6.2 (0.48a)",
            theory.yield_depth_ratio(0.3),
            1e-3,
        ),
    ]


def _green_fit() -> Check:
    """C(ν) against Green's (2005) fit at the ν in [0.10, 0.45] where they differ most (the fit claims 0.1%)."""
    nus = np.linspace(0.1, 0.45, 8)
    dev = [abs(theory.yield_coefficient(n) / float(theory.green_yield_coefficient(n)) - 1) for n in nus]
    k = int(np.argmax(dev))
    return relative(
        "contact",
        f"C(ν) vs Green's fit (worst ν = {nus[k]:.2f})",
        "ν = 0.10-0.45",
        float(theory.green_yield_coefficient(nus[k])),
        "Green 2005, Proc. IMechE J 219 (fit within 0.1%)",
        theory.yield_coefficient(nus[k]),
        1e-3,
    )


def _hertz_profile_force() -> Check:
    """The force (N) of Eq. 16's pressure profile by quadrature of 2πr p(r) against 2πa²p0/3, for a = 0.1 mm and
    p0 = 2 GPa."""
    a, p0 = 1e-4, 2e9
    force = 2 * math.pi * quad(lambda r: r * float(theory.hertz_pressure(r, a, p0)), 0, a, epsrel=1e-12)[0]
    return relative(
        "contact",
        "∫ p dA of Eq. 16 (corrected Hertz profile)",
        "a 0.1 mm, p0 2 GPa",
        2 / 3 * math.pi * a * a * p0,
        "Johnson 1985: F = 2πa²p0/3",
        force,
        1e-8,
        "N",
    )


def _mesarovic_johnson_force() -> Check:
    """The force (N) of Eq. 19's unloading pressure profile by quadrature against its closed form, at a/a* = 0.6
    for a* = 0.2 mm and p* = 1.5 GPa."""
    a_star, p_star, x = 2e-4, 1.5e9, 0.6
    f_mj = (
        2
        * math.pi
        * quad(
            lambda r: r * float(theory.mesarovic_johnson_pressure(r, x * a_star, a_star, p_star)),
            0,
            x * a_star,
            epsrel=1e-12,
            limit=200,
        )[0]
    )
    return relative(
        "contact",
        "∫ p dA of Eq. 19 at a/a* = 0.6",
        "a* 0.2 mm, p* 1.5 GPa",
        float(theory.mesarovic_johnson_force(x * a_star, a_star, p_star)),
        "Mesarovic & Johnson 2000: F/F* = (2/π)[asin x − x√(1−x²)]",
        f_mj,
        1e-6,
        "N",
    )


def thornton_table(
    e_star: float, p_y: float, radius: float, dmax_table: float, n_curves: int = 30, n_points: int = 200
) -> TabulatedLaw:
    """Thornton (1997) loading (F = F_y + πp_yR(δ − δ_y) past δ_y) and Hertz-with-R_p unloading, written out as an
    FE-like table up to ``dmax_table`` (m), for E* ``e_star`` and limiting pressure ``p_y`` (Pa), radius (m)."""

    dy = (math.pi * p_y / (2 * e_star)) ** 2 * radius
    k = 4 / 3 * e_star * math.sqrt(radius)
    fy = k * dy**1.5

    def load(d):
        return np.where(d <= dy, k * d**1.5, fy + math.pi * p_y * radius * (d - dy))

    lo = np.linspace(0.0, dmax_table, 2000)
    curves = np.geomspace(dmax_table / 200, dmax_table, n_curves)
    uo, uf, ua = [], [], []
    for ds in curves:
        fp = float(load(ds))
        ap2 = (2 * fp + fy) / (2 * math.pi * p_y) if ds > dy else radius * ds
        rp = 4 * e_star * ap2**1.5 / (3 * fp)
        dp = max(ds - ap2 / rp, 0.0)
        d = np.linspace(ds, dp, n_points)
        uo.append(d)
        uf.append(4 / 3 * e_star * math.sqrt(rp) * np.maximum(d - dp, 0) ** 1.5)
        ua.append(np.sqrt(rp * np.maximum(d - dp, 0)))
    return TabulatedLaw(lo, load(lo), np.sqrt(radius * lo), curves, np.array(uo), np.array(uf), np.array(ua))


def tabulated_law(quick: bool) -> list[Check]:
    """The tabulated normal law (the FE → impact path of the two-way coupling) with tables written from closed
    forms: a Hertz table reproduces the Hertz impact closed form (errata equations 10-11, 0.2%); a table of
    Thornton's curves reproduces Thornton's restitution (0.5%: interpolation between unloading curves)."""

    steel = Material(E=210e9, nu=0.3, density=7800.0)
    radius = 5e-3
    e_star = effective_modulus(steel, RIGID)
    h = theory.hertz_impact(theory.sphere_mass(radius, 7800.0), radius, e_star, 2.0)
    lo = np.linspace(0, 2 * h.max_overlap, 3000)
    um = np.linspace(0.05, 2.0, 40) * h.max_overlap
    uo = np.array([np.linspace(d, 0.0, 400) for d in um])
    law = TabulatedLaw(
        lo,
        theory.hertz_force(lo, radius, e_star),
        np.sqrt(radius * lo),
        um,
        uo,
        theory.hertz_force(uo, radius, e_star),
        np.sqrt(radius * uo),
    )
    speed = 2.0 / math.cos(math.radians(30))
    t = simulate_impact(radius, steel, RIGID, speed, 30.0, 0.3, normal_model="tabulated", force_law=law, history=False)
    case = "steel R 5 mm on rigid, Hertz table, v_n 2 m/s, 30°"
    src = "Hertz impact closed form (errata Eqs. 10-11)"
    out = [
        relative("contact", "max overlap, tabulated law", case, h.max_overlap, src, t.max_overlap, 2e-3, "m"),
        relative("contact", "max force, tabulated law", case, h.max_force, src, t.max_force, 2e-3, "N"),
        relative("contact", "contact time, tabulated law", case, h.contact_time, src, t.contact_time, 2e-3, "s"),
    ]
    ball = Material(E=70e9, nu=0.3, density=2700.0, yield_strength=100e6)
    e_star = effective_modulus(ball, RIGID)
    law = thornton_table(e_star, theory.default_limiting_pressure(ball, RIGID), radius, dmax_table=3e-6)
    vy = yield_velocity(radius, ball, RIGID)
    b = simulate_impacts(radius, ball, RIGID, 5.0 * vy, 0.0, 0.0, normal_model="tabulated", force_law=law)
    out.append(
        relative(
            "contact",
            "normal restitution, table of Thornton's curves",
            "Al ball R 5 mm, Y 100 MPa, V/V_y = 5",
            float(theory.thornton_restitution(5.0)),
            "Thornton 1997 closed form",
            b.normal_restitution[0],
            5e-3,
        )
    )
    return out


def contact_halfspace(quick: bool) -> list[Check]:
    """The half-space contact solver (contact.halfspace) on a sphere: peak pressure and approach against Hertz."""

    radius, e_star, force = 2.5e-3, 1.5e11, 200.0
    a = float(theory.hertz_contact_radius_from_force(force, radius, e_star))
    cells = 48 if quick else 128
    spacing = 4.0 * a / cells
    x = (np.arange(cells) - (cells - 1) / 2) * spacing
    xx, yy = np.meshgrid(x, x)
    sol = halfspace_contact((xx**2 + yy**2) / (2.0 * radius), spacing, force, e_star)
    case = f"sphere R 2.5 mm, E* 150 GPa, 200 N, {cells // 4} cells across a"
    src = "Hertz (Johnson 1985 §4.2)"
    return [
        relative(
            "contact",
            "half-space solver: peak pressure",
            case,
            float(theory.hertz_peak_pressure(force, radius, e_star)),
            src,
            sol.max_pressure,
            0.01,
            "Pa",
        ),
        relative(
            "contact",
            "half-space solver: approach",
            case,
            float(theory.hertz_overlap(force, radius, e_star)),
            src,
            sol.approach,
            0.01,
            "m",
        ),
    ]
