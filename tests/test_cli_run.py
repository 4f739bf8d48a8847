"""``impactwear run``: the default case runs; malformed case files give one line naming the key, exit status 2 and
no output; the default round-trips through --print-default."""

import json

import pytest

from wear.app.cli import main
from wear.case import JOBS, Case, dump_case, load_case

GOOD = dump_case(Case(), JOBS["run"].tables)


def _replace(old, new):
    assert old in GOOD
    return GOOD.replace(old, new, 1)


# (case text, text the one-line error must contain): at least 10 kinds of malformed case
MALFORMED = {
    "unknown key": (_replace("alpha = 1.0", "alpha = 1.0\nalfa = 2.0"), "wear.alfa"),
    "negative K": (_replace("K = 1e-11", "K = -1.0"), "wear.K=-1"),
    "string for a number": (_replace("speed = 3.0", 'speed = "fast"'), "impact.speed='fast'"),
    "angle 120": (_replace("angle = 30.0", "angle = 120.0"), "impact.angle=120"),
    "missing table": (GOOD.replace("[wear]", "[unused]").split("[unused]")[0], "[wear] is missing"),
    "unknown table": (GOOD + "\n[turbo]\nx = 1\n", "[turbo]"),
    "modulus in GPa": (_replace("E = 1.14e11", "E = 114.0"), "plate.E=114"),
    "bad choice": (_replace('pressure = "fe"', 'pressure = "guess"'), "wear.pressure='guess'"),
    "not TOML": ("[ball\nradius = ", "not valid TOML"),
    "boolean as string": (_replace("figures = true", 'figures = "yes"'), "output.figures='yes'"),
    "integer expected": (_replace("points_across = 64", "points_across = 64.5"), "wear.points_across=64.5"),
    "nu out of range": (_replace("nu = 0.34", "nu = 0.7"), "plate.nu=0.7"),
    "negative density": (_replace("density = 3950.0", "density = -1.0"), "ball.density=-1"),
    "missing plate mesh file": (GOOD + "\n", None),
}
MALFORMED["missing plate mesh file"] = (
    _replace('plate_mesh = ""', 'plate_mesh = "nowhere.vtu"'),
    "output.plate_mesh='nowhere.vtu'",
)


@pytest.mark.parametrize("kind", sorted(MALFORMED))
def test_malformed_case_one_line_exit_2_no_output(kind, tmp_path, capsys):
    text, expected = MALFORMED[kind]
    case_file = tmp_path / "case.toml"
    case_file.write_text(text)
    out = tmp_path / "out"
    status = main(["run", str(case_file), "--out", str(out), "--quiet"])
    err = capsys.readouterr().err.strip()
    assert status == 2
    assert len(err.splitlines()) == 1, err
    assert expected in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["case.toml"]


def test_default_case_file_matches_python_default(capsys):
    """--print-default prints Case() (one documented default), and no file means that case."""
    assert main(["run", "--print-default"]) == 0
    assert capsys.readouterr().out.endswith(GOOD)
    assert load_case(None, "run") == Case()


def test_run_case_without_fe_from_cli(tmp_path, capsys):
    text = _replace('pressure = "fe"', 'pressure = "thornton"').replace('coupling = "two-way"', 'coupling = "none"')
    text = text.replace('speed = "local"', 'speed = "sliding"')
    text = text.replace("render = true", "render = false").replace("figures = true", "figures = false")
    case_file = tmp_path / "case.toml"
    case_file.write_text(text)
    status = main(["run", str(case_file), "--out", str(tmp_path / "out"), "--json"])
    assert status == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["wear"]["volume_m3"] > 0
    assert (tmp_path / "out" / "summary.json").is_file()


@pytest.mark.filterwarnings("ignore:elastic ball")
def test_default_run_succeeds(tmp_path, capsys):
    """`impactwear run` with no case file runs the default case (two-way FE coupling)."""
    status = main(["run", "--out", str(tmp_path / "out"), "--json"])
    assert status == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["coupling"]["converged"]
    assert summary["yield"]["fe_first_yield_force"] is not None
    assert summary["regime"] in ("surface-plastic", "fully-plastic")
    assert summary["dent"]["max_depth_m"] > 0
    # the FE first-yield force against the exact closed form F_c (errata Eq. 18 with C(0.34)), fem's 3% criterion
    assert summary["yield"]["fe_first_yield_force"] == pytest.approx(summary["yield"]["F_c_exact"], rel=0.03)
    for name in ("surface.vtu", "plate.vtu", "plate_fe.vtu", "summary.json", "history.csv", "pressure.npz"):
        assert (tmp_path / "out" / name).is_file()
