"""The figures of ``impactwear reproduce`` that run the coupled pipeline (``wear.run``: the impact two-way coupled to
the finite-element plate) on the default case: the regime map, the normal restitution against Thornton (1997), and
the worn mass per impact against angle of the paper's wear figure (:mod:`wear.app.reproduce.paper`).

SI units; angles in degrees from the plate normal.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np

from contact.theory import thornton_restitution
from fem import REGIMES
from wear.app.figures import paper as plots
from wear.app.reproduce.report import FigureReport
from wear.case import Case
from wear.chain.restitution import restitution_sweep
from wear.chain.single import run

__all__ = ["FIGURES", "default_case_wear"]


def _run_case(quick: bool):
    """The pipeline's default case (``wear.Case()``) without output files; quick: coarser FE."""
    fem_options = dict(mesh_scale=4.0, load_steps=6, unload_steps=4) if quick else {}
    return Case().with_(fem=fem_options, output={"figures": False, "render": False})


def _at_max_overlap(fe):
    """Regime and p_max/p_mean of an FE cycle at its maximum overlap."""
    k = int(np.argmax(fe.overlap))
    a, force = float(fe.contact_radius[k]), float(fe.force[k])
    ratio = float(np.max(fe.pressure[k]) / (force / (math.pi * a * a))) if a > 0 else math.nan
    return fe.regime[k], ratio


REGIME_SPEEDS = (0.3, 0.6, 1.5, 3.0)
REGIME_YIELDS = (500e6, 900e6, 1600e6)


def regime_grid(quick: bool) -> tuple[np.ndarray, np.ndarray]:
    """(speeds (m/s), yield strengths (Pa)) of the regime map: :data:`REGIME_SPEEDS` × :data:`REGIME_YIELDS`, 12
    cells; quick: the end values only, still two by two, so that the map is a map (one row of cells showed
    nothing)."""
    if quick:
        return np.array(REGIME_SPEEDS[:: len(REGIME_SPEEDS) - 1]), np.array(REGIME_YIELDS[:: len(REGIME_YIELDS) - 1])
    return np.array(REGIME_SPEEDS), np.array(REGIME_YIELDS)


def regime_map(quick: bool) -> dict:
    """Coupled FE normal impacts (wear.run, two-way) of the default case's ball on its plate with the
    yield strength changed, over :func:`regime_grid`. A cell whose FE run fails is NaN and listed in ``failed``."""
    base = _run_case(quick)
    speeds, yields = regime_grid(quick)
    shape = (yields.size, speeds.size)
    regime, ratio, e_fe, e_th, v_ratio = (np.full(shape, math.nan) for _ in range(5))
    failed = []
    for i, Y in enumerate(yields):
        for j, V in enumerate(speeds):
            case = base.with_(impact={"speed": float(V), "angle": 0.0}, plate={"yield_strength": float(Y)})
            try:
                res = run(case)
            except Exception as exc:  # an FE run that does not converge leaves a gap, reported
                failed.append(f"{V:g} m/s, Y {Y / 1e6:g} MPa: {type(exc).__name__}: {exc}")
                continue
            name, ratio[i, j] = _at_max_overlap(res.fe)
            regime[i, j] = REGIMES.index(name)
            e_fe[i, j] = res.impact.normal_restitution
            v_ratio[i, j] = V / res.yield_info["V_y"]
            e_th[i, j] = float(thornton_restitution(v_ratio[i, j]))
    if not np.any(np.isfinite(e_fe)):
        raise RuntimeError("every coupled FE run of the regime map failed: " + "; ".join(failed))
    return dict(
        speeds=speeds,
        yields=yields,
        regime=regime,
        ratio=ratio,
        e_fe=e_fe,
        e_thornton=e_th,
        speed_ratio=v_ratio,
        failed=failed,
        case=base,
    )


def fig_regime_map(out: Path, quick: bool) -> FigureReport:
    rep = FigureReport("fig_regime_map", "Regime map over impact speed and plate yield strength (coupled FE)")
    d = regime_map(quick)
    c = d["case"]
    plots.plot_regime_map(
        d["speeds"],
        d["yields"],
        d["regime"],
        d["ratio"],
        d["e_fe"],
        d["e_thornton"],
        out / f"{rep.name}.png",
        f"this toolkit: wear.run, two-way impact-FE coupling, normal impacts of the default case "
        f"({c.ball.name} R {c.ball.radius * 1e3:g} mm on {c.plate.name}, E {c.plate.E / 1e9:g} GPa) with the plate "
        "yield strength varied; Thornton 1997 closed form for e",
    )
    diff = np.abs(d["e_fe"] / d["e_thornton"] - 1)
    rep.numbers = {
        "V/V_y range": f"{np.nanmin(d['speed_ratio']):.3g}-{np.nanmax(d['speed_ratio']):.3g}",
        "max |e_FE/e_Thornton - 1|": float(np.nanmax(diff)),
        "p_max/p_mean range": f"{np.nanmin(d['ratio']):.3f}-{np.nanmax(d['ratio']):.3f}",
        "FE runs failed": len(d["failed"]),
    }
    rep.paper = "No such figure: the paper switches from Eq. 16 to Eq. 19 at F_y and never resolves the regimes."
    cells = d["regime"].size
    rep.ours = (
        f"{cells} coupled normal impacts (V/V_y {rep.numbers['V/V_y range']}): the regime at maximum overlap runs "
        f"from elastic to plastic at the surface as V/V_y grows; p_max/p_mean falls from the Hertz 1.5 towards 1 "
        f"(range {rep.numbers['p_max/p_mean range']}); the coupled restitution differs from Thornton's by at most "
        f"{np.nanmax(diff):.1%}."
        + (" FE runs that failed (gaps in the map): " + "; ".join(d["failed"]) + "." if d["failed"] else "")
    )
    rep.differences = (
        "Thornton's model caps the pressure at p_y ≈ 1.61Y with a Hertz-shaped unloading; the FE plate hardens "
        "geometrically (mean pressure rising towards ~2.8Y) and unloads from its own dent, so e_FE departs from "
        "Thornton as V/V_y grows. The rigid-sphere FE stands for the elastic ball through E* (exact while elastic)."
    )
    return rep


RESTITUTION_RATIOS = (1.5, 2.0, 5.0, 15.0)
#: quick: two of them, so that the figure still shows the trend against Thornton (one point showed none).
QUICK_RESTITUTION_RATIOS = (1.5, 5.0)


def fig_restitution(out: Path, quick: bool) -> FigureReport:
    rep = FigureReport("fig_restitution", "Normal restitution vs V/V_y: coupled FE against Thornton 1997")
    case = _run_case(quick)
    ratios, e_fe, failed, v_y = [], [], [], math.nan
    for x in QUICK_RESTITUTION_RATIOS if quick else RESTITUTION_RATIOS:
        try:  # one coupled run per ratio, so that a failed FE run leaves a gap, reported
            one = restitution_sweep(case, [x])
        except Exception as exc:
            failed.append(f"V/V_y = {x:g}: {type(exc).__name__}: {exc}")
            continue
        ratios.append(x)
        e_fe.append(float(one.restitution[0]))
        v_y = one.yield_speed
    if not ratios:
        raise RuntimeError("every coupled FE run of the restitution sweep failed: " + "; ".join(failed))
    ratios, e_fe = np.array(ratios), np.array(e_fe)
    e_th = np.asarray(thornton_restitution(ratios), dtype=float)
    difference = e_fe / e_th - 1.0
    curve = np.geomspace(1.0, 100.0, 200)
    plots.plot_restitution(
        ratios,
        e_fe,
        curve,
        thornton_restitution(curve),
        out / f"{rep.name}.png",
        f"this toolkit: wear.chain.restitution.restitution_sweep (two-way impact-FE coupling, {case.ball.name} on "
        f"{case.plate.name}, V_y = {v_y:.3g} m/s); Thornton 1997, J. Appl. Mech. 64:383",
    )
    rep.numbers = {f"e_FE at V/V_y = {x:g}": float(e) for x, e in zip(ratios, e_fe, strict=True)}
    rep.numbers.update({f"(e_FE - e_T)/e_T at {x:g}": float(d) for x, d in zip(ratios, difference, strict=True)})
    rep.numbers["FE runs failed"] = len(failed)
    low = np.abs(difference[ratios <= 2.0])
    rep.paper = "No such figure (the paper has no restitution model beyond its dashpot, Eq. 6)."
    rep.ours = (
        "Coupled FE normal restitution at V/V_y = "
        + ", ".join(f"{x:g}" for x in ratios)
        + ": "
        + ", ".join(f"{e:.3f}" for e in e_fe)
        + "; Thornton: "
        + ", ".join(f"{e:.3f}" for e in e_th)
        + "."
        + (f" For V/V_y ≤ 2 they differ by at most {low.max():.1%}." if low.size else "")
        + (" FE runs that failed: " + "; ".join(failed) + "." if failed else "")
    )
    rep.differences = (
        "Both are near-Hertz just above V_y. Further up, Thornton's limiting pressure (no hardening of the mean "
        "pressure, Hertz-shaped unloading with an enlarged radius) and the FE plate (contact pressure rising "
        "towards ~2.8Y, unloading from the real dent) part; the difference is listed per point above."
    )
    return rep


#: name → function(out_dir, quick) -> FigureReport, in the order of reproduce.md.
FIGURES: dict[str, Callable[[Path, bool], FigureReport]] = {
    "fig_regime_map": fig_regime_map,
    "fig_restitution": fig_restitution,
}


#: The angles (deg) of the default case's worn mass against angle; quick mode skips it (one FE point, which it
#: had, shows no maximum, and four coupled FE runs are most of a quick reproduction).
DEFAULT_CASE_ANGLES = (15.0, 35.0, 55.0, 75.0)


def default_case_wear(quick: bool) -> dict:
    """Worn mass per impact against impact angle for the pipeline's default case (wear.run: two-way
    coupled FE plate, FE pressure p(r, t), α = 1, β = 0.3). A failed FE run leaves NaN (listed in ``failed``);
    quick: no run, ``skipped`` says why."""
    base = _run_case(quick)
    angles = np.array([] if quick else DEFAULT_CASE_ANGLES)
    mass, failed, source = np.full(angles.size, math.nan), [], "fe"
    for i, a in enumerate(angles):
        try:
            res = run(base.with_(impact={"angle": float(a)}))
        except Exception as exc:  # reported, never filled in
            failed.append(f"{a:g}°: {type(exc).__name__}: {exc}")
            continue
        mass[i] = res.wear.mass_kg
        source = res.pressure.source
    c, w = base, base.wear
    label = (
        f"default run case: {c.ball.name} on {c.plate.name}, {c.impact.speed:g} m/s, μ {c.impact.friction:g}\n"
        f"pressure: FE ({c.fem.coupling} coupling), K {w.K:g}"
    )
    skipped = "skipped in quick mode (4 coupled FE runs);\nrun `impactwear reproduce` without --quick" if quick else ""
    return dict(label=label, angles=angles, mass=mass, failed=failed, source=source, skipped=skipped)
