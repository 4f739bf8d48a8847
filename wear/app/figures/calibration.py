"""The figure of a calibration (``calibration.png``): measured and predicted wear against the impact angle (deg from
the normal) at each speed, and against the speed (m/s) at each angle, on log axes of the measured quantity."""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from wear.app.figures.common import place_legends, plain_log_ticks, save_figure, subplots
from wear.chain.calibrate import CalibrationResult

__all__ = ["plot_calibration"]

_LABELS = {
    "erosion_kg_per_kg": "erosion ratio (kg/kg)",
    "mass_per_impact_kg": "mass worn per impact (kg)",
    "volume_per_impact_m3": "volume worn per impact (m³)",
}


#: The most groups (speeds, or angles) a panel draws and its legend lists: beyond, the rows are drawn in this many
#: ranges of the grouping value. One curve and legend entry per distinct value of thousands of scattered rows took
#: minutes and a legend no layout could fit (matplotlib's "Tight layout not applied" warning to the user).
MAX_GROUPS = 8


def _groups(group: np.ndarray, label: str) -> list[tuple[np.ndarray, str, bool]]:
    """(the rows of each group, its legend label, whether its rows share the grouping value, so that the prediction
    is a curve): each distinct value, or :data:`MAX_GROUPS` ranges of about as many rows each."""
    values = np.unique(group)
    if values.size <= MAX_GROUPS:
        return [(group == g, f"{label} {g:g}", True) for g in values]
    edges = np.unique(np.quantile(values, np.linspace(0.0, 1.0, MAX_GROUPS + 1)))
    which = np.clip(np.searchsorted(edges, group, side="right") - 1, 0, edges.size - 2)
    return [
        (which == k, f"{label} {edges[k]:.3g}–{edges[k + 1]:.3g}", False)
        for k in range(edges.size - 1)
        if np.any(which == k)
    ]


def _panel(ax, x, group, measured, predicted, xlabel: str, label: str) -> None:
    for k, (sel, name, curve) in enumerate(_groups(group, label)):
        colour = f"C{k % 10}"
        if curve:
            order = np.argsort(x[sel])
            ax.plot(x[sel][order], predicted[sel][order], "-", color=colour, lw=1.2)
        else:  # rows of a range of values: no one curve, the prediction of each row as a dot
            ax.plot(x[sel], predicted[sel], ".", color=colour, ms=2)
        ok = sel & np.isfinite(measured)
        ax.plot(x[ok], measured[ok], "o", color=colour, ms=4 if curve else 2.5, label=name)
        only = sel & ~np.isfinite(measured)  # rows to predict: the prediction alone
        ax.plot(x[only], predicted[only], "x", color=colour, ms=6)
    ax.set_xlabel(xlabel)
    shown = np.r_[measured, predicted]
    shown = shown[np.isfinite(shown) & (shown > 0.0)]
    if shown.size and shown.max() <= shown.min() * (1.0 + 1e-9):
        # one value (one row, or a prediction equal to it to round-off): a decade about it, where autoscaling
        # would make the log axis singular (matplotlib's warning to the user)
        ax.set_ylim(shown[0] / 10**0.5, shown[0] * 10**0.5)
    ax.set_yscale("log")


def plot_calibration(result: CalibrationResult, path: str | os.PathLike) -> Path:
    """Measured (markers) and predicted (lines) wear of ``result`` into ``path`` (PNG)."""
    d = result.data
    predicted = np.where(result.predicted > 0, result.predicted, np.nan)
    fig, (a1, a2) = subplots(1, 2, figsize=(11, 4.2))
    _panel(a1, d.angle, d.speed, d.measured, predicted, "impact angle from the normal (deg)", "m/s:")
    _panel(a2, d.speed, d.angle, d.measured, predicted, "impact speed (m/s)", "deg:")
    a2.set_xscale("log")
    plain_log_ticks(a2.xaxis, d.speed)
    a1.set_ylabel(_LABELS[d.quantity])
    a2.set_ylabel(_LABELS[d.quantity])
    f = result.fit
    text = ", ".join(f"{n} = {v:.4g}" for n, v in zip(f.names, f.values, strict=True))
    fig.suptitle(
        f"wear.law = {result.case.wear.law!r}: {text} (RMS log error {f.rms_log_error:.3f})\n"
        "markers: measured; lines (dots: rows of a range of values): predicted; x: rows without a measurement",
        fontsize=9,
    )
    place_legends(fig, (a1, a2), fontsize=7, ncol=2)
    return save_figure(fig, path)
