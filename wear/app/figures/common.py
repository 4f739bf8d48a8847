"""What every figure module shares: figures drawn on their own Agg canvas, and the atomic PNG save.

The figures are built with matplotlib's object-oriented API (:class:`matplotlib.figure.Figure` on a
:class:`~matplotlib.backends.backend_agg.FigureCanvasAgg`), never through pyplot: writing a PNG needs no display,
and importing or running the toolkit leaves the user's pyplot backend and open figures as they were.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from wear.app.outputs.writer import atomic_write

__all__ = ["save_figure", "subplots"]


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
