"""Inputs a new user gives that once went wrong after the work, or ran for hours: a closed-form law's calibration
without impacts, stream angles that collide in the output, a case file with a byte-order
mark or after an option, and sweeps whose stages would fail in a worker. Refusals: exit 2, one line, nothing
written (``tests/refusal.py``)."""

from pathlib import Path

import pytest
from refusal import refused

from wear.app.cli import main
from wear.case import default_case, dump_case, load_case
from wear.chain.calibrate import calibrate
from wear.chain.calibration_data import read_data
from wear.laws.dnv import dnv_erosion_ratio

ANGLES = (15.0, 30.0, 45.0, 60.0, 75.0)
SPEEDS = (20.0, 40.0, 80.0)


def _dnv_csv(path: Path, K: float, n: float) -> Path:
    """Erosion ratios of DNV-RP-O501's correlation E = K U^n F(α) (an independent formula) on a speed × angle grid."""
    rows = ["angle_deg,speed_m_s,erosion_kg_per_kg"]
    rows += [f"{a},{v},{float(dnv_erosion_ratio(v, a, K, n)):.12g}" for v in SPEEDS for a in ANGLES]
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    return path


def test_a_closed_form_law_is_calibrated_without_any_impact(tmp_path, monkeypatch):
    """DNV's K and n recovered from data made with K = 3e-9, n = 2.4 (to 1e-6), while every impact engine fails the
    test if called: the closed form needs none (4000 rows once took 99 s and 1.9 GB running them)."""

    def no_impacts(*args, **kwargs):
        raise AssertionError("an impact was simulated for a closed-form law")

    monkeypatch.setattr("wear.chain.forward_model.simulate_impacts", no_impacts)
    monkeypatch.setattr("wear.chain.forward_model.ForwardModel._batched", no_impacts)
    monkeypatch.setattr("wear.chain.forward_model.ForwardModel._coupled", no_impacts)
    case = default_case("calibrate").with_(wear={"law": "dnv"})
    result = calibrate(case, read_data(_dnv_csv(tmp_path / "dnv.csv", 3e-9, 2.4)), ("dnv_K", "dnv_n"))
    fitted = dict(zip(result.fit.names, result.fit.values, strict=True))
    assert fitted["dnv_K"] == pytest.approx(3e-9, rel=1e-6)
    assert fitted["dnv_n"] == pytest.approx(2.4, rel=1e-6)


@pytest.mark.parametrize("angles", ["30,30", "30,30.000001"])
def test_stream_angles_that_share_an_output_folder_are_refused(angles, tmp_path, capsys):
    """Each angle writes angle_<a:g>/: two that print alike once failed with a 15-line FileExistsError after the
    work."""
    err = refused(["erode", "--angles", angles], tmp_path, capsys)
    assert f"--angles={angles}" in err and "twice" in err, err


def test_a_case_file_with_a_byte_order_mark_is_read(tmp_path):
    """Notepad's and Excel's "UTF-8" starts with a BOM; the CSV readers skip it, and so does the case reader."""
    text = dump_case(default_case("run").with_(impact={"angle": 40.0}))
    path = tmp_path / "case.toml"
    path.write_text("\ufeff" + text, encoding="utf-8")
    assert load_case(path, "run").impact.angle == 40.0


def test_a_case_file_after_an_option_is_the_case(tmp_path, capsys):
    """``impactwear impact --json CASE.toml`` once failed with "unrecognized arguments"."""
    path = tmp_path / "case.toml"
    path.write_text(dump_case(default_case("run").with_(impact={"angle": 40.0})), encoding="utf-8")
    err = refused(["run", "--quiet", str(path), "--set", "impact.speed=1e5"], tmp_path, capsys)
    assert "unrecognized" not in err and "impact.speed" in err, err


def test_an_indent_sweep_of_the_3d_plate_is_refused_before_any_work(tmp_path, capsys):
    """indent presses the axisymmetric plate only: the sweep once made its folder and failed in the worker."""
    sweep = tmp_path / "sweep.toml"
    sweep.write_text('[sweep]\nstage = "indent"\n[base.fem]\nmodel = "3d"\n[grid]\n"impact.angle" = [0.0]\n', "utf-8")
    err = refused(["sweep", str(sweep)], tmp_path, capsys)
    assert "fem.model" in err, err


def test_positionals_after_an_option_are_read(tmp_path, capsys):
    """``calibrate --quiet DATA.csv --law dnv``: the data file after an option once gave "unrecognized arguments";
    the valid command line runs and writes its outputs."""
    data = _dnv_csv(tmp_path / "dnv.csv", 2e-9, 2.6)
    out = tmp_path / "out"
    assert main(["calibrate", "--quiet", str(data), "--law", "dnv", "--out", str(out)]) == 0
    assert (out / "calibration.json").is_file()
