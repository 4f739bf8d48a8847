"""impactwear calibrate (wear/chain/calibrate.py): outputs, the calibrated case reproduced by `erode`, what the data
cannot determine, and one-line errors on bad data."""

import json

import numpy as np
import pytest

from wear.app.cli import main
from wear.app.sweep.runner import run_sweep
from wear.app.sweep.spec import parse_sweep
from wear.case import default_case, load_case
from wear.chain.calibrate import calibrate
from wear.chain.calibration_data import CalibrationData, read_data
from wear.laws import oka_erosion_ratio

ANGLES = (0.0, 15.0, 30.0, 45.0, 60.0, 70.0, 80.0)


def _oka_csv(path, speeds=(30.0, 60.0), extra_row="45,45,"):
    rows = ["angle_deg,speed_m_s,erosion_kg_per_kg"]
    for v in speeds:
        rows += [f"{a},{v},{float(oka_erosion_ratio(v, a, 1.4e9, 300e-6, 6.154e-4)):.8g}" for a in ANGLES]
    path.write_text("\n".join([*rows, extra_row]) + "\n")
    return path


def test_calibrate_writes_outputs_and_calibrated_case(tmp_path, capsys):
    """DNV's law fitted to Oka et al.'s (2005) curve at two speeds: its exponent n is Oka's k2 = 2.3 H_v^0.038 =
    2.3296 (an independent formula; within 1%); every output is written; the row without a measurement is
    predicted; calibrated.toml holds the fitted constants and reads as a case."""
    data = _oka_csv(tmp_path / "oka.csv")
    out = tmp_path / "out"
    assert main(["calibrate", str(data), "--law", "dnv", "--free", "dnv_K,dnv_n", "--set", "plate.hardness=1.4e9",
                 "--out", str(out), "--json"]) == 0  # fmt: skip
    summary = json.loads(capsys.readouterr().out)
    assert summary["constants"]["dnv_n"]["value"] == pytest.approx(2.3 * 1.4**0.038, rel=0.01)
    lo, hi = summary["constants"]["dnv_n"]["interval_95"]
    assert lo < summary["constants"]["dnv_n"]["value"] < hi
    assert summary["fitted_rows"] == 14 and summary["rows"] == 15
    assert sorted(p.name for p in out.iterdir()) == [".impactwear.json", "calibrated.toml", "calibration.csv",
                                                      "calibration.json",
                                                      "calibration.png"]  # fmt: skip
    rows = (out / "calibration.csv").read_text().splitlines()
    assert len(rows) == 16 and rows[-1].split(",")[-1] == "0" and float(rows[-1].split(",")[4]) > 0
    case = load_case(out / "calibrated.toml", "run")
    assert case.wear.law == "dnv" and case.wear.dnv_n == pytest.approx(summary["constants"]["dnv_n"]["value"])


@pytest.mark.filterwarnings("ignore:elastic ball")
def test_calibrated_case_reproduces_the_fitted_curve_in_erode(tmp_path, capsys):
    """calibrate → calibrated.toml → impactwear erode --angles: the stream's erosion rate at each angle equals the
    calibration's prediction there (the stream erodes a flat patch with the same impacts and law; measured within
    0.12%, at 80°: the slight roughening; tolerance 0.5%; 1.5% at 60° and 5.1% at 80° when the response table was
    interpolated linearly in the normal speed)."""
    data = _oka_csv(tmp_path / "oka.csv", speeds=(30.0,), extra_row="")
    out = tmp_path / "cal"
    assert main(["calibrate", str(data), "--law", "finnie", "--set", "plate.hardness=1.4e9", "--out", str(out),
                 "--quiet"]) == 0  # fmt: skip
    predicted = {float(r.split(",")[1]): float(r.split(",")[4]) for r in (out / "calibration.csv").read_text()
                 .splitlines()[1:]}  # fmt: skip
    case_file = out / "calibrated.toml"
    assert main(["erode", str(case_file), "--angles", "30,60,80", "--out", str(tmp_path / "erode"), "--quiet",
                 "--set", "impact.speed=30.0", "--set", "erosion.grid=128", "--set", "erosion.patch_size=9e-4",
                 "--set", "erosion.exposure_time=2.0", "--set", "erosion.samples=2"]) == 0  # fmt: skip
    rows = (tmp_path / "erode" / "erosion_vs_angle.csv").read_text().splitlines()[1:]
    assert len(rows) == 3
    for row in rows:
        angle, rate = float(row.split(",")[0]), float(row.split(",")[1])
        assert rate == pytest.approx(predicted[angle], rel=0.005), angle


def test_a_speed_exponent_from_one_speed_is_not_determined():
    """One speed: DNV's K and n trade off exactly, so no number is given for them, only the statement."""
    data = CalibrationData(np.array(ANGLES), np.full(len(ANGLES), 50.0), "erosion_kg_per_kg",
                           oka_erosion_ratio(50.0, np.array(ANGLES), 1.4e9, 300e-6, 6.154e-4), {})  # fmt: skip
    result = calibrate(default_case("calibrate").with_(wear={"law": "dnv"}), data, ("dnv_K", "dnv_n"))
    assert result.fit.determined == (False, False) and result.fit.intervals == (None, None)
    assert "cannot determine dnv_K and dnv_n" in result.summary()["statements"][0]


def test_rows_with_case_keys_and_a_sweep_of_laws(tmp_path):
    """A per-row case key (ball.radius) enters each row's impacts; the calibrate sweep stage fits one law per case
    on the same data (Oka's E ∝ D^0.19 is followed by the laws through the particle mass)."""
    path = tmp_path / "d.csv"
    rows = ["angle_deg,speed_m_s,ball.radius,erosion_kg_per_kg"]
    for r in (100e-6, 200e-6):
        rows += [f"{a},40,{r},{float(oka_erosion_ratio(40.0, a, 1.4e9, 2 * r, 6.154e-4)):.8g}" for a in ANGLES]
    path.write_text("\n".join(rows) + "\n")
    data = read_data(path)
    assert data.keys["ball.radius"].tolist() == [100e-6] * 7 + [200e-6] * 7
    spec = parse_sweep({"sweep": {"stage": "calibrate"}, "base": {"calibration": {"data": str(path)},
                        "plate": {"hardness": 1.4e9}}, "grid": {"wear.law": ["oka", "dnv"]}})  # fmt: skip
    outcome = run_sweep(spec, tmp_path / "sweep", workers=1, quiet=True)
    assert (outcome.computed, outcome.failed) == (2, 0), outcome.failures
    records = [json.loads(p.read_text()) for p in sorted((tmp_path / "sweep" / "cases").glob("*.json"))]
    oka = next(r for r in records if r["case"]["wear"]["law"] == "oka")["results"]
    assert oka["oka_e90"] == pytest.approx(6.154e-4, rel=1e-6) and oka["rms_log_error"] < 1e-6  # its own curve


BAD = {
    "missing column": ("speed_m_s,erosion_kg_per_kg\n20,1e-5\n", "column 'angle_deg' is missing"),
    "unknown column": ("angle_deg,speed_m_s,erosion_kg_per_kg,colour\n30,20,1e-5,red\n", "column 'colour'"),
    "two measured": ("angle_deg,speed_m_s,erosion_kg_per_kg,mass_per_impact_kg\n30,20,1e-5,1e-12\n",
                     "2 measured columns"),
    "no measured rows": ("angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,\n45,20,\n", "empty in every row"),
    "zero measured": ("angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-5\n45,20,0\n",
                      "erosion_kg_per_kg=0 in row 2 is out of range"),
    "negative measured": ("angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,-1e-5\n",
                          "erosion_kg_per_kg=-1e-05 in row 1 is out of range"),
    "angle 90": ("angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-5\n90,20,1e-5\n", "angle_deg=90 in row 2"),
    "angle negative": ("angle_deg,speed_m_s,erosion_kg_per_kg\n-5,20,1e-5\n", "angle_deg=-5 in row 1"),
    "nan": ("angle_deg,speed_m_s,erosion_kg_per_kg\n30,nan,1e-5\n", "speed_m_s='nan' in row 1 is not finite"),
    "text": ("angle_deg,speed_m_s,erosion_kg_per_kg\n30,fast,1e-5\n", "speed_m_s='fast' in row 1 is not a number"),
}  # fmt: skip


@pytest.mark.parametrize("kind", sorted(BAD))
def test_bad_data_is_one_line_naming_column_and_row(kind, tmp_path, capsys):
    text, expected = BAD[kind]
    path = tmp_path / "d.csv"
    path.write_text(text)
    assert main(["calibrate", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and expected in err, err
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(
    "args, expected",
    [
        (["--law", "dnv", "--free", "K"], "--free 'K' is not a constant of wear.law='dnv'"),
        (["--law", "dnv", "--free", "dnv_K,dnv_n,dnv_K"], "names a constant twice"),
        (["--law", "local", "--free", "K,alpha,beta"], "2 measured rows for 3 free constants"),
    ],
)
def test_bad_free_constants_are_one_line(args, expected, tmp_path, capsys):
    path = tmp_path / "d.csv"
    path.write_text("angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-5\n45,20,2e-5\n")
    assert main(["calibrate", str(path), *args, "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and expected in err, err
    assert not (tmp_path / "out").exists()
