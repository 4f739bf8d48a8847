"""Figures of a component's wall erosion (matplotlib, Agg; SI units on every axis, angles in degrees from the wall
normal, written atomically).

``wall.png``: the wall in 3-D with equal axes, each face coloured by its thickness-loss rate (mm/year, logarithmic
scale; faces without wear in grey), the hot spot (the fastest face) circled and labelled beside the wall.
``impacts.png``: the particles that hit the wall (each record stands for its particle count) by speed (m/s, 10
logarithmic bins per decade) and by impact angle (deg from the normal).
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from matplotlib import colormaps
from matplotlib.cm import ScalarMappable
from matplotlib.colors import LogNorm
from matplotlib.ticker import MaxNLocator
from mpl_toolkits.mplot3d import proj3d
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from wear.app.figures.common import plain_log_ticks, save_figure, subplots
from wear.wall.mesh import Wall

__all__ = ["plot_wall_rate", "plot_impact_histograms"]

#: Colour of the faces no particle wore.
UNWORN = (0.8, 0.8, 0.8, 1.0)
#: Decades of thickness-loss rate the colour scale spans below the fastest face (slower worn faces take its lowest
#: colour): the hot spot is often tens of times faster than the rest of a wall, which a linear scale would hide.
RATE_DECADES = 3.0
#: Smallest extent of an axis, as a share of the largest (a flat wall keeps a visible thickness of box).
MIN_ASPECT = 0.05


def plot_wall_rate(
    wall: Wall, rate_mm_year: np.ndarray, hot_face: int | None, path: str | os.PathLike, title: str = ""
) -> Path:
    """``wall`` coloured by ``rate_mm_year`` (one per face; logarithmic scale over :data:`RATE_DECADES` decades,
    unworn faces grey) with equal axes that the wall fills, the face ``hot_face`` marked and labelled beside the
    wall, into ``path``."""
    rate = np.asarray(rate_mm_year, float)
    fig, ax = subplots(figsize=(8.0, 6.5), subplot_kw={"projection": "3d"})
    tri, owner = wall.triangles
    top = float(rate.max()) if rate.size and rate.max() > 0 else 1.0
    norm = LogNorm(top * 10.0**-RATE_DECADES, top, clip=True)
    cmap = colormaps["viridis"]
    colours = np.where((rate[owner] > 0)[:, None], cmap(norm(np.maximum(rate[owner], norm.vmin))), UNWORN)
    ax.add_collection3d(Poly3DCollection(wall.points[tri], facecolors=colours, edgecolors="none"))
    low, high = wall.points.min(axis=0), wall.points.max(axis=0)
    span = np.maximum(high - low, MIN_ASPECT * float((high - low).max()))
    centre = 0.5 * (low + high)
    for axis, c, half in zip("xyz", centre, 0.5 * span, strict=True):
        getattr(ax, f"set_{axis}lim")(c - half, c + half)
        getattr(ax, f"set_{axis}label")(f"{axis} (m)")
        # ticks in proportion to the axis' length: a short axis of many ticks writes them over each other
        getattr(ax, f"{axis}axis").set_major_locator(MaxNLocator(max(2, round(6 * half * 2 / span.max()))))
    ax.set_box_aspect(tuple(span), zoom=1.0)  # equal axes: a metre is as long on each
    ax.tick_params(labelsize=8)
    bar = fig.colorbar(ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.6, pad=0.04)
    bar.set_label("thickness-loss rate (mm/year, log scale; grey: unworn)")
    if hot_face is not None:
        x, y, z = wall.centre[hot_face]
        ax.scatter([x], [y], [z], s=60, marker="o", facecolors="none", edgecolors="red", depthshade=False)
        # the label in the axes' corner, an arrow to the face: on the wall it would hide what it points at
        u, v, _ = proj3d.proj_transform(x, y, z, ax.get_proj())
        ax.annotate(
            f"hot spot: {rate[hot_face]:.3g} mm/year\nat ({x:.3g}, {y:.3g}, {z:.3g}) m",
            xy=(u, v),
            xytext=(0.02, 0.98),
            textcoords="axes fraction",
            va="top",
            fontsize=9,
            bbox={"boxstyle": "round", "facecolor": "white", "edgecolor": "0.5"},
            arrowprops={"arrowstyle": "->", "color": "red"},
        )
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
        plain_log_ticks(ax1.xaxis, edges[first : last + 1])
    ax1.set_xlabel("impact speed (m/s)")
    ax1.set_ylabel("particles per bin")
    ax2.stairs(np.asarray(angle_particles, float), np.asarray(angle_edges_deg, float), fill=True, alpha=0.7)
    ax2.set_xlim(0.0, 90.0)
    ax2.set_xlabel("impact angle (deg from the wall normal)")
    ax2.set_ylabel("particles per bin")
    if title:
        fig.suptitle(title)
    return save_figure(fig, path)
