r"""The paper's own figures (4, 5, 6, 9, 11) recomputed with this toolkit.

Each entry of :data:`FIGURES` computes one figure from our own models (SI units; angles in degrees from the
plate normal), draws it with the reference it is compared with (:mod:`wear.app.figures.paper`) and returns a
:class:`~wear.app.reproduce.report.FigureReport`: what the paper shows, what we get (with numbers), where and why
they differ. ``quick=True`` runs the same code at reduced sizes (fewer angles, speeds and FE increments).

Contact setup of Figs. 5, 6 (and 4, 11): Kharaz, Gorham & Salman (2001), Powder Technol. 120:281: alumina ball
R = 2.5 mm (E 380 GPa, ν 0.23, 4000 kg/m³) on soda-lime glass (E 70 GPa, ν 0.25), 3.9 m/s, μ = 0.092, normal
restitution 0.98 (the value commonly used with this experiment, e.g. Chung & Ooi 2011).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np

from contact import Material, simulate_impact, simulate_impacts
from contact.materials import effective_modulus
from contact.theory import hertz_impact, speed_components, sphere_mass
from wear import WearLaw, wear_from_impact
from wear.app.figures import paper as plots
from wear.app.reproduce.coupled import default_case_wear
from wear.app.reproduce.report import FigureReport
from wear.app.validation.references import KHARAZ, KHARAZ_SOURCE, kharaz_batch, kharaz_data, kharaz_rms
from wear.case import default_case

__all__ = ["FIGURES", "WEAR_LAW", "STEEL_ON_ALUMINIUM"]

#: The paper's wear-law exponents of Fig. 9 and a K inside its range 1e-13..1e-10 (m^0.7 s^-0.7 Pa^-1).
WEAR_LAW = dict(K=1e-12, alpha=1.0, beta=0.3)
#: Second material pair of Fig. 9: a steel ball on an aluminium-alloy plate that yields (paper's recipe).
STEEL_ON_ALUMINIUM = dict(
    radius=2.5e-3,
    ball=Material(E=210e9, nu=0.3, density=7850.0, name="steel"),
    plate=Material(E=70e9, nu=0.33, density=2700.0, yield_strength=150e6, name="aluminium alloy"),
    speed=3.9,
    friction=0.3,
    restitution=1.0,
)


def _angles(step: float, stop: float = 85.0, start: float = 0.0) -> np.ndarray:
    return np.arange(start, stop + 1e-9, step)


# ----------------------------------------------------------------------------------------------- Fig. 4
def fig04(out: Path, quick: bool) -> FigureReport:
    rep = FigureReport("fig04_peak_force_vs_angle", "Fig. 4: peak normal force vs impact angle")
    angles = _angles(15.0 if quick else 5.0)
    speeds = np.array([0.5, 1.0, 2.0, 3.9])
    k = KHARAZ
    model = np.array(
        [
            simulate_impacts(k["radius"], k["ball"], k["plate"], v, angles, k["friction"], k["restitution"]).max_force
            for v in speeds
        ]
    )
    e_star = effective_modulus(k["ball"], k["plate"])
    mass = sphere_mass(k["radius"], k["ball"].density)
    closed = np.array(
        [[hertz_impact(mass, k["radius"], e_star, speed_components(v, a)[0]).max_force for a in angles] for v in speeds]
    )
    dev = np.abs(model / closed - 1.0)
    plots.plot_peak_force(
        angles,
        speeds,
        model,
        closed,
        out / f"{rep.name}.png",
        "H-DD model (this toolkit, e = 0.98 dashpot) vs Hertz closed form F_max = (4/3)E*√R δ_max^1.5, "
        "δ_max = (15 m v_n² / (16E*√R))^(2/5) (errata Eqs. 4, 10-11); alumina on glass (Kharaz et al. 2001 setup)",
    )
    rep.numbers = {
        "max |F_model/F_Hertz - 1|": float(dev.max()),
        "F_max at 3.9 m/s, 0 deg (N)": float(model[-1, 0]),
    }
    rep.paper = (
        "Peak normal force against impact angle for several initial speeds (given in mm/s), model against the "
        "experiments of its ref. [17]; the force falls as the angle from the normal grows."
    )
    rep.ours = (
        f"The H-DD model for the Kharaz alumina-on-glass pair at 0.5, 1, 2 and 3.9 m/s, with the Hertz closed form "
        f"F_max(v cos θ) drawn through it. The model follows the closed form within {dev.max():.2%} at every angle "
        f"and speed (peak force {model[-1, 0]:.0f} N at 3.9 m/s, normal impact): the normal force of the H-DD model "
        "depends only on the normal speed, and the tangential force does not change it."
    )
    rep.differences = (
        "The paper's experimental points (ref. [17]) are not available to us, so only the closed form is compared; "
        f"the remaining {dev.max():.2%} is the e = 0.98 dashpot, which lowers the peak below the undamped Hertz "
        "value. The paper's Eq. 6 dashpot is dimensionally inconsistent (errata); we use the Tsuji-form dashpot "
        "calibrated to e."
    )
    return rep


# ------------------------------------------------------------------------------------------ Figs. 5, 6
def fig05(out: Path, quick: bool) -> FigureReport:
    rep = FigureReport("fig05_rebound_angles", "Fig. 5: rebound angles of the centre and of the contact point")
    angles = _angles(5.0 if quick else 1.0)
    b = kharaz_batch(angles)
    data = kharaz_data()
    da, dc = data["centre_rebound_angle_deg"]
    rms = kharaz_rms()["centre_rebound_angle_deg"]
    plots.plot_rebound_angles(
        angles,
        b.rebound_angle,
        b.contact_point_rebound_angle,
        da,
        dc,
        out / f"{rep.name}.png",
        f"model: H-DD (this toolkit), e = 0.98, μ = 0.092; points: {KHARAZ_SOURCE}",
        note=f"RMS model - data {rms:.2f}°",
    )
    i_min = int(np.argmin(b.contact_point_rebound_angle))
    negative = angles[b.contact_point_rebound_angle < 0.0]
    rep.numbers = {
        "RMS centre rebound angle (deg)": rms,
        "min contact-point rebound angle (deg)": float(b.contact_point_rebound_angle[i_min]),
        "at impact angle (deg)": float(angles[i_min]),
    }
    rep.paper = (
        "Rebound angles of the centre of mass and of the contact point against impact angle, model against the "
        "Kharaz et al. (2001) measurements; the contact-point angle is negative at small angles (the ball spins "
        "backwards relative to its motion)."
    )
    rep.ours = (
        f"Same setup (alumina R 2.5 mm on glass, 3.9 m/s, μ 0.092, e 0.98). **RMS difference model - measured "
        f"centre rebound angle: {rms:.2f}°** over the {da.size} points (model simulated at the measured angles). "
        f"The contact-point rebound angle is negative from {negative[0]:.0f}° to {negative[-1]:.0f}°, minimum "
        f"{b.contact_point_rebound_angle[i_min]:.1f}° at {angles[i_min]:.0f}°."
    )
    rep.differences = (
        "The shipped data set has no contact-point rebound angles, so only the centre angle is compared. The model "
        "follows the data within the scatter of the digitised points; the largest misfit is at ~10° (micro-slip "
        "regime), where the H-DD tangential spring (Di Renzo & Di Maio 2005, errata Eq. 8) and the assumed "
        "e = 0.98 matter most. The paper's Eq. 8 misprints the spring (errata); we implement k_t = 8G*a with "
        "the 2/3 factor."
    )
    return rep


def fig06(out: Path, quick: bool) -> FigureReport:
    rep = FigureReport("fig06_spin", "Fig. 6: spin after impact")
    angles = _angles(5.0 if quick else 1.0)
    b = kharaz_batch(angles)
    data = kharaz_data()
    rms = kharaz_rms()
    plots.plot_spin(
        angles,
        b.spin,
        *data["spin_rad_per_s"],
        b.tangential_restitution,
        *data["tangential_restitution"],
        out / f"{rep.name}.png",
        f"model: H-DD (this toolkit), e = 0.98, μ = 0.092; points: {KHARAZ_SOURCE}",
        note=f"RMS {rms['spin_rad_per_s']:.0f} rad/s",
    )
    i = int(np.argmax(b.spin))
    rep.numbers = {
        "RMS spin (rad/s)": rms["spin_rad_per_s"],
        "RMS tangential restitution": rms["tangential_restitution"],
        "peak spin (rad/s)": float(b.spin[i]),
        "at impact angle (deg)": float(angles[i]),
    }
    rep.paper = "Final rotational speed of the ball against impact angle, model against Kharaz et al. (2001)."
    rep.ours = (
        f"**RMS difference model - measured spin: {rms['spin_rad_per_s']:.1f} rad/s** over "
        f"{data['spin_rad_per_s'][0].size} points (measured spin up to ~610 rad/s); peak model spin "
        f"{b.spin[i]:.0f} rad/s at {angles[i]:.0f}°. Extra panel: tangential restitution, **RMS "
        f"{rms['tangential_restitution']:.3f}** over {data['tangential_restitution'][0].size} points."
    )
    rep.differences = (
        "Above ~32° (tan θ > 3.5μ(1+e)) the contact slides throughout and spin = 2.5μ(1+e)v cos θ/R exactly "
        "(rigid-body theory), so the model/data gap there measures the friction coefficient and e of the "
        "experiment. Below, the measured tangential restitution dips less deeply than the model's (the largest "
        "misfit, near 10°): tangential compliance and micro-slip of the real contact are only approximated by "
        "the H-DD spring."
    )
    return rep


# ----------------------------------------------------------------------------------------------- Fig. 9
def _peak(angles, mass) -> float:
    """Angle (deg) of the largest finite ``mass``; NaN if there is none."""
    mass = np.asarray(mass, dtype=float)
    return float(np.asarray(angles)[int(np.nanargmax(mass))]) if np.any(np.isfinite(mass)) else math.nan


def _wear_mass_series(setup: dict, angles, pressure: str, fe_table: Callable | None = None) -> np.ndarray:
    law = WearLaw(**WEAR_LAW)
    masses = []
    for a in angles:
        imp = simulate_impact(
            setup["radius"],
            setup["ball"],
            setup["plate"],
            setup["speed"],
            float(a),
            setup["friction"],
            restitution=setup["restitution"],
        )
        fe = fe_table(imp) if fe_table is not None else None
        masses.append(wear_from_impact(imp, law, pressure=pressure, speed="sliding", fe=fe).mass_kg)
    return np.array(masses)


def fig09(out: Path, quick: bool) -> FigureReport:
    rep = FigureReport("fig09_wear_mass_vs_angle", "Fig. 9: worn mass vs impact angle (α = 1, β = 0.3)")
    angles = _angles(10.0 if quick else 5.0, stop=85.0)
    default = default_case("impact").impact_arguments()
    d = dict(default, restitution=KHARAZ["restitution"])
    series = [
        dict(
            label=f"Kharaz case: {d['ball'].name} on {d['plate'].name}, {d['speed']:g} m/s, μ {d['friction']:g}\n"
            "pressure: Hertz Eq. 16 (the plate does not yield)",
            angles=angles,
            mass=_wear_mass_series(d, angles, "hertz"),
        ),
        dict(
            label="steel on aluminium alloy (Y 150 MPa), 3.9 m/s, μ 0.3\npressure: paper's recipe Eqs. 16-19",
            angles=angles,
            mass=_wear_mass_series(STEEL_ON_ALUMINIUM, angles, "paper"),
        ),
    ]
    default = default_case_wear(quick)
    series.insert(0, default)
    fe_note = f"{int(np.sum(np.isfinite(default['mass'])))} coupled FE runs" + (
        f"; failed: {'; '.join(default['failed'])}" if default["failed"] else ""
    )
    if default["skipped"]:
        fe_note = "no FE run: " + default["skipped"].replace("\n", " ")
    law = f"K = {WEAR_LAW['K']:g} m^0.7 s^-0.7 Pa^-1"
    plots.plot_wear_mass(
        series,
        out / f"{rep.name}.png",
        f"this toolkit: H-DD impact + Eq. 15 (dw/dt = K p^α v^β, w a depth, {law}, gross-sliding speed), "
        "integrated over the moving contact patch; mass = plate density × worn volume",
    )
    peaks = [_peak(s["angles"], s["mass"]) for s in series]
    names = ["default run case (FE)", "Kharaz case", "steel on aluminium"]
    rep.numbers = {}
    for name, s, peak in zip(names, series, peaks, strict=True):
        if s.get("skipped"):
            continue
        rep.numbers[f"angle of max wear, {name} (deg)"] = peak
        rep.numbers[f"max worn mass, {name} (kg)"] = float(np.nanmax(s["mass"])) if np.isfinite(peak) else math.nan
    rep.paper = (
        "Worn mass of one impact against impact angle for α = 1, β = 0.3, with a maximum near 60° from the normal "
        "(sliding time grows with the angle, the normal load falls)."
    )
    rep.ours = (
        "Angle of maximum wear (the largest of the angles computed): "
        + ", ".join(
            f"**{p:g}°** for the {n} (angles {plots.grid_step(s['angles']):g}° apart)"
            for n, p, s in zip(names, peaks, series, strict=True)
            if not s.get("skipped")
        )
        + f". The default run case (wear.run, K and exponents of its [wear] table) is computed with {fe_note}; "
        f"the other panels use {law}. The mass scales linearly with K; the angle of maximum wear does not."
    )
    rep.differences = (
        "The paper does not give its materials, speed or K, so only the shape and the angle of the maximum can be "
        "compared. With α = 1 and a sliding speed uniform over the patch the pressure shape drops out of the "
        "volume (∫p dA = F), so the pressure source changes the depth map more than the mass; what moves the "
        "maximum is how the normal load and the sliding time share out with the angle (material pair, μ). Each "
        "panel states its pressure source."
    )
    return rep


# ---------------------------------------------------------------------------------------------- Fig. 11
def fig11(out: Path, quick: bool) -> FigureReport:
    rep = FigureReport("fig11_sliding_duration", "Fig. 11: sliding time / contact time vs impact angle")
    angles = _angles(10.0 if quick else 2.5, stop=85.0)
    speeds = np.array([1.0, 3.9, 10.0, 30.0])
    k = KHARAZ
    ratio = np.array(
        [
            (lambda b: b.sliding_time / b.contact_time)(
                simulate_impacts(k["radius"], k["ball"], k["plate"], v, angles, k["friction"], k["restitution"])
            )
            for v in speeds
        ]
    )
    onset = math.degrees(math.atan(3.5 * k["friction"] * (1.0 + k["restitution"])))
    plots.plot_sliding_duration(
        angles,
        speeds,
        ratio,
        out / f"{rep.name}.png",
        "this toolkit (H-DD, alumina on glass, μ 0.092, e 0.98); t_s = time in gross sliding, t* = contact time; "
        "rigid-body sliding-throughout limit tan θ = 3.5 μ (1 + e)",
        rigid_body=(onset, f"rigid body: slides throughout above {onset:.1f}°"),
    )
    spread = float(np.max(np.ptp(ratio, axis=0)))
    rep.numbers = {"max spread of t_s/t* across speeds": spread, "rigid-body limit (deg)": onset}
    rep.paper = (
        "Dimensionless sliding duration t_s/t* against impact angle, independent of the impact speed, growing "
        "with the angle; the paper links it to the maximum of wear near 60°."
    )
    rep.ours = (
        f"t_s/t* at 1, 3.9, 10 and 30 m/s coincide (largest spread between speeds {spread:.1e}): with a Hertz "
        "spring, a speed-independent dashpot and Coulomb friction the impact is self-similar in the speed. "
        f"t_s/t* rises from 0 at normal impact to ~1 at {onset:.0f}° (rigid-body limit tan θ = 3.5μ(1+e)) and stays "
        "there: above it the contact slides throughout."
    )
    rep.differences = (
        "The speed independence agrees with the paper. Our ratio saturates at 1 beyond ~32°, so the wear maximum "
        "near 60° comes from the product of the sliding distance and the normal load, not from t_s/t* still "
        "rising; t_s is the time in gross sliding (errata), t* the contact time."
    )
    return rep


#: name → function(out_dir, quick) -> FigureReport, in the order of reproduce.md.
FIGURES: dict[str, Callable[[Path, bool], FigureReport]] = {
    "fig04_peak_force_vs_angle": fig04,
    "fig05_rebound_angles": fig05,
    "fig06_spin": fig06,
    "fig09_wear_mass_vs_angle": fig09,
    "fig11_sliding_duration": fig11,
}
