"""Figures of a 1-D or 2-D sweep grid: every numeric result against the swept key(s) (matplotlib, Agg).

``sweep_1d.png``: one panel per result, the result against the single swept key. ``sweep_2d.png``: one panel per
result against the first swept key, one line per value of the second. Keys with a single value do not count as
axes; grids with more than two varying keys get no figure. Failed cases are gaps. Units are those of the case
schema and of the stage's results (SI; angles in degrees), named in the column names.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

from wear.app.figures.common import plt, save_figure

__all__ = ["plot_sweep", "MAX_PANELS"]

#: At most this many results are drawn (the first ones that vary across the sweep).
MAX_PANELS = 16


def _number(value) -> float:
    if isinstance(value, bool) or value is None or value == "":
        return math.nan
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


def _is_numeric_axis(values: list) -> bool:
    return all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in values)


def _positions(values: list) -> tuple[list[float], list[str] | None]:
    """x positions of an axis and, for a non-numeric axis, its tick labels."""
    if _is_numeric_axis(values):
        return [float(v) for v in values], None
    return [float(i) for i in range(len(values))], [str(v) for v in values]


def plot_sweep(
    axes: dict[str, list],
    rows: list[dict],
    results: list[str],
    out: str | os.PathLike,
    units: dict[str, str] | None = None,
) -> Path | None:
    """Draw the figure of a 1-D or 2-D grid into ``out`` (atomically) and return its path, else None.

    ``axes``: swept key → values (``SweepSpec.axes``); ``rows``: one dict per case (column → value, with
    ``status`` and the swept keys); ``results``: the result columns to consider; ``units``: result → SI unit.
    A result is drawn if it varies by more than 1e-9 of its magnitude (round-off is not a trend).
    """
    units = units or {}
    varying = {k: v for k, v in axes.items() if len(v) > 1}
    if not 1 <= len(varying) <= 2:
        return None
    ok_rows = [r for r in rows if r["status"] == "ok"]
    panels = []
    for name in results:
        finite = [v for v in (_number(r.get(name)) for r in ok_rows) if math.isfinite(v)]
        if finite and max(finite) - min(finite) > 1e-9 * max(abs(v) for v in finite):
            panels.append(name)
    if not panels:
        return None
    panels = panels[:MAX_PANELS]
    keys = list(varying)
    x_key = keys[0]
    line_key = keys[1] if len(keys) == 2 else None
    x_pos, x_labels = _positions(varying[x_key])
    x_of = {repr(v): p for v, p in zip(varying[x_key], x_pos, strict=True)}
    line_values = varying[line_key] if line_key else [None]

    ncols = min(4, len(panels))
    nrows = math.ceil(len(panels) / ncols)
    fig, grid = plt.subplots(
        nrows, ncols, figsize=(3.6 * ncols + (1.2 if line_key else 0), 2.9 * nrows), squeeze=False, layout="constrained"
    )
    for ax, name in zip(grid.flat, panels, strict=False):
        for lv in line_values:
            pts = {}
            for r in rows:
                if line_key is not None and repr(r[line_key]) != repr(lv):
                    continue
                x = x_of.get(repr(r[x_key]))
                if x is not None:
                    pts[x] = _number(r.get(name)) if r["status"] == "ok" else math.nan
            xs = sorted(pts)
            ax.plot(xs, [pts[x] for x in xs], marker="o", ms=3, label=None if lv is None else f"{lv}")
        ax.set_xlabel(f"{x_key} [{units[x_key]}]" if units.get(x_key) else x_key)
        ax.set_title(f"{name} [{units[name]}]" if units.get(name) else name, fontsize=9)
        if x_labels is not None:
            ax.set_xticks(x_pos, x_labels, rotation=30)
        ax.tick_params(labelsize=7)
    for ax in list(grid.flat)[len(panels) :]:
        ax.set_visible(False)
    if line_key is not None:
        handles, labels = grid.flat[0].get_legend_handles_labels()
        title = f"{line_key} [{units[line_key]}]" if units.get(line_key) else line_key
        fig.legend(handles, labels, title=title, loc="outside right upper", fontsize=7, title_fontsize=8)
    fig.suptitle(f"sweep over {' × '.join(keys)} (failed cases are gaps)", fontsize=10)
    name = "sweep_2d.png" if line_key else "sweep_1d.png"
    return save_figure(fig, Path(out) / name, dpi=110)
