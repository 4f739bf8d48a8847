"""Figures of ``impactwear reproduce``: the paper's figures redrawn from our computations (matplotlib, Agg).

Every function takes plain numpy arrays (SI units, angles in degrees from the plate normal), draws one figure
with the reference it is compared with, names the source on the figure, and writes a PNG atomically
(:func:`wear.app.figures.common.save_figure`). The computations live in :mod:`wear.app.reproduce.paper`.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

import numpy as np
from matplotlib.colors import BoundaryNorm, ListedColormap

from contact.theory import thornton_restitution
from fem import REGIMES
from wear.app.figures.common import place_legends, plain_log_ticks, save_figure, subplots

__all__ = [
    "save_sourced",
    "plot_peak_force",
    "plot_rebound_angles",
    "plot_spin",
    "plot_wear_mass",
    "plot_sliding_duration",
    "plot_yield_onset",
    "plot_pressure_regimes",
    "plot_regime_map",
    "plot_restitution",
    "plot_wear_laws",
    "grid_step",
]

DPI = 100
COLORS = ("C0", "C1", "C2", "C3", "C4", "C5", "C6", "C7")


def save_sourced(fig, path: str | os.PathLike, source: str) -> Path:
    """Write ``fig`` to ``path`` (PNG, atomically) with ``source`` printed at its bottom; close it."""
    fig.text(0.01, 0.005, "Source: " + source, fontsize=7, color="0.3", ha="left", va="bottom", wrap=True)
    return save_figure(fig, path, dpi=DPI)


def _above_the_source(fig) -> None:
    """``tight_layout`` over all but the bottom 12 % of ``fig``, where :func:`save_sourced` writes the source."""
    fig.tight_layout(rect=(0.0, 0.12, 1.0, 1.0))


def plot_peak_force(angles, speeds, model_force, hertz_force, path, source: str) -> Path:
    """Peak normal force (N) against impact angle (deg), one line per speed (m/s), with the Hertz closed form
    F_max(v cos θ) as dashed lines. ``model_force`` and ``hertz_force`` have shape (speeds, angles)."""
    fig, ax = subplots(figsize=(7, 4.6))
    for k, v in enumerate(speeds):
        c = COLORS[k % len(COLORS)]
        ax.plot(angles, model_force[k], "o", ms=3.5, color=c, label=f"H-DD model, {v * 1e3:g} mm/s")
        ax.plot(angles, hertz_force[k], "-", lw=1, color=c, alpha=0.7)
    ax.plot([], [], "k-", lw=1, label="Hertz closed form $F_{max}(v\\cos\\theta)$")
    ax.set_xlabel("impact angle from the normal θ (deg)")
    ax.set_ylabel("peak normal force (N)")
    ax.set_title("Fig. 4: peak normal force vs impact angle")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.subplots_adjust(bottom=0.16)
    return save_sourced(fig, path, source)


def plot_rebound_angles(angles, centre, contact_point, data_angles, data_centre, path, source: str, note="") -> Path:
    """Rebound angle (deg from the normal) of the centre and of the contact point against impact angle (deg),
    with the measured centre rebound angles."""
    fig, ax = subplots(figsize=(7, 4.6))
    ax.plot(angles, centre, "-", color="C0", label="model: centre of mass")
    ax.plot(angles, contact_point, "-", color="C1", label="model: contact point")
    ax.plot(data_angles, data_centre, "s", color="C0", mfc="none", label="Kharaz et al. 2001: centre of mass")
    ax.axhline(0.0, color="0.5", lw=0.6)
    ax.plot(angles, angles, ":", color="0.5", lw=0.8, label="specular (θ_r = θ)")
    ax.set_xlabel("impact angle from the normal θ (deg)")
    ax.set_ylabel("rebound angle from the normal (deg)")
    ax.set_title("Fig. 5: rebound angles" + (f" ({note})" if note else ""))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.subplots_adjust(bottom=0.16)
    return save_sourced(fig, path, source)


def plot_spin(angles, spin, data_angles, data_spin, et, data_et_angles, data_et, path, source: str, note="") -> Path:
    """Spin after impact (rad/s) and tangential restitution against impact angle (deg), with measured points."""
    fig, (ax, ax2) = subplots(1, 2, figsize=(9, 4.2))
    ax.plot(angles, spin, "-", color="C2", label="model")
    ax.plot(data_angles, data_spin, "s", color="C2", mfc="none", label="Kharaz et al. 2001")
    ax.set_xlabel("impact angle θ (deg)")
    ax.set_ylabel("spin after impact ω (rad/s)")
    ax.set_title("Fig. 6: spin" + (f" ({note})" if note else ""), fontsize=10)
    ax2.plot(angles, et, "-", color="C3", label="model")
    ax2.plot(data_et_angles, data_et, "s", color="C3", mfc="none", label="Kharaz et al. 2001")
    ax2.set_xlabel("impact angle θ (deg)")
    ax2.set_ylabel("tangential restitution $v_{t,out}/v_{t,in}$")
    ax2.set_title("tangential restitution (extra)", fontsize=10)
    for a in (ax, ax2):
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.subplots_adjust(bottom=0.18, wspace=0.3)
    return save_sourced(fig, path, source)


def plot_wear_mass(series: Sequence[dict], path, source: str) -> Path:
    """Worn mass (kg) against impact angle (deg), one panel per series (each dict: ``label``, ``angles``,
    ``mass``, optionally ``skipped``: why it was not computed, said in its panel), the angle of maximum wear
    marked."""
    n = len(series)
    fig, axes = subplots(1, n, figsize=(4.6 * n, 4.2), squeeze=False)
    for k, (ax, s) in enumerate(zip(axes[0], series, strict=True)):
        angles, mass = np.asarray(s["angles"]), np.asarray(s["mass"])
        c = COLORS[k % len(COLORS)]
        ax.plot(angles, mass, "o-", ms=3.5, color=c)
        if s.get("skipped"):
            ax.text(0.5, 0.5, s["skipped"], transform=ax.transAxes, ha="center", va="center", fontsize=8, wrap=True)
            ax.set_xlim(0.0, 90.0)
            ax.set_yticks([])
        elif np.any(np.isfinite(mass)):
            i = int(np.nanargmax(mass))
            # the largest of the computed angles, not a maximum located between them: the spacing says how closely
            label = f"largest at {angles[i]:g}°" + (
                f"\n(of angles {grid_step(angles):g}° apart)" if angles.size > 1 else ""
            )
            ax.plot(angles[i], mass[i], "*", ms=13, color="k", label=label)
            ax.axvline(angles[i], color="k", lw=0.6, ls=":")
        else:
            ax.text(0.5, 0.5, "no result (FE runs failed)", transform=ax.transAxes, ha="center", color="C3")
        ax.set_title(s["label"], fontsize=9)
        ax.set_xlabel("impact angle from the normal θ (deg)")
        ax.set_ylabel("worn mass per impact (kg)")
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=8)
    fig.suptitle("Fig. 9: worn mass vs impact angle, α = 1, β = 0.3", fontsize=11)
    fig.subplots_adjust(bottom=0.2, top=0.82, wspace=0.35)
    return save_sourced(fig, path, source)


def grid_step(angles) -> float:
    """The spacing (deg) of the computed ``angles``: the smallest step between neighbours."""
    return float(np.min(np.diff(np.unique(np.asarray(angles, float)))))


def plot_sliding_duration(angles, speeds, ratio, path, source: str, rigid_body=None) -> Path:
    """Sliding time / contact time against impact angle (deg), one line per speed (m/s); ``ratio`` has shape
    (speeds, angles). ``rigid_body``: optional (angle of the rigid-body onset of sliding throughout, label)."""
    fig, ax = subplots(figsize=(7, 4.6))
    markers = ("o", "s", "^", "v", "D", "x")
    for k, v in enumerate(speeds):
        ax.plot(angles, ratio[k], markers[k % len(markers)] + "-", ms=3.5, lw=0.8, label=f"{v:g} m/s", alpha=0.8)
    if rigid_body is not None:
        ax.axvline(rigid_body[0], color="k", lw=0.8, ls="--", label=rigid_body[1])
    ax.set_xlabel("impact angle from the normal θ (deg)")
    ax.set_ylabel("sliding time / contact time $t_s/t^*$")
    ax.set_title("Fig. 11: dimensionless sliding duration")
    ax.set_ylim(-0.02, 1.05)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.subplots_adjust(bottom=0.16)
    return save_sourced(fig, path, source)


def plot_yield_onset(rows: Sequence[dict], path, source: str) -> Path:
    """FE first-yield force over F_c of equation 18 with the exact C(ν) (and with C = 1.6), one point per case.

    Each row: ``label`` (case text), ``fe`` (N), ``exact`` (N, C(ν)), ``paper`` (N, C = 1.6)."""
    fig, ax = subplots(figsize=(8, 4.6))
    x = np.arange(len(rows))
    fe = np.array([r["fe"] for r in rows])
    exact = np.array([r["exact"] for r in rows])
    paper = np.array([r["paper"] for r in rows])
    ax.plot(x, fe / exact, "o", color="C0", label="FE first yield / $F_c$ (exact C(ν))")
    ax.plot(x, paper / exact, "_", ms=14, mew=2, color="C3", label="Eq. 18 with C = 1.6 / $F_c$ (exact C(ν))")
    ax.axhline(1.0, color="k", lw=0.8)
    ax.axhspan(0.97, 1.03, color="0.85", alpha=0.6, label="±3%")
    ax.set_xticks(x)
    ax.set_xticklabels([r["label"] for r in rows], rotation=30, ha="right", fontsize=7)
    ax.set_ylabel("first-yield force / $F_c$")
    ax.set_title("First yield: FE against Eq. 18 (C = 1.6 and exact C(ν))")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.subplots_adjust(bottom=0.32)
    return save_sourced(fig, path, source)


def plot_pressure_regimes(loading: Sequence[dict], unloading: Sequence[dict], path, source: str) -> Path:
    """FE pressure profiles (left: loading at w = δ/δ_c, against Hertz equation 16 at the same force; right:
    unloading from the deepest load, against Mesarovic-Johnson equation 19 from the FE's p*, a*).

    Each dict: ``label``, ``r`` (m), ``p`` (Pa), ``ref_r`` (m), ``ref_p`` (Pa); axes normalised by ``scale_r``
    (m) and ``scale_p`` (Pa) given in each dict."""
    fig, (ax1, ax2) = subplots(1, 2, figsize=(11, 4.4))
    for k, s in enumerate(loading):
        c = COLORS[k % len(COLORS)]
        ax1.plot(s["r"] / s["scale_r"], s["p"] / s["scale_p"], "-", color=c, label=s["label"])
        ax1.plot(s["ref_r"] / s["scale_r"], s["ref_p"] / s["scale_p"], ":", color=c, lw=1)
    # the FE curves are the pressure at the surface nodes: after yield it ripples node to node (the imprint of the
    # load increments), which the legend names so that a reader does not take it for noise of the plot
    ax1.plot([], [], "k-", lw=1, label="FE, surface nodes")
    ax1.plot([], [], "k:", lw=1, label="Hertz, Eq. 16 (same F)")
    ax1.set_xlabel("r / a (FE contact radius)")
    ax1.set_ylabel("p / p_mean (FE)")
    ax1.set_title("loading, w = δ/δ_c", fontsize=10)
    for k, s in enumerate(unloading):
        c = COLORS[k % len(COLORS)]
        ax2.plot(s["r"] / s["scale_r"], s["p"] / s["scale_p"], "-", color=c, label=s["label"])
        ax2.plot(s["ref_r"] / s["scale_r"], s["ref_p"] / s["scale_p"], ":", color=c, lw=1)
    ax2.plot([], [], "k-", lw=1, label="FE, surface nodes")
    ax2.plot([], [], "k:", lw=1, label="Mesarovic-Johnson, Eq. 19")
    ax2.set_xlabel("r / a*")
    ax2.set_ylabel("p / p*")
    ax2.set_title("unloading from w = 50", fontsize=10)
    for a in (ax1, ax2):
        a.set_xlim(0, 1.3)
        a.set_ylim(bottom=0)
        a.grid(alpha=0.3)
    # the profiles fill both panels up to their peaks: the legends go beside them, above the source line
    place_legends(fig, (ax1, ax2), layout=_above_the_source, fontsize=7)
    return save_sourced(fig, path, source)


def _log_edges(values) -> np.ndarray:
    """Edges of cells centred (geometrically) on ``values`` (sorted, > 0): midway in log between neighbours, the
    outer ones as far out as the inner ones; a single value gets the cell from half to twice it."""
    v = np.log(np.asarray(values, float))
    if v.size == 1:
        return np.exp(v[0] + np.log(2.0) * np.array([-1.0, 1.0]))
    mid = 0.5 * (v[1:] + v[:-1])
    return np.exp(np.concatenate([[2.0 * v[0] - mid[0]], mid, [2.0 * v[-1] - mid[-1]]]))


def plot_regime_map(speeds, yields, regime, ratio, e_fe, e_thornton, path, source: str) -> Path:
    """Maps over impact speed (m/s, x) and plate yield strength (Pa, y): regime (index into :data:`REGIMES`),
    p_max/p_mean, and the coupled-FE normal restitution against Thornton 1997. Arrays have shape (yields, speeds);
    each cell is drawn round its speed and yield strength (any number of rows and columns, one included)."""
    fig, axes = subplots(1, 3, figsize=(13, 4.3))
    sx, sy = np.asarray(speeds, float), np.asarray(yields, float) / 1e6
    ex, ey = _log_edges(sx), _log_edges(sy)
    cmap = ListedColormap(["#4c72b0", "#55a868", "#dd8452", "#c44e52"])
    im = axes[0].pcolormesh(ex, ey, regime, cmap=cmap, norm=BoundaryNorm(np.arange(-0.5, 4.5), 4), shading="flat")
    cb = fig.colorbar(im, ax=axes[0], ticks=range(4))
    cb.ax.set_yticklabels(REGIMES, fontsize=7)
    axes[0].set_title("regime at maximum overlap", fontsize=10)
    im = axes[1].pcolormesh(ex, ey, ratio, shading="flat", cmap="viridis")
    fig.colorbar(im, ax=axes[1])
    axes[1].set_title("$p_{max}/p_{mean}$ at maximum overlap (Hertz: 1.5)", fontsize=10)
    diff = np.asarray(e_fe) / np.asarray(e_thornton) - 1.0
    lim = max(float(np.nanmax(np.abs(diff))), 1e-3) if np.any(np.isfinite(diff)) else 1e-3
    im = axes[2].pcolormesh(ex, ey, diff * 100, shading="flat", cmap="RdBu_r", vmin=-lim * 100, vmax=lim * 100)
    fig.colorbar(im, ax=axes[2], label="%")
    axes[2].set_title("$e_{FE}/e_{Thornton} - 1$", fontsize=10)
    for i in range(len(sy)):
        for j in range(len(sx)):
            text = f"e = {e_fe[i][j]:.2f}" if np.isfinite(e_fe[i][j]) else "failed"
            axes[2].text(
                sx[j],
                sy[i],
                text,
                ha="center",
                va="center",
                fontsize=7,
                clip_on=True,
                bbox=dict(facecolor="white", alpha=0.8, linewidth=0, pad=1.5),
            )
    for a in axes:
        a.set_xscale("log")
        a.set_yscale("log")
        a.set_xlim(ex[0], ex[-1])
        a.set_ylim(ey[0], ey[-1])
        plain_log_ticks(a.xaxis, sx)
        plain_log_ticks(a.yaxis, sy)
        a.set_xlabel("impact speed (m/s)")
        a.set_ylabel("plate yield strength (MPa)")
    fig.subplots_adjust(bottom=0.18, wspace=0.5, left=0.06, right=0.94)  # the last colour bar's label inside
    return save_sourced(fig, path, source)


def plot_restitution(ratio, e_fe, ratio_curve, e_thornton, path, source: str, note="") -> Path:
    """Normal restitution against V/V_y: coupled FE points against Thornton's (1997) closed form."""
    fig, (ax, ax2) = subplots(1, 2, figsize=(10, 4.3), gridspec_kw={"width_ratios": [3, 2]})
    ax.semilogx(ratio_curve, e_thornton, "-", color="k", lw=1, label="Thornton 1997 (closed form)")
    ax.semilogx(ratio, e_fe, "o", color="C0", label="coupled FE (this toolkit)")
    ax.set_xlabel("impact speed / yield velocity $V/V_y$")
    ax.set_ylabel("normal restitution e")
    ax.set_title("Normal restitution" + (f" ({note})" if note else ""), fontsize=10)
    ax.grid(alpha=0.3, which="both")
    plain_log_ticks(ax.xaxis, ratio_curve)  # 1, 2, 5, 10…, not 10⁰ and 10¹ alone
    ax.legend(fontsize=8)
    ax2.semilogx(ratio, (np.asarray(e_fe) / thornton_restitution(ratio) - 1) * 100, "o-", color="C0")
    ax2.axhline(0, color="k", lw=0.8)
    plain_log_ticks(ax2.xaxis, ratio)  # a few ratios within a decade: 1.5 and 5, not 2×10⁰
    ax2.set_xlabel("$V/V_y$")
    ax2.set_ylabel("$e_{FE}/e_{Thornton} - 1$ (%)")
    ax2.grid(alpha=0.3, which="both")
    fig.subplots_adjust(bottom=0.16, wspace=0.3)
    return save_sourced(fig, path, source)


def plot_wear_laws(curves: list[dict], data_angle, data_rate, speeds, path, source: str) -> Path:
    """Erosion ratio (kg/kg) against the angle from the surface at the calibration speed, and against the speed at
    30° from the surface, for each law (``curves``: label, angles deg from the surface, rate, speeds m/s,
    rate_vs_speed; ``reference``: drawn in black), with the data they were calibrated to (markers)."""
    fig, (ax, ax2) = subplots(1, 2, figsize=(11, 6.4))
    styles = iter(("--", ":", "-."))
    for k, c in enumerate(curves):
        style, colour = (next(styles), "k") if c.get("reference") else ("-", COLORS[k % len(COLORS)])
        ax.semilogy(
            c["angles"],
            np.where(np.asarray(c["rate"]) > 0, c["rate"], np.nan),
            style,
            color=colour,
            lw=1.3,
            label=c["label"],
        )
        ax2.loglog(c["speeds"], c["rate_vs_speed"], style, color=colour, lw=1.3)
    ax.plot(data_angle, data_rate, "ko", ms=4, label="calibration data (Oka et al. 2005 correlation, 50 m/s)")
    top = max(np.nanmax(c["rate"]) for c in curves)
    ax.set_ylim(top * 1e-3, top * 2)
    ax.set_xlabel("impact angle from the surface (deg)")
    ax.set_ylabel("erosion ratio (kg/kg)")
    ax.set_title("at 50 m/s (the calibration speed)", fontsize=9)
    ax.grid(alpha=0.3, which="both")
    plain_log_ticks(ax2.xaxis, c["speeds"])  # 10, 20, 50, 100 m/s, not 10¹ and 10²
    ax2.set_xlabel("impact speed (m/s)")
    ax2.set_title("at 30° from the surface (grey lines: the calibration speeds)", fontsize=9)
    ax2.grid(alpha=0.3, which="both")
    for s in speeds:
        ax2.axvline(s, color="0.7", lw=0.8)
    # one legend for both panels, below them in the panels' own type size (it names 11 curves: in small type
    # beside the panels it was unreadable), above the source line
    legend = fig.legend(
        *ax.get_legend_handles_labels(),
        loc="lower center",
        bbox_to_anchor=(0.5, 0.06),
        ncol=2,
        fontsize=9,
        frameon=False,
    )
    fig.canvas.draw()
    top = fig.transFigure.inverted().transform(legend.get_window_extent().get_points())[1, 1]
    fig.subplots_adjust(bottom=top + 0.11, wspace=0.25, top=0.94)  # room for the x labels above the legend
    return save_sourced(fig, path, source)
