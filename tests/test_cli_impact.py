"""The ``impactwear impact`` command: default case, overrides, JSON, one-line errors with exit status 2."""

import json
import math
import subprocess
import sys

import pytest

from contact import Material, simulate_impact
from wear.app.cli import main


def test_default_case_runs_and_prints_table(capsys):
    assert main(["impact"]) == 0
    out = capsys.readouterr().out
    assert "normal restitution" in out and "contact time" in out


def test_json_matches_api(capsys):
    assert main(["impact", "--json", "--angle", "45", "--speed", "2", "--set", "plate.rigid=true"]) == 0
    data = json.loads(capsys.readouterr().out)
    r = simulate_impact(2.5e-3, Material(E=380e9, nu=0.23, density=4000.0), Material.rigid(), 2.0, 45.0, 0.092)
    assert data["result"]["spin"] == pytest.approx(r.spin, rel=1e-12)
    assert data["case"]["impact"]["angle"] == 45.0
    # rigid-body gross sliding check (Chung & Ooi 2011 test 4 form): e_t = 1 - 2 mu / tan(theta)
    assert data["result"]["tangential_restitution"] == pytest.approx(
        1 - 2 * 0.092 / math.tan(math.radians(45)), rel=5e-3
    )


def test_config_file(tmp_path, capsys):
    path = tmp_path / "case.toml"
    path.write_text("[impact]\nangle = 0\nrestitution = 0.5\n[plate]\nrigid = true\n")
    assert main(["impact", "--config", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["result"]["normal_restitution"] == pytest.approx(0.5, rel=5e-3)
    assert data["result"]["tangential_restitution"] is None  # normal impact: undefined, null in JSON


@pytest.mark.parametrize(
    "argv, name",
    [
        (["--angle", "95"], "impact.angle=95"),
        (["--speed", "nan"], "impact.speed=nan"),
        (["--radius", "-1"], "ball.radius=-1"),
        (["--normal-model", "jkr"], "impact.normal_model"),
        (["--set", "ball.E=210"], "ball.E=210"),
        (["--set", "impact.sped=3"], "impact.sped"),
        (["--config", "/nonexistent/case.toml"], "config="),
        (["--normal-model", "thornton"], "yield_strength"),
    ],
)
def test_bad_input_one_line_exit_2(argv, name, capsys):
    assert main(["impact", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert name in err and "\n" not in err and "Traceback" not in err


def test_console_script_subprocess():
    proc = subprocess.run(
        [sys.executable, "-m", "wear.app.cli", "impact", "--angle", "120"], capture_output=True, text=True, timeout=120
    )
    assert proc.returncode == 2
    assert proc.stderr.strip().count("\n") == 0 and "impact.angle=120" in proc.stderr


def test_json_with_rigid_plate_is_valid_json(capsys):
    # JSON has no inf: a rigid plate's E is written as "inf" in both the case and the result.
    assert main(["impact", "--json", "--set", "plate.rigid=true", "--set", "plate.E=inf"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["case"]["plate"]["E"] == "inf" and data["result"]["plate"]["E"] == "inf"
