r"""``impactwear reproduce``: the paper's figures recomputed with this toolkit, and ``reproduce.md``.

Each entry of :data:`FIGURES` computes one figure from our own models (SI units; angles in degrees from the
plate normal), draws it with the reference it is compared with (:mod:`wear.app.figures.paper`) and returns a
:class:`FigureReport`: what the paper shows, what we get (with numbers), where and why they differ.
:func:`reproduce` runs them all into ``DIR/figures/*.png`` and writes ``DIR/reproduce.md`` (atomically).
``quick=True`` runs the same code at reduced sizes (fewer angles, speeds and FE increments): for the tests.

Contact setup of Figs. 5, 6 (and 4, 11): Kharaz, Gorham & Salman (2001), Powder Technol. 120:281: alumina ball
R = 2.5 mm (E 380 GPa, ν 0.23, 4000 kg/m³) on soda-lime glass (E 70 GPa, ν 0.25), 3.9 m/s, μ = 0.092, normal
restitution 0.98 (the value commonly used with this experiment, e.g. Chung & Ooi 2011).
"""

from __future__ import annotations

import math
import os
import tempfile
import time
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path

import numpy as np

from contact import Material, simulate_impact, simulate_impacts
from contact.materials import effective_modulus
from contact.theory import hertz_impact, sphere_mass

from . import case as case_module
from .figures import paper as plots

__all__ = [
    "FigureReport",
    "FIGURES",
    "reproduce",
    "render_markdown",
    "kharaz_data",
    "KHARAZ",
    "WEAR_LAW",
]

#: Kharaz, Gorham & Salman (2001) setup (see the module docstring).
KHARAZ = dict(
    radius=2.5e-3,
    ball=Material(E=380e9, nu=0.23, density=4000.0, name="alumina"),
    plate=Material(E=70e9, nu=0.25, density=2500.0, name="soda-lime glass"),
    speed=3.9,
    friction=0.092,
    restitution=0.98,
)
KHARAZ_SOURCE = "Kharaz, Gorham & Salman (2001) Powder Technol. 120:281 (digitised points)"
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


@dataclass
class FigureReport:
    """One figure of the reproduction: file name (``name``.png), title, and the three paragraphs of
    ``reproduce.md`` (``paper``: what the paper shows; ``ours``: what we get; ``differences``: where and why they
    differ); ``numbers``: key results (name → value); ``missing``: why the figure was not produced, else None."""

    name: str
    title: str
    paper: str = ""
    ours: str = ""
    differences: str = ""
    numbers: dict = field(default_factory=dict)
    missing: str | None = None
    seconds: float = 0.0


def kharaz_data() -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """The Kharaz, Gorham & Salman (2001) points shipped as package data: quantity → (angles deg, values).

    Quantities: ``tangential_restitution``, ``spin_rad_per_s``, ``centre_rebound_angle_deg``."""
    text = resources.files("wear.app").joinpath("data/kharaz2001.csv").read_text(encoding="utf-8")
    out: dict[str, list] = {}
    for line in text.splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        quantity, angle, value = line.split(",")
        out.setdefault(quantity, []).append((float(angle), float(value)))
    return {q: (np.array([a for a, _ in v]), np.array([x for _, x in v])) for q, v in out.items()}


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
        [
            [hertz_impact(mass, k["radius"], e_star, v * math.cos(math.radians(a))).max_force for a in angles]
            for v in speeds
        ]
    )
    dev = np.abs(model / closed - 1.0)
    plots.plot_peak_force(
        angles, speeds, model, closed, out / f"{rep.name}.png",
        "H-DD model (this toolkit, e = 0.98 dashpot) vs Hertz closed form F_max = (4/3)E*√R δ_max^1.5, "
        "δ_max = (15 m v_n² / (16E*√R))^(2/5) (errata Eqs. 4, 10-11); alumina on glass (Kharaz et al. 2001 setup)",
    )  # fmt: skip
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
def _kharaz_batch(angles):
    k = KHARAZ
    return simulate_impacts(k["radius"], k["ball"], k["plate"], k["speed"], angles, k["friction"], k["restitution"])


def _rms(model, data) -> float:
    return float(np.sqrt(np.mean((np.asarray(model) - np.asarray(data)) ** 2)))


def kharaz_rms() -> dict[str, float]:
    """RMS differences between the model (simulated at the measured angles) and the Kharaz et al. 2001 points:
    centre rebound angle (deg), spin (rad/s), tangential restitution."""
    data = kharaz_data()
    out = {}
    for quantity, attr in (
        ("centre_rebound_angle_deg", "rebound_angle"),
        ("spin_rad_per_s", "spin"),
        ("tangential_restitution", "tangential_restitution"),
    ):
        angles, values = data[quantity]
        out[quantity] = _rms(getattr(_kharaz_batch(angles), attr), values)
    return out


def fig05(out: Path, quick: bool) -> FigureReport:
    rep = FigureReport("fig05_rebound_angles", "Fig. 5: rebound angles of the centre and of the contact point")
    angles = _angles(5.0 if quick else 1.0)
    b = _kharaz_batch(angles)
    data = kharaz_data()
    da, dc = data["centre_rebound_angle_deg"]
    rms = kharaz_rms()["centre_rebound_angle_deg"]
    plots.plot_rebound_angles(
        angles, b.rebound_angle, b.contact_point_rebound_angle, da, dc, out / f"{rep.name}.png",
        f"model: H-DD (this toolkit), e = 0.98, μ = 0.092; points: {KHARAZ_SOURCE}",
        note=f"RMS model - data {rms:.2f}°",
    )  # fmt: skip
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
    b = _kharaz_batch(angles)
    data = kharaz_data()
    rms = kharaz_rms()
    plots.plot_spin(
        angles, b.spin, *data["spin_rad_per_s"], b.tangential_restitution, *data["tangential_restitution"],
        out / f"{rep.name}.png", f"model: H-DD (this toolkit), e = 0.98, μ = 0.092; points: {KHARAZ_SOURCE}",
        note=f"RMS {rms['spin_rad_per_s']:.0f} rad/s",
    )  # fmt: skip
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
    from wear import WearLaw, wear_from_impact

    law = WearLaw(**WEAR_LAW)
    masses = []
    for a in angles:
        imp = simulate_impact(
            setup["radius"], setup["ball"], setup["plate"], setup["speed"], float(a), setup["friction"],
            restitution=setup["restitution"],
        )  # fmt: skip
        fe = fe_table(imp) if fe_table is not None else None
        masses.append(wear_from_impact(imp, law, pressure=pressure, speed="sliding", fe=fe).mass_kg)
    return np.array(masses)


def fig09(out: Path, quick: bool) -> FigureReport:
    rep = FigureReport("fig09_wear_mass_vs_angle", "Fig. 9: worn mass vs impact angle (α = 1, β = 0.3)")
    angles = _angles(10.0 if quick else 5.0, stop=85.0)
    default = case_module.impact_arguments(case_module.default_case())
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
    fe_note = "the pipeline's default case (FE pressure) needs the FE stage, not available in this build"
    try:
        from .reproduce_fe import default_case_wear
    except ImportError:
        default = None
    else:
        default = default_case_wear(quick)
        series.insert(0, default)
        fe_note = f"{int(np.sum(np.isfinite(default['mass'])))} coupled FE runs" + (
            f"; failed: {'; '.join(default['failed'])}" if default["failed"] else ""
        )
    law = f"K = {WEAR_LAW['K']:g} m^0.7 s^-0.7 Pa^-1"
    plots.plot_wear_mass(
        series, out / f"{rep.name}.png",
        f"this toolkit: H-DD impact + Eq. 15 (dw/dt = K p^α v^β, w a depth, {law}, gross-sliding speed), "
        "integrated over the moving contact patch; mass = plate density × worn volume",
    )  # fmt: skip
    peaks = [_peak(s["angles"], s["mass"]) for s in series]
    names = (["default run case (FE)"] if default is not None else []) + ["Kharaz case", "steel on aluminium"]
    rep.numbers = {}
    for name, s, peak in zip(names, series, peaks, strict=True):
        rep.numbers[f"angle of max wear, {name} (deg)"] = peak
        rep.numbers[f"max worn mass, {name} (kg)"] = float(np.nanmax(s["mass"])) if np.isfinite(peak) else math.nan
    rep.paper = (
        "Worn mass of one impact against impact angle for α = 1, β = 0.3, with a maximum near 60° from the normal "
        "(sliding time grows with the angle, the normal load falls)."
    )
    rep.ours = (
        "Angle of maximum wear: "
        + ", ".join(f"**{p:g}°** for the {n}" for n, p in zip(names, peaks, strict=True))
        + f". The default run case (wear.pipeline, K and exponents of its [wear] table) is computed with {fe_note}; "
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
        angles, speeds, ratio, out / f"{rep.name}.png",
        "this toolkit (H-DD, alumina on glass, μ 0.092, e 0.98); t_s = time in gross sliding, t* = contact time; "
        "rigid-body sliding-throughout limit tan θ = 3.5 μ (1 + e)",
        rigid_body=(onset, f"rigid body: slides throughout above {onset:.1f}°"),
    )  # fmt: skip
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


def _register_fe_figures() -> dict[str, str]:
    """Add the figures that need the FE plate (:mod:`wear.app.reproduce_fe`); return name → why missing for the
    FE figures that this build cannot produce."""
    try:
        from . import reproduce_fe
    except ImportError as exc:
        why = f"needs the FE plate (fem.indent), not available in this build ({exc})"
        return {name: why for name in FE_FIGURE_NAMES}
    FIGURES.update(reproduce_fe.FIGURES)
    return {name: reproduce_fe.MISSING.get(name, "not produced") for name in FE_FIGURE_NAMES if name not in FIGURES}


def _write_text(path: Path, text: str) -> None:
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def _fmt(x) -> str:
    if isinstance(x, float):
        return f"{x:.4g}"
    return str(x)


def render_markdown(reports: list[FigureReport], quick: bool = False) -> str:
    """The text of ``reproduce.md`` for ``reports`` (figures linked as ``figures/<name>.png``)."""
    lines = [
        "# Reproducing the paper",
        "",
        "Generated by `impactwear reproduce" + (" --quick" if quick else "") + "` (do not edit by hand). Paper: "
        '"A Computational Wear Model of the Oblique Impact of a Ball on a Flat Plate"; its printed equations are '
        "partly wrong and the toolkit implements the corrected forms listed in the errata (Eqs. 4-19). Angles are "
        "measured from the plate normal; SI units.",
        "",
    ]
    if quick:
        lines += ["**Quick mode: reduced sizes; the numbers below are not the full reproduction.**", ""]
    missing = [r for r in reports if r.missing]
    if missing:
        lines += ["Figures not produced in this run:", ""]
        lines += [f"- `{r.name}.png`: {r.missing}" for r in missing]
        lines.append("")
    for r in reports:
        if r.missing:
            continue
        lines += [f"## {r.title}", "", f"![{r.name}](figures/{r.name}.png)", ""]
        lines += [f"**Paper.** {r.paper}", "", f"**We get.** {r.ours}", "", f"**Differences.** {r.differences}", ""]
        if r.numbers:
            lines += ["| quantity | value |", "|---|---|"]
            lines += [f"| {k} | {_fmt(v)} |" for k, v in r.numbers.items()]
            lines.append("")
    return "\n".join(lines)


def reproduce(out: str | os.PathLike, *, quick: bool = False, only=None, progress=None) -> list[FigureReport]:
    """Compute every figure of :data:`FIGURES` (or those named in ``only``) into ``out/figures/`` and write
    ``out/reproduce.md``. ``progress(name)`` is called before each figure. A figure whose computation raises is
    listed in reproduce.md as not produced, with the error. Returns the reports."""
    missing = _register_fe_figures()
    out = Path(out)
    (out / "figures").mkdir(parents=True, exist_ok=True)
    names = list(FIGURES) + list(missing)
    if only:
        unknown = [n for n in only if n not in names]
        if unknown:
            raise ValueError(f"only={unknown[0]!r} is not a figure: choose from {', '.join(names)}")
        names = [n for n in names if n in only]
    reports = []
    for name in names:
        if progress is not None:
            progress(name)
        if name not in FIGURES:
            reports.append(FigureReport(name, name, missing=missing[name]))
            continue
        start = time.perf_counter()
        try:
            with warnings.catch_warnings():
                # the FE stands for an elastic ball by its effective modulus: stated in the figures' sources
                warnings.filterwarnings("ignore", message="elastic ball: represented by a rigid sphere")
                rep = FIGURES[name](out / "figures", quick)
        except Exception as exc:  # one failed figure (e.g. an FE run that does not converge) is reported
            rep = FigureReport(name, name, missing=f"failed: {type(exc).__name__}: {exc}")
        rep.seconds = time.perf_counter() - start
        reports.append(rep)
    _write_text(out / "reproduce.md", render_markdown(reports, quick))
    return reports


#: Figures that need the FE plate and the coupled pipeline (issue 5).
FE_FIGURE_NAMES = ("fig_yield_onset", "fig_pressure_regimes", "fig_regime_map", "fig_restitution")
