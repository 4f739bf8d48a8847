"""Figures of a particle-stream erosion (matplotlib, Agg; SI units on every axis, written atomically).

``erosion.png``: mass loss (kg) and erosion rate (kg of plate per kg of particles: cumulative and between
samples) against time.
``surface.png``: the eroded surface depth map (µm) with the stream direction. ``erosion_vs_angle.png``:
erosion rate and mass loss against the stream angle (deg from the plate normal).
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from wear.app.figures.common import save_figure, subplots

__all__ = ["plot_time_series", "plot_surface", "plot_angles", "HEADROOM", "headroom_top"]

#: The top of a rate axis is this many times the largest value drawn (room for the legend above a flat line).
HEADROOM = 1.15


def headroom_top(values: np.ndarray, headroom: float = HEADROOM) -> float:
    """Upper y limit ``headroom`` × the largest finite value of ``values`` (1 if there is none > 0)."""
    finite = np.asarray(values, dtype=float)
    finite = finite[np.isfinite(finite)]
    top = float(finite.max()) if finite.size else 0.0
    return headroom * top if top > 0.0 else 1.0


def plot_time_series(
    time, mass_loss_kg, erosion_rate, path: str | os.PathLike, title: str = "", interval_rate=None
) -> Path:
    """Mass loss (kg) and cumulative erosion rate (kg/kg; with ``interval_rate`` also the rate between samples)
    against exposure time (s) into ``path``."""
    fig, (ax1, ax2) = subplots(1, 2, figsize=(10, 4))
    t = np.asarray(time)
    ax1.plot(t, np.asarray(mass_loss_kg), "-")
    ax1.set_xlabel("exposure time (s)")
    ax1.set_ylabel("mass loss of the patch (kg)")
    ax1.grid(alpha=0.3)
    rate = np.asarray(erosion_rate, dtype=float)
    ax2.plot(t[1:], rate[1:], "-", label="cumulative")
    shown = [rate[1:]]
    if interval_rate is not None:
        shown.append(np.asarray(interval_rate, dtype=float)[1:])
        ax2.plot(t[1:], shown[-1], ".", ms=3, label="between samples")
    ax2.set_xlabel("exposure time (s)")
    ax2.set_ylabel("erosion rate (kg/kg of particles)")
    # a steady rate is a flat line at the maximum: without headroom it sits on the frame, under the legend
    ax2.set_ylim(0.0, headroom_top(np.concatenate(shown)))
    if interval_rate is not None:
        ax2.legend(loc="best")
    ax2.grid(alpha=0.3)
    if title:
        fig.suptitle(title)
    fig.tight_layout()
    return save_figure(fig, path)


def plot_surface(x, y, depth, path: str | os.PathLike, azimuth_deg: float = 0.0, title: str = "") -> Path:
    """Depth map (µm, into the plate) over the patch (x, y in mm) with an arrow along the stream azimuth."""
    fig, ax = subplots(figsize=(6, 5))
    x, y = np.asarray(x), np.asarray(y)
    extent = (x[0] * 1e3, x[-1] * 1e3, y[0] * 1e3, y[-1] * 1e3)
    im = ax.imshow(np.asarray(depth) * 1e6, origin="lower", extent=extent, cmap="viridis", interpolation="nearest")
    fig.colorbar(im, ax=ax, label="depth (µm)")
    span = 0.15 * (extent[1] - extent[0])
    cx, cy = 0.5 * (extent[0] + extent[1]), 0.5 * (extent[2] + extent[3])
    psi = math.radians(azimuth_deg)
    ax.annotate(
        "stream",
        xy=(cx + span * math.cos(psi), cy + span * math.sin(psi)),
        xytext=(cx - span * math.cos(psi), cy - span * math.sin(psi)),
        arrowprops=dict(arrowstyle="->", color="white"),
        color="white",
    )
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    if title:
        ax.set_title(title)
    fig.tight_layout()
    return save_figure(fig, path)


def plot_angles(angles_deg, erosion_rate, mass_loss_kg, path: str | os.PathLike, title: str = "") -> Path:
    """Erosion rate (kg/kg) and mass loss (kg) against the stream angle (deg from the plate normal)."""
    fig, ax1 = subplots(figsize=(6, 4))
    a = np.asarray(angles_deg, dtype=float)
    ax1.plot(a, np.asarray(erosion_rate), "o-", color="C0")
    ax1.set_xlabel("stream angle from the plate normal (deg)")
    ax1.set_ylabel("erosion rate (kg/kg of particles)", color="C0")
    ax1.set_ylim(bottom=0.0)
    ax1.grid(alpha=0.3)
    ax2 = ax1.twinx()
    ax2.plot(a, np.asarray(mass_loss_kg), "s--", color="C1")
    ax2.set_ylabel("mass loss of the patch (kg)", color="C1")
    ax2.set_ylim(bottom=0.0)
    if title:
        ax1.set_title(title)
    fig.tight_layout()
    return save_figure(fig, path)
