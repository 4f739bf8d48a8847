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


def _panel(ax, x, group, measured, predicted, xlabel: str, label: str) -> None:
    for k, g in enumerate(np.unique(group)):
        sel = group == g
        order = np.argsort(x[sel])
        colour = f"C{k % 10}"
        ax.plot(x[sel][order], predicted[sel][order], "-", color=colour, lw=1.2)
        ok = sel & np.isfinite(measured)
        ax.plot(x[ok], measured[ok], "o", color=colour, ms=4, label=f"{label} {g:g}")
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
        "markers: measured; lines: predicted; x: rows without a measurement",
        fontsize=9,
    )
    place_legends(fig, (a1, a2), fontsize=7, ncol=2)
    return save_figure(fig, path)
