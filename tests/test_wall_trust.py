"""``impactwear wall`` on inputs as users have them: records and a wall in other units, duplicate faces, empty
records, NaN points and thicknesses, a tiny exposure, grazing hits, a subset of an OpenFOAM run's patches and a
forged output manifest. Each is refused in one line (exit 2, nothing written, tests/refusal.py) or noted and run."""

from __future__ import annotations

import gzip
import json
import shutil
from pathlib import Path

import meshio
import numpy as np
import pytest
from refusal import refused
from wall_cases import OUTPUTS, RECORDS, flat_mesh, write_csv

from wear.app.cli import main
from wear.app.outputs.folder import MANIFEST
from wear.case import default_case
from wear.wall import hits_on_wall, read_table
from wear.wall.mesh import read_surface
from wear.wall.options import WallOptions
from wear.wall.per_record import wall_law

HEADER = ["x_m", "y_m", "z_m", "u_m_s", "v_m_s", "w_m_s", "diameter_m", "density_kg_m3", "time_s"]
QUIET = ["--no-figures", "--quiet"]


def _row(x=0.01, y=0.01, z=0.0, u=3.0, w=-10.0, density=2650.0, time=0.0) -> list[str]:
    return [str(x), str(y), str(z), str(u), "0.0", str(w), "3e-4", str(density), str(time)]


def _spread(**change) -> list[list[str]]:
    """20 hits spread over the 4 cm x 3 cm plate (m), times 0 ... 19 s."""
    return [
        _row(x=0.002 + 0.036 * (k % 5) / 4, y=0.002 + 0.026 * (k // 5) / 3, time=float(k), **change) for k in range(20)
    ]


@pytest.fixture
def plate(tmp_path) -> Path:
    path = tmp_path / "plate.stl"
    meshio.write(path, flat_mesh())
    return path


def _run(argv: list[str], capsys) -> tuple[dict, str]:
    """Run ``impactwear`` (exit 0 asserted); the summary.json of its --out and its stderr."""
    capsys.readouterr()
    assert main(argv) == 0
    err = capsys.readouterr().err
    out = Path(argv[argv.index("--out") + 1])
    return json.loads((out / "summary.json").read_text()), err


# --- 1. units ---------------------------------------------------------------------------------------------------


def test_records_in_m_on_a_wall_in_mm_are_refused_as_other_units(tmp_path, capsys):
    """Before: exit 0 with every hit on 2 corner faces of a 40 m x 30 m plate (a 40 mm plate read in m)."""
    mm = flat_mesh()
    wall = tmp_path / "plate_mm.stl"
    meshio.write(wall, meshio.Mesh(mm.points * 1e3, mm.cells))
    records = write_csv(tmp_path / "hits.csv", HEADER, _spread())
    line = refused(["wall", str(records), str(wall), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "hits.csv" in line and "span" in line and "other units" in line and "mm" in line, line


def test_records_in_mm_on_a_wall_in_m_are_refused_as_other_units(tmp_path, plate, capsys):
    rows = [[str(float(v) * 1e3) if j < 3 else v for j, v in enumerate(r)] for r in _spread()]
    records = write_csv(tmp_path / "hits_mm.csv", HEADER, rows)
    line = refused(["wall", str(records), str(plate), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "hits_mm.csv" in line and "typically" in line and "other units" in line, line


def test_hits_typically_off_the_surface_are_refused(tmp_path, plate, capsys):
    """Every hit 1 mm above the plate: within the tolerance of one record (1.77 mm), but a CFD code records hits
    on the face; 1 mm is 0.14 of the face size (7.07 mm)."""
    records = write_csv(tmp_path / "off.csv", HEADER, _spread(z=0.001))
    line = refused(["wall", str(records), str(plate), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "off.csv" in line and "typically 0.001 m" in line and "0.141 of a face's size" in line, line


def test_a_record_faster_than_2000_m_s_names_its_file_row_and_column(tmp_path, plate, capsys):
    rows = _spread()
    rows[4] = _row(w=-1e5, time=4.0)  # 100 m/s given in mm/s
    records = write_csv(tmp_path / "fast.csv", HEADER, rows)
    line = refused(["wall", str(records), str(plate), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "fast.csv, row 5, columns u_m_s v_m_s w_m_s" in line and "at most 2000 m/s" in line, line


def test_values_in_other_units_are_noted(tmp_path, plate, capsys):
    """A density of 2.65 (g/cm^3), a thickness of 5 (mm), a budget beyond the thickness and an erosion ratio above
    1 each get a note; the run goes on."""
    records = write_csv(tmp_path / "light.csv", HEADER, _spread(density=2.65))
    argv = ["wall", str(records), str(plate), *QUIET, "--out", str(tmp_path / "out")]
    keys = ["wall.exposure=1.0", "wall.thickness=5", "wall.loss_budget=6", "wear.dnv_K=0.01"]
    summary, err = _run([*argv, *[a for k in keys for a in ("--set", k)]], capsys)
    notes = [n for n in err.splitlines() if "note:" in n]
    assert any("light.csv, row 1, column density_kg_m3" in n and "g/cm^3" in n for n in notes), err
    assert any("thickness of 5 m" in n and "mm" in n for n in notes), err
    assert any("wall.loss_budget=6 m is more than the wall's thickness (5 m" in n for n in notes), err
    ratio = summary["results"]["erosion_ratio_kg_per_kg"]
    assert ratio > 1 and any(f"{ratio:.4g} kg per kg" in n for n in notes), (ratio, err)
    assert all(n in summary["notes"] for n in (x.split("note: ", 1)[1] for x in notes))


def test_a_plain_run_has_no_unit_notes(tmp_path, plate, capsys):
    records = write_csv(tmp_path / "hits.csv", HEADER, _spread())
    argv = ["wall", str(records), str(plate), *QUIET, "--set", "wall.thickness=0.005", "--out", str(tmp_path / "o")]
    summary, err = _run(argv, capsys)
    assert "note:" not in err and summary["results"]["erosion_ratio_kg_per_kg"] < 1


# --- 2. duplicate faces ---------------------------------------------------------------------------------------------


def test_a_wall_with_every_face_twice_is_refused(tmp_path, capsys):
    """Before: exit 0 with twice the area and half the worn depth."""
    mesh = flat_mesh()
    triangles = mesh.cells[0].data
    twice = tmp_path / "twice.stl"
    meshio.write(twice, meshio.Mesh(mesh.points, [("triangle", np.concatenate([triangles, triangles[:, [1, 2, 0]]]))]))
    records = write_csv(tmp_path / "hits.csv", HEADER, _spread())
    line = refused(["wall", str(records), str(twice), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "twice.stl" in line and "face 24 (label 24) of patch twice repeats face 0" in line, line
    assert "24 faces repeat another" in line, line


def test_a_wall_folder_holding_a_part_twice_is_refused(tmp_path, capsys):
    parts = tmp_path / "parts"
    parts.mkdir()
    meshio.write(parts / "a.stl", flat_mesh())
    meshio.write(parts / "b.stl", flat_mesh())
    records = write_csv(tmp_path / "hits.csv", HEADER, _spread())
    line = refused(["wall", str(records), str(parts), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "of patch b repeats face 0 (label 0) of patch a" in line, line


@pytest.mark.parametrize("patches", ["bend,bend", "bend, wallIn,bend"])
def test_a_patch_named_twice_is_refused(tmp_path, capsys, patches):
    line = refused(["wall", str(RECORDS), str(OUTPUTS), "--patches", patches], tmp_path, capsys)
    assert f"--patches={patches}" in line and "'bend' is named twice" in line, line


# --- 3. empty records, NaN thickness, tiny exposure, forged manifest ------------------------------------------------


def test_openfoam_records_with_a_header_and_no_rows_are_refused(tmp_path, capsys):
    """Before: '0 of 0 impact records ... largest thickness loss 0 mm/year at face 0', exit 0."""
    header = gzip.decompress((RECORDS / "0.02" / "bend.post.gz").read_bytes()).decode().splitlines()[0]
    empty = tmp_path / "empty.post"
    empty.write_text(header + "\n")
    line = refused(["wall", str(empty), str(OUTPUTS), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "empty.post" in line and "no rows" in line, line


def test_a_csv_with_a_header_and_no_rows_is_still_refused(tmp_path, plate, capsys):
    records = write_csv(tmp_path / "none.csv", HEADER, [])
    line = refused(["wall", str(records), str(plate), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "none.csv" in line and "no rows" in line, line


def test_a_nan_thickness_in_the_wall_file_names_file_face_and_column(tmp_path, capsys):
    """Before: accepted, and the face left out of the shortest remaining life."""
    mesh = flat_mesh()
    thickness = np.full(len(mesh.cells[0].data), 0.005)
    thickness[7] = np.nan
    wall = tmp_path / "thick.vtu"
    meshio.write(wall, meshio.Mesh(mesh.points, mesh.cells, cell_data={"thickness_m": [thickness]}))
    records = write_csv(tmp_path / "hits.csv", HEADER, _spread())
    line = refused(["wall", str(records), str(wall), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "thick.vtu" in line and "face 7, column thickness_m: nan is not a finite number" in line, line


@pytest.mark.parametrize("exposure", ["1e-320", "1e-12"])
def test_an_exposure_too_short_for_the_rates_is_refused(tmp_path, plate, capsys, exposure):
    """Before: numpy's divide-by-zero warnings on stderr and rates of null (refused() asserts one line)."""
    records = write_csv(tmp_path / "hits.csv", HEADER, _spread())
    line = refused(["wall", str(records), str(plate), "--set", f"wall.exposure={exposure}"], tmp_path, capsys)
    assert f"wall.exposure={float(exposure):g} s is out of range: give at least 1e-09 s" in line, line


@pytest.mark.parametrize("forged", ["notes.txt", "../outside.txt"])
def test_a_forged_manifest_does_not_make_a_rerun_delete_a_user_file(tmp_path, plate, capsys, forged):
    records = write_csv(tmp_path / "hits.csv", HEADER, _spread())
    out = tmp_path / "out"
    argv = ["wall", str(records), str(plate), *QUIET, "--set", "wall.exposure=1.0", "--out", str(out)]
    _run(argv, capsys)
    user = out / "notes.txt"
    user.write_text("mine")
    outside = tmp_path / "outside.txt"
    outside.write_text("mine too")
    manifest = json.loads((out / MANIFEST).read_text())
    (out / MANIFEST).write_text(json.dumps({**manifest, "entries": [*manifest["entries"], forged]}))
    _run(argv, capsys)
    assert user.read_text() == "mine" and outside.read_text() == "mine too"
    assert (out / "faces.csv").exists() and forged not in json.loads((out / MANIFEST).read_text())["entries"]


# --- 5. a NaN point in the wall file --------------------------------------------------------------------------------


def test_a_nan_point_in_a_surface_file_names_the_file_and_the_point(tmp_path, capsys):
    """Before: 'tolerance=nan is out of range', then a segmentation fault."""
    mesh = flat_mesh()
    points = mesh.points.copy()
    points[6, 1] = np.nan
    wall = tmp_path / "holed.vtu"
    meshio.write(wall, meshio.Mesh(points, mesh.cells))
    records = write_csv(tmp_path / "hits.csv", HEADER, _spread())
    line = refused(["wall", str(records), str(wall), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "holed.vtu" in line and "point 6: (" in line and "nan" in line and "not a finite position" in line, line


def test_a_nan_point_in_an_openfoam_mesh_names_the_points_file_and_row(tmp_path, capsys):
    case = tmp_path / "case"
    shutil.copytree(OUTPUTS / "polyMesh", case / "constant" / "polyMesh")
    points = case / "constant" / "polyMesh" / "points.gz"
    lines = gzip.decompress(points.read_bytes()).decode().splitlines()
    first = next(i for i, line in enumerate(lines) if line.startswith("("))
    lines[first + 1 + 12] = "(nan 0 0)"  # point 12
    points.write_bytes(gzip.compress(("\n".join(lines) + "\n").encode()))
    line = refused(["wall", str(RECORDS), str(case), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "points.gz, point 12: (nan 0 0) is not a finite position (m)" in line, line


# --- 10. grazing hits and --patches ---------------------------------------------------------------------------------


def test_a_grazing_hit_past_90_deg_by_round_off_is_90_deg(tmp_path, plate):
    """A record at 90.0001 deg from the face normal is a grazing hit, not one leaving the wall; at 90.01 deg it
    leaves."""
    wall = read_surface(plate)
    grazing = np.tan(np.radians(1e-4))  # w/u: 1e-4 deg past 90 (the plate's normal is -z)
    path = write_csv(tmp_path / "graze.csv", HEADER, [_row(u=10.0, w=10.0 * grazing), _row(u=10.0, w=-1.0)])
    hits = hits_on_wall(read_table(path), wall, WallOptions(normal="face"))
    assert hits.kept.all() and hits.angle[0] == 90.0 and hits.skipped == {}
    past = write_csv(tmp_path / "past.csv", HEADER, [_row(u=10.0, w=10.0 * np.tan(np.radians(1e-2)))])
    with pytest.raises(ValueError, match=r"past\.csv, row 1, .* points out of the wall \(90\.01 deg"):
        hits_on_wall(read_table(past), wall, WallOptions(normal="face"))


def test_the_bend_alone_of_a_multi_patch_run_notes_the_other_patches_hits(tmp_path, capsys):
    """Before: refused with 'give the polyMesh of the run that wrote the records'. The hits on wallIn and wallOut
    are counted in a note and summary.json, the bend's on the wall."""
    on_bend = sum(
        len(gzip.decompress(f.read_bytes()).decode().splitlines()) - 1 for f in RECORDS.glob("*/bend.post.gz")
    )
    argv = ["wall", str(RECORDS), str(OUTPUTS), "--patches", "bend", *QUIET, "--set", "wall.exposure=0.05"]
    summary, err = _run([*argv, "--out", str(tmp_path / "bend")], capsys)
    records = summary["records"]
    assert records["read"] == 4528 and records["on_wall"] == on_bend > 0
    assert records["skipped"] == {"other_patches": 4528 - on_bend}
    assert f"note: {4528 - on_bend} of 4528 records hit patches of the mesh that are not part of the wall" in err
    assert summary["wall"]["patches"] == ["bend"]


@pytest.mark.parametrize("patches", ["", " , "])
def test_patches_naming_no_patch_is_refused_naming_the_option(tmp_path, capsys, patches):
    """Before: 'need at least one array to concatenate'."""
    line = refused(["wall", str(RECORDS), str(OUTPUTS), "--patches", patches], tmp_path, capsys)
    assert f"--patches={patches!r} names no patch" in line, line


# --- 11. the response table's reach ---------------------------------------------------------------------------


def test_a_response_table_too_coarse_for_the_impact_speeds_is_refused_naming_what_fits(tmp_path, plate, capsys):
    """Before: ``wall.table_speeds = 2`` failed after the work with "speed=5729.87 is out of range", a value the
    user never gave: two normal speeds 5.7e4 apart ask for an impact at 100 m/s normal speed at 89 deg."""
    records = write_csv(tmp_path / "hits.csv", HEADER, _spread())
    argv = ["wall", str(records), str(plate), "--set", 'wear.law="local"', "--set", "wall.table_speeds=2"]
    line = refused(argv, tmp_path, capsys)
    assert line.startswith("impactwear wall: error: wall.table_speeds=2 is too coarse"), line
    assert "above the impact's 1000 m/s" in line and "wall.table_speeds >= 6" in line, line
    assert "wall.table_speed_max <= 1.321 m/s" in line, line


@pytest.mark.parametrize(
    ("change", "past"),
    [({"table_speeds": 6}, {"table_speeds": 5}), ({"table_speed_max": 575.5}, {"table_speed_max": 576.0})],
)
def test_the_response_table_the_refusal_suggests_builds_within_the_impact_speeds(change, past):
    """The values the refusal above names (the fewest speeds; the fastest table) build: every impact of the table
    within the engine's range (contact.impact refuses a speed above 1000 m/s), every lookup's entries computed."""
    case = default_case("wall").with_(wear={"law": "local"}, wall={"table_angles": 2, **change})
    case.wall.check()
    law = wall_law(case)
    assert np.isfinite(law.volume_per_kg).sum() >= 2
    speeds = np.array([case.wall.table_speed_min, case.wall.table_speed_max])
    for angle in (0.0, 45.0, 89.0):
        volume = law.volume(np.full(2, angle), speeds, np.full(2, 3e-4), np.full(2, 2650.0), np.ones(2))
        assert np.all(np.isfinite(volume)) and np.all(volume >= 0.0), (angle, volume)
    with pytest.raises(ValueError, match="too coarse"):  # one step past the bound
        default_case("wall").with_(wall=past).wall.check()


def test_a_record_outside_the_response_tables_speeds_is_refused_before_the_table(tmp_path, plate, capsys):
    """Before: refused after the table was built (7-32 s); now on the first records, before any impact (the
    refusal is asserted quick, tests/refusal.py)."""
    records = write_csv(tmp_path / "hits.csv", HEADER, _spread())
    argv = ["wall", str(records), str(plate), "--set", 'wear.law="local"', "--set", "wall.table_speed_max=5.0"]
    line = refused([*argv, "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert "hits.csv, row 1, columns u_m_s v_m_s w_m_s" in line, line
    assert "the speed 10.4403 m/s is outside the response table's speeds [0.1, 5] m/s" in line, line
