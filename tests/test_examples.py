"""Every script in examples/ runs to completion (at reduced size, IMPACTWEAR_QUICK=1), as ``python examples/NAME.py``
with its output folder given by IMPACTWEAR_EXAMPLE_OUT, writes there only, warns of nothing, and each gives a number
that is checked against an independent reference (closed form, Newton's second law, the stream's flux, the law the
sample data were drawn from)."""

import csv
import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples").glob("*.py"))
SAMPLE = ROOT / "wear" / "app" / "data" / "calibration_sample.csv"


def _rows(path: Path) -> list[dict]:
    with open(path, newline="", encoding="utf-8") as f:
        return list(csv.DictReader(f))


def _column(rows: list[dict], name: str) -> np.ndarray:
    return np.array([float(r[name]) for r in rows])


def _dnv(speed, angle, K, n):
    """DNV-RP-O501 (2015), ductile materials: E = K U^n F(a), a from the surface (rad); typed from the standard."""
    a = np.radians(90.0 - np.asarray(angle, float))
    f = 0.6 * (np.sin(a) + 7.2 * (np.sin(a) - np.sin(a) ** 2)) ** 0.6 * (1.0 - np.exp(-20.0 * a))
    return K * np.asarray(speed, float) ** n * f


def _sphere_mass(radius: float, density: float) -> float:
    return 4.0 / 3.0 * math.pi * radius**3 * density


def check_calibrate_your_data(out: Path, stdout: str) -> None:
    """The fit recovers the DNV constants the sample was drawn from (K = 3e-9, n = 2.3): both inside the 95%
    intervals, n within 0.1 and K within 25% (the noise, 0.10 in ln, on 24 rows gives about 0.04 and 12%); the rms log
    error is the scatter of ln(data / true law) (the fitted law has the true law's form)."""
    summary = json.loads((out / "calibration.json").read_text())
    c = summary["constants"]
    for name, truth in (("dnv_K", 3.0e-9), ("dnv_n", 2.3)):
        lo, hi = c[name]["interval_95"]
        assert lo <= truth <= hi, (name, lo, hi)
    assert c["dnv_n"]["value"] == pytest.approx(2.3, abs=0.1)
    assert c["dnv_K"]["value"] == pytest.approx(3.0e-9, rel=0.25)
    rows = _rows(SAMPLE)
    noise = np.log(
        _column(rows, "erosion_kg_per_kg") / _dnv(_column(rows, "speed_m_s"), _column(rows, "angle_deg"), 3e-9, 2.3)
    )
    assert summary["rms_log_error"] == pytest.approx(np.sqrt(np.mean(noise**2)), rel=0.1)
    assert sorted(p.name for p in out.iterdir() if not p.name.startswith(".")) == [
        "calibrated.toml",
        "calibration.csv",
        "calibration.json",
        "calibration.png",
    ]


def check_tutorial_case_to_figure(out: Path, stdout: str) -> None:
    """The elastic impact of the tutorial against Hertz (Johnson 1985, §11.4): largest force
    F = (4/3) E* √R δ^(3/2), δ = (15 m V_n² / (16 E* √R))^(2/5), and contact time t_c = 2.868 (m²/(R E*² V_n))^(1/5)
    (alumina R 2.5 mm, 380 GPa, 0.23, 3950 kg/m³, on glass 70 GPa, 0.25; 3.9 m/s at 30°); within 1%."""
    h = _rows(out / "run" / "history.csv")
    e_star = 1.0 / ((1 - 0.23**2) / 380e9 + (1 - 0.25**2) / 70e9)
    m, radius, v_n = _sphere_mass(2.5e-3, 3950.0), 2.5e-3, 3.9 * math.cos(math.radians(30.0))
    overlap = (15.0 * m * v_n**2 / (16.0 * e_star * math.sqrt(radius))) ** 0.4
    assert _column(h, "normal_force_N").max() == pytest.approx(
        4 / 3 * e_star * math.sqrt(radius) * overlap**1.5, rel=0.01
    )
    t = _column(h, "time_s")[_column(h, "overlap_m") > 0]
    assert t[-1] - t[0] == pytest.approx(2.868 * (m**2 / (radius * e_star**2 * v_n)) ** 0.2, rel=0.01)
    assert (out / "glass.toml").is_file() and (out / "run" / "summary.json").is_file()


def check_component_wall_bend(out: Path, stdout: str) -> None:
    """OpenFOAM v1912's own eroded volume Q of the committed bend run (particleErosion, Finnie): the example's
    ``finnie`` law with the run's constants matches it on every face to 1e-6; the DNV rates of ``dnv/faces.csv``
    are their definitions (mm/year = m/s × 1e3 × 365.25 days; life = 5 mm over the rate) and the hot spot lies in
    a band (0.25–4) around DNV-RP-O501's bend model for the flow (123 mm/year at G = 1, coded in
    tests/test_wall_dnv_bend.py) that a unit slip would leave."""
    found = re.search(r"finnie against OpenFOAM's Q on (\d+) faces: largest relative difference (\S+)", stdout)
    assert found and int(found[1]) > 700 and float(found[2]) < 1e-6, stdout
    rows = _rows(out / "dnv" / "faces.csv")
    rate = _column(rows, "thickness_loss_rate_m_s")
    assert _column(rows, "thickness_loss_mm_year") == pytest.approx(rate * 1e3 * 365.25 * 86400.0, rel=1e-9)
    worn = rate > 0
    assert _column(rows, "remaining_life_s")[worn] == pytest.approx(5e-3 / rate[worn], rel=1e-9)
    hot = float(re.search(r"hot spot: (\S+) mm/year", stdout)[1])
    assert hot == pytest.approx(_column(rows, "thickness_loss_mm_year").max(), rel=1e-3)
    assert 0.25 < hot / 123.0 < 4.0
    assert (out / "wall.png").is_file() and (out / "along_the_bend.png").is_file()


def check_default_run(out: Path, stdout: str) -> None:
    """Newton's second law on the saved history: the normal impulse ∫F dt equals the ball's change of normal momentum
    m (V_in − V_out) (alumina, R 2.5 mm, 3950 kg/m³; V_in = 3 cos 30° m/s); within 0.5%."""
    h = _rows(out / "history.csv")
    v = _column(h, "normal_velocity_m_s")
    assert v[0] == pytest.approx(3.0 * math.cos(math.radians(30.0)), rel=1e-9)
    impulse = np.trapezoid(_column(h, "normal_force_N"), _column(h, "time_s"))
    assert impulse == pytest.approx(_sphere_mass(2.5e-3, 3950.0) * (v[0] - v[-1]), rel=0.005)
    assert (out / "summary.json").is_file()


def check_erosion_stream(out: Path, stdout: str) -> None:
    """The stream's flux: impacts on the patch = concentration × speed × cos(angle) × patch area × time / particle
    mass (0.464 kg/m³, 20 m/s, 2 s, sand R 150 µm at 2650 kg/m³), within 2% (the patch side is printed to 3 digits)."""
    m = _sphere_mass(150e-6, 2650.0)
    found = re.findall(r"(\d+) deg:\s+(\d+) impacts on a ([\d.]+) mm patch", stdout)
    assert len(found) == 3
    for angle, impacts, side in found:
        expected = 0.464 * 20.0 * math.cos(math.radians(float(angle))) * (float(side) * 1e-3) ** 2 * 2.0 / m
        assert int(impacts) == pytest.approx(expected, rel=0.02), (angle, impacts, expected)
    assert len(_rows(out / "erosion_angles.csv")) == 3


def check_indentation(out: Path, stdout: str) -> None:
    """The first load step is the elastic limit δ_c: its FE force is Hertz's (4/3) E* √R δ^(3/2) (rigid 10 mm ball,
    steel 210 GPa, ν 0.3), within 2% on the quick mesh."""
    rows = _rows(out / "force_overlap.csv")
    overlap, force = float(rows[0]["overlap_m"]), float(rows[0]["force_N"])
    assert force == pytest.approx(4 / 3 * 210e9 / (1 - 0.3**2) * math.sqrt(10e-3) * overlap**1.5, rel=0.02)


def check_oblique_impact(out: Path, stdout: str) -> None:
    """Rigid-body gross sliding (normal restitution 1 on glass): e_t = 1 − 2μ/tan θ where tan θ > 7μ (μ = 0.092);
    within 0.002."""
    rows = _rows(out / "oblique_impact.csv")
    theta = np.radians(_column(rows, "angle_deg"))
    sliding = np.tan(theta) > 7 * 0.092
    assert sliding.sum() >= 4
    et = _column(rows, "tangential_restitution")[sliding]
    np.testing.assert_allclose(et, 1 - 2 * 0.092 / np.tan(theta[sliding]), atol=0.002)


def check_repeated_impacts(out: Path, stdout: str) -> None:
    """Shakedown: the last impact is elastic, so it returns the energy (e_n > 0.995) and leaves the dent as it was
    (within 1% of the one before)."""
    rows = _rows(out / "repeat.csv")
    assert _column(rows, "normal_restitution")[-1] > 0.995
    dent = _column(rows, "dent_depth_m")
    assert dent[-1] == pytest.approx(dent[-2], rel=0.01)
    assert "shakedown at impact" in stdout


def check_sliding_surface_yield(out: Path, stdout: str) -> None:
    """The pressure's shift towards the trailing edge is proportional to β = (1 − 2ν)/(2(1 − ν)) (Johnson 1985 §7):
    the shift per unit β at ν = 0.3 and 0.45 agree within 5%."""
    rows = re.findall(r"^\s+(0\.\d\d)\s+([\d.]+)\s+([-+][\d.]+)\s+([-+][\d.]+)", stdout, re.MULTILINE)
    per_beta = {float(nu): float(ratio) for nu, _, _, ratio in rows}
    assert set(per_beta) == {0.3, 0.45}
    assert per_beta[0.3] < 0 and per_beta[0.45] == pytest.approx(per_beta[0.3], rel=0.05)
    surface = (out / "surface.csv").read_text().splitlines()
    assert {line.split(",")[0] for line in surface[2:]} == {"0.3", "0.45"}


def check_sweep_angles(out: Path, stdout: str) -> None:
    """Coulomb impulse in gross sliding (rigid body): tan(rebound) = (tan θ − μ(1 + e_n))/e_n where
    tan θ > 3.5 μ (1 + e_n) (μ = 0.092), within 0.05°; the spec written equals examples/sweep_angles.toml."""
    rows = _rows(out / "run" / "results.csv")
    assert len(rows) == 17 and {r["status"] for r in rows} == {"ok"}
    theta = np.radians(_column(rows, "impact.angle_deg"))
    e_n = _column(rows, "normal_restitution")
    sliding = np.tan(theta) > 3.5 * 0.092 * (1 + e_n)
    assert sliding.sum() >= 8
    expected = np.degrees(np.arctan((np.tan(theta) - 0.092 * (1 + e_n)) / e_n))
    np.testing.assert_allclose(_column(rows, "rebound_angle_deg")[sliding], expected[sliding], atol=0.05)
    shipped = tomllib.loads((ROOT / "examples" / "sweep_angles.toml").read_text())
    assert tomllib.loads((out / "sweep_angles.toml").read_text()) == shipped


def check_worn_surface_pressure(out: Path, stdout: str) -> None:
    """The gap between the 10 mm ball, r²/(2R), and the pit's floor, −D (1 − r²/a₀²)² with D = 0.5 a₀²/R, is smallest
    on the ring r = a₀/√2: the ball first touches there at δ = 0.375 a₀²/R (closed form); within 0.1% (printed to 4
    digits)."""
    first = float(re.search(r"first contact at δ = ([\d.e+-]+) m", stdout).group(1))
    a0 = 0.01 * 10e-3
    assert first == pytest.approx(0.375 * a0**2 / 10e-3, rel=1e-3)
    assert (out / "profiles.csv").is_file()


CHECKS = {name.removeprefix("check_"): f for name, f in globals().items() if name.startswith("check_")}


def test_every_example_has_a_check():
    assert sorted(CHECKS) == sorted(p.stem for p in EXAMPLES)


@pytest.mark.parametrize("script", EXAMPLES, ids=lambda p: p.name)
def test_example_runs(script, tmp_path):
    env = dict(os.environ, IMPACTWEAR_QUICK="1", MPLBACKEND="Agg", IMPACTWEAR_EXAMPLE_OUT=str(tmp_path / "out"))
    cwd = tmp_path / "cwd"
    cwd.mkdir()
    proc = subprocess.run([sys.executable, str(script)], cwd=cwd, env=env, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, f"{script.name} failed:\n{proc.stdout[-2000:]}\n{proc.stderr[-4000:]}"
    assert "Warning" not in proc.stderr, proc.stderr[-2000:]
    assert [p.name for p in (tmp_path / "out").iterdir()] == [script.stem]  # its own folder, nothing else
    assert not any(cwd.iterdir())
    CHECKS[script.stem](tmp_path / "out" / script.stem, proc.stdout)


def test_calibration_sample_is_the_stated_law():
    """wear/app/data/calibration_sample.csv is what calibrate_your_data.py says: DNV-RP-O501 with K = 3.0e-9,
    n = 2.3 at angles 10-80° and speeds 15, 30, 60 m/s, times exp(0.10 z), z from numpy default_rng(2026) in file
    order, rounded to 4 significant digits."""
    rows = _rows(SAMPLE)
    angle, speed = _column(rows, "angle_deg"), _column(rows, "speed_m_s")
    np.testing.assert_array_equal(angle, np.tile(np.arange(10.0, 81.0, 10.0), 3))
    np.testing.assert_array_equal(speed, np.repeat([15.0, 30.0, 60.0], 8))
    z = np.random.default_rng(2026).standard_normal(angle.size)
    expected = _dnv(speed, angle, 3.0e-9, 2.3) * np.exp(0.10 * z)
    np.testing.assert_allclose(_column(rows, "erosion_kg_per_kg"), expected, rtol=5e-4)
