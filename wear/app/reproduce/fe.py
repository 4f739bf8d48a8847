"""The figures of ``impactwear reproduce`` that press the finite-element plate (``fem.indent``): first yield and the
pressure profiles from elastic to fully plastic and during unloading (those of the coupled pipeline:
:mod:`wear.app.reproduce.coupled`).

SI units; w = δ/δ_c is the overlap over the first-yield overlap (exact C(ν), Eq. 18).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np

import fem
from contact import Material
from contact.theory import (
    PAPER_YIELD_COEFFICIENT,
    first_yield,
    hertz_pressure,
    mesarovic_johnson_pressure,
    yield_coefficient,
)
from wear.app.figures import paper as plots
from wear.app.reproduce.report import FigureReport
from wear.app.validation.references import unloading_path_w

__all__ = ["FIGURES", "STEEL", "indent", "loading_path", "unloading_path"]

#: The FE reference plate (steel): E 210 GPa, ν 0.3, Y 210 MPa (rigid ball R 10 mm).
STEEL = dict(E=210e9, nu=0.3, Y=210e6, radius=10e-3)


def plate(E: float, nu: float, Y: float | None) -> Material:
    return Material(E=E, nu=nu, density=7850.0, yield_strength=Y, name="plate")


def indent(radius: float, material: Material, overlaps, elements: tuple[int, int]):
    """``fem.indent`` with a rigid ball on a case mesh with ``elements`` = (P2 elements across the largest contact
    radius, across the first-yield contact radius)."""
    overlaps = np.asarray(overlaps, dtype=float)
    mesh = fem.plate_mesh(
        radius, material, float(overlaps.max()), contact_elements=elements[0], yield_elements=elements[1]
    )
    return fem.indent(radius=radius, plate=material, overlaps=overlaps, mesh=mesh)


def _critical(radius, material):
    e_star = material.E / (1.0 - material.nu**2)
    return first_yield(radius, e_star, material.yield_strength, material.nu), e_star


# ------------------------------------------------------------------------------------------- yield onset
YIELD_CASES = (
    ("R 10 mm, Y 210 MPa, ν 0.3", 10e-3, 210e6, 0.3),
    ("Y 105 MPa", 10e-3, 105e6, 0.3),
    ("Y 420 MPa", 10e-3, 420e6, 0.3),
    ("R 2.5 mm", 2.5e-3, 210e6, 0.3),
    ("R 40 mm", 40e-3, 210e6, 0.3),
    ("ν 0.2", 10e-3, 210e6, 0.2),
    ("ν 0.4", 10e-3, 210e6, 0.4),
)


def yield_onset_rows(quick: bool) -> list[dict]:
    """FE first-yield force against F_c (exact C(ν)) and equation 18 with C = 1.6, for the cases of YIELD_CASES."""
    cases = YIELD_CASES[::6] if quick else YIELD_CASES
    rows = []
    for label, radius, Y, nu in cases:
        mat = plate(STEEL["E"], nu, Y)
        fy, e_star = _critical(radius, mat)
        paper = first_yield(radius, e_star, Y, nu, coefficient=PAPER_YIELD_COEFFICIENT)
        path = np.linspace(0.0, 1.6 * fy.overlap, 7 if quick else 9)[1:]
        res = indent(radius, mat, path, (8, 8) if quick else (24, 20))
        found = res.first_yield
        rows.append(
            dict(
                label=label,
                fe=math.nan if found is None else found.force,
                fe_depth=math.nan if found is None else found.depth,
                exact=fy.force,
                paper=paper.force,
                depth=fy.depth,
                contact_radius=fy.contact_radius,
            )
        )
    return rows


def fig_yield_onset(out: Path, quick: bool) -> FigureReport:
    rep = FigureReport("fig_yield_onset", "First yield: FE against Eq. 18 (C = 1.6 and the exact C(ν))")
    rows = yield_onset_rows(quick)
    plots.plot_yield_onset(
        rows,
        out / f"{rep.name}.png",
        "FE: fem.indent (this toolkit, axisymmetric J2 plate, rigid ball, E 210 GPa); F_c = π³(C Y)³R²/(6E*²) "
        "(errata Eq. 18) with C(ν) exact (Johnson 1985 §6.2) and with the paper's C = 1.6",
    )
    ratio = np.array([r["fe"] / r["exact"] for r in rows])
    paper = np.array([r["paper"] / r["exact"] for r in rows])
    worst = int(np.nanargmax(np.abs(ratio - 1)))
    rep.numbers = {
        "max |F_FE/F_c - 1|": float(np.nanmax(np.abs(ratio - 1))),
        "worst case": rows[worst]["label"],
        "F(C = 1.6)/F_c range": f"{paper.min():.4f}-{paper.max():.4f}",
    }
    rep.paper = (
        "Eq. 18 gives the force at first yield, F_y = π³(1.65y)³R²/(6E*²) as printed (the text says P_max = 1.6 S_y); "
        "no FE comparison."
    )
    rep.ours = (
        f"Over {len(rows)} cases varying Y (105-420 MPa), R (2.5-40 mm) and ν (0.2-0.4) the FE first-yield force "
        f"is within {np.nanmax(np.abs(ratio - 1)):.1%} of F_c with the exact C(ν) (worst: {rows[worst]['label']}). "
        f"With the paper's C = 1.6 Eq. 18 gives {paper.min():.3f}-{paper.max():.3f} × F_c."
    )
    c02, c03, c04 = (yield_coefficient(nu) for nu in (0.2, 0.3, 0.4))
    rep.differences = (
        f"The printed Eq. 18 has 1.65 where the text has 1.6, and C depends on ν (exact C = {c02:.3f}, {c03:.4f}, "
        f"{c04:.3f} at ν = 0.2, 0.3, 0.4; Green's fit within 0.1%). Since F ∝ C³, a constant 1.6 puts F_y "
        f"{(1.6 / c03) ** 3 - 1:+.1%} off at ν = 0.3, {(1.6 / c02) ** 3 - 1:+.0%} at ν = 0.2 and "
        f"{(1.6 / c04) ** 3 - 1:+.0%} at ν = 0.4. The FE locates first yield inside the increment in which it "
        "occurs, on the axis below the surface (Hertz self-similarity of an elastic state, re-solved on the same "
        "mesh until within 1% in force)."
    )
    return rep


# -------------------------------------------------------------------------------------- pressure regimes
REGIME_W = (0.5, 1.0, 3.0, 6.0, 20.0, 100.0)
UNLOADING_FRACTIONS = (0.75, 0.5)


def loading_path(delta_c: float, quick: bool) -> tuple[np.ndarray, np.ndarray]:
    """Overlaps (m) of a load to w = 100 through the w of :data:`REGIME_W` (increments growing geometrically:
    plasticity spreads gradually), and the step index of each w."""
    w = np.unique(np.concatenate([np.geomspace(0.05, 100.0, 24 if quick else 32), REGIME_W]))
    return w * delta_c, np.array([int(np.argmin(np.abs(w - x))) for x in REGIME_W])


def unloading_path(delta_c: float, quick: bool) -> np.ndarray:
    """Overlaps (m) of a load to w = 50 (increments ≤ 0.25 δ_c up to w = 2: the radial return integrates the
    path) and an unload in steps of ~1 w to w ≈ 28 (a/a* ≈ 0.5 is reached near w ≈ 30): the path of the
    Mesarovic-Johnson check of ``impactwear validate`` (:func:`wear.app.validation.references.unloading_path_w`)."""
    w_load, w_unload = unloading_path_w(quick)
    return np.concatenate([w_load, w_unload]) * delta_c


def _sorted(res):
    order = np.argsort(res.surface_r)
    return np.asarray(res.surface_r)[order], np.asarray(res.pressure)[:, order]


def pressure_regimes(quick: bool) -> dict:
    """Two FE runs on the steel plate :data:`STEEL`: a load to w = 100 (profiles at :data:`REGIME_W` against Hertz at
    the same force) and a load to w = 50 with unloading (profiles at a/a* = 0.75, 0.5 against equation 19)."""
    mat = plate(STEEL["E"], STEEL["nu"], STEEL["Y"])
    radius = STEEL["radius"]
    fy, e_star = _critical(radius, mat)
    path, at_w = loading_path(fy.overlap, quick)
    res = indent(radius, mat, path, (12, 6) if quick else (24, 10))
    r, pressure = _sorted(res)
    loading = []
    for w, k in zip(REGIME_W, at_w, strict=True):
        force, a = float(res.force[k]), float(res.contact_radius[k])
        a_h = (3 * force * radius / (4 * e_star)) ** (1 / 3)
        p0_h = 3 * force / (2 * math.pi * a_h**2)
        rr = np.linspace(0, 1.3 * a, 300)
        loading.append(
            dict(
                label=f"w = {w:g} ({res.regime[k]})",
                r=r,
                p=pressure[k],
                ref_r=rr,
                ref_p=hertz_pressure(rr, a_h, p0_h),
                scale_r=a,
                scale_p=force / (math.pi * a * a),
                ratio=float(res.max_pressure[k] / res.mean_pressure[k]),
            )
        )
    path = unloading_path(fy.overlap, quick)
    res = indent(radius, mat, path, (16, 10) if quick else (24, 14))
    r, pressure = _sorted(res)
    k_star = int(np.argmax(path))
    a_star, f_star = float(res.contact_radius[k_star]), float(res.force[k_star])
    p_star = f_star / (math.pi * a_star**2)
    unloading = [
        dict(
            label="a/a* = 1 (start of unloading, w = 50)",
            r=r,
            p=pressure[k_star],
            ref_r=r,
            ref_p=np.where(r < a_star, p_star, 0.0),
            scale_r=a_star,
            scale_p=p_star,
        )
    ]
    rms = {}
    after = np.arange(k_star + 1, len(path))
    for frac in UNLOADING_FRACTIONS:
        k = int(after[np.argmin(np.abs(res.contact_radius[after] / a_star - frac))])
        a = float(res.contact_radius[k])
        ref = mesarovic_johnson_pressure(r, a, a_star, p_star)
        inside = r <= a_star
        rms[frac] = float(np.sqrt(np.mean((pressure[k][inside] - ref[inside]) ** 2)) / p_star)
        unloading.append(
            dict(
                label=f"a/a* = {a / a_star:.2f} (RMS {rms[frac]:.1%} of p*)",
                r=r,
                p=pressure[k],
                ref_r=r,
                ref_p=ref,
                scale_r=a_star,
                scale_p=p_star,
            )
        )
    return dict(loading=loading, unloading=unloading, rms=rms, a_star=a_star, p_star=p_star)


def fig_pressure_regimes(out: Path, quick: bool) -> FigureReport:
    rep = FigureReport("fig_pressure_regimes", "Pressure profiles from elastic to fully plastic, and unloading")
    d = pressure_regimes(quick)
    plots.plot_pressure_regimes(
        d["loading"],
        d["unloading"],
        out / f"{rep.name}.png",
        "FE: fem.indent (this toolkit; steel plate E 210 GPa, ν 0.3, Y 210 MPa, rigid ball R 10 mm); Hertz Eq. 16 "
        "at the FE force; Mesarovic & Johnson 2000 (Eq. 19) from the FE's a*, p* = F*/(πa*²) after a load to w = 50. "
        "FE curves: the pressure at the surface nodes along the load path; after yield it ripples from node to node, "
        "the imprint of the load increments (docs: the FE plate, 'The pressure it reports')",
    )
    ratios = {s["label"]: s["ratio"] for s in d["loading"]}
    rep.numbers = {f"p_max/p_mean at {k}": v for k, v in ratios.items()}
    rep.numbers.update({f"RMS(FE - Eq. 19)/p* at a/a* = {k:g}": v for k, v in d["rms"].items()})
    rep.paper = (
        "Fig. 8 (from its ref. [16]) shows the pressure flattening once the plastic zone reaches the surface; the "
        "paper uses Eq. 16 (printed as the parabola p_max(1 − r²/a²), which does not carry F) up to F_y and "
        "Eq. 19 (printed with a garbled argument) during unloading."
    )
    text = ", ".join(f"{k}: {v:.2f}" for k, v in ratios.items())
    rep.ours = (
        f"p_max/p_mean along the load (Hertz: 1.5): {text}. During unloading from w = 50 the FE profile is "
        + ", ".join(f"{v:.1%} of p* RMS from Eq. 19 at a/a* = {k:g}" for k, v in d["rms"].items())
        + "."
    )
    rep.differences = (
        "Up to w ≈ 1 the FE follows the corrected Eq. 16. In the contained elastic-plastic range the profile is "
        "still close to Hertz; once the plastic zone reaches the surface it flattens (p_max/p_mean → ~1) and "
        "its edge sharpens, which neither Eq. 16 nor a truncated Hertz profile captures. Eq. 19 assumes a "
        "uniform p* at the start of unloading; the FE p* profile is not exactly uniform, hence the RMS above."
    )
    return rep


#: name → function(out_dir, quick) -> FigureReport, in the order of reproduce.md.
FIGURES: dict[str, Callable[[Path, bool], FigureReport]] = {
    "fig_yield_onset": fig_yield_onset,
    "fig_pressure_regimes": fig_pressure_regimes,
}
