"""Inputs a new user gives that ran work before failing, or failed with words that do not fit: duplicate stream
angles, a repeat that would run for hours, sweeps their stage cannot run, a case file with a byte-order mark or
after an option, a mesh meshio half-reads, a key named without its table, a report file called a folder. Each bad
one: exit 2, one stderr line naming what the user gave, nothing written, before any work (:mod:`refusal`)."""

import json

import pytest
from refusal import refused

from wear.app.cli import main
from wear.case import check_job_case, default_case
from wear.case.work import REPEAT_BLOCK_PASS, fe_seconds, repeat_block_impacts


@pytest.mark.parametrize("angles", ["30,30", "30,30.000001", "0,15,15.0000001"])
def test_erode_refuses_angles_that_print_alike(angles, tmp_path, capsys):
    """Each angle's outputs go to angle_<deg>/ with 6 digits: two that print alike collided there after the work
    (a 15-line FileExistsError)."""
    err = refused(["erode", "--angles", angles], tmp_path, capsys)
    assert f"--angles={angles}" in err and "twice" in err


def test_erode_distinct_close_angles_still_parse():
    from wear.app.commands.erode import parse_angles

    assert parse_angles("30,30.001") == [30.0, 30.001]


def test_repeat_that_would_run_for_hours_is_refused_with_the_largest_value_that_fits(tmp_path, capsys):
    """The impacts computed between cycle-jump blocks are counted (they were not: the estimate saw 20 passes
    whatever the impacts): a small ``surface_fraction`` makes 10^9 impacts hours of work."""
    setting = "repeat.surface_fraction=0.02"
    err = refused(["repeat", "--impacts", "1e9", "--set", setting], tmp_path, capsys)
    assert err.startswith("impactwear repeat: error: repeat.impacts=1e+09 needs ~") and "between cycle-jump" in err
    largest = int(err.rsplit("give repeat.impacts <= ", 1)[1])
    case = default_case("repeat").with_(repeat={"surface_fraction": 0.02})
    check_job_case(case.with_(repeat={"impacts": largest}), "repeat")  # the value given fits
    with pytest.raises(ValueError, match="repeat.impacts"):
        check_job_case(case.with_(repeat={"impacts": largest + 1}), "repeat")


def test_repeat_estimate_counts_the_impacts_between_blocks_as_measured():
    """The default repeat at 10^9 impacts computed 20 impacts one by one and 214 between blocks (stopped at impact
    13,309 by the worn depth, 24 min on 2 shared cores): the estimate counts 150-400 and accepts it; none for
    fewer impacts than are computed one by one, one block without geometry update."""
    case = default_case("repeat")
    between = repeat_block_impacts(case, 10**9)
    assert 150 <= between <= 400
    f = case.fem
    assert fe_seconds(f.mesh_scale, f.load_steps + f.unload_steps, 20 + REPEAT_BLOCK_PASS * between) < 3600.0
    check_job_case(case.with_(repeat={"impacts": 10**9}), "repeat")
    assert repeat_block_impacts(case, case.repeat.max_plastic_impacts) == 0
    assert repeat_block_impacts(case.with_(repeat={"geometry_update": False}), 10**9) == 1


@pytest.mark.parametrize(
    "text, named",
    [
        (
            '[sweep]\nstage = "indent"\n[base]\nfem.model = "3d"\n[grid]\n"impact.angle" = [10, 30]\n',
            "fem.model='3d'",
        ),
        ('[sweep]\nstage = "wall"\n[grid]\n"plate.density" = [7800, 7850]\n', "wall.records is missing"),
    ],
)
def test_sweep_the_stage_cannot_run_is_refused_before_any_work(text, named, tmp_path, capsys, monkeypatch):
    """Both made the folder and failed every case in the workers (exit 1); now refused while the file is read."""

    def no_work(*_args, **_kwargs):
        raise AssertionError("the sweep ran")

    monkeypatch.setattr("wear.app.commands.sweep.run_sweep", no_work)
    path = tmp_path / "sweep.toml"
    path.write_text(text, encoding="utf-8")
    err = refused(["sweep", str(path)], tmp_path, capsys)
    assert named in err


def test_case_file_with_a_byte_order_mark_is_read(tmp_path, capsys):
    path = tmp_path / "case.toml"
    path.write_bytes("\ufeff[impact]\nangle = 40.0\n".encode())
    assert main(["impact", "--config", str(path), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["case"]["impact"]["angle"] == 40.0


def test_case_file_after_an_option_is_read(tmp_path, capsys):
    """calibrate DATA.csv --out DIR CASE.toml: argparse's first pass filled both positionals from DATA.csv alone
    and called CASE.toml unrecognized."""
    data = tmp_path / "d.csv"
    data.write_text("angle_deg,speed_m_s,erosion_kg_per_kg\n30,40,1e-4\n45,40,1.2e-4\n", encoding="utf-8")
    case = tmp_path / "case.toml"
    case.write_text('[wear]\nlaw = "dnv"\n', encoding="utf-8")
    out = tmp_path / "out"
    assert main(["calibrate", str(data), "--out", str(out), str(case), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["law"] == "dnv"
    # an argument that is still extra is named as before
    err = refused(["calibrate", str(data), "--out", str(tmp_path / "o2"), str(case), "extra.toml"], tmp_path, capsys)
    assert "unrecognized arguments: extra.toml" in err


def test_indent_mesh_meshio_half_reads_is_one_line(tmp_path, capsys):
    """An STL (meshio warned "overflow encountered in scalar multiply" in two raw lines before the refusal)."""
    meshio = pytest.importorskip("meshio")
    import numpy as np

    path = tmp_path / "plate.stl"
    meshio.write(str(path), meshio.Mesh(np.eye(3), [("triangle", np.array([[0, 1, 2]]))]))
    err = refused(["indent", "--mesh", str(path)], tmp_path, capsys)
    assert f"--mesh={str(path)!r}" in err and "Warning" not in err


def test_erosion_messages_name_the_dotted_key(tmp_path, capsys):
    err = refused(["erode", "--set", "erosion.exposure_time=1e-12"], tmp_path, capsys, quick=120.0)
    assert "erosion.exposure_time=1e-12 is out of range" in err


def test_validate_report_file_is_called_a_file(tmp_path, capsys):
    report = tmp_path / "mine.md"
    report.write_text("# my notes\n", encoding="utf-8")
    err = refused(["validate", "--report", str(report), "--quick"], tmp_path, capsys, out=False)
    assert f"--report={str(report)!r} is a file" in err and "folder" not in err
