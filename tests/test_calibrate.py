"""impactwear calibrate (wear/chain/calibrate.py): outputs, the calibrated case reproduced by `erode`, what the data
cannot determine, and one-line errors on bad data."""

import json

import numpy as np
import pytest
from refusal import refused

from wear.app.cli import main
from wear.app.sweep.runner import run_sweep
from wear.app.sweep.spec import parse_sweep
from wear.case import default_case, load_case
from wear.chain.calibrate import calibrate
from wear.chain.calibration_data import CalibrationData, read_data
from wear.chain.forward_model import ForwardModel
from wear.laws.oka import oka_erosion_ratio

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
    assert (
        main(
            [
                "calibrate",
                str(data),
                "--law",
                "dnv",
                "--free",
                "dnv_K,dnv_n",
                "--set",
                "plate.hardness=1.4e9",
                "--out",
                str(out),
                "--json",
            ]
        )
        == 0
    )
    summary = json.loads(capsys.readouterr().out)
    assert summary["constants"]["dnv_n"]["value"] == pytest.approx(2.3 * 1.4**0.038, rel=0.01)
    lo, hi = summary["constants"]["dnv_n"]["interval_95"]
    assert lo < summary["constants"]["dnv_n"]["value"] < hi
    assert summary["fitted_rows"] == 14 and summary["rows"] == 15
    assert sorted(p.name for p in out.iterdir()) == [
        ".impactwear.json",
        "calibrated.toml",
        "calibration.csv",
        "calibration.json",
        "calibration.png",
    ]
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
    assert (
        main(["calibrate", str(data), "--law", "finnie", "--set", "plate.hardness=1.4e9", "--out", str(out), "--quiet"])
        == 0
    )
    predicted = {
        float(r.split(",")[1]): float(r.split(",")[4]) for r in (out / "calibration.csv").read_text().splitlines()[1:]
    }
    case_file = out / "calibrated.toml"
    assert (
        main(
            [
                "erode",
                str(case_file),
                "--angles",
                "30,60,80",
                "--out",
                str(tmp_path / "erode"),
                "--quiet",
                "--set",
                "impact.speed=30.0",
                "--set",
                "erosion.grid=128",
                "--set",
                "erosion.patch_size=9e-4",
                "--set",
                "erosion.exposure_time=2.0",
                "--set",
                "erosion.samples=2",
            ]
        )
        == 0
    )
    rows = (tmp_path / "erode" / "erosion_vs_angle.csv").read_text().splitlines()[1:]
    assert len(rows) == 3
    for row in rows:
        angle, rate = float(row.split(",")[0]), float(row.split(",")[1])
        assert rate == pytest.approx(predicted[angle], rel=0.005), angle


def test_a_speed_exponent_from_one_speed_is_not_determined():
    """One speed: DNV's K and n trade off exactly, so no number is given for them, only the statement."""
    data = CalibrationData(
        np.array(ANGLES),
        np.full(len(ANGLES), 50.0),
        "erosion_kg_per_kg",
        oka_erosion_ratio(50.0, np.array(ANGLES), 1.4e9, 300e-6, 6.154e-4),
        {},
    )
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
    spec = parse_sweep(
        {
            "sweep": {"stage": "calibrate"},
            "base": {"calibration": {"data": str(path)}, "plate": {"hardness": 1.4e9}},
            "grid": {"wear.law": ["oka", "dnv"]},
        }
    )
    outcome = run_sweep(spec, tmp_path / "sweep", workers=1, quiet=True)
    assert (outcome.computed, outcome.failed) == (2, 0), outcome.failures
    records = [json.loads(p.read_text()) for p in sorted((tmp_path / "sweep" / "cases").glob("*.json"))]
    oka = next(r for r in records if r["case"]["wear"]["law"] == "oka")["results"]
    assert oka["oka_e90"] == pytest.approx(6.154e-4, rel=1e-6) and oka["rms_log_error"] < 1e-6  # its own curve


BAD = {
    "missing column": ("speed_m_s,erosion_kg_per_kg\n20,1e-5\n", "column 'angle_deg' is missing"),
    "unknown column": ("angle_deg,speed_m_s,erosion_kg_per_kg,colour\n30,20,1e-5,red\n", "column 'colour'"),
    "two measured": (
        "angle_deg,speed_m_s,erosion_kg_per_kg,mass_per_impact_kg\n30,20,1e-5,1e-12\n",
        "2 measured columns",
    ),
    "no measured rows": ("angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,\n45,20,\n", "empty in every row"),
    "zero measured": (
        "angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-5\n45,20,0\n",
        "erosion_kg_per_kg=0 in row 2 is out of range",
    ),
    "negative measured": (
        "angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,-1e-5\n",
        "erosion_kg_per_kg=-1e-05 in row 1 is out of range",
    ),
    "angle 90": ("angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-5\n90,20,1e-5\n", "angle_deg=90 in row 2"),
    "angle negative": ("angle_deg,speed_m_s,erosion_kg_per_kg\n-5,20,1e-5\n", "angle_deg=-5 in row 1"),
    "nan": ("angle_deg,speed_m_s,erosion_kg_per_kg\n30,nan,1e-5\n", "speed_m_s='nan' in row 1 is not finite"),
    "text": ("angle_deg,speed_m_s,erosion_kg_per_kg\n30,fast,1e-5\n", "speed_m_s='fast' in row 1 is not a number"),
    # two angle columns were read as the last one (K off by 3.8 times, exit 0): any duplicate name is refused
    "duplicate angle": (
        "angle_deg,speed_m_s,angle_deg,erosion_kg_per_kg\n30,20,60,1e-5\n",
        "column 'angle_deg' appears 2 times in data=",
    ),
    "duplicate key": (
        "angle_deg,speed_m_s,ball.radius,erosion_kg_per_kg,ball.radius\n30,20,1e-4,1e-5,2e-4\n",
        "column 'ball.radius' appears 2 times",
    ),
    "unread table": (
        "angle_deg,speed_m_s,erosion.grid,erosion_kg_per_kg\n30,20,64,1e-5\n45,20,64,2e-5\n",
        "column 'erosion.grid' of data=",
    ),
    "free constant per row": (
        "angle_deg,speed_m_s,wear.K,erosion_kg_per_kg\n30,20,1e-9,1e-5\n45,20,1e-9,2e-5\n",
        "K is a free constant",
    ),
    "speed twice": (
        "angle_deg,speed_m_s,impact.speed,erosion_kg_per_kg\n30,20,40,1e-5\n45,20,40,2e-5\n",
        "a row's speed is its speed_m_s column",
    ),
    "another law's key": (
        "angle_deg,speed_m_s,wear.dnv_n,erosion_kg_per_kg\n30,20,2.6,1e-5\n45,20,2.6,2e-5\n",
        "wear.law='local' does not read it",
    ),
    "fem without FE": (
        "angle_deg,speed_m_s,fem.load_steps,erosion_kg_per_kg\n30,20,20,1e-5\n45,20,20,2e-5\n",
        "computes no FE plate",
    ),
}


@pytest.mark.parametrize("kind", sorted(BAD))
def test_bad_data_is_one_line_naming_column_and_row(kind, tmp_path, capsys):
    text, expected = BAD[kind]
    path = tmp_path / "d.csv"
    path.write_text(text)
    assert expected in refused(["calibrate", str(path)], tmp_path, capsys)


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
    assert expected in refused(["calibrate", str(path), *args], tmp_path, capsys)


@pytest.mark.parametrize(
    "content",
    [
        bytes(range(256)) * 4,
        b"angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-5\n\x0045,20,2e-5\n",
        "angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-5\n".encode("utf-16"),
    ],
    ids=["binary", "nul", "utf-16"],
)
def test_binary_data_names_the_file(content, tmp_path, capsys):
    path = tmp_path / "d.csv"
    path.write_bytes(content)
    assert f"data={str(path)!r} is not a CSV text file" in refused(["calibrate", str(path)], tmp_path, capsys)


def test_a_byte_order_mark_is_read(tmp_path):
    """Excel's "CSV UTF-8" starts with a UTF-8 byte-order mark: the file reads as the same data without it."""
    text = "angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-5\n45,20,2e-5\n"
    (tmp_path / "plain.csv").write_text(text, encoding="utf-8")
    (tmp_path / "excel.csv").write_text(text, encoding="utf-8-sig")
    assert (tmp_path / "excel.csv").read_bytes()[:3] == b"\xef\xbb\xbf"
    plain, excel = read_data(tmp_path / "plain.csv"), read_data(tmp_path / "excel.csv")
    assert excel.angle.tolist() == plain.angle.tolist() == [30.0, 45.0]
    assert excel.measured.tolist() == plain.measured.tolist()


def test_a_fem_column_the_coupled_plate_does_not_read_is_refused(tmp_path, capsys):
    """With the FE plate coupled, a [fem] column is read per row only if the coupling reads that key."""
    path = tmp_path / "d.csv"
    path.write_text("angle_deg,speed_m_s,fem.solid_iterations,erosion_kg_per_kg\n30,20,10,1e-5\n45,20,10,2e-5\n")
    assert (
        main(
            [
                "calibrate",
                str(path),
                "--law",
                "deformation",
                "--set",
                "fem.coupling='two-way'",
                "--out",
                str(tmp_path / "out"),
            ]
        )
        == 2
    )
    err = capsys.readouterr().err.strip()
    assert (
        len(err.splitlines()) == 1
        and "column 'fem.solid_iterations'" in err
        and "only the plate fem.model='3d' reads it" in err
    ), err
    assert not (tmp_path / "out").exists()


@pytest.mark.filterwarnings("error")
def test_a_single_row_reaches_the_user_without_a_library_warning(tmp_path, capsys):
    """One data row: its impact batch of one broadcast against a scalar friction used to reach numba as a read-only
    broadcast view (numba's FutureWarning on stderr). Any warning fails this test."""
    path = tmp_path / "d.csv"
    path.write_text("angle_deg,speed_m_s,erosion_kg_per_kg\n30,30,1e-5\n")
    assert main(["calibrate", str(path), "--out", str(tmp_path / "out")]) == 0
    assert capsys.readouterr().err == ""


def test_a_free_constant_needs_no_value_in_the_case(tmp_path, capsys):
    """The docs' own `--law combined --free K,beta,deformation_factor` with no deformation_factor in the case: the
    start comes from the data. Data made by the combined law with known constants (K = 3e-11, β = 1.2, ε = 5e10
    J/m³) at 30 and 60 m/s give them back (within 1e-4; exact data), and ε starts within a factor 3 of its value."""
    known = {"K": 3e-11, "beta": 1.2, "deformation_factor": 5e10}
    template = CalibrationData(
        np.tile(ANGLES, 2), np.repeat([30.0, 60.0], len(ANGLES)), "erosion_kg_per_kg", np.ones(2 * len(ANGLES)), {}
    )
    case = default_case("calibrate").with_(plate={"hardness": 1.4e9}, wear={"law": "combined", **known})
    made = ForwardModel(case, template).predict({})
    path = tmp_path / "d.csv"
    path.write_text(
        "angle_deg,speed_m_s,erosion_kg_per_kg\n"
        + "".join(f"{a:g},{v:g},{m:.12g}\n" for a, v, m in zip(template.angle, template.speed, made, strict=True))
    )
    out = tmp_path / "out"
    assert (
        main(
            [
                "calibrate",
                str(path),
                "--law",
                "combined",
                "--free",
                "K,beta,deformation_factor",
                "--set",
                "plate.hardness=1.4e9",
                "--out",
                str(out),
                "--json",
            ]
        )
        == 0
    )
    constants = json.loads(capsys.readouterr().out)["constants"]
    for name, value in known.items():
        assert constants[name]["value"] == pytest.approx(value, rel=1e-4), name
    assert 5e10 / 3.0 < constants["deformation_factor"]["start"] < 5e10 * 3.0
    assert load_case(out / "calibrated.toml", "run").wear.deformation_factor == pytest.approx(5e10, rel=1e-4)


def test_a_case_without_deformation_factor_is_refused_where_nothing_fits_it(tmp_path, capsys):
    """Without a calibration fitting ε (here: only K free), the combined law still needs it in the case."""
    path = _oka_csv(tmp_path / "oka.csv")
    assert main(["calibrate", str(path), "--law", "combined", "--free", "K", "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "wear.deformation_factor=None" in err, err


def test_k_and_alpha_are_reported_interchangeable_and_a_bound_is_reported(tmp_path, capsys):
    """Eq. 15's K and α fitted to Oka's curve at two speeds: ln y = ln K + α ln p + …, and ln p varies little
    between rows next to its size (ln 1e9 Pa ≈ 21), so the two are nearly interchangeable: said so, as a
    statement; K runs onto the upper bound of its valid range (1e-3): said so in the text and calibration.json,
    and its interval stops there. The text and the JSON say the same of every constant."""
    path = _oka_csv(tmp_path / "oka.csv", extra_row="")
    out = tmp_path / "out"
    assert (
        main(
            [
                "calibrate",
                str(path),
                "--law",
                "local",
                "--free",
                "K,alpha",
                "--set",
                "plate.hardness=1.4e9",
                "--out",
                str(out),
            ]
        )
        == 0
    )
    text = capsys.readouterr().out
    summary = json.loads((out / "calibration.json").read_text())
    interchangeable = [s for s in summary["statements"] if "hardly tell K and alpha apart" in s]
    assert len(interchangeable) == 1 and interchangeable[0] in text
    k = summary["constants"]["K"]
    assert k["on_bound"] == "high" and k["value"] == pytest.approx(1e-3) and k["interval_95"][1] <= 1e-3
    assert "K = 0.001 sits on the upper bound" in text and "on its upper bound" in text
    assert summary["constants"]["alpha"]["on_bound"] is None
    for name, c in summary["constants"].items():
        line = next(row for row in text.splitlines() if row.startswith(f"  {name} = "))
        assert c["determined"] and "not determined" not in line and "95% [" in line


def test_an_interval_is_clipped_to_the_valid_range():
    """β of Eq. 15 (valid range [0, 4]) fitted with K to Oka's curve at two speeds: the symmetric 95% interval
    would reach below 0 (value − half-width < 0); it is cut at 0, and its upper end is kept."""
    data = CalibrationData(
        np.tile(ANGLES, 2),
        np.repeat([30.0, 60.0], len(ANGLES)),
        "erosion_kg_per_kg",
        oka_erosion_ratio(np.repeat([30.0, 60.0], len(ANGLES)), np.tile(ANGLES, 2), 1.4e9, 300e-6, 6.154e-4),
        {},
    )
    case = default_case("calibrate").with_(plate={"hardness": 1.4e9}, wear={"law": "local"})
    fit = calibrate(case, data, ("K", "beta")).fit
    beta = fit.values[1]
    lo, hi = fit.intervals[1]
    assert beta - (hi - beta) < 0.0 and lo == 0.0 and hi > beta


def test_text_says_no_interval_where_the_json_says_determined(tmp_path, capsys):
    """One row for one constant: determined (the JSON's `determined: true`) but without a residual degree of
    freedom there is no interval; the text says that, not "not determined"."""
    path = tmp_path / "d.csv"
    path.write_text("angle_deg,speed_m_s,erosion_kg_per_kg\n30,30,1e-5\n")
    out = tmp_path / "out"
    assert main(["calibrate", str(path), "--law", "dnv", "--out", str(out)]) == 0
    text = capsys.readouterr().out
    c = json.loads((out / "calibration.json").read_text())["constants"]["dnv_K"]
    assert c["determined"] and c["interval_95"] is None
    assert "no interval: no residual degree of freedom" in text and "not determined" not in text
