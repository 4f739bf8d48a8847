"""Validation checks of ``contact`` (the H-DD impact engine and the closed forms), for ``impactwear validate``.

Every reference is independent of the code it checks: numbers published by Chung & Ooi (2011), Thornton (1997),
Maw, Barber & Fawcett (1976, 1981), Kharaz, Gorham & Salman (2001), Johnson (1985), the MOOSE contact benchmark;
rigid-body impact theory evaluated here; and numerical quadrature of the closed-form pressure profiles.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import quad

from contact import Material, TabulatedLaw, simulate_impact, simulate_impacts, theory, yield_velocity
from contact.halfspace import halfspace_contact
from contact.materials import effective_modulus
from wear.app.validation.checks import Check, absolute, register, relative
from wear.app.validation.references import kharaz_data, kharaz_rms

RIGID = Material.rigid()
AL_OXIDE = Material(E=380e9, nu=0.23, density=4000.0, name="Al oxide")
CHUNG_OOI = "Chung & Ooi 2011, Granular Matter 13:643"


@register("contact")
def chung_ooi_test2(quick: bool) -> list[Check]:
    """Chung & Ooi (2011) test 2, Table 4: Hertz normal impacts on a rigid plane (tolerance 0.2%)."""
    cases = [
        ("Al alloy R 0.1 m, 0.2 m/s", Material(70e9, 0.30, 2699.0), 0.1, 0.2, 49.717e-6, 11.370e3, 731.66e-6),
        ("Mg alloy R 0.1 m, 0.2 m/s", Material(40e9, 0.35, 1800.0), 0.1, 0.2, 52.123e-6, 7232.7, 767.07e-6),
        ("Al oxide R 2.5 mm, 3.9 m/s", AL_OXIDE, 2.5e-3, 3.9, 8.0888e-6, 615.35, 6.1045e-6),
    ]
    out = []
    for label, material, radius, speed, overlap, force, time in cases:
        r = simulate_impact(radius, material, RIGID, speed, 0.0, 0.0, history=False)
        src = f"{CHUNG_OOI}, test 2"
        out.append(relative("contact", "max overlap", label, overlap, src, r.max_overlap, 2e-3, "m"))
        out.append(relative("contact", "max normal force", label, force, src, r.max_force, 2e-3, "N"))
        out.append(relative("contact", "contact time", label, time, src, r.contact_time, 2e-3, "s"))
    return out


@register("contact")
def chung_ooi_test3(quick: bool) -> list[Check]:
    """Chung & Ooi (2011) test 3: the simulated normal restitution equals the requested e (0.5%), and with the
    Tsuji-form dashpot (errata Eq. 6) it does not depend on the speed."""
    out = []
    for material in (AL_OXIDE, Material(E=100e9, nu=0.25, density=7000.0, name="cast iron")):
        es = np.array([0.2, 0.4, 0.6, 0.8])
        got = np.array(
            [
                simulate_impact(2.5e-3, material, RIGID, 3.9, 0.0, 0.0, restitution=e, history=False).normal_restitution
                for e in es
            ]
        )
        worst = int(np.argmax(np.abs(got / es - 1)))
        out.append(
            relative(
                "contact",
                f"normal restitution (worst of e = 0.2-0.8: e = {es[worst]:g})",
                f"{material.name} R 2.5 mm on rigid, 3.9 m/s",
                es[worst],
                f"{CHUNG_OOI}, test 3",
                got[worst],
                5e-3,
            )
        )
    b = simulate_impacts(2.5e-3, AL_OXIDE, RIGID, [0.1, 1.0, 10.0], 0.0, 0.0, restitution=0.5)
    worst = float(b.normal_restitution[np.argmax(np.abs(b.normal_restitution - 0.5))])
    out.append(
        relative(
            "contact",
            "normal restitution at 0.1, 1, 10 m/s (worst)",
            "Al oxide on rigid, e = 0.5 asked",
            0.5,
            "errata Eq. 6 (Tsuji et al. 1992 form): e independent of speed",
            worst,
            5e-3,
        )
    )
    return out


@register("contact")
def chung_ooi_test4(quick: bool) -> list[Check]:
    """Chung & Ooi (2011) test 4 at θ = 50°, e = 1 (published values, 0.5%); and rigid-body theory in gross
    sliding over 40-85° with e = 0.98, evaluated here: e_t = 1 − μ(1+e)/tan θ, ω = 2.5μ(1+e)v cos θ/R."""
    r = simulate_impact(2.5e-3, AL_OXIDE, RIGID, 3.9, 50.0, 0.092, history=False)
    case = "Al oxide R 2.5 mm on rigid, 3.9 m/s, 50°, μ 0.092"
    src = f"{CHUNG_OOI}, test 4"
    out = [
        relative("contact", "tangential restitution", case, 0.8456, src, r.tangential_restitution, 5e-3),
        relative("contact", "spin after impact", case, 461.26, src, r.spin, 5e-3, "rad/s"),
        relative(
            "contact", "contact-point rebound angle", case, 28.712, src, r.contact_point_rebound_angle, 5e-3, "deg"
        ),
        relative("contact", "centre rebound angle", case, 45.221, src, r.rebound_angle, 5e-3, "deg"),
    ]
    e, mu = 0.98, 0.092
    angles = np.arange(40.0, 86.0, 5.0 if quick else 1.0)
    b = simulate_impacts(2.5e-3, AL_OXIDE, RIGID, 3.9, angles, mu, restitution=e)
    th = np.radians(angles)
    et = 1 - mu * (1 + e) / np.tan(th)
    spin = 2.5 * mu * (1 + e) * 3.9 * np.cos(th) / 2.5e-3
    case = f"Al oxide on rigid, 3.9 m/s, {angles[0]:g}-{angles[-1]:g}°, μ 0.092, e 0.98"
    src = "rigid-body impact theory with Coulomb sliding (Brach 1991), evaluated here"
    for name, got, ref, unit in (
        ("tangential restitution", b.tangential_restitution, et, ""),
        ("spin", b.spin, spin, "rad/s"),
    ):
        k = int(np.argmax(np.abs(got / ref - 1)))
        out.append(relative("contact", f"{name} (worst angle {angles[k]:g}°)", case, ref[k], src, got[k], 5e-3, unit))
    return out


@register("contact")
def maw_barber_fawcett(quick: bool) -> list[Check]:
    """Maw, Barber & Fawcett (1976, 1981) in the form of Chung & Ooi (2011) test 5, ν = 0.3, e = 1, μ = 0.1.

    Ψ1 = tan θ/μ ≥ 6: sliding throughout, Ψ2 = Ψ1 − 7 and Rω/(μV_n) = 5. Smallest Ψ1 sliding throughout:
    7 − (2−ν)/(2(1−ν)) = 5.786 with the H-DD 2/3 factor and with Mindlin–Deresiewicz's memory (MBF's own contact
    law), and 7 − (2−ν)/(3(1−ν)) = 6.190 with Mindlin's spring."""
    steel = Material(E=210e9, nu=0.3, density=7800.0)
    mu, radius = 0.1, 0.01

    def batch(psi1, model="hdd"):
        angle = np.degrees(np.arctan(mu * psi1))
        return simulate_impacts(
            radius, steel, RIGID, 1.0 / np.cos(np.radians(angle)), angle, mu, tangential_model=model
        )

    psi1 = np.array([6.0, 7.0, 8.0, 10.0, 15.0, 20.0])
    b = batch(psi1)
    psi2 = (b.rebound_tangential_velocity - radius * b.spin) / mu
    case = "steel ball on rigid, ν 0.3, e 1, μ 0.1, Ψ1 = 6-20"
    src = "Maw, Barber & Fawcett 1976 (Chung & Ooi 2011 test 5)"
    k = int(np.argmax(np.abs(psi2 - (psi1 - 7))))
    ratio = radius * np.abs(b.spin) / mu
    j = int(np.argmax(np.abs(ratio - 5)))
    out = [
        absolute(
            "contact",
            f"Ψ2 = Ψ1 − 7 (worst Ψ1 = {psi1[k]:g})",
            case,
            psi1[k] - 7,
            src,
            psi2[k],
            0.035,
            measure="absolute (0.5% of 7)",
        ),
        relative("contact", f"Rω/(μV_n) = 5 (worst Ψ1 = {psi1[j]:g})", case, 5.0, src, ratio[j], 5e-3),
    ]
    step = 0.01 if quick else 0.002
    for model, divisor in (("hdd", 2.0), ("mindlin", 3.0), ("mindlin_deresiewicz", 2.0)):
        ref = 7.0 - (2 - 0.3) / (divisor * (1 - 0.3))
        grid = np.arange(5.5, 6.5, step)
        bb = batch(grid, model)
        slides = bb.sliding_time >= (bb.steps - 1) * bb.time_step * (1 - 1e-9)
        first = float(grid[np.argmax(slides)])
        out.append(
            relative(
                "contact",
                f"smallest Ψ1 sliding throughout ({model})",
                case.replace(", Ψ1 = 6-20", ""),
                ref,
                "Maw, Barber & Fawcett; Di Renzo & Di Maio 2005",
                first,
                1e-2,
            )
        )
    return out


@register("contact")
def thornton_1997(quick: bool) -> list[Check]:
    """Thornton (1997) J. Appl. Mech. 64:383: restitution of elastic-perfectly plastic impacts (engine, 0.2%)."""
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


@register("contact")
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


@register("contact")
def integration_and_energy(quick: bool) -> list[Check]:
    """Velocity Verlet converges at order 2 (errata Eqs. 12-14 note) and the reported works close the energy
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


@register("contact")
def closed_forms(quick: bool) -> list[Check]:
    """Closed forms against published numbers and against quadrature: MOOSE Hertz benchmark, exact first-yield
    coefficient C(0.3) = 1.6128 at z = 0.481a (Johnson 1985 §6.2; errata Eq. 18), Green's (2005) fit, and the
    force carried by the Eq. 16 and Eq. 19 profiles (scipy quadrature)."""
    out = [
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
    nus = np.linspace(0.1, 0.45, 8)
    dev = [abs(theory.yield_coefficient(n) / float(theory.green_yield_coefficient(n)) - 1) for n in nus]
    k = int(np.argmax(dev))
    out.append(
        relative(
            "contact",
            f"C(ν) vs Green's fit (worst ν = {nus[k]:.2f})",
            "ν = 0.10-0.45",
            float(theory.green_yield_coefficient(nus[k])),
            "Green 2005, Proc. IMechE J 219 (fit within 0.1%)",
            theory.yield_coefficient(nus[k]),
            1e-3,
        )
    )
    a, p0 = 1e-4, 2e9
    force = 2 * math.pi * quad(lambda r: r * float(theory.hertz_pressure(r, a, p0)), 0, a, epsrel=1e-12)[0]
    out.append(
        relative(
            "contact",
            "∫ p dA of Eq. 16 (corrected Hertz profile)",
            "a 0.1 mm, p0 2 GPa",
            2 / 3 * math.pi * a * a * p0,
            "Johnson 1985: F = 2πa²p0/3",
            force,
            1e-8,
            "N",
        )
    )
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
    out.append(
        relative(
            "contact",
            "∫ p dA of Eq. 19 at a/a* = 0.6",
            "a* 0.2 mm, p* 1.5 GPa",
            float(theory.mesarovic_johnson_force(x * a_star, a_star, p_star)),
            "Mesarovic & Johnson 2000: F/F* = (2/π)[asin x − x√(1−x²)]",
            f_mj,
            1e-6,
            "N",
        )
    )
    return out


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


@register("contact")
def tabulated_law(quick: bool) -> list[Check]:
    """The tabulated normal law (the FE → impact path of the two-way coupling) with tables written from closed
    forms: a Hertz table reproduces the Hertz impact closed form (errata Eqs. 10-11, 0.2%); a table of
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


@register("contact")
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
