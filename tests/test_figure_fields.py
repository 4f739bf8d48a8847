"""Figures of fields and profiles a reviewer accepts: the 3-D plastic zone over the whole section up to the surface
(no white wedges), the wear map as a smooth field (no blocks, no facets), every line of ``indent``'s pressure
figure named in its legend.

Each figure function is called directly on small synthetic data (matplotlib Agg) and its artists inspected.
"""

import math
from types import SimpleNamespace

import numpy as np
import pytest
from figure_capture import capture_figures
from matplotlib.collections import QuadMesh
from matplotlib.contour import ContourSet

import wear.app.figures.run as run_figures
from contact.theory import hertz_pressure
from wear.app.figures.field import cell_field_on_nodes, refine_grid
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


# ------------------------------------------------------------------ run (3-D plate): plastic_zone.png


@pytest.fixture
def captured(monkeypatch):
    """The figures the run's plotting functions would save (keyed by file name), instead of saving them."""
    return capture_figures(monkeypatch, run_figures)


def _section(half_width: float, depth: float, cells: int, seed: int = 3):
    """An unstructured-looking triangulation of [−w, w] × [−depth, 0] (m): a grid of right triangles whose inner
    vertices are jittered by up to a quarter cell (boundary vertices stay on the rectangle's edges)."""
    x = np.linspace(-half_width, half_width, 2 * cells + 1)
    z = np.linspace(-depth, 0.0, cells + 1)
    gx, gz = np.meshgrid(x, z, indexing="ij")
    inner = (np.abs(gx) < half_width) & (gz > -depth) & (gz < 0.0)
    jitter = np.random.default_rng(seed).uniform(-0.25, 0.25, (2,) + gx.shape) * (x[1] - x[0])
    points = np.column_stack([(gx + inner * jitter[0]).ravel(), (gz + inner * jitter[1]).ravel()])
    idx = np.arange(points.shape[0]).reshape(gx.shape)
    a, b, c, d = idx[:-1, :-1].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()
    return points, np.vstack([np.column_stack([a, b, c]), np.column_stack([a, c, d])])


def test_cell_values_on_nodes_are_the_area_weighted_mean():
    """Two triangles of areas 1 and 3 m² sharing an edge, values 0 and 4: the shared vertices get
    (1·0 + 3·4)/4 = 3, the others their own triangle's value; a constant is kept exactly."""
    points = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 2.0], [3.0, 2.0]])  # areas 1 (0 1 2) and 3 (1 3 2)
    triangles = np.array([[0, 1, 2], [1, 3, 2]])
    np.testing.assert_allclose(cell_field_on_nodes(points, triangles, np.array([0.0, 4.0])), [0.0, 3.0, 3.0, 4.0])
    points, triangles = _section(1.0, 1.0, 6)
    np.testing.assert_allclose(cell_field_on_nodes(points, triangles, np.full(len(triangles), 0.7)), 0.7)


def test_plastic_zone_fills_the_whole_section_up_to_the_surface(captured, tmp_path):
    """The largest strain sits at the surface under the dent (as on the 3-D plate); the figure shows the section
    from the surface z = 0 down to 3a and ±3a about the dent centre with no white inside the axes (the old one
    triangulated element centroids: white wedges at the corners where their hull did not reach, and nothing in
    the top layer of elements), and its highest filled level reaches the surface."""
    a = 100e-6
    points, triangles = _section(6 * a, 5 * a, 24)
    centroid = points[triangles].mean(axis=1)
    strain = 0.03 * np.clip(1.0 - np.hypot(centroid[:, 0] - 0.5 * a, centroid[:, 1]) / (1.5 * a), 0.0, None)
    plate = SimpleNamespace(fields={"plastic_section": (points, triangles, strain, a)})
    result = SimpleNamespace(
        plate=plate,
        surface=SimpleNamespace(dent_centre=(0.5 * a, 0.0)),
        case=SimpleNamespace(impact=SimpleNamespace(friction=0.3)),
    )
    run_figures.plastic_zone(result, tmp_path / "plastic_zone.png")
    fig = captured["plastic_zone.png"]
    ax = fig.axes[0]
    assert ax.get_ylim() == pytest.approx((-300.0, 0.0)) and ax.get_xlim() == pytest.approx((-250.0, 350.0))
    fig.canvas.draw()
    pixels = np.asarray(fig.canvas.buffer_rgba())[..., :3].astype(int)
    height = pixels.shape[0]
    box, legend = ax.get_window_extent(), ax.get_legend().get_window_extent()
    rows, cols = np.mgrid[0:height, 0 : pixels.shape[1]]
    px, py = cols + 0.5, height - rows - 0.5  # pixel centres in display coordinates (origin at the bottom)
    inside = (px > box.x0 + 2) & (px < box.x1 - 2) & (py > box.y0 + 2) & (py < box.y1 - 2)
    inside &= ~((px > legend.x0) & (px < legend.x1) & (py > legend.y0) & (py < legend.y1))
    white = inside & (pixels.min(axis=2) >= 250)
    assert inside.sum() > 10_000 and white.sum() == 0, white.sum()
    filled = next(c for c in ax.collections if isinstance(c, ContourSet) and c.filled)
    highest = [p for p in filled.get_paths() if len(p.vertices)][-1]  # the highest level band drawn
    assert highest.vertices[:, 1].max() == pytest.approx(0.0, abs=1e-9)
    fig.savefig(tmp_path / "look.png")


# ------------------------------------------------------------------ run: wear_map.png


def _bump(x, y):
    """A smooth wear scar (m): a Gaussian of 50 nm depth and 60 µm width, offset along x."""
    gx, gy = np.meshgrid(x, y)
    return 50e-9 * np.exp(-(((gx - 20e-6) / 60e-6) ** 2 + (gy / 60e-6) ** 2))


def test_refine_grid_keeps_the_grid_values_and_follows_a_smooth_field():
    """The bicubic resampling passes through the grid values, stays within their range, and between the grid
    points follows the Gaussian it was sampled from to 1 % of its depth (piecewise-constant cells, what the
    blocky map showed, are off by more than 15 % of it on this grid)."""
    x = np.linspace(-200e-6, 200e-6, 21)
    y = np.linspace(-140e-6, 140e-6, 15)
    depth = _bump(x, y)
    fx, fy, fine = refine_grid(x, y, depth)
    assert fx.size == 81 and fy.size == 57
    np.testing.assert_allclose(fine[::4, ::4], depth, atol=1e-12 * depth.max())
    assert fine.min() >= depth.min() and fine.max() <= depth.max()
    exact = _bump(fx, fy)
    assert np.abs(fine - exact).max() < 0.01 * depth.max()
    nearest = depth[np.ix_(np.round(np.arange(fy.size) / 4).astype(int), np.round(np.arange(fx.size) / 4).astype(int))]
    assert np.abs(nearest - exact).max() > 0.15 * depth.max()


def test_wear_map_is_a_smooth_filled_field_not_cells(captured, tmp_path):
    """Filled contours of ≥ 20 bands from 0 to the largest depth, no grid cells (the blocky map was a
    pcolormesh of the wear grid); the title still gives the worn volume and the largest depth."""
    x = np.linspace(-200e-6, 200e-6, 21)
    y = np.linspace(-140e-6, 140e-6, 15)
    depth = _bump(x, y)
    wm = SimpleNamespace(x=x, y=y, depth=depth, volume_m3=3.9e-15, max_depth_m=float(depth.max()))
    run_figures.wear_map(SimpleNamespace(wear=wm), tmp_path / "wear_map.png")
    ax = captured["wear_map.png"].axes[0]
    assert not any(isinstance(c, QuadMesh) for c in ax.collections)
    filled = [c for c in ax.collections if isinstance(c, ContourSet) and c.filled]
    assert len(filled) == 1 and len(filled[0].levels) >= 21
    assert filled[0].levels[0] == 0.0 and filled[0].levels[-1] == pytest.approx(depth.max() * 1e9)
    assert "3.9e-15 m³" in ax.get_title() and "50 nm" in ax.get_title()
