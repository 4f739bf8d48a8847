"""Sweep files: expansion, validation before anything runs, bad files, stable case ids (wear.app.sweep.spec).

References: the Cartesian-product and merge rules are those stated in issue 5 §3 (``[grid]`` dotted keys to lists,
``[[cases]]`` explicit list, ``[base]`` keys left out come from the default case); the case-id rule is the one in
the sweep_spec module docstring (SHA-256 of the canonical JSON), recomputed here independently with hashlib.
"""

from __future__ import annotations

import hashlib
import json
import re
import subprocess
import sys
import textwrap

import pytest
from refusal import refused

from wear.app import cli
from wear.app.sweep.spec import case_id, load_sweep, parse_sweep
from wear.case import default_case


def _write(tmp_path, text: str, name: str = "sweep.toml"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    return path


def test_grid_is_cartesian_product_first_key_slowest(tmp_path):
    spec = load_sweep(
        _write(
            tmp_path,
            """
            [sweep]
            stage = "impact"
            [base]
            impact.speed = 2.0
            [grid]
            "impact.angle" = [10, 30, 50]
            impact.friction = [0.1, 0.3]
            """,
        )
    )
    assert spec.stage == "impact"
    assert spec.axes == {"impact.angle": [10, 30, 50], "impact.friction": [0.1, 0.3]}
    got = [(c.case["impact"]["angle"], c.case["impact"]["friction"]) for c in spec.cases]
    assert got == [(10.0, 0.1), (10.0, 0.3), (30.0, 0.1), (30.0, 0.3), (50.0, 0.1), (50.0, 0.3)]
    default = default_case("impact").to_dict()
    for c in spec.cases:
        assert c.case["impact"]["speed"] == 2.0  # from [base]
        assert c.case["ball"] == default["ball"]  # left out: the embedded default case
        assert c.case["plate"] == default["plate"]
        assert set(c.case) == {"ball", "plate", "impact"}  # only the tables the impact stage reads
    assert len({c.case_id for c in spec.cases}) == 6
    assert spec.swept_keys == ["impact.angle", "impact.friction"]


def test_explicit_cases_override_base(tmp_path):
    spec = load_sweep(
        _write(
            tmp_path,
            """
            [sweep]
            stage = "impact"
            description = "two cases"
            [base]
            ball.radius = 1e-3
            [[cases]]
            impact.angle = 10
            [[cases]]
            "impact.angle" = 40
            impact.speed = 2.0
            ball.radius = 2e-3
            """,
        )
    )
    assert spec.axes is None
    assert [c.case["impact"]["angle"] for c in spec.cases] == [10.0, 40.0]
    assert [c.case["ball"]["radius"] for c in spec.cases] == [1e-3, 2e-3]
    assert spec.cases[1].case["impact"]["speed"] == 2.0
    assert spec.cases[0].case["impact"]["speed"] == default_case("impact").impact.speed


def test_case_id_matches_independent_sha256_of_canonical_json():
    """The id is sha256 of the canonical JSON (sorted keys, compact, ints as floats) of {"case", "stage"}."""
    case = {"impact": {"speed": 3.9, "angle": 30, "name": "x", "rigid": False, "limit": None}, "ball": {"E": 1e9}}
    text = (
        '{"case":{"ball":{"E":1000000000.0},"impact":{"angle":30.0,"limit":null,"name":"x","rigid":false,'
        '"speed":3.9}},"stage":"impact"}'
    )
    assert case_id("impact", case) == hashlib.sha256(text.encode()).hexdigest()[:16]


def test_case_id_independent_of_dict_order_int_float_and_negative_zero():
    a = {"impact": {"speed": 3.9, "angle": 30}, "ball": {"radius": 2.5e-3, "E": float("inf"), "x": 0.0}}
    b = {"ball": {"x": -0.0, "E": float("inf"), "radius": 2.5e-3}, "impact": {"angle": 30.0, "speed": 3.9}}
    assert case_id("impact", a) == case_id("impact", b)
    assert case_id("impact", a) != case_id("run", a)  # the stage is part of what a result means
    c = json.loads(json.dumps(a))
    c["impact"]["speed"] = 3.9000000000000004  # one ulp away is another case
    assert case_id("impact", c) != case_id("impact", a)


def test_case_id_independent_of_python_hash_seed(tmp_path):
    """The same sweep file gives the same ids in processes with different PYTHONHASHSEED."""
    path = _write(tmp_path, '[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [5, 45]\n"plate.name" = ["a", "b"]\n')
    code = f"from wear.app.sweep.spec import load_sweep; print([c.case_id for c in load_sweep({str(path)!r}).cases])"
    outs = {
        subprocess.run(
            [sys.executable, "-c", code], env={"PYTHONHASHSEED": seed, "PATH": ""}, capture_output=True, text=True
        ).stdout
        for seed in ("1", "12345")
    }
    assert len(outs) == 1
    assert outs.pop().strip() == str([c.case_id for c in load_sweep(path).cases])


def test_same_case_same_id_whether_written_in_base_grid_or_cases(tmp_path):
    """A case's id depends on the full case, not on how the sweep file spelled it."""
    grid = load_sweep(_write(tmp_path, '[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [20.0]\n', "a.toml"))
    cases = load_sweep(
        _write(tmp_path, '[sweep]\nstage = "impact"\n[base]\nimpact.angle = 20\n[[cases]]\nimpact.friction = 0.092\n')
    )
    assert grid.cases[0].case_id == cases.cases[0].case_id


# Each bad file: (TOML text, the key the one-line message must name).
BAD_FILES = {
    "toml syntax": ('[sweep]\nstage = "impact\n', "not valid TOML"),
    "missing [sweep]": ('[grid]\n"impact.angle" = [1]\n', "sweep"),
    "missing stage": ('[sweep]\n[grid]\n"impact.angle" = [1]\n', "sweep.stage"),
    "unknown stage": ('[sweep]\nstage = "impacts"\n[grid]\n"impact.angle" = [1]\n', "sweep.stage"),
    "unknown [sweep] key": ('[sweep]\nstage = "impact"\nworkers = 2\n[grid]\n"impact.angle" = [1]\n', "sweep.workers"),
    "unknown table": ('[sweep]\nstage = "impact"\n[grids]\n"impact.angle" = [1]\n', "grids"),
    "neither grid nor cases": ('[sweep]\nstage = "impact"\n', "grid/cases"),
    "both grid and cases": (
        '[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [1]\n[[cases]]\nimpact.angle = 2\n',
        "grid/cases",
    ),
    "grid value not a list": ('[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = 10\n', "grid.impact.angle"),
    "empty grid list": ('[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = []\n', "grid.impact.angle"),
    "repeated grid value": (
        '[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [10, 20, 10.0]\n',
        "grid.impact.angle[2]",
    ),
    "unknown case key in grid": ('[sweep]\nstage = "impact"\n[grid]\n"impact.angel" = [10]\n', "impact.angel"),
    "out of range in grid": ('[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [10, 120]\n', "impact.angle=120"),
    "string for a number": ('[sweep]\nstage = "impact"\n[[cases]]\nimpact.speed = "fast"\n', "impact.speed"),
    "bad key in base": (
        '[sweep]\nstage = "impact"\n[base]\nplate.nu = 0.5\n[grid]\n"impact.angle" = [1, 2]\n',
        "base: plate.nu=0.5",
    ),
    "duplicate explicit case": (
        '[sweep]\nstage = "impact"\n[[cases]]\nimpact.angle = 5\n[[cases]]\nimpact.angle = 5.0\n',
        "cases[1]",
    ),
    "unknown case table": ('[sweep]\nstage = "impact"\n[[cases]]\nimpcat.angle = 5\n', "impcat"),
    "empty explicit case": ('[sweep]\nstage = "impact"\n[[cases]]\n[[cases]]\nimpact.angle = 5\n', "cases[0]"),
}


@pytest.mark.parametrize("kind", list(BAD_FILES))
def test_bad_sweep_file_exits_2_with_one_line_naming_the_key(kind, tmp_path, capsys):
    text, key = BAD_FILES[kind]
    line = refused(["sweep", str(_write(tmp_path, text)), "--quiet"], tmp_path, capsys)
    assert line.startswith("impactwear sweep: error: ")
    assert key in line, line  # validated before anything runs or is written


def test_missing_file_exits_2(tmp_path, capsys):
    assert cli.main(["sweep", str(tmp_path / "nope.toml"), "--out", str(tmp_path / "o")]) == 2
    assert "no such file" in capsys.readouterr().err


def test_parse_sweep_from_dict_rejects_non_table_grid():
    with pytest.raises(ValueError, match=r"^grid must be a table"):
        parse_sweep({"sweep": {"stage": "impact"}, "grid": [1, 2]})


def test_run_and_indent_stages_lay_base_over_the_default_run_case(tmp_path):
    """The FE stages start from the default run case (wear.Case()), the impact stage from impactwear impact's
    default case; only the tables a stage reads enter its cases."""
    run_default = default_case("run").to_dict()
    spec = load_sweep(_write(tmp_path, '[sweep]\nstage = "run"\n[grid]\n"wear.K" = [1e-12, 1e-11]\n'))
    assert [c.case["wear"]["K"] for c in spec.cases] == [1e-12, 1e-11]
    assert set(spec.cases[0].case) == {"ball", "plate", "impact", "wear", "fem"}
    for table in ("ball", "plate", "impact"):
        for key, value in run_default[table].items():
            assert spec.cases[0].case[table][key] == value, f"{table}.{key}"
    indent = load_sweep(_write(tmp_path, '[sweep]\nstage = "indent"\n[grid]\n"fem.mesh_scale" = [2.0, 4.0]\n'))
    assert set(indent.cases[0].case) == {"ball", "plate", "impact", "fem"}
    assert indent.cases[0].case["plate"]["yield_strength"] == run_default["plate"]["yield_strength"]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        (
            '[sweep]\nstage = "impact"\n[grid]\n"wear.K" = [1e-12, 1e-11]\n',
            "grid.wear.K: the impact stage does not read [wear]",
        ),
        ('[sweep]\nstage = "run"\n[grid]\n"fem.load_steps" = [1]\n', "fem.load_steps=1 is out of range"),
        ('[sweep]\nstage = "indent"\n[[cases]]\nfem.coupling = "both"\n', "fem.coupling='both'"),
    ],
)
def test_fe_stage_keys_are_checked_before_running(text, message, tmp_path):
    with pytest.raises(ValueError, match=re.escape(message)):
        load_sweep(_write(tmp_path, text))


def test_dask_options_without_distributed_give_one_line_naming_the_options(tmp_path, monkeypatch, capsys):
    """distributed is optional at import time: without it, --dask-local/--scheduler fail with one line."""
    monkeypatch.setitem(sys.modules, "distributed", None)  # makes `import distributed` raise ImportError
    sweep = _write(tmp_path, '[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [10]\n')
    status = cli.main(["sweep", str(sweep), "--out", str(tmp_path / "out"), "--dask-local", "2", "--quiet"])
    err = capsys.readouterr().err.strip().splitlines()
    assert status == 2 and len(err) == 1
    assert "--dask-local/--scheduler" in err[0] and "impactwear[dask]" in err[0]
