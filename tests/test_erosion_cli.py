"""``impactwear erode``: outputs (CSV, .vtu/.pvd readable by meshio, figures), --angles, and one-line errors."""

import csv
import json
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest

from wear.app.cli import main

# the embedded default case (alumina R 2.5 mm on glass, 3.9 m/s, 30°) on a small grid and a coarse table
SMALL = [
    "--set",
    "erosion.grid=128",
    "--set",
    "erosion.angle_step=10.0",
    "--set",
    "erosion.table_speeds=2",
    "--set",
    "erosion.points_per_length=6",
    "--set",
    "erosion.frames=2",
    "--set",
    "erosion.samples=5",
    "--set",
    "erosion.exposure_time=600.0",
]


def _rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def test_erode_writes_series_surface_and_table(tmp_path, capsys):
    out = tmp_path / "run"
    assert main(["erode", "--out", str(out), "--quiet", *SMALL]) == 0
    assert capsys.readouterr().out == ""
    rows = _rows(out / "erosion.csv")
    assert len(rows) == 6
    assert list(rows[0]) == [
        "time_s",
        "impacts",
        "particle_mass_kg",
        "mass_loss_kg",
        "mass_loss_per_area_kg_m2",
        "erosion_rate_kg_per_kg",
        "interval_erosion_rate_kg_per_kg",
        "max_depth_m",
        "rms_slope",
    ]
    mass = np.array([float(r["mass_loss_kg"]) for r in rows])
    assert mass[0] == 0.0 and np.all(np.diff(mass) > 0)
    assert float(rows[-1]["time_s"]) == pytest.approx(600.0)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["results"]["impacts"] == int(rows[-1]["impacts"])
    assert summary["results"]["mass_loss_kg"] == pytest.approx(mass[-1])
    assert "normal speeds" in summary["table"]["resolution"]
    table = _rows(out / "response_table.csv")
    assert len(table) == 2 * 5 and float(table[-1]["volume_m3"]) > 0
    # the final surface: a 128 x 128 structured quad grid with point data total_depth_m, z = -depth
    mesh = meshio.read(out / "surface.vtu")
    assert mesh.points.shape == (128 * 128, 3) and mesh.cells[0].type == "quad"
    depth = mesh.point_data["total_depth_m"]
    np.testing.assert_allclose(mesh.points[:, 2], -depth)
    h = float(summary["patch"]["spacing_m"])
    assert depth.sum() * h * h * 2500.0 == pytest.approx(mass[-1], rel=1e-9)
    # the .pvd series lists the initial flat surface and every frame, with increasing times
    sets = ET.parse(out / "erosion.pvd").getroot().find("Collection").findall("DataSet")
    assert len(sets) == 3
    times = [float(s.get("timestep")) for s in sets]
    assert times == sorted(times) and times[-1] == pytest.approx(600.0)
    for s in sets:
        assert (out / s.get("file")).is_file()
    np.testing.assert_allclose(meshio.read(out / sets[-1].get("file")).point_data["total_depth_m"], depth)
    for name in ("erosion.png", "surface.png"):
        assert (out / name).stat().st_size > 1000
    assert [p.name for p in out.glob(".*")] == [".impactwear.json"], "temporary files left behind"


def test_erode_angles_writes_erosion_vs_angle(tmp_path):
    out = tmp_path / "angles"
    assert main(["erode", "--out", str(out), "--quiet", "--angles", "0,45", *SMALL]) == 0
    rows = _rows(out / "erosion_vs_angle.csv")
    assert list(rows[0]) == ["angle_deg", "erosion_rate_kg_per_kg", "mass_loss_kg"]
    assert [float(r["angle_deg"]) for r in rows] == [0.0, 45.0]
    # Eq. 15 without Bitter's term: nothing at normal incidence (no sliding), wear at 45°
    assert float(rows[0]["erosion_rate_kg_per_kg"]) == 0.0
    assert float(rows[1]["erosion_rate_kg_per_kg"]) > 0.0
    # one patch for every angle
    sizes = {json.loads((out / f"angle_{a}" / "summary.json").read_text())["patch"]["size_m"] for a in ("0", "45")}
    assert len(sizes) == 1
    assert (out / "erosion_vs_angle.png").stat().st_size > 1000


@pytest.mark.parametrize(
    "extra, message",
    [
        (["--set", "erosion.concentration=3000.0"], "concentration=3000 is out of range"),
        (["--set", "erosion.patch_size=0.004"], "patch_size=0.004 is out of range"),
        (["--set", "wear.K=-1.0"], "wear.K=-1 is out of range"),
        (["--angles", "0,95"], "angle=95 is out of range"),
        (["--set", "wear.law='combined'"], "wear.deformation_factor=None"),
    ],
)
def test_erode_bad_input_is_one_line(tmp_path, capsys, extra, message):
    assert main(["erode", "--out", str(tmp_path / "x"), "--quiet", *SMALL, *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and message in err, err
