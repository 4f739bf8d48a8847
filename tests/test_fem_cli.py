"""``impactwear indent``: outputs and bad input (issue 3, CLI). Elastic plate, tiny path: checks the plumbing; the
physics is checked in the other test_fem_* files."""

import json

from wear.app.cli import main


def test_indent_cli_writes_outputs(tmp_path, capsys):
    out = tmp_path / "ind"
    code = main(
        [
            "indent",
            "--yield-strength",
            "inf",
            "--max-overlap",
            "1e-7",
            "--load-steps",
            "3",
            "--unload-steps",
            "2",
            "--out",
            str(out),
            "--json",
        ]
    )
    assert code == 0
    summary = json.loads(capsys.readouterr().out)
    for name in (
        "force_overlap.csv",
        "pressure.csv",
        "summary.json",
        "plate.vtu",
        "pressure.png",
        "force_overlap.png",
        "plastic_zone.png",
        "residual_depth.csv",
    ):
        assert (out / name).is_file(), name
    # Hertz (Johnson 1985 Eq. 4.23) at δ = 1e-7 m, R = 10 mm, E* = 230.8 GPa: F = 0.9730 N
    assert abs(summary["max_force_N"] / 0.97301 - 1.0) < 0.02
    assert summary["fe_first_yield"] is None


def test_indent_cli_bad_input_is_one_line(tmp_path, capsys):
    code = main(["indent", "--max-overlap=-1e-7", "--out", str(tmp_path / "x")])
    assert code == 2
    err = capsys.readouterr().err
    assert "--max-overlap=-1e-07 is out of range" in err and len(err.strip().splitlines()) == 1
