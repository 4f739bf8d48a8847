"""Validation checks of ``fem`` (the axisymmetric elastic-plastic plate), for ``impactwear validate``.

References: the Hertz closed forms (Johnson 1985; errata Eqs. 4, 16-17), the MOOSE contact module's Hertz benchmark,
first yield F_c with the exact C(0.3) = 1.6128 at depth 0.481a (errata Eq. 18), Kogut & Etsion (2002) J. Appl.
Mech. 69:657 fits, the exact elastic unloading stiffness dF/dδ = 2E*a, and Mesarovic & Johnson (2000) (Eq. 19).
This module is skipped (not imported) when the FE stage is not in the build.
"""

from __future__ import annotations

import math

import numpy as np

import fem
from contact import Material
from contact.halfspace import sphere_on_axisymmetric_surface
from contact.theory import first_yield, hertz_force, hertz_peak_pressure, mesarovic_johnson_pressure
from wear.app.validation.checks import Check, absolute, relative
from wear.app.validation.references import unloading_path_w

if not hasattr(fem, "indent"):
    raise ModuleNotFoundError("fem.indent is not available", name=__name__)

E, NU, Y, R = 210e9, 0.3, 210e6, 10e-3
E_STAR = E / (1 - NU**2)
CASE = "rigid ball R 10 mm on steel E 210 GPa, ν 0.3"


def _plate(yield_strength=Y, E_=E, nu=NU):
    return Material(E=E_, nu=nu, density=7850.0, yield_strength=yield_strength)


def _indent(radius, plate, overlaps, elements: tuple[int, int], **kwargs):
    """``fem.indent`` (rigid ball) on a case mesh with ``elements`` = (P2 elements across the largest contact
    radius, across the first-yield contact radius; 0 = no first-yield box)."""
    overlaps = np.asarray(overlaps, dtype=float)
    mesh = fem.plate_mesh(
        radius, plate, float(overlaps.max()), contact_elements=elements[0], yield_elements=elements[1]
    )
    return fem.indent(radius=radius, plate=plate, overlaps=overlaps, mesh=mesh, **kwargs)


def _critical():
    return first_yield(R, E_STAR, Y, NU)


def fem_hertz(quick: bool) -> list[Check]:
    """Elastic plate (yield_strength=None) up to a = 0.05R: force within 1% of (4/3)E*√R δ^{3/2}, contact radius
    within 3% of √(Rδ), pressure within 5% RMS of p0 of p0√(1 − r²/a²) (Hertz); the MOOSE
    Hertz benchmark (E* = 7.5 MPa, R = 1 m, F = 1e4 N → a = 0.1 m, δ = 0.01 m) within 2%."""
    delta = (0.05 * R) ** 2 / R
    res = _indent(R, _plate(None), np.linspace(0.0, delta, 5)[1:], (12, 0) if quick else (32, 0))
    f_ref = float(hertz_force(delta, R, E_STAR))
    a = float(res.contact_radius[-1])
    p0 = float(hertz_peak_pressure(res.force[-1], R, E_STAR))
    a_h = math.sqrt(R * delta)
    r = np.asarray(res.surface_r)
    inside = r < a_h
    p_ref = p0 * np.sqrt(np.clip(1 - (r / a_h) ** 2, 0, None))
    rms = float(np.sqrt(np.mean((res.pressure[-1][inside] - p_ref[inside]) ** 2)) / p0)
    case = f"elastic {CASE}, δ = {delta * 1e6:g} µm (a = 0.05R)"
    src = "Hertz (Johnson 1985; errata Eqs. 4, 16)"
    out = [
        relative("fem", "force", case, f_ref, src, float(res.force[-1]), 0.01, "N"),
        relative("fem", "contact radius", case, a_h, src, a, 0.03, "m"),
        Check(
            "fem",
            "pressure profile",
            case,
            p0,
            src,
            float(np.max(res.pressure[-1])),
            rms,
            0.05,
            "RMS(p − Hertz)/p0 inside a",
            "Pa",
        ),
    ]
    nu = 0.3
    moose = Material(E=7.5e6 * (1 - nu**2), nu=nu, density=1000.0)
    res = _indent(1.0, moose, [0.005, 0.01], (12, 0) if quick else (24, 0))
    case = "MOOSE: E* 7.5 MPa, R 1 m, δ 0.01 m"
    src = "MOOSE contact module Hertz benchmark"
    out.append(relative("fem", "force at δ = 0.01 m", case, 1e4, src, float(res.force[-1]), 0.02, "N"))
    out.append(
        relative("fem", "contact radius at δ = 0.01 m", case, 0.1, src, float(res.contact_radius[-1]), 0.02, "m")
    )
    return out


def fem_first_yield(quick: bool) -> list[Check]:
    """First yield (Y = 210 MPa) within 3% of F_c = π³C³Y³R²/(6E*²), C(0.3) = 1.6128, on the axis at depth
    0.481a ± 0.03a; loading to 0.9 F_c and unloading leaves no plastic strain."""
    fc = _critical()
    path = np.linspace(0.0, 1.5 * fc.overlap, 7 if quick else 13)[1:]
    res = _indent(R, _plate(), path, (12, 10) if quick else (24, 20))
    fy = res.first_yield
    case = f"{CASE}, Y 210 MPa"
    out = [
        relative(
            "fem",
            "first-yield force",
            case,
            fc.force,
            "F_c, errata Eq. 18 with exact C(0.3) = 1.6128",
            math.nan if fy is None else fy.force,
            0.03,
            "N",
        ),
        absolute(
            "fem",
            "first-yield depth / a_c",
            case,
            0.481,
            "Johnson 1985 §6.2 (z = 0.481a)",
            math.nan if fy is None else fy.depth / fc.contact_radius,
            0.03,
        ),
    ]
    d09 = float((0.9 * fc.force * 3 / (4 * E_STAR * math.sqrt(R))) ** (2 / 3))
    path = np.concatenate([np.linspace(0, d09, 4)[1:], np.linspace(d09, 0, 4)[1:]])
    res = _indent(R, _plate(), path, (8, 8) if quick else (16, 16))
    out.append(
        absolute(
            "fem",
            "max equivalent plastic strain after 0.9 F_c",
            case,
            0.0,
            "elastic below F_c (Eq. 18)",
            float(np.max(res.max_equivalent_plastic_strain)),
            1e-12,
        )
    )
    return out


KE_W = (2.0, 6.0, 20.0)


def _kogut_etsion(w: float) -> tuple[float, float]:
    """Kogut & Etsion (2002): P/P_c and A/A_c at w = δ/δ_c (1 ≤ w ≤ 6 and 6 ≤ w ≤ 110 fits)."""
    if w <= 6.0:
        return 1.03 * w**1.425, 0.93 * w**1.136
    return 1.40 * w**1.263, 0.94 * w**1.146


def fem_elastic_plastic(quick: bool) -> list[Check]:
    """Elastic-plastic loading against Kogut & Etsion (2002), w = δ/δ_c: P/P_c and A/A_c within 15% at w = 2, 6, 20
    (their case is a deformable sphere on a rigid flat: the same while elastic, close in early plasticity); the
    plastic zone reaches the surface between w = 4 and 10; elastic unloading stiffness
    dF/dδ = 2E*a at the start of unloading within 3%; after w = 50, the unloading pressure at
    a/a* = 0.75 and 0.5 within 15% RMS of p* of Mesarovic & Johnson (equation 19) from the FE's own a*, p*."""
    fc = _critical()
    dc = fc.overlap
    w_load, w_unload = unloading_path_w(quick)
    path = np.concatenate([w_load, w_unload]) * dc
    res = _indent(R, _plate(), path, (16, 10) if quick else (32, 20))
    k_star = w_load.size - 1  # the last loading step: unloading starts from w = 50
    return [
        *_kogut_etsion_loading(res, w_load, fc.force, math.pi * R * dc),
        _plastic_zone_surface(res, w_load),
        _unloading_stiffness(res, path, k_star),
        *_unloading_pressures(res, path, k_star),
    ]


def _kogut_etsion_loading(res: fem.IndentationResult, w_load: np.ndarray, pc: float, ac: float) -> list[Check]:
    """P/P_c and A/A_c of the FE run ``res`` at w = :data:`KE_W` against Kogut & Etsion's fits; ``w_load``: the
    loading path's w = δ/δ_c, ``pc`` the first-yield force (N), ``ac`` = πRδ_c its contact area (m²)."""
    src = "Kogut & Etsion 2002, J. Appl. Mech. 69:657"
    out = []
    for w in KE_W:
        k = int(np.argmin(np.abs(w_load - w)))
        p_ref, a_ref = _kogut_etsion(w)
        out.append(relative("fem", f"P/P_c at w = {w:g}", CASE + ", Y 210 MPa", p_ref, src, res.force[k] / pc, 0.15))
        out.append(
            relative(
                "fem",
                f"A/A_c at w = {w:g}",
                CASE + ", Y 210 MPa",
                a_ref,
                src,
                math.pi * res.contact_radius[k] ** 2 / ac,
                0.15,
            )
        )
    return out


def _plastic_zone_surface(res: fem.IndentationResult, w_load: np.ndarray) -> Check:
    """The first w = δ/δ_c of the loading path ``w_load`` at which the plastic zone of ``res`` reaches the surface
    (inf if it never does), against Kogut & Etsion's 4 ≤ w ≤ 10."""
    regimes = [res.regime[i] for i in range(w_load.size)]
    surface = [w for w, g in zip(w_load, regimes, strict=True) if g in ("surface-plastic", "fully-plastic")]
    w_surface = float(surface[0]) if surface else math.inf
    return Check(
        "fem",
        "w at which the plastic zone reaches the surface",
        CASE + ", Y 210 MPa",
        "4 ≤ w ≤ 10",
        "Kogut & Etsion 2002",
        w_surface,
        max(4.0 - w_surface, w_surface - 10.0, 0.0),
        0.0,
        "distance outside [4, 10]",
    )


def _unloading_stiffness(res: fem.IndentationResult, path: np.ndarray, k_star: int) -> Check:
    """The FE's first unloading stiffness dF/dδ (N/m) from step ``k_star`` of the overlaps ``path`` (m), against
    the exact elastic 2E*a at the mean contact radius of that step."""
    k1 = k_star + 1
    stiffness = (res.force[k_star] - res.force[k1]) / (path[k_star] - path[k1])
    a_mid = 0.5 * (res.contact_radius[k_star] + res.contact_radius[k1])
    return relative(
        "fem",
        "unloading stiffness dF/dδ at w = 50",
        CASE + ", Y 210 MPa",
        2 * E_STAR * a_mid,
        "exact for elastic unloading: 2E*a (Johnson 1985 Eq. 3.22)",
        stiffness,
        0.03,
        "N/m",
    )


def _unloading_pressures(res: fem.IndentationResult, path: np.ndarray, k_star: int) -> list[Check]:
    """The FE's surface pressure (Pa) on unloading from step ``k_star`` at a/a* ≈ 0.75 and 0.5 against
    Mesarovic & Johnson's Eq. 19 with the FE's own a* (m) and p* = F*/(πa*²) (Pa): the value on the axis, and the
    RMS difference over r ≤ a* relative to p*."""
    k1 = k_star + 1
    a_star, f_star = float(res.contact_radius[k_star]), float(res.force[k_star])
    p_star = f_star / (math.pi * a_star**2)
    r = np.asarray(res.surface_r)
    axis = int(np.argmin(r))
    after = np.arange(k1, path.size)
    out = []
    for frac in (0.75, 0.5):
        k = int(after[np.argmin(np.abs(res.contact_radius[after] / a_star - frac))])
        a = float(res.contact_radius[k])
        ref = mesarovic_johnson_pressure(r, a, a_star, p_star)
        inside = r <= a_star
        rms = float(np.sqrt(np.mean((res.pressure[k][inside] - ref[inside]) ** 2)) / p_star)
        out.append(
            Check(
                "fem",
                f"unloading pressure on the axis, a/a* = {a / a_star:.2f}",
                CASE + ", Y 210 MPa, from w = 50",
                float(ref[axis]),
                "Mesarovic & Johnson 2000 (Eq. 19) with the FE's a*, p*",
                float(res.pressure[k][axis]),
                rms,
                0.15,
                "RMS(p − Eq. 19)/p* over r ≤ a*",
                "Pa",
            )
        )
    return out


def fem_worn_surface(quick: bool) -> list[Check]:
    """FE plate with a worn pit w = D(1 − r²/a₀²)², D = 0.5 a₀²/R (fem.Plate.move_surface), elastic, against the
    half-space solution of the same gap and force (contact.halfspace, itself checked against Hertz)."""

    a0 = 0.01 * R
    d0 = a0**2 / R

    def pit(rho):
        return 0.5 * d0 * np.clip(1.0 - (rho / a0) ** 2, 0.0, None) ** 2

    plate_material = _plate(None)
    mesh = fem.plate_mesh(R, plate_material, 2.0 * d0, contact_elements=16 if quick else 32, yield_elements=10)
    plate = fem.Plate(R, plate_material, 2.0 * d0, mesh=mesh)
    r = plate.surface_r
    plate.move_surface(pit(r))
    res = plate.load(plate.first_contact_overlap() + np.linspace(0.0, 1.0, 5)[1:] * d0)
    bem, _ = sphere_on_axisymmetric_surface(R, pit, float(res.force[-1]), E_STAR, 3.2 * a0)
    case = f"elastic {CASE}, worn pit 0.5 a₀²/R deep, a₀ wide"
    src = "half-space BEM (Love 1929; Polonsky & Keer 1999), same gap and force"
    return [
        relative(
            "fem", "peak pressure on a worn pit", case, bem.max_pressure, src, float(res.pressure[-1].max()), 0.03, "Pa"
        ),
        relative("fem", "approach on a worn pit", case, bem.approach, src, float(res.overlap[-1]), 0.01, "m"),
    ]


def fem_elastic_reload(quick: bool) -> list[Check]:
    """Elastic reload of a dent (fem.elastic_reload: the plate's elastic response condensed onto its surface, used for
    repeated impacts after shakedown): a plate indented to 8 δ_y and unloaded, reloaded half-way back, against the
    half-space solution of the dent's gap at the same force (contact.halfspace, itself checked against Hertz)."""

    material = _plate()
    d_max = 8.0 * _critical().overlap
    mesh = fem.plate_mesh(R, material, d_max, contact_elements=16, yield_elements=10)
    plate = fem.Plate(R, material, d_max, mesh=mesh)
    plate.unload(plate.load(np.linspace(0.0, d_max, 9)[1:]), d_max, steps=6)
    d0 = plate.first_contact_overlap()
    res = fem.elastic_reload(plate, [d0 + 0.5 * (d_max - d0)]).result

    def dent(rho):
        return fem.surface_profile(plate.surface_r, plate.dent_depth, rho)

    bem, _ = sphere_on_axisymmetric_surface(R, dent, float(res.force[0]), E_STAR, 3.0 * float(res.contact_radius[0]))
    case = f"{CASE}, Y 210 MPa, dent of 8 δ_y, elastic reload"
    src = "half-space BEM (Love 1929; Polonsky & Keer 1999), the dent's gap, same force"
    return [
        relative(
            "fem",
            "peak pressure, elastic reload of a dent",
            case,
            bem.max_pressure,
            src,
            float(res.max_pressure[0]),
            0.03,
            "Pa",
        ),
        relative(
            "fem", "approach, elastic reload of a dent", case, bem.approach, src, float(res.overlap[0]), 0.02, "m"
        ),
    ]
