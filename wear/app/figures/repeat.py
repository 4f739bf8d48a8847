"""Figures of repeated impacts at one site (matplotlib, Agg; SI units on every axis, written atomically).

``repeat.png``: against the impact number (log axis), (a) the dent depth, the pile-up height, the FE surface depth
(dent + wear) and the 2-D map's largest wear depth (µm); (b) the worn volume (m³) and the plastic work of each
impact (J); (c) the normal and tangential restitution; (d) the largest contact pressure (GPa) and the plastic-strain
increment of each computed impact (shakedown). Computed
impacts are markers, cycle-jump blocks the lines between them.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from matplotlib.ticker import MaxNLocator

from wear.app.figures.common import place_legends, save_figure, subplots

__all__ = ["plot_repeat", "shakedown_note"]


def shakedown_note(shakedown_impact: int | None, tolerance: float | None = None) -> str:
    """The title's remark on shakedown: where it happened, "no shakedown" where it was looked for (a
    ``tolerance`` is given) and not found, else nothing."""
    if shakedown_impact is not None:
        return f"  (shakedown at impact {shakedown_impact}, dotted)"
    return "  (no shakedown: every Δᾱ above the tolerance)" if tolerance else ""


def plot_repeat(
    columns: dict,
    path: str | os.PathLike,
    title: str = "",
    shakedown_impact: int | None = None,
    tolerance: float | None = None,
) -> Path:
    """The four panels above from ``columns`` (``wear.chain.records.RepeatResult.columns()``) into ``path``."""
    n = np.asarray(columns["impact_last"], float)
    computed = np.asarray(columns["computed"], float) > 0
    fig, axes = subplots(2, 2, figsize=(11, 7.5), sharex=True)
    (ax_d, ax_v), (ax_e, ax_p) = axes

    def series(ax, key, scale, label, style="-"):
        y = np.asarray(columns[key], float) * scale
        (line,) = ax.plot(n, y, style, label=label)
        ax.plot(n[computed], y[computed], "o", ms=3, color=line.get_color())

    series(ax_d, "dent_depth_m", 1e6, "dent (plastic, FE)")
    series(ax_d, "pile_up_height_m", 1e6, "pile-up (FE, above the plane)")
    series(ax_d, "surface_depth_m", 1e6, "dent + wear (FE surface)")
    series(ax_d, "total_wear_max_depth_m", 1e6, "wear (max of the 2-D map)")
    ax_d.set_ylabel("depth (µm)")
    series(ax_v, "total_wear_volume_m3", 1.0, "total worn volume")
    ax_v.set_ylabel("worn volume (m³)")
    ax_w = ax_v.twinx()
    work = np.asarray(columns["plastic_work_per_impact_J"], float)
    ax_w.plot(n[computed], work[computed], "^", ms=3, color="tab:purple", label="plastic work of impact")
    ax_w.set_ylabel("plastic work per impact (J)", color="tab:purple")
    series(ax_e, "normal_restitution", 1.0, "normal e_n")
    if np.isfinite(np.asarray(columns["tangential_restitution"], float)).any():
        series(ax_e, "tangential_restitution", 1.0, "tangential e_t")
    ax_e.set_ylabel("restitution")
    series(ax_p, "max_pressure_Pa", 1e-9, "max contact pressure (FE)")
    ax_p.set_ylabel("max contact pressure (GPa)")
    ax2 = ax_p.twinx()
    inc = np.asarray(columns["plastic_strain_increment"], float)
    ax2.semilogy(n[computed], np.maximum(inc[computed], 1e-12), "s", ms=3, color="tab:red", label="Δᾱ of impact")
    if tolerance:
        ax2.axhline(tolerance, color="tab:red", lw=0.8, ls="--", label="shakedown tolerance")
    ax2.set_ylabel("plastic strain increment Δᾱ", color="tab:red")
    for ax in axes.ravel():
        if n[-1] > 20:
            ax.set_xscale("log")
        else:
            # impacts are counted: a linear axis over a few of them would otherwise tick at 1.5, 2.5, …
            ax.xaxis.set_major_locator(MaxNLocator(integer=True))
        ax.grid(alpha=0.3)
        if shakedown_impact is not None:
            ax.axvline(shakedown_impact, color="0.5", lw=0.8, ls=":")
    for ax in (ax_e, ax_p):
        ax.set_xlabel("impact number")
    fig.suptitle(title + shakedown_note(shakedown_impact, tolerance))
    place_legends(fig, (ax_d, (ax_v, ax_w), ax_e, (ax_p, ax2)), fontsize=8)
    return save_figure(fig, path)
