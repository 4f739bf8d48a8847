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

from wear.app.figures.common import save_figure, subplots

__all__ = ["plot_sweep", "panel_results", "scaled_unit", "MAX_PANELS", "ROUND_OFF"]

#: At most this many results are drawn (the first ones that vary across the sweep).
MAX_PANELS = 16


def _number(value) -> float:
    if isinstance(value, bool) or value is None or value == "":
        return math.nan
    try:
        return float(value)
    except (TypeError, ValueError):
        return math.nan


#: A result is round-off, not a trend, if it varies by at most this fraction of its magnitude, or if its
#: magnitude is at most this fraction of the largest result in the same unit (e.g. a work of 1e-14 J beside
#: energies of 2e-3 J).
ROUND_OFF = 1e-9

#: SI prefixes by power of ten, for the units that take them plainly (not kg, deg, or compound units).
_PREFIXES = {-15: "f", -12: "p", -9: "n", -6: "µ", -3: "m", 3: "k", 6: "M", 9: "G", 12: "T"}
_PREFIXABLE = {"s", "m", "N", "Pa", "J", "W", "Hz", "V"}


def _finite(values) -> list[float]:
    return [v for v in (_number(x) for x in values) if math.isfinite(v)]


def _same_as_input(values: list, inputs: list) -> bool:
    pairs = [(_number(v), _number(w)) for v, w in zip(values, inputs, strict=True)]
    pairs = [(v, w) for v, w in pairs if math.isfinite(v) and math.isfinite(w)]
    return bool(pairs) and all(abs(v - w) <= ROUND_OFF * max(abs(v), abs(w)) for v, w in pairs)


def panel_results(
    varying: dict[str, list], rows: list[dict], results: list[str], units: dict[str, str] | None = None
) -> list[str]:
    """The results worth a panel, in order: those that vary across the sweep beyond round-off and are not the
    swept inputs over again.

    Dropped: a result whose range is ≤ :data:`ROUND_OFF` × its largest magnitude (constant), whose largest
    magnitude is ≤ :data:`ROUND_OFF` × the largest magnitude among the results in the same SI unit (``units``:
    result → unit; zero to round-off), or that is a swept key of ``varying`` (by name, or ``result.<key>``, or
    equal to it in every successful row).
    """
    units = units or {}
    ok_rows = [r for r in rows if r["status"] == "ok"]
    magnitude = {name: max((abs(v) for v in _finite(r.get(name) for r in ok_rows)), default=0.0) for name in results}
    unit_scale: dict[str, float] = {}
    for name in results:
        if units.get(name):
            unit_scale[units[name]] = max(unit_scale.get(units[name], 0.0), magnitude[name])
    panels = []
    for name in results:
        values = [r.get(name) for r in ok_rows]
        finite = _finite(values)
        if not finite or max(finite) - min(finite) <= ROUND_OFF * magnitude[name]:
            continue
        if units.get(name) and magnitude[name] <= ROUND_OFF * unit_scale[units[name]]:
            continue
        if any(
            name in (key, f"result.{key}") or _same_as_input(values, [r.get(key) for r in ok_rows]) for key in varying
        ):
            continue
        panels.append(name)
    return panels


def scaled_unit(values, unit: str = "") -> tuple[float, str]:
    """(divisor, unit label) that shows ``values`` with numbers between 0.1 and 1000: an SI prefix on a plain
    unit (5e-6 s → (1e-6, "µs")), else the power of ten in the label (5e-6 kg/kg → (1e-6, "×1e-06 kg/kg"))."""
    finite = _finite(values)
    top = max((abs(v) for v in finite), default=0.0)
    if top == 0.0 or 0.1 <= top < 1000.0:
        return 1.0, unit
    exponent = 3 * math.floor(math.log10(top) / 3)
    if unit in _PREFIXABLE and exponent in _PREFIXES:
        return 10.0**exponent, _PREFIXES[exponent] + unit
    return 10.0**exponent, f"×1e{exponent:+03d} {unit}".rstrip()


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
    The panels are :func:`panel_results`; each shows its numbers scaled by :func:`scaled_unit`.
    """
    units = units or {}
    varying = {k: v for k, v in axes.items() if len(v) > 1}
    if not 1 <= len(varying) <= 2:
        return None
    panels = panel_results(varying, rows, results, units)
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
    fig, grid = subplots(
        nrows, ncols, figsize=(3.6 * ncols + (1.2 if line_key else 0), 2.9 * nrows), squeeze=False, layout="constrained"
    )
    x_scale, x_unit = (1.0, units.get(x_key, "")) if x_labels is not None else scaled_unit(x_pos, units.get(x_key, ""))
    for ax, name in zip(grid.flat, panels, strict=False):
        y_scale, y_unit = scaled_unit([_number(r.get(name)) for r in rows if r["status"] == "ok"], units.get(name, ""))
        for lv in line_values:
            pts = {}
            for r in rows:
                if line_key is not None and repr(r[line_key]) != repr(lv):
                    continue
                x = x_of.get(repr(r[x_key]))
                if x is not None:
                    pts[x] = _number(r.get(name)) if r["status"] == "ok" else math.nan
            xs = sorted(pts)
            ax.plot(
                [x / x_scale for x in xs],
                [pts[x] / y_scale for x in xs],
                marker="o",
                ms=3,
                label=None if lv is None else f"{lv}",
            )
        ax.set_xlabel(f"{x_key} [{x_unit}]" if x_unit else x_key)
        ax.set_title(f"{name} [{y_unit}]" if y_unit else name, fontsize=9)
        if x_labels is not None:
            ax.set_xticks(x_pos, x_labels, rotation=30)
        else:
            ax.ticklabel_format(axis="x", useOffset=False, style="plain")
        # the power of ten is in the title: an offset text ("1e−5") above the axis would run into it
        ax.ticklabel_format(axis="y", useOffset=False, style="plain")
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
