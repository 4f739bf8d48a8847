"""What every figure module shares: figures drawn on their own Agg canvas, a legend placed clear of the data, a
check that no text of a figure overlaps another or runs off its edge, and the atomic PNG save.

The figures are built with matplotlib's object-oriented API (:class:`matplotlib.figure.Figure` on a
:class:`~matplotlib.backends.backend_agg.FigureCanvasAgg`), never through pyplot: writing a PNG needs no display,
and importing or running the toolkit leaves the user's pyplot backend and open figures as they were.
"""

from __future__ import annotations

import os
import warnings
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.axes import Axes
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.collections import PathCollection
from matplotlib.figure import Figure
from matplotlib.legend import Legend
from matplotlib.text import Text
from matplotlib.ticker import FixedLocator, FuncFormatter, LogLocator, NullFormatter
from matplotlib.transforms import offset_copy

from wear.app.outputs.writer import atomic_write

__all__ = [
    "FigureTextWarning",
    "figure",
    "overlapping_texts",
    "place_legend",
    "place_legends",
    "plain_log_ticks",
    "save_figure",
    "subplots",
]

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


#: Overlap (pixels at the figure's dpi, in each direction) from which two texts collide, or a text runs off the
#: figure: less is two boxes that touch (neighbouring tick labels' boxes often do, their glyphs clear).
OVERLAP_PX = 1.0


class FigureTextWarning(UserWarning):
    """A figure's texts overlap one another or run off its edge (:func:`overlapping_texts`)."""


def figure(figsize: tuple[float, float] | None = None, layout: str | None = None) -> Figure:
    """An empty figure of ``figsize`` (inches) on an Agg canvas."""
    fig = Figure(figsize=figsize, layout=layout)
    FigureCanvasAgg(fig)
    return fig


def subplots(
    nrows: int = 1, ncols: int = 1, *, figsize: tuple[float, float] | None = None, layout: str | None = None, **kw: Any
) -> tuple[Figure, Any]:
    """A figure of ``figsize`` (inches) on an Agg canvas and its axes, as ``pyplot.subplots`` returns them
    (``kw``: ``sharex``, ``sharey``, ``squeeze``, ``gridspec_kw``, … of :meth:`matplotlib.figure.Figure.subplots`)."""
    fig = figure(figsize, layout)
    return fig, fig.subplots(nrows, ncols, **kw)


def _axis_texts(ax: Axes, name: str) -> list[tuple[str, Text]]:
    """The texts an axes draws: its titles, its axes' labels, offset texts and the labels of the ticks it draws
    (a tick outside the view limits is not drawn), and its own texts and annotations (``name``: for the report)."""
    texts = [(f"title of {name}", t) for t in (ax.title, ax._left_title, ax._right_title)]
    axes = [ax.xaxis, ax.yaxis] + ([ax.zaxis] if hasattr(ax, "zaxis") else [])
    for axis in (a for a in axes if a.get_visible()):  # a twin's shared axis is hidden
        letter = axis.axis_name
        texts += [(f"{letter} label of {name}", axis.label), (f"{letter} offset of {name}", axis.offsetText)]
        for tick in axis._update_ticks():  # the ticks drawn (matplotlib's own choice at draw time)
            texts += [(f"{letter} tick label of {name}", t) for t in (tick.label1, tick.label2)]
    texts += [(f"text of {name}", t) for t in ax.texts]
    return texts


def _text_box(text: Text, renderer):
    """The box of a text's glyphs (an annotation's without its arrow; a text's bbox patch left out)."""
    return Text.get_window_extent(text, renderer)


def overlapping_texts(fig: Figure) -> list[str]:
    """The texts of ``fig`` that a reader cannot read whole: each pair of texts whose boxes overlap, and each text
    that runs off the figure's edge, as sentences (empty: every text clear).

    The texts: the figure's own (a suptitle, a source line), and of every axes (a colour bar's included) the
    titles, the axis labels, the drawn tick labels, the offset texts and the texts and annotations placed on it;
    a legend counts as one box. Boxes are in pixels at the figure's dpi after a draw; they collide when they
    overlap by more than :data:`OVERLAP_PX` both ways. A text of its own axes' box (a cell's value in a map) is
    a text like any other."""
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    named = [("figure text", t) for t in fig.texts]
    for k, ax in enumerate(fig.axes):
        if not ax.get_visible():
            continue
        name = f"axes {k + 1}" + (
            f" ({ax.get_label()})" if ax.get_label() and not ax.get_label().startswith("<") else ""
        )
        named += [(n, t) for n, t in _axis_texts(ax, name) if ax.axison or n.startswith(("title", "text"))]
    boxes = []
    for name, text in named:
        if text.get_visible() and text.get_text().strip() and text.get_alpha() != 0:
            boxes.append((f"{name} {text.get_text()!r}", _text_box(text, renderer)))
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None] + list(fig.legends)
    boxes += [
        (f"legend {legend.get_texts()[0].get_text()!r}…", legend.get_window_extent(renderer)) for legend in legends
    ]
    found = []
    for i, (a, box_a) in enumerate(boxes):
        for b, box_b in boxes[i + 1 :]:
            wide = min(box_a.x1, box_b.x1) - max(box_a.x0, box_b.x0)
            high = min(box_a.y1, box_b.y1) - max(box_a.y0, box_b.y0)
            if wide > OVERLAP_PX and high > OVERLAP_PX:
                found.append(f"{a} overlaps {b}")
    edge = fig.bbox
    for name, box in boxes:
        off = [
            side
            for side, past in (
                ("left", edge.x0 - box.x0),
                ("right", box.x1 - edge.x1),
                ("bottom", edge.y0 - box.y0),
                ("top", box.y1 - edge.y1),
            )
            if past > OVERLAP_PX
        ]
        if off:
            found.append(f"{name} runs off the figure's {' and '.join(off)} edge")
    return found


def save_figure(fig: Figure, path: str | os.PathLike, dpi: int = 120, **savefig: Any) -> Path:
    """Write ``fig`` to ``path`` as PNG (``savefig`` options passed on; through the one atomic writer). A text that
    overlaps another or runs off the figure (:func:`overlapping_texts`) is warned of (:class:`FigureTextWarning`):
    the figure is written all the same."""
    found = overlapping_texts(fig)
    if found:
        warnings.warn(f"{Path(path).name}: {'; '.join(found)}", FigureTextWarning, stacklevel=2)
    return atomic_write(path, lambda name: fig.savefig(name, dpi=dpi, format="png", **savefig), mode="path")


def plain_log_ticks(axis, values, few: int = 8) -> None:
    """Ticks of a log ``axis`` written as plain numbers (20, 30, 50, not 2×10¹): at each of ``values`` where there
    are a few (≤ ``few``: the speeds measured, the cells of a map), else at 1, 2, 5 × 10ⁿ; minor ticks unlabelled.
    ``few=0``: always at 1, 2, 5 × 10ⁿ (a histogram's bin edges are no values to label)."""
    values = np.asarray(values, float)
    distinct = np.unique(values[np.isfinite(values)])
    axis.set_major_locator(FixedLocator(distinct) if len(distinct) <= few else LogLocator(subs=(1.0, 2.0, 5.0)))
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
