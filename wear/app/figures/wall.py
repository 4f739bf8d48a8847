"""Figures of a component's wall erosion (matplotlib, Agg; SI units on every axis, angles in degrees from the wall
normal, written atomically).

``wall.png``: the wall in 3-D, each face coloured by its thickness-loss rate (mm/year; faces without wear in grey),
the hot spot (the fastest face) marked and labelled. ``impacts.png``: the particles that hit the wall by speed
(m/s, logarithmic bins) and by impact angle (deg from the normal).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from matplotlib import colormaps
from matplotlib.cm import ScalarMappable
from matplotlib.colors import Normalize
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from wear.app.figures.common import save_figure, subplots
from wear.wall.mesh import Wall

__all__ = ["plot_wall_rate", "plot_impact_histograms"]

#: Colour of the faces no particle wore.
UNWORN = (0.85, 0.85, 0.85, 1.0)


def plot_wall_rate(
    wall: Wall, rate_mm_year: np.ndarray, hot_face: int | None, path: str | os.PathLike, title: str = ""
) -> Path:
    """``wall`` coloured by ``rate_mm_year`` (one per face), the face ``hot_face`` marked, into ``path``."""
    rate = np.asarray(rate_mm_year, float)
    fig, ax = subplots(figsize=(8.0, 6.5), subplot_kw={"projection": "3d"})
    tri, owner = wall.triangles
    top = float(rate.max()) if rate.size and rate.max() > 0 else 1.0
    norm = Normalize(0.0, top)
    cmap = colormaps["inferno_r"]
    colours = np.where((rate[owner] > 0)[:, None], cmap(norm(rate[owner])), UNWORN)
    ax.add_collection3d(Poly3DCollection(wall.points[tri], facecolors=colours, edgecolors="none"))
    low, high = wall.points.min(axis=0), wall.points.max(axis=0)
    centre, half = 0.5 * (low + high), 0.5 * float((high - low).max())
    for axis, c in zip("xyz", centre, strict=True):
        getattr(ax, f"set_{axis}lim")(c - half, c + half)
        getattr(ax, f"set_{axis}label")(f"{axis} (m)")
    ax.set_box_aspect((1, 1, 1))
    if hot_face is not None:
        x, y, z = wall.centre[hot_face]
        ax.scatter([x], [y], [z], s=80, marker="x", color="tab:blue", depthshade=False, zorder=10)
        ax.text(x, y, z, f"  hot spot: {rate[hot_face]:.3g} mm/year", color="tab:blue", zorder=10)
    bar = fig.colorbar(ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.7, pad=0.1)
    bar.set_label("thickness-loss rate (mm/year)")
    if title:
        ax.set_title(title)
    return save_figure(fig, path)


def plot_impact_histograms(
    speed_edges_m_s: np.ndarray,
    speed_particles: np.ndarray,
    angle_edges_deg: np.ndarray,
    angle_particles: np.ndarray,
    path: str | os.PathLike,
    title: str = "",
) -> Path:
    """The particles on the wall by speed (bins ``speed_edges_m_s``, m/s; the empty bins at both ends left out) and
    by angle (bins ``angle_edges_deg``, deg from the normal), into ``path``."""
    fig, (ax1, ax2) = subplots(1, 2, figsize=(10, 4), layout="constrained")
    speed = np.asarray(speed_particles, float)
    edges = np.asarray(speed_edges_m_s, float)
    used = np.flatnonzero(speed > 0)
    if used.size:
        first, last = used[0], used[-1] + 1
        ax1.stairs(speed[first:last], edges[first : last + 1], fill=True, alpha=0.7)
        ax1.set_xscale("log")
    ax1.set_xlabel("impact speed (m/s)")
    ax1.set_ylabel("particles")
    ax2.stairs(np.asarray(angle_particles, float), np.asarray(angle_edges_deg, float), fill=True, alpha=0.7)
    ax2.set_xlim(0.0, 90.0)
    ax2.set_xlabel("impact angle (deg from the wall normal)")
    ax2.set_ylabel("particles")
    if title:
        fig.suptitle(title)
    return save_figure(fig, path)
