"""Figures of fields and profiles a reviewer accepts: the 3-D plastic zone over the whole section up to the surface
(no white wedges), the wear map as a smooth field (no blocks, no facets), every line of ``indent``'s pressure
figure named in its legend.

Each figure function is called directly on small synthetic data (matplotlib Agg) and its artists inspected.
"""

import math
from types import SimpleNamespace

import numpy as np

from contact.theory import hertz_pressure
from wear.app.figures.indent import pressure_figure

# ------------------------------------------------------------------ indent: pressure.png


def _indentation(steps: int = 12):
    """A Hertzian loading and a shrinking unloading (SI units): what :func:`pressure_figure` reads."""
    e_star, radius = 100e9, 5e-3
    up = np.linspace(0.1, 1.0, steps) * 1e-6
    overlap = np.r_[up, up[-2::-1]]
    a = np.sqrt(radius * overlap)
    force = 4.0 / 3.0 * e_star * math.sqrt(radius) * overlap**1.5
    r = np.linspace(0.0, 1.5 * a.max(), 60)
    pressure = np.array([hertz_pressure(r, ak, 2.0 * e_star * ak / (math.pi * radius)) for ak in a])
    return SimpleNamespace(
        surface_r=r,
        pressure=pressure,
        contact_radius=a,
        overlap=overlap,
        force=force,
        effective_modulus=e_star,
        radius=radius,
        mean_pressure=force / (math.pi * a**2),
    )


def test_every_line_of_the_indent_pressure_figure_is_named_in_its_legend():
    """Each drawn line is named: its own legend entry, or its colour names its step (an FE entry of that colour)
    and its style names what it is (an entry of that style). The dotted lines (the FE contact radius, which had
    no entry) have one, and the title says what they are."""
    fig = pressure_figure(_indentation())
    fig.canvas.draw()
    for ax in fig.axes:
        legend = ax.get_legend()
        assert legend is not None
        pairs = zip(legend.legend_handles, legend.texts, strict=True)
        entries = [(h.get_color(), h.get_linestyle(), t.get_text()) for h, t in pairs]
        colours = {c for c, style, _ in entries if style == "-"}
        styles = {style for _, style, _ in entries}
        for line in ax.get_lines():
            own = (line.get_color(), line.get_linestyle(), line.get_label()) in entries
            assert own or (line.get_color() in colours and line.get_linestyle() in styles), (
                line.get_color(),
                line.get_linestyle(),
            )
    loading = fig.axes[0]
    dotted = [line for line in loading.get_lines() if line.get_linestyle() == ":"]
    assert len(dotted) >= 3
    labels = [t.get_text() for t in loading.get_legend().texts]
    assert any("contact radius" in label for label in labels)
    assert "dotted" in loading.get_title() and "contact radius" in loading.get_title()
