"""Figures of a component's wall erosion (matplotlib, Agg; SI units on every axis, angles in degrees from the wall
normal, written atomically).

``wall.png``: the wall in 3-D, orthographic, with equal axes (a metre as long on each) whose box is the wall's own
extent, seen from the side the hot spot (the fastest face) faces; each face coloured by its thickness-loss rate
(mm/year, logarithmic scale), the faces no particle wore in a light grey a legend names "no wear"; the hot spot
circled, its rate and position in a black-on-white label set off the wall with an arrow to the face.
``impacts.png``: the particles that hit the wall (each impact record stands for its particle count) by speed (m/s,
10 logarithmic bins per decade) and by impact angle (deg from the normal); the title gives both counts.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
from matplotlib import colormaps
from matplotlib.cm import ScalarMappable
from matplotlib.colors import LogNorm
from matplotlib.figure import Figure
from matplotlib.patches import Patch
from matplotlib.path import Path as Polygon2D
from matplotlib.text import Text
from matplotlib.ticker import MaxNLocator
from mpl_toolkits.mplot3d import proj3d
from mpl_toolkits.mplot3d.art3d import Poly3DCollection
from scipy.spatial import ConvexHull, QhullError

from wear.app.figures.common import figure, plain_log_ticks, save_figure, subplots
from wear.wall.mesh import Wall

__all__ = ["draw_wall_rate", "plot_wall_rate", "plot_impact_histograms"]

#: Colour of the faces no particle wore: a light neutral grey, apart from every colour of the rate scale, that
#: reads as bare wall (the legend says "no wear").
UNWORN = (0.9, 0.9, 0.9, 1.0)
#: Decades of thickness-loss rate the colour scale spans below the fastest face (slower worn faces take its lowest
#: colour): the hot spot is often tens of times faster than the rest of a wall, which a linear scale would hide.
RATE_DECADES = 3.0
#: Smallest extent of an axis, as a share of the largest (a flat wall keeps a visible thickness of box).
MIN_ASPECT = 0.05
#: The views (elevation, azimuth in deg) the wall may be seen from, all oblique (seen along an axis, a wall looks
#: flat and that axis' ticks fall on one another); the first is matplotlib's own, kept when no other does better.
VIEWS = tuple((e, a) for e in (30.0, 20.0, 45.0) for a in (-60.0, -30.0, -120.0, -150.0, 150.0, 120.0, 60.0, 30.0))
#: Share of the axes the wall's box may fill once zoomed (the rest: its tick labels and axis labels).
FILL = 0.8
#: Where the hot-spot label may go (axes fraction of its anchor corner; horizontal and vertical alignment), tried
#: nearest the hot spot first: the first clear of the drawn wall is kept.
LABEL_PLACES = (
    ((0.02, 0.98), "left", "top"),
    ((0.98, 0.98), "right", "top"),
    ((0.02, 0.02), "left", "bottom"),
    ((0.98, 0.02), "right", "bottom"),
    ((0.5, 0.98), "center", "top"),
    ((0.5, 0.02), "center", "bottom"),
)


#: Size (inches) of the wall figure.
WALL_FIGSIZE = (8.0, 6.5)


def plot_wall_rate(
    wall: Wall, rate_mm_year: np.ndarray, hot_face: int | None, path: str | os.PathLike, title: str = ""
) -> Path:
    """:func:`draw_wall_rate` on a figure of :data:`WALL_FIGSIZE`, into ``path``."""
    fig = figure(WALL_FIGSIZE)
    draw_wall_rate(fig, wall, rate_mm_year, hot_face, title)
    return save_figure(fig, path)


def draw_wall_rate(fig: Figure, wall: Wall, rate_mm_year: np.ndarray, hot_face: int | None, title: str = "") -> None:
    """``wall`` coloured by ``rate_mm_year`` (one per face; logarithmic scale over :data:`RATE_DECADES` decades,
    unworn faces in :data:`UNWORN`, named in a legend), orthographic with equal axes that the wall fills, seen from
    the side the face ``hot_face`` faces, that face marked and labelled off the wall, on the empty figure ``fig``
    (laid out for :data:`WALL_FIGSIZE`; a pyplot figure too, so that a script or a notebook shows it)."""
    rate = np.asarray(rate_mm_year, float)
    # one collection of faces (depth-sorted within itself), then the marker and the label over it: mplot3d's own
    # stacking by depth would bury the marker among the faces around it
    ax = fig.add_subplot(projection="3d", proj_type="ortho", computed_zorder=False)
    ax.set_position((0.0, 0.0, 0.84, 0.92 if title else 0.98))  # the colour bar and the legend to its right
    tri, owner = wall.triangles
    top = float(rate.max()) if rate.size and rate.max() > 0 else 1.0
    norm = LogNorm(top * 10.0**-RATE_DECADES, top, clip=True)
    cmap = colormaps["viridis"]
    colours = np.where((rate[owner] > 0)[:, None], cmap(norm(np.maximum(rate[owner], norm.vmin))), UNWORN)
    # each face's edge drawn in its own colour: without one, antialiasing leaves white seams between faces
    ax.add_collection3d(Poly3DCollection(wall.points[tri], facecolors=colours, edgecolors=colours, linewidths=0.3))
    _equal_axes(ax, wall.points)
    ax.view_init(*_view_of(wall, hot_face))
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.set_pane_color((1.0, 1.0, 1.0, 0.0))  # the page's white behind the wall: a grey pane hides unworn faces
    bar = fig.colorbar(ScalarMappable(norm=norm, cmap=cmap), cax=fig.add_axes((0.86, 0.3, 0.025, 0.55)))
    bar.set_label("thickness-loss rate (mm/year, log scale)")
    # "no wear", not "no hit": a face hit only where the law gives nothing (a grazing hit, a slow one) is unworn too
    unworn = Patch(facecolor=UNWORN, edgecolor="0.4", label="no wear\n(rate 0)")
    fig.legend(handles=[unworn], loc="lower right", bbox_to_anchor=(0.995, 0.1), fontsize=9, frameon=False)
    if title:
        fig.suptitle(title)
    _fill_axes(ax)
    if hot_face is not None:
        _label_hot_spot(ax, wall, rate, hot_face)


def _equal_axes(ax, points: np.ndarray) -> None:
    """Limits of ``ax`` tight around ``points`` and a box of their extents: a metre as long on each axis (a flat
    wall's thin axis kept at :data:`MIN_ASPECT` of the longest), ticks in proportion to each axis' length."""
    low, high = points.min(axis=0), points.max(axis=0)
    span = np.maximum(high - low, MIN_ASPECT * float((high - low).max()))
    centre = 0.5 * (low + high)
    for axis, c, half in zip("xyz", centre, 0.5 * span, strict=True):
        getattr(ax, f"set_{axis}lim")(c - half, c + half)
        getattr(ax, f"set_{axis}label")(f"{axis} (m)")
        # ticks in proportion to the axis' length (a pipe's diameter may get one): a short axis of many ticks
        # writes them over each other
        bins = max(1, round(5 * half * 2 / span.max()))
        getattr(ax, f"{axis}axis").set_major_locator(MaxNLocator(bins, min_n_ticks=1 if bins == 1 else 2))
    ax.set_box_aspect(tuple(span), zoom=1.0)
    ax.tick_params(labelsize=8)


def _eye(elev: float, azim: float) -> np.ndarray:
    """The unit vector from the wall towards the viewer of ``ax.view_init(elev, azim)`` (z up)."""
    e, a = np.radians([elev, azim])
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def _view_of(wall: Wall, hot_face: int | None) -> tuple[float, float]:
    """The view of :data:`VIEWS` that shows the wall widest among those that see the hot face unhidden and within
    60° of face-on (the face's normal points out of the flow, to a viewer outside the component); failing any, the
    one that sees it most face-on; without a hot face, matplotlib's."""
    if hot_face is None:
        return VIEWS[0]
    tri, owner = wall.triangles
    corners = wall.points[tri[owner != hot_face]]
    normal, centre = wall.normal[hot_face], wall.centre[hot_face]
    best, best_key = VIEWS[0], (-np.inf, -np.inf)
    for view in VIEWS:
        eye = _eye(*view)
        facing = float(normal @ eye)
        if facing <= 0.0 or _hidden(centre, eye, corners):
            continue
        key = (1.0, _projected_area(wall.points, eye)) if facing >= 0.5 else (0.0, facing)
        if key > best_key:
            best, best_key = view, key
    return best


def _hidden(point: np.ndarray, eye: np.ndarray, corners: np.ndarray) -> bool:
    """Whether the ray from ``point`` towards ``eye`` passes through one of the triangles ``corners`` (t, 3, 3)
    (Möller–Trumbore, all at once)."""
    a, b, c = corners[:, 0], corners[:, 1], corners[:, 2]
    e1, e2 = b - a, c - a
    p = np.cross(eye, e2)
    det = np.einsum("ij,ij->i", e1, p)
    ok = np.abs(det) > 1e-30
    inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
    s = point - a
    u = np.einsum("ij,ij->i", s, p) * inv
    q = np.cross(s, e1)
    v = (q @ eye) * inv
    t = np.einsum("ij,ij->i", e2, q) * inv
    size = float(np.ptp(corners.reshape(-1, 3), axis=0).max()) if len(corners) else 1.0
    return bool(np.any(ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 1e-6 * size)))


def _projected_area(points: np.ndarray, eye: np.ndarray) -> float:
    """Area of the convex hull of ``points`` seen along ``eye`` (orthographic): how wide the wall shows."""
    side = np.cross(eye, [0.0, 0.0, 1.0])
    side = side / np.linalg.norm(side) if np.linalg.norm(side) > 1e-9 else np.array([1.0, 0.0, 0.0])
    flat = np.column_stack([points @ side, points @ np.cross(side, eye)])
    try:
        return float(ConvexHull(flat).volume)  # in 2-D, Qhull's volume is the area
    except QhullError:
        return 0.0  # a wall seen edge-on


def _display(ax, points: np.ndarray) -> np.ndarray:
    """``points`` (n, 3) of ``ax``'s data where ``ax`` draws them, in display coordinates (pixels)."""
    u, v, _ = proj3d.proj_transform(*np.asarray(points, float).T, ax.get_proj())
    return ax.transData.transform(np.column_stack([u, v]))


def _fill_axes(ax) -> None:
    """Zoom ``ax`` so that its box (the wall's extents) fills :data:`FILL` of the axes: matplotlib leaves room for
    any view, a sixth of the frame for a pipe."""
    ax.apply_aspect()  # the axes' place as it will be drawn (a 3-D axes narrows itself to its box)
    corners = np.array(np.meshgrid(ax.get_xlim(), ax.get_ylim(), ax.get_zlim())).reshape(3, -1).T
    centre = _display(ax, corners.mean(axis=0, keepdims=True))[0]
    offset = _display(ax, corners) - centre
    frame = ax.bbox
    room = [frame.x1 - centre[0], centre[0] - frame.x0, frame.y1 - centre[1], centre[1] - frame.y0]
    need = [offset[:, 0].max(), -offset[:, 0].min(), offset[:, 1].max(), -offset[:, 1].min()]
    zoom = FILL * min((r / n for r, n in zip(room, need, strict=True) if n > 0), default=1.0 / FILL)
    ax.set_box_aspect(ax.get_box_aspect(), zoom=zoom)


def _drawn_outline(ax, points: np.ndarray) -> Polygon2D:
    """The convex hull of ``points`` as ``ax`` draws them (display coordinates)."""
    flat = _display(ax, points)
    try:
        ring = flat[ConvexHull(flat).vertices]
    except QhullError:  # seen edge-on: a segment, kept as its bounding box
        (x0, y0), (x1, y1) = flat.min(axis=0), flat.max(axis=0)
        ring = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
    return Polygon2D(np.vstack([ring, ring[:1]]), closed=True)


def _label_hot_spot(ax, wall: Wall, rate: np.ndarray, hot_face: int) -> None:
    """The face ``hot_face`` circled, and its rate and position in a label set in the first of
    :data:`LABEL_PLACES` (nearest the face first) clear of the drawn wall, with an arrow to the face: on the wall it
    would hide what it points at."""
    x, y, z = wall.centre[hot_face]
    ax.scatter(
        [x], [y], [z], s=90, marker="o", facecolors="none", edgecolors="red", linewidths=1.5, depthshade=False, zorder=5
    )
    outline = _drawn_outline(ax, wall.points)
    spot = _display(ax, wall.centre[hot_face : hot_face + 1])[0]
    renderer = ax.figure.canvas.get_renderer()
    places = sorted(LABEL_PLACES, key=lambda p: np.hypot(*(ax.transAxes.transform(p[0]) - spot)))
    u, v, _ = proj3d.proj_transform(x, y, z, ax.get_proj())
    for i, (anchor, ha, va) in enumerate(places):
        label = ax.annotate(
            f"hot spot: {rate[hot_face]:.3g} mm/year\nat ({x:.3g}, {y:.3g}, {z:.3g}) m",
            xy=(u, v),
            xytext=anchor,
            textcoords="axes fraction",
            ha=ha,
            va=va,
            fontsize=9,
            color="black",
            zorder=6,
            bbox={"boxstyle": "round", "facecolor": "white", "edgecolor": "0.3"},
            arrowprops={"arrowstyle": "->", "color": "black", "linewidth": 1.2, "shrinkB": 7},
        )
        # the text and its box only (an annotation's own extent takes in its arrow, which does reach the wall)
        clear = not outline.intersects_bbox(Text.get_window_extent(label, renderer).padded(6.0))
        if clear or i == len(places) - 1:  # none clear (a wall filling every corner): the last place kept
            return
        label.remove()


def plot_impact_histograms(
    speed_edges_m_s: np.ndarray,
    speed_particles: np.ndarray,
    angle_edges_deg: np.ndarray,
    angle_particles: np.ndarray,
    path: str | os.PathLike,
    title: str = "",
) -> Path:
    """The particles on the wall by speed (bins ``speed_edges_m_s``, m/s; the empty bins at both ends left out) and
    by angle (bins ``angle_edges_deg``, deg from the normal), into ``path``; each axis says what a bin holds."""
    fig, (ax1, ax2) = subplots(1, 2, figsize=(10, 4), layout="constrained")
    speed = np.asarray(speed_particles, float)
    edges = np.asarray(speed_edges_m_s, float)
    used = np.flatnonzero(speed > 0)
    if used.size:
        first, last = used[0], used[-1] + 1
        ax1.stairs(speed[first:last], edges[first : last + 1], fill=True, alpha=0.7)
        ax1.set_xscale("log")
        plain_log_ticks(ax1.xaxis, edges[first : last + 1], few=0)  # 1, 2, 5 m/s…: edges 0.1 decade apart crowd
    ax1.set_xlabel("impact speed (m/s)")
    ax1.set_ylabel(f"particles per speed bin{_bin_width(np.log10(edges), ' per decade', reciprocal=True)}")
    angle_edges = np.asarray(angle_edges_deg, float)
    ax2.stairs(np.asarray(angle_particles, float), angle_edges, fill=True, alpha=0.7)
    ax2.set_xlim(0.0, 90.0)
    ax2.set_xlabel("impact angle (deg from the wall normal)")
    ax2.set_ylabel(f"particles per angle bin{_bin_width(angle_edges, ' deg')}")
    if title:
        fig.suptitle(title)
    return save_figure(fig, path)


def _bin_width(edges: np.ndarray, unit: str, reciprocal: bool = False) -> str:
    """`` (w unit)`` for bins ``edges`` of one width w (``reciprocal``: bins per unit), or nothing: uneven bins."""
    widths = np.diff(edges)
    if len(widths) == 0 or not np.allclose(widths, widths[0], rtol=1e-6) or widths[0] <= 0:
        return ""
    return f" ({1.0 / widths[0]:.3g}{unit})" if reciprocal else f" ({widths[0]:.3g}{unit})"
