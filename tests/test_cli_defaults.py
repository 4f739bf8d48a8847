"""Each command's default case round-trips: --print-default → TOML file → the command reads the same case; empty
tables give the default; a key unknown to the schema is a one-line error naming it."""

import json
from pathlib import Path

import pytest

from wear.app.cli import build_parser, main
from wear.app.commands.common import case_from_args
from wear.app.sweep.spec import load_sweep
from wear.case import JOBS, default_case, load_case

COMMANDS = ("run", "repeat", "impact", "indent", "erode")


def _case_read_by(command: str, path) -> object:
    args = build_parser().parse_args([command, *(["--config"] if command in ("impact", "indent") else []), str(path)])
    return case_from_args(args, command)


@pytest.mark.parametrize("command", COMMANDS)
def test_print_default_round_trips_through_the_command(command, tmp_path, capsys):
    assert main([command, "--print-default"]) == 0
    text = capsys.readouterr().out
    path = tmp_path / "case.toml"
    path.write_text(text)
    assert _case_read_by(command, path) == default_case(command)
    for table in JOBS[command].tables:  # every table the command reads is printed
        assert f"[{table}]" in text


@pytest.mark.parametrize("command", COMMANDS)
def test_empty_tables_give_the_commands_default(command, tmp_path):
    path = tmp_path / "case.toml"
    path.write_text("".join(f"[{t}]\n" for t in JOBS[command].tables))
    assert _case_read_by(command, path) == default_case(command)


def test_impact_output_from_the_printed_default_equals_the_default(tmp_path, capsys):
    assert main(["impact", "--json"]) == 0
    direct = json.loads(capsys.readouterr().out)
    assert main(["impact", "--print-default"]) == 0
    path = tmp_path / "case.toml"
    path.write_text(capsys.readouterr().out)
    assert main(["impact", "--config", str(path), "--json"]) == 0
    assert json.loads(capsys.readouterr().out) == direct


@pytest.mark.parametrize("command", COMMANDS)
def test_unknown_key_is_one_line_naming_it(command, tmp_path, capsys):
    path = tmp_path / "case.toml"
    path.write_text("".join(f"[{t}]\n" for t in JOBS[command].tables if t != "impact") + "[impact]\nsped = 3.0\n")
    flag = ["--config"] if command in ("impact", "indent") else []
    assert (
        main(
            [command, *flag, str(path), "--out", str(tmp_path / "out")]
            if command != "impact"
            else [command, *flag, str(path)]
        )
        == 2
    )
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "impact.sped is not a known key" in err
    assert not (tmp_path / "out").exists()


#: The case and sweep files of examples/ (its ruff.toml is the formatter's, not a case).
EXAMPLE_CASES = sorted(
    p for p in (Path(__file__).resolve().parents[1] / "examples").glob("*.toml") if p.name != "ruff.toml"
)


@pytest.mark.parametrize("path", EXAMPLE_CASES, ids=lambda p: p.name)
def test_example_case_files_are_valid(path):
    """The case and sweep files shipped in examples/ stay valid against the schema."""
    if "[sweep]" in path.read_text(encoding="utf-8"):
        assert load_sweep(path).cases
    else:
        case = load_case(path, "erode")
        assert case.wear.pressure == "paper" and case.erosion.seed == 2012  # the file's own values were read
