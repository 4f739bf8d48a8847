"""Figures a paper can use: a plastic zone drawn as a field with its boundary, a 3-D view whose relief is visible,
a legend that covers no data, sweep panels without round-off or offset labels, integer impact numbers, no text
over another or off the figure (every figure captured here is checked for that: tests/figure_capture.py).

Each figure function is called directly on small synthetic data (matplotlib Agg); the figure is taken before it
is saved (``save_figure`` replaced) so its artists can be inspected.
"""

import math
from types import SimpleNamespace

import meshio
import numpy as np
import pytest
from figure_capture import capture_figures
from matplotlib.contour import ContourSet
from matplotlib.ticker import MaxNLocator

import wear.app.figures.calibration as calibration_figures
import wear.app.figures.common as common_figures
import wear.app.figures.erosion as erosion_figures
import wear.app.figures.paper as paper_figures
import wear.app.figures.repeat as repeat_figures
import wear.app.figures.run as run_figures
import wear.app.figures.sweep as sweep_figures
from wear.app.figures.field import barycentric, child_of, project_to_nodes, split_in_four
from wear.app.figures.indent import plastic_zone_figure
from wear.app.outputs.render import default_exaggeration, exaggeration_for, round_ticks


@pytest.fixture
def captured(monkeypatch):
    """The figures the plotting functions would save (keyed by file name), instead of saving them."""
    return capture_figures(
        monkeypatch, erosion_figures, repeat_figures, sweep_figures, run_figures, calibration_figures, paper_figures
    )


# ------------------------------------------------------------------ plastic zone


def _grid_mesh(size: float, cells: int):
    """Right triangles on [0, size] × [−size, 0] (m): points (n, 2), triangles (m, 3)."""
    x = np.linspace(0.0, size, cells + 1)
    r, z = np.meshgrid(x, -x[::-1], indexing="ij")
    points = np.column_stack([r.ravel(), z.ravel()])
    idx = np.arange(points.shape[0]).reshape(cells + 1, cells + 1)
    a, b, c, d = idx[:-1, :-1].ravel(), idx[1:, :-1].ravel(), idx[1:, 1:].ravel(), idx[:-1, 1:].ravel()
    return points, np.vstack([np.column_stack([a, b, c]), np.column_stack([a, c, d])])


def _quadrature_points(points, triangles):
    """Three interior points per triangle (the degree-2 Gauss rule's barycentric positions)."""
    lam = np.array([[2 / 3, 1 / 6, 1 / 6], [1 / 6, 2 / 3, 1 / 6], [1 / 6, 1 / 6, 2 / 3]])
    xy = np.einsum("qi,eid->eqd", lam, points[triangles])
    return xy[..., 0], xy[..., 1]


def test_split_in_four_and_child_coordinates_reproduce_the_points():
    """Children tile the parent (areas ¼ each, one shared midpoint per edge), and a point's child coordinates
    rebuild the point from the child's vertices (the map used to place quadrature values on the fine mesh)."""
    points, triangles = _grid_mesh(1.0, 3)
    fine, children = split_in_four(points, triangles)
    edges = {tuple(sorted(e)) for t in triangles for e in ((t[0], t[1]), (t[1], t[2]), (t[0], t[2]))}
    assert fine.shape[0] == points.shape[0] + len(edges)

    def area(p, t):
        d1, d2 = p[t[:, 1]] - p[t[:, 0]], p[t[:, 2]] - p[t[:, 0]]
        return 0.5 * np.abs(d1[:, 0] * d2[:, 1] - d1[:, 1] * d2[:, 0])

    np.testing.assert_allclose(area(fine, children), np.repeat(area(points, triangles) / 4, 4))
    rng = np.random.default_rng(1)
    owner = rng.integers(0, triangles.shape[0], 200)
    w = rng.dirichlet([1.0, 1.0, 1.0], 200)
    xy = np.einsum("ki,kid->kd", w, points[triangles[owner]])
    lam = barycentric(points, triangles, owner, xy)
    np.testing.assert_allclose(lam, w, atol=1e-12)
    child, local = child_of(lam)
    assert local.min() > -1e-12 and np.allclose(local.sum(axis=1), 1.0)
    rebuilt = np.einsum("ki,kid->kd", local, fine[children[4 * owner + child]])
    np.testing.assert_allclose(rebuilt, xy, atol=1e-12)
    # a constant is projected exactly; the projection stays within the values' range
    values = rng.uniform(0.0, 1.0, 200)
    nodal = project_to_nodes(fine.shape[0], children, 4 * owner + child, local, values)
    assert nodal.min() >= 0.0 and nodal.max() <= 1.0
    ones = project_to_nodes(fine.shape[0], children, 4 * owner + child, local, np.ones(200))
    assert set(np.unique(ones)) <= {0.0, 1.0}


def test_plastic_zone_is_a_filled_field_with_the_boundary_as_a_line():
    """A plastic zone that is a disc of radius 40 µm round (0, −50 µm) (ᾱ decreasing to 0 at its rim, exactly 0
    outside) gives filled contours, a colour bar in %, µm axes at equal aspect, and a boundary line whose points
    all lie within one element (10 µm) of the 40 µm circle."""
    a = 50e-6
    points, triangles = _grid_mesh(2.5 * a, 12)
    qp_r, qp_z = _quadrature_points(points, triangles)
    dist = np.hypot(qp_r, qp_z + a)
    alpha = np.where(dist < 40e-6, 0.004 * (1.0 - dist / 40e-6), 0.0)
    disc = SimpleNamespace(mesh=SimpleNamespace(p=points.T, t=triangles.T), qp_r=qp_r, qp_z=qp_z)
    res = SimpleNamespace(
        run=SimpleNamespace(solver=SimpleNamespace(disc=disc), final=SimpleNamespace(alpha=alpha)),
        contact_radius=np.array([0.0, a, 0.8 * a]),
    )
    fig = plastic_zone_figure(res)
    ax, cax = fig.axes
    sets = [c for c in ax.collections if isinstance(c, ContourSet)]
    filled = [c for c in sets if c.filled]
    lines = [c for c in sets if not c.filled]
    assert len(filled) == 1 and len(lines) == 1
    assert filled[0].levels[0] == 0.0 and filled[0].levels[-1] >= 0.4  # ᾱ max 0.4 %
    boundary = np.vstack([p.vertices for p in lines[0].get_paths() if len(p.vertices)])
    radius_um = np.hypot(boundary[:, 0], boundary[:, 1] + 50.0)
    assert np.all(np.abs(radius_um - 40.0) < 10.0), (radius_um.min(), radius_um.max())
    assert "µm" in ax.get_xlabel() and "µm" in ax.get_ylabel()
    assert ax.get_aspect() == 1.0
    assert "%" in cax.get_ylabel() and "plastic strain" in cax.get_ylabel()
    assert ax.get_xlim() == pytest.approx((0.0, 125.0)) and ax.get_ylim() == pytest.approx((-125.0, 0.0))


# ------------------------------------------------------------------ 3-D surface exaggeration


@pytest.mark.parametrize(
    "relief, span",
    [(3.75e-6, 0.4e-3), (3.1e-6, 0.4e-3), (0.2e-6, 1e-3), (50e-9, 20e-6), (1.2e-6, 5e-3), (7e-6, 0.3e-3)],
)
def test_exaggeration_draws_the_relief_at_10_to_25_percent_of_the_span(relief, span):
    """The factor is on the 1-2-5 series and puts the drawn relief between 10 % and 25 % of the span: enough to
    see the dent, never a spike (checked on the ratio itself, not on the rule)."""
    factor = exaggeration_for(relief, span)
    mantissa = factor / 10 ** math.floor(math.log10(factor) + 1e-12)
    assert min(abs(mantissa - m) for m in (1.0, 2.0, 5.0)) < 1e-9
    assert 0.10 < factor * relief / span <= 0.25


def test_exaggeration_of_the_user_case_and_of_a_mesh():
    """3.75 µm of depth over 0.4 mm: ×20 (relief 18.75 % of the span; ×10 drew it at 9 %, which looked flat).
    A mesh's relief is peak-to-valley (0.25 µm pile-up counts) and its span the larger in-plane extent."""
    assert exaggeration_for(3.75e-6, 0.4e-3) == 20.0
    assert 20.0 * 3.75e-6 / 0.4e-3 == pytest.approx(0.1875)
    assert exaggeration_for(1e-3, 1e-3) == 1.0  # deep relief is drawn at true scale, not shrunk
    assert exaggeration_for(0.0, 1e-3) == 1.0
    x = np.linspace(-0.2e-3, 0.2e-3, 5)
    gx, gy = np.meshgrid(x, 0.5 * x, indexing="ij")
    z = np.where(np.hypot(gx, gy) < 1e-4, -3.75e-6, 0.25e-6)
    mesh = meshio.Mesh(np.column_stack([gx.ravel(), gy.ravel(), z.ravel()]), [("vertex", np.arange(25)[:, None])])
    factor = default_exaggeration(mesh)
    assert factor == exaggeration_for(4.0e-6, 0.4e-3) == 20.0


def test_colour_bar_ticks_are_round():
    """Labels at round values inside the data range (VTK alone labelled 3.75, 2.75, 1.76, 0.764, −0.232)."""
    np.testing.assert_allclose(round_ticks(-0.232, 3.75), [0.0, 1.0, 2.0, 3.0])
    ticks = round_ticks(0.0123, 0.0871)
    assert ticks[0] >= 0.0123 and ticks[-1] <= 0.0871 and 3 <= len(ticks) <= 6
    assert all(len(f"{t:.3g}".lstrip("-").replace("0.", "")) <= 3 for t in ticks)
    np.testing.assert_allclose(round_ticks(0.1, 0.9), [0.2, 0.4, 0.6, 0.8])
    assert round_ticks(-1.0, 1.0)[2] == 0.0  # exactly 0, not 1e-17 (which "%.3g" would print as such)


# ------------------------------------------------------------------ erosion


def test_erosion_rate_has_headroom_and_the_legend_covers_no_data(captured, tmp_path):
    """A steady rate (a flat line at the maximum) no longer sits on the frame: the y axis ends ≥ 1.1 × the
    largest value drawn, and the legend's box holds none of the drawn points."""
    t = np.linspace(0.0, 3000.0, 80)
    rate = np.full(80, 1.5e-7)
    interval = rate * (1.0 + 0.01 * np.sin(t))
    erosion_figures.plot_time_series(t, rate * t, rate, tmp_path / "erosion.png", "3.9 m/s", interval_rate=interval)
    fig = captured["erosion.png"]
    ax = fig.axes[1]
    assert ax.get_ylim()[1] >= 1.1 * interval[1:].max()
    fig.canvas.draw()
    box = ax.get_legend().get_window_extent()
    for line in ax.get_lines():
        xy = ax.transData.transform(np.column_stack(line.get_data()))
        inside = (xy[:, 0] > box.x0) & (xy[:, 0] < box.x1) & (xy[:, 1] > box.y0) & (xy[:, 1] < box.y1)
        assert not inside.any(), line.get_label()


# ------------------------------------------------------------------ sweep


def _sweep_rows():
    angles = [5.0, 25.0, 45.0, 65.0, 85.0]
    rows = []
    for k, angle in enumerate(angles):
        rows.append(
            {
                "status": "ok",
                "impact.angle": angle,
                "normal_work": (-1) ** k * 1e-14 * (1 + k),  # zero to round-off beside energies of mJ
                "energy_out": 1.9e-3 - 1e-5 * k,
                "energy_in": 1.99e-3,  # constant
                "incidence": angle,  # the swept input over again
                "result.impact.angle": angle,
                "contact_time": 1.28e-5 + 1e-7 * k * k,
            }
        )
    return {"impact.angle": angles}, rows


def test_sweep_panels_skip_round_off_constants_and_inputs():
    axes, rows = _sweep_rows()
    units = {"normal_work": "J", "energy_out": "J", "energy_in": "J", "contact_time": "s", "incidence": "deg"}
    results = ["normal_work", "energy_out", "energy_in", "incidence", "result.impact.angle", "contact_time"]
    assert sweep_figures.panel_results(axes, rows, results, units) == ["energy_out", "contact_time"]


def test_sweep_figure_puts_the_scale_in_the_title_not_an_offset(captured, tmp_path):
    """No "1e−5" offset text above a panel (it ran into the title): the SI prefix is in the title instead."""
    axes, rows = _sweep_rows()
    units = {"normal_work": "J", "energy_out": "J", "contact_time": "s", "impact.angle": "deg"}
    sweep_figures.plot_sweep(axes, rows, ["normal_work", "energy_out", "contact_time"], tmp_path, units=units)
    fig = captured["sweep_1d.png"]
    fig.canvas.draw()
    shown = [ax for ax in fig.axes if ax.get_visible()]
    assert [ax.get_title() for ax in shown] == ["energy_out [mJ]", "contact_time [µs]"]
    for ax in shown:
        assert ax.yaxis.get_offset_text().get_text() == ""
        assert 0.1 <= max(abs(v) for v in ax.get_lines()[0].get_ydata()) < 1000.0
    assert sweep_figures.scaled_unit([2e-6, 5e-6], "kg/kg") == (1e-6, "×1e-06 kg/kg")
    assert sweep_figures.scaled_unit([3.2e9], "Pa") == (1e9, "GPa")
    assert sweep_figures.scaled_unit([0.5, 3.0], "m/s") == (1.0, "m/s")


# ------------------------------------------------------------------ repeat


def test_repeat_axis_counts_whole_impacts_and_says_no_shakedown(captured, tmp_path):
    n = np.arange(1, 6)
    columns = {
        "impact_last": n,
        "computed": np.ones(5),
        "dent_depth_m": 1e-6 * np.sqrt(n),
        "pile_up_height_m": 2e-7 * np.sqrt(n),
        "surface_depth_m": 1.1e-6 * np.sqrt(n),
        "total_wear_max_depth_m": 1e-7 * n,
        "total_wear_volume_m3": 3e-15 * n,
        "normal_restitution": 0.8 + 0.04 * n,
        "tangential_restitution": np.full(5, np.nan),
        "plastic_work_per_impact_J": 1e-4 / n,
        "max_pressure_Pa": 2e9 + 1e7 * n,
        "plastic_strain_increment": 1e-2 / n,
    }
    repeat_figures.plot_repeat(columns, tmp_path / "repeat.png", title="5 impacts", tolerance=7.7e-6)
    fig = captured["repeat.png"]
    fig.canvas.draw()
    for ax in fig.axes[:4]:
        locator = ax.xaxis.get_major_locator()
        assert isinstance(locator, MaxNLocator)
        lo, hi = ax.get_xlim()
        ticks = [t for t in ax.get_xticks() if lo <= t <= hi]
        assert ticks and all(t == round(t) for t in ticks), ticks
    title = fig._suptitle.get_text()
    assert "no shakedown" in title and "None" not in title
    assert "shakedown at impact 3" in repeat_figures.shakedown_note(3, 7.7e-6)
    assert repeat_figures.shakedown_note(None) == ""


# ------------------------------------------------------------------ legends clear of the data


def _under_legends(fig) -> list[str]:
    """The labels of what a legend of ``fig`` covers: a drawn point or line vertex inside a legend's box, or a
    point of a drawn line between its vertices (sampled every ~1/200 of each segment: an ``axhline`` has only its
    two ends as vertices). Every axes drawn over the same area (a twin) counts; what lies outside the axes is
    clipped and does not."""
    fig.canvas.draw()
    covered, found = [], 0
    for host in fig.axes:
        legend = host.get_legend()
        if legend is None:
            continue
        found += 1
        box, frame = legend.get_window_extent(), host.get_window_extent()
        for ax in fig.axes:
            if not np.allclose(ax.get_window_extent().bounds, frame.bounds):
                continue
            drawn = [
                (line.get_label(), line.get_transform().transform(line.get_xydata()), line.get_linestyle())
                for line in ax.get_lines()
                if len(line.get_xydata())
            ]
            drawn += [
                (c.get_label(), c.get_offset_transform().transform(c.get_offsets()), "None")
                for c in ax.collections
                if hasattr(c, "get_offsets") and len(c.get_offsets())
            ]
            for label, xy, style in drawn:
                if style not in ("None", "none", "", " ") and len(xy) > 1:
                    t = np.linspace(0.0, 1.0, 200)[:, None, None]
                    xy = np.concatenate([xy, (xy[:-1] + t * (xy[1:] - xy[:-1])).reshape(-1, 2)])
                xy = xy[np.isfinite(xy).all(axis=1)]
                xy = xy[
                    (xy[:, 0] >= frame.x0) & (xy[:, 0] <= frame.x1) & (xy[:, 1] >= frame.y0) & (xy[:, 1] <= frame.y1)
                ]
                inside = (xy[:, 0] > box.x0) & (xy[:, 0] < box.x1) & (xy[:, 1] > box.y0) & (xy[:, 1] < box.y1)
                if inside.any():
                    covered.append(label)
    assert found, "no legend drawn"
    return covered


def _flat_topped(r, a, p0):
    """A plastic contact's pressure: flat at ``p0`` to 0.8 a, then falling to 0 at ``a`` (an FE-like profile
    that fills the top of the axes, where a legend used to go)."""
    return np.where(
        r < 0.8 * a, p0, np.where(r < a, p0 * np.sqrt(np.clip(1.0 - ((r - 0.8 * a) / (0.2 * a)) ** 2, 0, 1)), 0.0)
    )


def _run_result(three_d: bool):
    """A synthetic run result for the run figures: a plastic impact with flat-topped pressures along it and, on
    the 3-D plate, the axisymmetric dent it started from."""
    t = np.linspace(0.0, 10e-6, 41)
    a = 200e-6 * np.sin(np.pi * t / t[-1]) ** 0.5
    p0 = 2.0e9 * (0.6 + 0.4 * np.sin(np.pi * t / t[-1]))
    pressure = SimpleNamespace(
        time=t,
        extent=np.where(a > 0, a * 1.05, 0.0),
        source="fe",
        force=lambda: 0.9 * np.pi * a**2 * p0,
        at=lambda i, r: _flat_topped(r, a[i], p0[i]),
    )
    x = np.linspace(-400e-6, 400e-6, 81)
    y = np.linspace(-300e-6, 300e-6, 61)
    gx, gy = np.meshgrid(x, y, indexing="ij")
    rho = np.hypot(gx - 20e-6, gy)
    dent = 4e-6 * np.clip(1.0 - (rho / 200e-6) ** 2, 0.0, None)
    r_fe = np.linspace(0.0, 400e-6, 50)
    surface = SimpleNamespace(
        x=x, y=y, dent_centre=(20e-6, 0.0), dent_on_grid=lambda: dent, wear_depth=2e-9 * dent / 4e-6 * 4.0
    )
    return SimpleNamespace(
        pressure=pressure,
        impact=SimpleNamespace(history=SimpleNamespace(t=t, contact_radius=a)),
        case=SimpleNamespace(plate=SimpleNamespace(yield_strength=4e8)),
        regime="plastic",
        surface=surface,
        plate=SimpleNamespace(
            fields={"start_dent": (r_fe, 3.8e-6 * np.clip(1.0 - (r_fe / 200e-6) ** 2, 0.0, None))} if three_d else {}
        ),
    )


@pytest.mark.parametrize("three_d", [False, True])
def test_run_pressure_profiles_and_cross_sections_legends_cover_no_data(captured, tmp_path, three_d):
    """pressure_profiles.png: flat-topped FE profiles and their Hertz curves fill the top of the axes, where the
    legend sat over them; cross_sections.png (the 3-D plate, with the axisymmetric start dent): the legend sat on
    the dent's flanks. Now neither legend holds a drawn point or line."""
    result = _run_result(three_d)
    run_figures.pressure_profiles(result, tmp_path / "pressure_profiles.png")
    run_figures.cross_sections(result, tmp_path / "cross_sections.png")
    assert _under_legends(captured["pressure_profiles.png"]) == []
    assert _under_legends(captured["cross_sections.png"]) == []


def test_repeat_tolerance_line_runs_under_no_legend(captured, tmp_path):
    """The shakedown tolerance crosses the Δᾱ panel (Δᾱ falls from above it to below it) and the shakedown
    impact is a vertical line across every panel: no legend box holds either, nor any series."""
    n = np.arange(1, 9)
    columns = {
        "impact_last": n,
        "computed": np.ones(8),
        "dent_depth_m": 1e-6 * np.sqrt(n),
        "pile_up_height_m": 2e-7 * np.sqrt(n),
        "surface_depth_m": 1.1e-6 * np.sqrt(n),
        "total_wear_max_depth_m": 1e-7 * n,
        "total_wear_volume_m3": 3e-15 * n,
        "normal_restitution": 0.8 + 0.01 * n,
        "tangential_restitution": 0.5 + 0.02 * n,
        "plastic_work_per_impact_J": 1e-4 / n,
        "max_pressure_Pa": 2e9 + 1e7 * n,
        "plastic_strain_increment": 1e-3 / n**3,
    }
    repeat_figures.plot_repeat(columns, tmp_path / "repeat.png", "8 impacts", shakedown_impact=5, tolerance=2e-5)
    fig = captured["repeat.png"]
    assert _under_legends(fig) == []
    labels = [t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()]
    assert "shakedown tolerance" in labels and "plastic work of impact" in labels


def _calibration_result():
    speeds = np.repeat([20.0, 30.0, 40.0, 50.0, 60.0], 5)
    angles = np.tile([10.0, 30.0, 45.0, 60.0, 75.0], 5)
    predicted = 2e-9 * speeds**2.6 * np.cos(np.radians(angles)) ** 0.3
    measured = predicted * np.exp(0.3 * np.sin(7.0 * np.arange(25)))
    return SimpleNamespace(
        data=SimpleNamespace(angle=angles, speed=speeds, measured=measured, quantity="erosion_kg_per_kg"),
        predicted=predicted,
        fit=SimpleNamespace(names=("dnv_K",), values=(2e-9,), rms_log_error=0.2),
        case=SimpleNamespace(wear=SimpleNamespace(law="dnv")),
    )


def test_calibration_speed_panel_is_labelled_in_plain_numbers(captured, tmp_path):
    """The right panel (against the speed, 20–60 m/s on a log axis) has its y label, and its speed ticks read
    20, 30, 40, 50, 60 (not 2×10¹ … 6×10¹); neither legend covers a point or a line."""
    calibration_figures.plot_calibration(_calibration_result(), tmp_path / "calibration.png")
    fig = captured["calibration.png"]
    fig.canvas.draw()
    left, right = fig.axes[:2]
    assert right.get_ylabel() == left.get_ylabel() == "erosion ratio (kg/kg)"
    lo, hi = right.get_xlim()
    shown = [t for t in right.xaxis.get_majorticklabels() if lo <= t.get_position()[0] <= hi and t.get_text()]
    assert [t.get_text() for t in shown] == ["20", "30", "40", "50", "60"]
    assert all(t.get_text() == "" for t in right.xaxis.get_minorticklabels())
    assert _under_legends(fig) == []


def test_pressure_regimes_legends_cover_no_data(captured, tmp_path):
    """As the FE gives them: loading profiles near p_mean out to r ≈ a under Hertz curves peaking at 1.5-4.5 p_mean
    near the axis, and unloading profiles that zigzag up to 1.3 p* (coarse elements) under Eq. 19's flat p* with
    its drop at a* (a near-vertical line): no legend box holds a drawn point or line (the unloading legend sat on
    the drop and the zigzag)."""
    r = np.linspace(0.0, 1.3, 53)

    def cap(a):
        return np.sqrt(np.clip(1.0 - (r / a) ** 2, 0.0, None))

    loading = [
        dict(label=f"w = {w:g}", r=r, p=np.where(r < 1.05, 1.0 + 0.1 * k, 0.0), ref_r=r, ref_p=1.5 / a**2 * cap(a))
        for k, (w, a) in enumerate(((0.5, 1.0), (1, 0.93), (3, 0.9), (6, 0.76), (20, 0.58), (100, 0.58)))
    ]
    for s in loading:
        s.update(scale_r=1.0, scale_p=1.0)
    unloading = []
    for k, (a, level) in enumerate(((1.0, 1.0), (0.78, 0.55), (0.6, 0.35))):
        zigzag = level * (1.0 + 0.15 * np.abs(np.sin(23.0 * r)) * (r > 0.5))
        # Eq. 19: flat at p* for the start of unloading (a* itself), a cap below it
        flat = level * (np.where(r < a, 1.0, 0.0) if k == 0 else cap(a))
        unloading.append(
            dict(
                label=f"a/a* = {a:g}",
                r=r,
                p=np.where(r < a, zigzag, 0.0),
                ref_r=r,
                ref_p=flat,
                scale_r=1.0,
                scale_p=1.0,
            )
        )
    paper_figures.plot_pressure_regimes(loading, unloading, tmp_path / "fig.png", "synthetic")
    assert _under_legends(captured["fig.png"]) == []
    # the zigzag is named: the solid curves are the FE's pressure at the surface nodes
    for ax in captured["fig.png"].axes[:2]:
        assert "FE, surface nodes" in [t.get_text() for t in ax.get_legend().get_texts()]


# ------------------------------------------------------------------ reproduce --quick: no blank map


@pytest.mark.parametrize("yields", [(1.6e9,), (5e8, 1.6e9)])
def test_regime_map_draws_every_cell_even_in_one_row(captured, tmp_path, yields):
    """Quick mode's map had one row of cells (one yield strength) and two of its three panels came out blank:
    every cell is now drawn with an area on the page, its speed and yield strength inside it, the ticks at the
    cells read as plain numbers, and each restitution note lies inside its panel."""
    speeds = np.array([0.3, 3.0])
    shape = (len(yields), 2)
    regime = np.tile([0.0, 2.0], (shape[0], 1))
    e_fe = np.tile([0.99, 0.9], (shape[0], 1))
    paper_figures.plot_regime_map(
        speeds, np.array(yields), regime, np.full(shape, 1.3), e_fe, e_fe / 1.02, tmp_path / "map.png", "synthetic"
    )
    fig = captured["map.png"]
    fig.canvas.draw()
    maps = [ax for ax in fig.axes if ax.collections and ax.get_xlabel()]
    assert len(maps) == 3
    for ax in maps:
        mesh = ax.collections[0]
        assert np.ma.count(mesh.get_array()) == 2 * len(yields)
        frame = ax.get_window_extent()
        cells = [p.get_extents(mesh.get_transform()) for p in mesh.get_paths()]
        assert all(c.width * c.height > 0.05 * frame.width * frame.height for c in cells)
        for v in speeds:
            for y in yields:
                inside = [c for c in cells if c.contains(*ax.transData.transform((v, y / 1e6)))]
                assert len(inside) == 1
        lo, hi = ax.get_xlim()
        assert [t.get_text() for t in ax.xaxis.get_majorticklabels() if lo <= t.get_position()[0] <= hi] == ["0.3", "3"]
        lo, hi = ax.get_ylim()
        shown = [t.get_text() for t in ax.yaxis.get_majorticklabels() if lo <= t.get_position()[1] <= hi]
        assert shown == [f"{y / 1e6:g}" for y in yields]
    for text in maps[2].texts:
        assert maps[2].get_window_extent().contains(*text.get_window_extent().get_points().mean(axis=0))


def test_quick_reproduction_sizes_draw_trends():
    """What quick mode computes: a two-by-two regime map, two restitution ratios, and Fig. 9's FE panel skipped
    (no FE run) with the reason, not one point."""
    from wear.app.reproduce.coupled import QUICK_RESTITUTION_RATIOS, default_case_wear, regime_grid

    speeds, yields = regime_grid(True)
    assert len(set(speeds)) >= 2 and len(set(yields)) >= 2
    assert len(set(QUICK_RESTITUTION_RATIOS)) >= 2
    skipped = default_case_wear(True)
    assert skipped["angles"].size == 0 and "skipped in quick mode" in skipped["skipped"]


# ------------------------------------------------------------------ texts that overlap


def test_overlapping_texts_finds_colliding_and_clipped_texts(tmp_path):
    """A figure made to fail: crowded tick labels, two texts on one another, a legend over a text, a text run off
    the right edge; each is found, and ``save_figure`` warns of them (and writes the figure). A plain figure
    passes."""
    fig, ax = common_figures.subplots(figsize=(4.0, 3.0))
    ax.plot([0.0, 1.0], [0.0, 1.0], label="a line")
    ax.set_xticks([0.0, 0.01, 0.5], ["0.000", "0.010", "0.5"])
    ax.text(0.3, 0.5, "one label here", transform=ax.transAxes)
    ax.text(0.32, 0.51, "another label", transform=ax.transAxes)
    ax.text(0.8, 0.9, "under the legend", transform=ax.transAxes, ha="center", va="center")
    ax.legend(loc="upper right")
    fig.text(0.9, 0.5, "runs off the edge")
    found = common_figures.overlapping_texts(fig)
    assert any("'0.000' overlaps" in f and "'0.010'" in f for f in found), found
    assert any("'one label here' overlaps" in f and "'another label'" in f for f in found), found
    assert any("'under the legend'" in f and "legend 'a line'" in f for f in found), found
    assert any("'runs off the edge' runs off the figure's right edge" in f for f in found), found
    assert not any("'0.5'" in f for f in found), found
    with pytest.warns(common_figures.FigureTextWarning, match="bad.png: .*'0.000' overlaps"):
        common_figures.save_figure(fig, tmp_path / "bad.png")
    assert (tmp_path / "bad.png").is_file()
    fig, ax = common_figures.subplots(figsize=(4.0, 3.0), layout="constrained")
    ax.plot([0.0, 1.0], [0.0, 1.0], label="a line")
    ax.set(title="title", xlabel="x (m)", ylabel="y (m)")
    ax.legend(loc="lower right")
    assert common_figures.overlapping_texts(fig) == []


def test_full_regime_map_reads(captured, tmp_path):
    """The full reproduction's map, 4 speeds by 3 yield strengths (12 coupled runs; 6 before): every speed and
    yield strength a plain tick label, no text over another (checked on capture)."""
    from wear.app.reproduce.coupled import regime_grid

    speeds, yields = regime_grid(False)
    assert speeds.size * yields.size == 12
    regime = np.add.outer(np.arange(yields.size)[::-1], np.arange(speeds.size)).clip(0, 3).astype(float)
    e_fe = 1.0 - 0.05 * regime
    paper_figures.plot_regime_map(
        speeds, yields, regime, 1.5 - 0.1 * regime, e_fe, e_fe / 1.1, tmp_path / "map.png", "synthetic " * 20
    )
    fig = captured["map.png"]
    for ax in [ax for ax in fig.axes if ax.collections and ax.get_xlabel()]:
        lo, hi = ax.get_xlim()
        assert [t.get_text() for t in ax.xaxis.get_majorticklabels() if lo <= t.get_position()[0] <= hi] == [
            "0.3",
            "0.6",
            "1.5",
            "3",
        ]


def test_restitution_ticks_are_plain_numbers(captured, tmp_path):
    """Both panels' V/V_y axes read as plain numbers (1, 2, 5, 10… and the ratios computed), not 10⁰ or 2×10⁰."""
    ratios = np.array([1.5, 2.0, 5.0, 15.0])
    curve = np.geomspace(1.0, 100.0, 50)
    paper_figures.plot_restitution(
        ratios, np.array([0.99, 0.97, 0.9, 0.78]), curve, np.linspace(1.0, 0.37, 50), tmp_path / "r.png", "s"
    )
    fig = captured["r.png"]
    fig.canvas.draw()
    for ax in fig.axes[:2]:
        lo, hi = ax.get_xlim()
        shown = [t.get_text() for t in ax.xaxis.get_majorticklabels() if lo <= t.get_position()[0] <= hi]
        assert shown and all(t.replace(".", "").isdigit() for t in shown), shown
    assert "1.5" in [t.get_text() for t in fig.axes[1].xaxis.get_majorticklabels()]


def test_wear_mass_maximum_says_the_angle_spacing(captured, tmp_path):
    """The marked maximum is the largest of the angles computed: its label gives their spacing (20° for the
    default run case, whose maximum is no finer than that)."""
    series = [
        dict(label="coarse", angles=np.array([15.0, 35.0, 55.0, 75.0]), mass=np.array([1.0, 2.0, 3.0, 2.0])),
        dict(label="fine", angles=np.arange(0.0, 86.0, 5.0), mass=np.sin(np.radians(np.arange(0.0, 86.0, 5.0)) * 2)),
    ]
    paper_figures.plot_wear_mass(series, tmp_path / "w.png", "s")
    labels = [t.get_text() for ax in captured["w.png"].axes for t in ax.get_legend().get_texts()]
    assert labels == ["largest at 55°\n(of angles 20° apart)", "largest at 45°\n(of angles 5° apart)"]


def test_wear_laws_legend_is_in_the_panels_type_size(captured, tmp_path):
    """Eleven curves (as the full reproduction draws) in one legend below the panels, in 9-pt type (it was 7 pt),
    none of its entries over a tick label, an axis label or the source line (checked on capture)."""
    theta = np.arange(0.0, 89.01, 1.0)
    speeds = np.geomspace(10.0, 150.0, 25)
    curves = [
        dict(
            label=f"law {k}: as long as the longest label {'x' * 20}",  # 52 characters
            reference=k >= 9,
            angles=90.0 - theta,
            rate=1e-4 * (1.0 + 0.1 * k) * np.sin(np.radians(2.0 * np.clip(90.0 - theta, 1.0, 89.0))),
            speeds=speeds,
            rate_vs_speed=1e-8 * speeds ** (2.0 + 0.1 * k),
        )
        for k in range(11)
    ]
    paper_figures.plot_wear_laws(curves, [30.0, 60.0], [1e-4, 9e-5], (30.0, 50.0, 60.0), tmp_path / "l.png", "s" * 200)
    fig = captured["l.png"]
    (legend,) = fig.legends
    assert len(legend.get_texts()) == 12 and all(t.get_fontsize() >= 9 for t in legend.get_texts())


@pytest.mark.parametrize("ratios", [[1.6, 1.7, 1.8, 2.0], [0.5, 3.0, 30.0], [1.2, 1.5, 60.0, 400.0]])
def test_restitution_comparison_labels_its_speed_ratios_apart(captured, tmp_path, ratios):
    # the coupled impacts of a validation run may span less than a decade of V/V_y, where matplotlib labels every
    # minor tick of a log axis (1.6×10⁰, 1.7×10⁰, ... on top of each other); the capture fails on any overlap
    x = np.array(ratios)
    run_figures.restitution_comparison(x, np.full(x.size, 0.9), tmp_path / "e_vs_vy.png")
    labels = [t.get_text() for t in captured["e_vs_vy.png"].axes[1].get_xticklabels() if t.get_text()]
    assert labels and all("times" not in label for label in labels), labels
