"""Flags and defaults that behave the same in every command: --quiet, --print-default (with a case file, options
and --json), negative numbers in exponent notation, one meaning for a yield strength, the erosion stream's supply,
and a run case file given to the other commands."""

from __future__ import annotations

import json
import math

import pytest

from wear.app.cli import build_parser, main
from wear.case import JOBS, dump_case, parse_case

CASE_COMMANDS = ("run", "impact", "indent", "repeat", "erode", "calibrate")


@pytest.mark.parametrize("command", CASE_COMMANDS)
def test_every_case_command_has_quiet_and_both_spellings_of_print_default(command):
    parser = build_parser()
    sub = parser._subparsers._group_actions[0].choices[command]  # the command's parser, as argparse built it
    flags = {s for a in sub._actions for s in a.option_strings}
    assert {"--print-default", "--print-defaults", "--set"} <= flags
    assert command == "impact" or "--quiet" in flags  # impact prints one table and has no progress to silence


@pytest.mark.parametrize("command", CASE_COMMANDS)
def test_print_default_with_a_case_file_and_options_prints_the_case_it_would_run(command, tmp_path, capsys):
    """``--print-default`` with a case file and ``--set`` prints the case the command would run (it silently printed
    the default); with ``--json`` as JSON (it silently ignored --json)."""
    case_file = tmp_path / "case.toml"
    case_file.write_text("[ball]\nradius = 0.004\n[plate]\n[impact]\n[wear]\n")
    where = ["--config", str(case_file)] if command in ("impact", "indent") else [str(case_file)]
    if command == "calibrate":
        where = ["--set", "ball.radius=0.004"]
    setting = ["--set", "plate.nu=0.31"]
    assert main([command, *where, *setting, "--print-default"]) == 0
    text = capsys.readouterr().out
    assert "the case it would run" in text
    case = parse_case(text, command)
    assert case.ball.radius == 0.004 and case.plate.nu == 0.31
    assert main([command, *where, *setting, "--print-default", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["ball"]["radius"] == 0.004 and data["plate"]["nu"] == 0.31
    assert main([command, "--print-default"]) == 0
    text = capsys.readouterr().out
    assert "the default case" in text and parse_case(text, command) == JOBS[command].default_case()


def test_a_key_the_command_does_not_read_is_refused(capsys):
    """``indent --set impact.speed=7.5`` was accepted and had no effect: indent reads no [impact]."""
    assert main(["indent", "--set", "impact.speed=7.5", "--print-default"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "impact.speed" in err[0] and "[ball], [plate], [fem]" in err[0]


def test_print_default_shows_every_key_with_its_range(capsys):
    """Keys without a default value (restitution's dashpot, the time step, …) are printed as comments saying what
    their absence means, and every key carries its valid range or choices."""
    assert main(["run", "--print-default"]) == 0
    text = capsys.readouterr().out
    for key in ("restitution", "scheme", "time_step", "max_iterations", "plate_mesh", "block_thickness"):
        line = next(line for line in text.splitlines() if line.lstrip("# ").startswith(f"{key} ="))
        assert any(w in line for w in ("in [", "in (", "> ", "one of", "text", "true or false")), line


@pytest.mark.parametrize(
    ("args", "named"),
    [
        (["indent", "--max-overlap", "-1e-6"], "--max-overlap=-1e-06"),
        (["impact", "--angle", "-1e1"], "impact.angle=-10"),
        (["impact", "--speed", "-2.5E+1"], "impact.speed=-25"),
    ],
)
def test_negative_numbers_in_exponent_notation_reach_the_range_check(args, named, tmp_path, capsys):
    """``--max-overlap -1e-6`` was argparse's "expected one argument": now the option's own range check names it."""
    assert main([*args, *(["--out", str(tmp_path / "o")] if args[0] == "indent" else [])]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and named in err[0] and "out of range" in err[0], err


def test_yield_strength_means_the_same_in_indent_and_in_case_files(tmp_path, capsys):
    """``--yield-strength 0`` meant "elastic" in indent and was an error in case files: now both reject 0, naming
    plate.yield_strength, and both take inf as "never yields"."""
    assert main(["indent", "--yield-strength", "0", "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert "plate.yield_strength=0" in err
    with pytest.raises(ValueError, match="plate.yield_strength=0"):
        parse_case("[ball]\n[plate]\nyield_strength = 0\n[impact]\n[wear]\n", "run")
    assert main(["indent", "--yield-strength", "inf", "--print-default", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["plate"]["yield_strength"] is None  # never yields: no value


def test_indent_help_says_where_the_path_goes_without_max_overlap_or_force():
    parser = build_parser()
    sub = parser._subparsers._group_actions[0].choices["indent"]
    text = " ".join(sub.format_help().split())
    assert "w = δ/δ_c = 20" in text and "a = 0.05 R" in text


def test_erosion_supply_is_concentration_or_mass_flux_not_both(tmp_path, capsys):
    out = tmp_path / "o"
    assert main(["erode", "--set", "erosion.concentration=1", "--set", "erosion.mass_flux=1", "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "erosion.concentration=1" in err[0] and "erosion.mass_flux=1" in err[0]
    assert not out.exists()


def test_erode_grid_too_coarse_names_the_grid(tmp_path, capsys):
    """``--set erosion.grid=64`` named ``patch_size``, which the user did not set: now the grid, and the least grid
    that works."""
    assert main(["erode", "--set", "erosion.grid=64", "--out", str(tmp_path / "o"), "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "grid=64" in err[0] and "use grid >=" in err[0]


@pytest.mark.parametrize("command", ["impact", "indent", "erode"])
def test_a_run_case_file_is_read_by_the_other_commands(command, tmp_path, capsys):
    """A run case holds everything impact, indent and erode need: they read it (erode notes that the stream cannot
    use the FE pressure of the run case and uses the closed form instead)."""
    case_file = tmp_path / "run.toml"
    case_file.write_text(dump_case(JOBS["run"].default_case(), JOBS["run"].tables))
    where = ["--config", str(case_file)] if command in ("impact", "indent") else [str(case_file)]
    assert main([command, *where, "--print-default", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    run = JOBS["run"].default_case()
    assert data["ball"]["radius"] == run.ball.radius and data["plate"]["E"] == run.plate.E
    if command == "impact":
        assert main([command, *where, "--json"]) == 0
        result = json.loads(capsys.readouterr().out)["result"]
        assert math.isfinite(result["normal_restitution"])
    if command == "erode":
        out = tmp_path / "o"
        small = [
            "--set",
            "erosion.grid=128",
            "--set",
            "erosion.table_speeds=2",
            "--set",
            "erosion.frames=1",
            "--set",
            "erosion.samples=3",
            "--set",
            "erosion.exposure_time=100.0",
        ]
        assert main([command, *where, *small, "--out", str(out), "--quiet"]) == 0
        notes = json.loads((out / "summary.json").read_text())["notes"]
        assert any("wear.pressure='fe'" in n for n in notes) and "wear.pressure='fe'" in capsys.readouterr().err
