"""What every figure module shares: figures drawn on their own Agg canvas, a legend placed clear of the data, and
the atomic PNG save.

The figures are built with matplotlib's object-oriented API (:class:`matplotlib.figure.Figure` on a
:class:`~matplotlib.backends.backend_agg.FigureCanvasAgg`), never through pyplot: writing a PNG needs no display,
and importing or running the toolkit leaves the user's pyplot backend and open figures as they were.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import PathCollection
from matplotlib.figure import Figure
from matplotlib.legend import Legend
from matplotlib.ticker import FixedLocator, FuncFormatter, LogLocator, NullFormatter
from matplotlib.transforms import offset_copy

from wear.app.outputs.writer import atomic_write

__all__ = ["place_legend", "place_legends", "plain_log_ticks", "save_figure", "subplots"]

#: Where :func:`place_legend` tries the legend inside the axes, in this order (matplotlib's location names).
INSIDE = (
    "upper right",
    "upper left",
    "lower left",
    "lower right",
    "center right",
    "center left",
    "upper center",
    "lower center",
    "center",
)
#: The most room :func:`place_legend` adds above (or below) the data for a legend: the y axis then spans at most
#: this many times what it spanned. A legend that needs more goes beside the axes instead.
MAX_HEADROOM = 1.5


def subplots(
    nrows: int = 1, ncols: int = 1, *, figsize: tuple[float, float] | None = None, layout: str | None = None, **kw: Any
) -> tuple[Figure, Any]:
    """A figure of ``figsize`` (inches) on an Agg canvas and its axes, as ``pyplot.subplots`` returns them
    (``kw``: ``sharex``, ``sharey``, ``squeeze``, ``gridspec_kw``, … of :meth:`matplotlib.figure.Figure.subplots`)."""
    fig = Figure(figsize=figsize, layout=layout)
    FigureCanvasAgg(fig)
    return fig, fig.subplots(nrows, ncols, **kw)


def save_figure(fig: Figure, path: str | os.PathLike, dpi: int = 120, **savefig: Any) -> Path:
    """Write ``fig`` to ``path`` as PNG (``savefig`` options passed on; through the one atomic writer)."""
    return atomic_write(path, lambda name: fig.savefig(name, dpi=dpi, format="png", **savefig), mode="path")


def plain_log_ticks(axis, values) -> None:
    """Ticks of a log ``axis`` written as plain numbers (20, 30, 50, not 2×10¹): at each of ``values`` where there
    are a few (≤ 8: the speeds measured, the cells of a map), else at 1, 2, 5 × 10ⁿ; minor ticks unlabelled."""
    values = np.asarray(values, float)
    distinct = np.unique(values[np.isfinite(values)])
    axis.set_major_locator(FixedLocator(distinct) if len(distinct) <= 8 else LogLocator(subs=(1.0, 2.0, 5.0)))
    axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    axis.set_minor_formatter(NullFormatter())


def _segments(ax: Axes) -> list[tuple[np.ndarray, bool]]:
    """What ``ax`` draws, in display coordinates: (points, joined) of every visible line (``joined``: drawn as a
    polyline, so its segments count, not only its vertices) and the offsets of every scatter."""
    drawn = []
    for line in ax.get_lines():
        xy = np.asarray(line.get_xydata(), float)
        if not line.get_visible() or xy.size == 0:
            continue  # legend proxies ``ax.plot([], [])`` draw nothing
        joined = line.get_linestyle() not in ("None", "none", "", " ")
        drawn.append((line.get_transform().transform(xy), joined))
    for c in ax.collections:
        if isinstance(c, PathCollection) and c.get_visible() and len(c.get_offsets()):
            drawn.append((c.get_offset_transform().transform(np.asarray(c.get_offsets(), float)), False))
    return drawn


def _hits(box, points: np.ndarray, joined: bool) -> int:
    """How many of ``points`` (display, (n, 2)) lie in ``box`` (x0, y0, x1, y1), with ``joined`` also how many
    segments between consecutive points cross it (Liang–Barsky clipping: the segment p + t (q − p), t ∈ [0, 1],
    meets the box where the intervals of t inside each slab overlap)."""
    x0, y0, x1, y1 = box
    finite = np.isfinite(points).all(axis=1)
    p = points[finite]
    inside = int(np.count_nonzero((p[:, 0] >= x0) & (p[:, 0] <= x1) & (p[:, 1] >= y0) & (p[:, 1] <= y1)))
    if not joined or len(points) < 2:
        return inside
    both = finite[:-1] & finite[1:]
    a, b = points[:-1][both], points[1:][both]
    d = b - a
    t0, t1 = np.zeros(len(a)), np.ones(len(a))
    meets = np.ones(len(a), bool)
    for k, (lo, hi) in enumerate(((x0, x1), (y0, y1))):
        flat = d[:, k] == 0.0
        meets &= ~flat | ((a[:, k] >= lo) & (a[:, k] <= hi))
        with np.errstate(divide="ignore", invalid="ignore"):
            ta, tb = (lo - a[:, k]) / d[:, k], (hi - a[:, k]) / d[:, k]
        t0 = np.where(flat, t0, np.maximum(t0, np.minimum(ta, tb)))
        t1 = np.where(flat, t1, np.minimum(t1, np.maximum(ta, tb)))
    return inside + int(np.count_nonzero(meets & (t0 <= t1)))


def _covered(legend: Legend, group: Sequence[Axes], renderer, pad: float) -> int:
    """How many drawn points and segments of the axes in ``group`` the legend's box (grown by ``pad`` pixels)
    holds; what lies outside the axes is clipped away and never counts."""
    box = legend.get_window_extent(renderer).padded(pad)
    frame = group[0].get_window_extent(renderer)
    box = (max(box.x0, frame.x0), max(box.y0, frame.y0), min(box.x1, frame.x1), min(box.y1, frame.y1))
    return sum(_hits(box, points, joined) for ax in group for points, joined in _segments(ax))


def _stretch(group: Sequence[Axes], factor: float, upwards: bool) -> None:
    """Stretch each y axis of ``group`` so that what it spans now fills ``1/factor`` of it (in the axis' own scale,
    linear or log), keeping its bottom (``upwards``) or its top."""
    for ax in group:
        scale = ax.yaxis.get_transform()
        lo, hi = scale.transform(np.asarray(ax.get_ylim(), float))
        span = (factor - 1.0) * (hi - lo)
        ax.set_ylim(*scale.inverted().transform([lo, hi + span] if upwards else [lo - span, hi]))


def _legend_of(group: Sequence[Axes]) -> Legend | None:
    """The legend drawn on one of the axes of ``group`` (the topmost first), if any."""
    return next((ax.get_legend() for ax in reversed(group) if ax.get_legend() is not None), None)


def place_legend(
    axes: Axes | Sequence[Axes], pad: float = 3.0, outside: bool = True, **legend_kw: Any
) -> Legend | None:
    """A legend of ``axes`` (one axes, or an axes and its twins, which share its area) that covers none of their
    data: drawn points, and the lines between them (an ``axhline`` across the panel counts).

    The legend holds the labelled artists of every axes in the group and is drawn on the last (topmost), so no
    twin's line is drawn over it. It goes to the first location of :data:`INSIDE` whose box (grown by ``pad``
    pixels) holds no data; failing that, the y axes get room above the data for it (at most
    :data:`MAX_HEADROOM` times their span, in their own scale) and the upper locations are tried again, then room
    below and the lower locations; failing that, the legend goes outside, to the right of the axes and of their
    tick labels (``outside``; else where it covers the fewest). Call it once the figure's layout is set and the
    limits drawn; :func:`place_legends` lays the figure out again around the legends.
    ``legend_kw``: other :meth:`matplotlib.axes.Axes.legend` options (``fontsize``, ``ncol``, …). Nothing
    labelled: no legend (None).
    """
    group = _group(axes)
    host = group[-1]
    handles, labels = [], []
    for ax in group:
        h, lab = ax.get_legend_handles_labels()
        handles += h
        labels += lab
        if ax.get_legend() is not None:
            ax.get_legend().remove()
    if not handles:
        return None
    renderer = host.figure.canvas.get_renderer()
    frame = host.get_window_extent(renderer)

    def first_clear(locations):
        for loc in locations:
            legend = host.legend(handles, labels, loc=loc, **legend_kw)
            if _covered(legend, group, renderer, pad) == 0:
                return legend
            legend.remove()
        return None

    legend = first_clear(INSIDE)
    if legend is not None:
        return legend
    probe = host.legend(handles, labels, loc="upper right", **legend_kw)
    # the share of the axes' height left to the data beside a legend at its top or bottom
    left = 1.0 - (probe.get_window_extent(renderer).height + 2.0 * pad) / frame.height - 0.04
    probe.remove()
    if left > 1.0 / MAX_HEADROOM:
        for upwards in (True, False):
            _stretch(group, 1.0 / left, upwards)
            legend = first_clear([loc for loc in INSIDE if loc.startswith("upper" if upwards else "lower")])
            if legend is not None:
                return legend
            _stretch(group, left, upwards)  # no use: the limits as they were
    if not outside:
        fewest = min(
            INSIDE, key=lambda loc: _covered(host.legend(handles, labels, loc=loc, **legend_kw), group, renderer, pad)
        )
        return host.legend(handles, labels, loc=fewest, **legend_kw)
    right = max(ax.get_tightbbox(renderer).x1 for ax in group) - frame.x1
    # an offset in points: it stays beside the tick labels when the layout resizes the axes or the PNG's dpi differs
    anchor = offset_copy(host.transAxes, fig=host.figure, x=right * 72.0 / host.figure.dpi + 4.0, units="points")
    return host.legend(handles, labels, loc="upper left", bbox_to_anchor=(1.0, 1.0), bbox_transform=anchor, **legend_kw)


def place_legends(
    fig: Figure,
    groups: Sequence[Axes | Sequence[Axes]],
    layout: Callable[[Figure], Any] | None = Figure.tight_layout,
    **legend_kw: Any,
) -> None:
    """:func:`place_legend` for each of ``groups`` (an axes, or an axes and its twins) of ``fig``.

    ``layout`` (``fig`` → None, e.g. ``tight_layout`` with a ``rect``) lays the figure out before, and again after
    with room for the legends put outside; a legend the new layout moved onto data is placed again. With ``None``
    the layout is fixed (``subplots_adjust``) and the legends stay inside the axes."""
    if layout is not None:
        layout(fig)
    for group in groups:
        place_legend(group, outside=layout is not None, **legend_kw)
    if layout is None:
        return
    renderer = fig.canvas.get_renderer()
    for _ in range(2):
        layout(fig)
        moved = [g for g in groups if (legend := _legend_of(_group(g))) and _covered(legend, _group(g), renderer, 0.0)]
        if not moved:
            return
        for group in moved:
            place_legend(group, **legend_kw)


def _group(axes: Axes | Sequence[Axes]) -> list[Axes]:
    """One axes, or an axes and its twins, as a list."""
    return [axes] if isinstance(axes, Axes) else list(axes)
