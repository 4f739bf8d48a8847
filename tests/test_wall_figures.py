"""The wall's figures show what they say: each face coloured by its own rate on a log scale of three decades below
the largest, the faces without wear in a light grey a legend names "no wear", equal axes the wall fills, seen from
a side that shows the hot spot, marked at its face's centre with its rate labelled off the drawn wall (black on
white) and an arrow to it, the units on the colour bar and the axes; the histograms hold every particle in the bins
given and say they count particles, per bin of which width."""

from __future__ import annotations

import meshio
import numpy as np
import pytest
from figure_capture import capture_figures
from matplotlib.text import Text
from mpl_toolkits.mplot3d.art3d import Poly3DCollection
from wall_cases import flat_mesh

import wear.app.figures.wall as wall_figures
from wear.app.data import OPENFOAM_BEND
from wear.wall import read_surface, read_wall


@pytest.fixture
def captured(monkeypatch):
    return capture_figures(monkeypatch, wall_figures)


def test_the_wall_is_coloured_face_by_face_with_the_hot_spot_marked(captured, tmp_path):
    meshio.write(tmp_path / "plate.stl", flat_mesh())
    wall = read_surface(tmp_path / "plate.stl")
    rate = np.zeros(len(wall))
    rate[[3, 7, 11]] = [40.0, 10.0, 80.0]
    wall_figures.plot_wall_rate(wall, rate, 11, tmp_path / "wall.png", "test")
    fig = captured["wall.png"]
    ax = fig.axes[0]
    faces = next(c for c in ax.collections if isinstance(c, Poly3DCollection))
    colours = faces.get_facecolor()
    _, owner = wall.triangles
    # matplotlib sorts a 3-D collection's faces by depth: compare the colours drawn as a set
    grey = np.all(np.isclose(colours[:, :3], wall_figures.UNWORN[:3]), axis=1)
    assert grey.sum() == (rate[owner] == 0.0).sum()  # grey exactly as many as the faces nothing wore
    bar = fig.axes[1]
    assert "mm/year" in bar.get_ylabel() and "log" in bar.get_ylabel()
    assert bar.get_ylim() == pytest.approx((0.08, 80.0))  # three decades up to the largest rate
    cmap = wall_figures.colormaps["viridis"]
    worn = {tuple(np.round(c, 6)) for c in colours[~grey]}
    assert worn == {tuple(np.round(cmap(np.log10(r / 0.08) / 3.0), 6)) for r in (40.0, 10.0, 80.0)}
    label = next(t for t in ax.texts if "hot spot" in t.get_text())
    assert "80 mm/year" in label.get_text() and label.anncoords == "axes fraction"
    _assert_label_off_the_wall(fig, ax, label, wall, 11)
    (unworn,) = [h for legend in fig.legends for h in legend.legend_handles]
    assert "no wear" in unworn.get_label() and np.allclose(unworn.get_facecolor(), wall_figures.UNWORN)
    marker = ax.collections[-1]._offsets3d
    assert np.allclose([m[0] for m in marker], wall.centre[11])
    # equal axes: each axis' box length in proportion to its range (the 4 cm x 3 cm plate, flat: 5% of 4 cm)
    ranges = np.array([np.ptp(ax.get_xlim()), np.ptp(ax.get_ylim()), np.ptp(ax.get_zlim())])
    assert ranges == pytest.approx([0.04, 0.03, 0.002], rel=1e-9)
    box = np.array(ax.get_box_aspect())
    assert box / box[0] == pytest.approx(ranges / ranges[0], rel=1e-9)
    assert all(u in ax.get_xlabel() + ax.get_ylabel() + ax.get_zlabel() for u in ("x (m)", "y (m)", "z (m)"))


def test_the_histograms_hold_every_particle(captured, tmp_path):
    speed_edges = np.geomspace(0.01, 1000.0, 51)
    speed = np.zeros(50)
    speed[[20, 25, 26]] = [5.0, 10.0, 2.5]
    angle_edges = np.arange(0.0, 91.0, 10.0)
    angle = np.array([0, 1, 2, 3, 4, 5, 2.5, 0, 0], float)
    wall_figures.plot_impact_histograms(speed_edges, speed, angle_edges, angle, tmp_path / "impacts.png", "t")
    ax1, ax2 = captured["impacts.png"].axes
    drawn = [p for p in ax1.patches]
    assert drawn and "m/s" in ax1.get_xlabel() and ax1.get_xscale() == "log"
    heights = drawn[0].get_path().vertices[:, 1]
    assert heights.max() == 10.0
    assert "deg" in ax2.get_xlabel() and ax2.get_xlim() == (0.0, 90.0)
    assert ax2.patches[0].get_path().vertices[:, 1].max() == 5.0
    assert ax1.get_ylabel() == "particles per speed bin (10 per decade)"  # 50 bins over 5 decades
    assert ax2.get_ylabel() == "particles per angle bin (10 deg)"
    uneven = np.array([0.0, 30.0, 60.0, 75.0, 90.0])
    wall_figures.plot_impact_histograms(speed_edges, speed, uneven, angle[:4], tmp_path / "uneven.png", "t")
    assert captured["uneven.png"].axes[1].get_ylabel() == "particles per angle bin"  # no single width to name


def _assert_label_off_the_wall(fig, ax, label, wall, face) -> None:
    """The hot-spot label's text box, as drawn, lies outside the convex hull of the drawn wall, in black on white,
    and its arrow ends on the face's centre as drawn."""
    fig.canvas.draw()
    outline = wall_figures._drawn_outline(ax, wall.points)
    box = Text.get_window_extent(label, fig.canvas.get_renderer())
    assert not outline.intersects_bbox(box), (box, outline.get_extents())
    assert label.get_color() == "black" and label.get_bbox_patch().get_facecolor()[:3] == (1.0, 1.0, 1.0)
    end = ax.transData.transform(label.xy)
    assert end == pytest.approx(wall_figures._display(ax, wall.centre[face : face + 1])[0], abs=0.5)


def test_the_bend_fills_its_equal_axes_and_shows_its_hot_spot(captured, tmp_path):
    """The shipped pipe bend (its hot spot on the outer wall at the bend's top): the axes' box has the wall's
    extents (equal axes, within 1%), the drawn wall spans most of the axes (it spanned about a sixth of the box
    when matplotlib's margins were kept), the view sees the hot face from its outer side unhidden, and the label
    lies off the drawn wall."""
    wall = read_wall(OPENFOAM_BEND)
    rate = np.zeros(len(wall))
    hot = int(np.argmax(wall.centre[:, 2] - np.abs(wall.centre[:, 1])))  # a face on the bend's top
    rate[::7] = 3.0
    rate[hot] = 200.0
    wall_figures.plot_wall_rate(wall, rate, hot, tmp_path / "wall.png", "bend")
    fig = captured["wall.png"]
    ax = fig.axes[0]
    extents = np.ptp(wall.points, axis=0)
    box = np.array(ax.get_box_aspect())
    assert box / box.max() == pytest.approx(extents / extents.max(), rel=0.01)
    fig.canvas.draw()
    drawn = wall_figures._drawn_outline(ax, wall.points).get_extents()
    assert max(drawn.width / ax.bbox.width, drawn.height / ax.bbox.height) > 0.7
    assert ax.bbox.x0 >= 0 and ax.bbox.y0 >= 0  # the zoomed box stays in the figure
    eye = wall_figures._eye(ax.elev, ax.azim)
    assert wall.normal[hot] @ eye > 0.5  # the outer side, within 60° of face-on
    tri, owner = wall.triangles
    assert not wall_figures._hidden(wall.centre[hot], eye, wall.points[tri[owner != hot]])
    assert wall_figures._hidden(wall.centre[hot], -eye, wall.points[tri[owner != hot]])  # seen from behind: hidden
    label = next(t for t in ax.texts if "hot spot" in t.get_text())
    _assert_label_off_the_wall(fig, ax, label, wall, hot)
