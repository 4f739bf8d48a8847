"""Bad input names what the user gave: a mistyped table or key of a partial case file (not the table it was meant to
be, reported missing), a key given twice, the option or key behind a derived quantity (``--max-force``,
``impact.speed``, not the FE plate's ``max_overlap``), a list of angles starting with a negative one, and a
malformed ``--scheduler``. Each: exit 2, one stderr line, nothing written."""

import math

import pytest
from refusal import refused

from contact import effective_modulus
from wear.app.cli import build_parser, main
from wear.case import default_case
from wear.chain.estimate import estimate_impact
from wear.chain.indent import largest_force


@pytest.mark.parametrize(
    "text, expected",
    [
        ("[plat]\nE = 1.1e11\n", "[plat] is not a known case table (did you mean [plate]?)"),
        ("[impact]\nangel = 30\n", "impact.angel is not a known key (did you mean impact.angle?)"),
        ("impact = 3\n", "impact=3 is not a table: write it as [impact]"),
        ("[impact.sub]\n", "impact.sub is not a known key"),
        ('[repeat]\nimpacts = "10"\n', "repeat.impacts='10' is not an integer"),
        ("[impact]\nangle = 30\nangle = 40\n", "impact.angle is given twice (lines 2 and 3)"),
        ("[impact]\nangle = 30\n[impact]\nspeed = 2.0\n", "[impact] is declared twice (lines 1 and 3)"),
    ],
)
def test_partial_case_file_names_the_mistyped_key_before_a_missing_table(text, expected, tmp_path, capsys):
    path = tmp_path / "case.toml"
    path.write_text(text, encoding="utf-8")
    err = refused(["run", str(path)], tmp_path, capsys)
    assert expected in err and "is missing" not in err


def test_a_partial_case_file_without_typos_still_names_the_missing_table(tmp_path, capsys):
    path = tmp_path / "case.toml"
    path.write_text("[ball]\nradius = 1e-3\n", encoding="utf-8")
    assert "[plate] is missing" in refused(["run", str(path)], tmp_path, capsys)


def test_max_force_beyond_the_plate_names_the_option_and_its_largest_value(tmp_path, capsys):
    err = refused(["indent", "--max-force", "1e12"], tmp_path, capsys)
    assert err.startswith("impactwear indent: error: --max-force=1e+12 is out of range: must be in (0, ")
    assert f"{largest_force(default_case('indent')):.5g}] N" in err
    assert "max_overlap" not in err


def test_largest_force_of_an_elastic_plate_is_hertz_at_an_overlap_of_one_radius():
    """Elastic plate: the force estimate is Hertz's, so the largest force is F(δ = R) = 4/3 E* R^2 (Johnson 1985,
    Eq. 4.23)."""
    case = default_case("indent").with_(plate={"yield_strength": math.inf})
    e_star = effective_modulus(case.ball.material(), case.plate.material())
    assert largest_force(case) == pytest.approx(4.0 / 3.0 * e_star * case.ball.radius**2, rel=1e-8)


def test_impact_speed_beyond_the_plate_names_the_key_and_a_speed_that_fits(tmp_path, capsys):
    err = refused(["run", "--set", "impact.speed=1000"], tmp_path, capsys)
    assert "impact.speed=1000 m/s drives the ball" in err and "max_overlap" not in err
    largest = float(err.rsplit("impact.speed <= ", 1)[1].split()[0])
    case = default_case("run")
    # the speed it names loads the FE plate within the ball radius, and not far below it (Hertz's 4/5 power)
    depth = (1.0 + case.fem.overshoot) * estimate_impact(case.with_(impact={"speed": largest})).max_overlap
    assert 0.5 * case.ball.radius < depth <= case.ball.radius


@pytest.mark.parametrize("value", ["-5,30", "-5", "-1e-6,30"])
def test_erode_angles_starting_with_a_negative_angle_names_the_option_and_range(value, tmp_path, capsys):
    err = refused(["erode", "--angles", value], tmp_path, capsys)
    assert "--angles: angle=-" in err and "must be in [0, 85] deg" in err


def test_sweep_scheduler_that_is_no_address_names_the_option(tmp_path, capsys):
    sweep = tmp_path / "sweep.toml"
    sweep.write_text('[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [10, 30]\n', encoding="utf-8")
    err = refused(["sweep", str(sweep), "--scheduler", "garbage"], tmp_path, capsys)
    assert "--scheduler='garbage' is not a Dask scheduler address" in err


def test_reproduce_only_an_unknown_figure_names_the_option_and_writes_nothing(tmp_path, capsys):
    err = refused(["reproduce", "--only", "nonexistent"], tmp_path, capsys)
    assert "--only='nonexistent' is not a figure: choose from " in err


def test_validate_writes_its_report_in_its_own_folder_by_default():
    """The default --out is not the current folder, whose validation.md (e.g. the committed one) it would replace."""
    args = build_parser().parse_args(["validate"])
    assert args.out == "impactwear-validate"


def test_sweep_scheduler_that_cannot_be_reached_is_refused_before_the_folder_is_made(tmp_path, capsys):
    pytest.importorskip("distributed")
    sweep = tmp_path / "sweep.toml"
    sweep.write_text('[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [10, 30]\n', encoding="utf-8")
    out = tmp_path / "out"
    assert main(["sweep", str(sweep), "--scheduler", "tcp://127.0.0.1:9", "--out", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "scheduler='tcp://127.0.0.1:9': cannot connect" in err
    assert not out.exists()
