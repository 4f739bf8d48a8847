"""``impactwear wall`` refuses bad input in one line naming the parameter (or the file, row and column), exit
status 2, nothing written (tests/refusal.py)."""

from __future__ import annotations

import math
from pathlib import Path

import meshio
import numpy as np
import pytest
from refusal import refused
from wall_cases import OUTPUTS, RECORDS, flat_mesh, write_csv

HEADER = ["x_m", "y_m", "z_m", "u_m_s", "v_m_s", "w_m_s", "diameter_m", "density_kg_m3", "time_s"]


def _row(x=0.01, y=0.01, z=0.0, w=-10.0, diameter="3e-4", time="0.0") -> list[str]:
    return [str(x), str(y), str(z), "3.0", "0.0", str(w), diameter, "2650.0", time]


@pytest.fixture
def inputs(tmp_path) -> tuple[Path, Path]:
    wall = tmp_path / "plate.stl"
    meshio.write(wall, flat_mesh())
    rows = [_row(time="0.0"), _row(x=0.02, time="1.0"), _row(x=0.03, y=0.02, time="2.0")]
    return write_csv(tmp_path / "hits.csv", HEADER, rows), wall


def _records(tmp_path: Path, **bad) -> Path:
    """The good records with row 2 changed."""
    rows = [_row(time="0.0"), _row(x=0.02, time="1.0", **bad), _row(x=0.03, y=0.02, time="2.0")]
    return write_csv(tmp_path / "bad.csv", HEADER, rows)


def _file(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def _volume_mesh(tmp_path: Path) -> Path:
    path = tmp_path / "solid.vtu"
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    meshio.write(path, meshio.Mesh(points, [("tetra", np.array([[0, 1, 2, 3]]))]))
    return path


def _thin_wall(tmp_path: Path) -> Path:
    mesh = flat_mesh()
    thickness = np.full(len(mesh.cells[0].data), 0.005)
    thickness[3] = -0.001
    path = tmp_path / "thin.vtu"
    meshio.write(path, meshio.Mesh(mesh.points, mesh.cells, cell_data={"thickness_m": [thickness]}))
    return path


#: (what, arguments after ``wall`` given the good records R and wall W, words the line must hold)
CASES = [
    ("no records", lambda t, r, w: [], ["RECORDS is missing"]),
    ("no wall", lambda t, r, w: [str(r)], ["WALL is missing"]),
    ("records not there", lambda t, r, w: [str(t / "none.csv"), str(w)], ["records=", "no such file"]),
    ("wall not there", lambda t, r, w: [str(r), str(t / "none.stl")], ["wall=", "no such file"]),
    ("wall not a surface", lambda t, r, w: [str(r), str(_file(t, "junk.stl", "not an stl"))], ["wall=", "junk.stl"]),
    ("volume mesh", lambda t, r, w: [str(r), str(_volume_mesh(t))], ["volume mesh", "tetra"]),
    ("NaN diameter", lambda t, r, w: [str(_records(t, diameter="nan")), str(w)], ["bad.csv", "row 2", "diameter_m"]),
    ("negative diameter", lambda t, r, w: [str(_records(t, diameter="-3e-4")), str(w)], ["row 2", "diameter_m"]),
    ("leaving the wall", lambda t, r, w: [str(_records(t, w=10.0)), str(w)], ["row 2", "--skip-bad"]),
    ("far from the wall", lambda t, r, w: [str(_records(t, z=0.5)), str(w)], ["row 2", "--skip-bad"]),
    (
        "unknown column",
        lambda t, r, w: [str(write_csv(t / "c.csv", [*HEADER, "colour"], [[*_row(), "red"]])), str(w)],
        ["colour"],
    ),
    ("patches of a surface", lambda t, r, w: [str(r), str(w), "--patches", "bend"], ["--patches=bend"]),
    ("flip of OpenFOAM", lambda t, r, w: [str(RECORDS), str(OUTPUTS), "--flip"], ["--flip"]),
    ("unknown patch", lambda t, r, w: [str(RECORDS), str(OUTPUTS), "--patches", "elbow"], ["elbow"]),
    ("scheduler", lambda t, r, w: [str(r), str(w), "--scheduler", "garbage"], ["--scheduler='garbage'"]),
    ("workers", lambda t, r, w: [str(r), str(w), "--workers", "0"], ["--workers", "0"]),
    ("exposure", lambda t, r, w: [str(r), str(w), "--set", "wall.exposure=-1"], ["wall.exposure", "-1"]),
    ("thickness", lambda t, r, w: [str(r), str(w), "--set", "wall.thickness=0"], ["wall.thickness", "0"]),
    ("thickness field", lambda t, r, w: [str(r), str(_thin_wall(t))], ["thickness_m=-0.001", "face 3"]),
    ("sand rate alone", lambda t, r, w: [str(r), str(w), "--set", "wall.sand_rate=2"], ["wall.sand_rate", "cfd"]),
    (
        "key the law does not read",
        lambda t, r, w: [str(r), str(w), "--set", "impact.friction=0.5"],
        ["impact.friction", "does not read"],
    ),
    ("table not read", lambda t, r, w: [str(r), str(w), "--set", 'fem.model="solid"'], ["[fem]"]),
    (
        "no time span",
        lambda t, r, w: [str(write_csv(t / "same.csv", HEADER, [_row(), _row(x=0.02)])), str(w)],
        ["wall.exposure", "span 0 s"],
    ),
    ("out is a file", lambda t, r, w: [str(r), str(w), "--out", str(_file(t, "taken", "x"))], ["--out", "taken"]),
]


@pytest.mark.parametrize("what, arguments, words", CASES, ids=[c[0] for c in CASES])
def test_bad_input_is_one_line_naming_it(inputs, tmp_path, capsys, what, arguments, words):
    records, wall = inputs
    argv = ["wall", *arguments(tmp_path, records, wall), "--set", "wall.exposure=1.0"]
    if what in ("exposure", "no time span"):
        argv = argv[:-2]
    line = refused(argv, tmp_path, capsys)
    for word in words:
        assert word in line, (word, line)


def test_skip_bad_counts_and_reports_the_records_left_out(inputs, tmp_path, capsys):
    """With --skip-bad a record leaving the wall and one far from it are counted in summary.json and named in a
    note, and the others give the answer they give alone."""
    import json

    from wear.app.cli import main

    records, wall = inputs
    bad = write_csv(
        tmp_path / "mixed.csv",
        HEADER,
        [_row(time="0.0"), _row(x=0.02, w=10.0), _row(x=0.03, y=0.02, time="2.0"), _row(x=0.01, z=0.5)],
    )
    common = ["--set", "wall.exposure=1.0", "--no-figures", "--quiet"]
    assert main(["wall", str(bad), str(wall), *common, "--skip-bad", "--out", str(tmp_path / "a")]) == 0
    err = capsys.readouterr().err
    assert "--skip-bad: 2 of 4 records skipped" in err
    good = write_csv(tmp_path / "good.csv", HEADER, [_row(time="0.0"), _row(x=0.03, y=0.02, time="2.0")])
    assert main(["wall", str(good), str(wall), *common, "--out", str(tmp_path / "b")]) == 0
    a, b = (json.loads((tmp_path / x / "summary.json").read_text()) for x in "ab")
    assert a["records"]["skipped"] == {"far_from_wall": 1, "leaving_wall": 1}
    assert a["records"]["read"] == 4 and a["records"]["on_wall"] == 2
    assert math.isclose(a["results"]["eroded_volume_m3"], b["results"]["eroded_volume_m3"], rel_tol=1e-14)
    assert any("--skip-bad" in note for note in a["notes"])
