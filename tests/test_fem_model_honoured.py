"""``fem.model`` is honoured or refused by every command that reads ``[fem]``, never ignored.

``impactwear run`` and ``repeat`` run either plate; ``calibrate`` and ``indent`` run the axisymmetric plate only and
refuse ``fem.model = "3d"`` in one line naming the key, before any work (exit 2, no output folder); ``impact`` and
``erode`` do not read ``[fem]`` and refuse ``--set fem.model``. Every summary.json a plate produced names its plate
model; a 3-D run's ``regime``, ``yield`` and ``coupling`` describe the 3-D plate the impact ran on
(``tests/test_solid_chain.py::test_3d_run_summary_describes_the_3d_plate``, on that file's reduced 3-D run).
The other ``[fem]`` keys likewise: one a command would not read for its case (the coupling's, the 3-D plate's,
indent's fixed few) is refused at any value but its default.
"""

import json

import pytest

from wear.app.cli import main
from wear.app.sweep.spec import parse_sweep
from wear.case import FEM_MODELS, JOBS, Case, dump_case
from wear.case.plate_cases import PLATE_CASES
from wear.chain.calibrate import calibrate
from wear.chain.calibration_data import read_data
from wear.chain.plates import PLATES
from wear.chain.repeated_impacts import repeat

AXISYMMETRIC_ONLY = ("calibrate", "indent")


def test_every_job_that_reads_fem_says_which_plates_it_runs():
    """The jobs that read [fem] are exactly run and repeat (both plates) and the axisymmetric-only ones."""
    reads_fem = {name for name, job in JOBS.items() if "fem" in job.tables}
    assert reads_fem == {"run", "repeat", *AXISYMMETRIC_ONLY}
    assert JOBS["run"].fem_models == JOBS["repeat"].fem_models == ("axisymmetric", "3d")
    for name in AXISYMMETRIC_ONLY:
        assert JOBS[name].fem_models == ("axisymmetric",)


@pytest.mark.parametrize("command", AXISYMMETRIC_ONLY)
@pytest.mark.parametrize("given", ["set", "file"])
def test_axisymmetric_only_commands_refuse_3d_in_one_line(command, given, tmp_path, capsys):
    out = tmp_path / "out"
    # calibrate's data file comes first; the case is refused before it is read
    argv = [command] + ([str(tmp_path / "absent.csv")] if command == "calibrate" else [])
    if given == "set":
        argv += ["--set", "fem.model=3d"]
    else:
        case = tmp_path / "case.toml"
        case.write_text(dump_case(JOBS[command].default_case().with_(fem={"model": "3d"}), JOBS[command].tables))
        argv += ["--config", str(case)] if command == "indent" else [str(case)]
    assert main([*argv, "--out", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.splitlines() == [
        f"impactwear {command}: error: fem.model='3d': impactwear {command} runs the axisymmetric plate only "
        f"({JOBS[command].fem_models_why}); set fem.model='axisymmetric'"
    ]
    assert not out.exists()


@pytest.mark.parametrize("command", ["impact", "erode"])
def test_commands_without_a_plate_refuse_fem_model(command, tmp_path, capsys):
    out = tmp_path / "out"
    argv = [command, "--set", "fem.model=3d"] + ([] if command == "impact" else ["--out", str(out)])
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert f"--set fem.model='3d': impactwear {command} does not read [fem]" in err
    assert not out.exists()


def test_python_api_and_sweeps_refuse_3d_where_it_would_be_ignored(tmp_path):
    data = tmp_path / "data.csv"
    data.write_text("angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-4\n")
    with pytest.raises(ValueError, match=r"^fem.model='3d': impactwear calibrate runs the axisymmetric plate only"):
        calibrate(JOBS["calibrate"].default_case().with_(fem={"model": "3d"}), read_data(str(data)))
    sweep = {"sweep": {"stage": "calibrate"}, "base": {"fem": {"model": "3d"}}, "grid": {"impact.angle": [30.0]}}
    with pytest.raises(ValueError, match="fem.model='3d': impactwear calibrate runs the axisymmetric plate only"):
        parse_sweep(sweep)


@pytest.mark.parametrize(
    ("sets", "named"),
    [
        ({"impacts": 1000}, "repeat.impacts=1000"),
        ({"impacts": 3, "surface_fraction": 0.2}, "repeat.surface_fraction=0.2"),
    ],
)
def test_the_3d_repeat_refuses_what_it_would_not_do_in_one_line(sets, named):
    """The 3-D repeat computes every impact: a cycle jump or more impacts than fit in a few hours are refused before
    any work, naming the key."""
    case = JOBS["repeat"].default_case().with_(fem={"model": "3d"}, repeat=sets)
    with pytest.raises(ValueError, match=r"^" + named.replace(".", r"\.")) as refused:
        repeat(case)
    assert len(str(refused.value).splitlines()) == 1


def test_indent_and_repeat_summaries_name_the_plate(tmp_path, capsys):
    """Tiny elastic runs (the plumbing: the physics is in test_fem_cli and test_repeat): each summary names its
    plate; the indent's force is Hertz's (Johnson 1985 Eq. 4.23: F = 0.9730 N at δ = 1e-7 m, R = 10 mm,
    E* = 230.8 GPa) within 2 % (0.5 % on this coarse mesh)."""
    out = tmp_path / "indent"
    argv = ["indent", "--yield-strength", "inf", "--max-overlap", "1e-7", "--load-steps", "3", "--unload-steps", "2"]
    assert main([*argv, "--set", "fem.mesh_scale=4", "--no-figures", "--out", str(out), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["fem_model"] == "axisymmetric"
    assert summary["max_force_N"] == pytest.approx(0.97301, rel=0.02)
    fem = {"mesh_scale": 8.0, "load_steps": 4, "unload_steps": 2}
    elastic = Case().with_(plate={"yield_strength": None}, fem=fem, output={"render": False})
    case = tmp_path / "case.toml"
    case.write_text(dump_case(elastic, JOBS["run"].tables) + "\n[repeat]\nimpacts = 1\nsave_every = 0\n")
    assert main(["repeat", str(case), "--out", str(tmp_path / "repeat"), "--json"]) == 0
    saved = json.loads((tmp_path / "repeat" / "summary.json").read_text())
    assert saved["fem_model"] == "axisymmetric"


def test_every_plate_model_of_the_schema_has_a_plate():
    """The case schema's plate models (``fem.model``'s choices) are the chain's (wear.chain.plates.PLATES): a model
    the schema accepts has a plate to run, and a plate the chain has can be chosen; the schema's other lists of the
    models (each model's declaration: its own ``[fem]`` keys, its work check) names the same models, and each
    chain's plate takes its declaration from it."""
    assert tuple(PLATES) == FEM_MODELS
    assert tuple(PLATE_CASES) == FEM_MODELS
    assert all(PLATES[name].declaration is PLATE_CASES[name] for name in FEM_MODELS)


@pytest.mark.parametrize(
    ("argv", "line"),
    [
        (
            ["indent", "--set", "fem.tolerance=0.1"],
            "fem.tolerance=0.1: impactwear indent reads only fem.model, fem.load_steps, fem.unload_steps, "
            "fem.mesh_scale; leave it out (default 0.005)",
        ),
        (
            ["run", "--set", "fem.solid_iterations=5"],
            "fem.solid_iterations=5: only the plate fem.model='3d' reads it; leave it out (default 3)",
        ),
        (
            ["run", "--set", "fem.coupling=none", "--set", "fem.load_steps=20"],
            "fem.load_steps=20: with fem.coupling='none' there is no FE plate; leave it out (default 16)",
        ),
        (
            ["run", "--set", "fem.coupling=one-way", "--set", "fem.overshoot=0.3"],
            "fem.overshoot=0.3: the one-way coupling reads only fem.load_steps, fem.unload_steps, fem.mesh_scale; "
            "leave it out (default 0.1)",
        ),
        (
            ["repeat", "--set", "fem.coupling=none"],
            "fem.coupling='none': impactwear repeat couples every impact two-way; leave fem.coupling out or set it "
            "to 'two-way'",
        ),
    ],
)
def test_fem_keys_a_command_would_not_read_are_refused(argv, line, tmp_path, capsys):
    """A [fem] key the command would not read for its case is refused in one line (key, value, why, its default),
    exit 2, before any work, nothing written; at its default it is accepted (a case file from another command's
    --print-default still runs)."""
    out = tmp_path / "out"
    assert main([*argv, "--out", str(out)]) == 2
    assert capsys.readouterr().err.strip().splitlines() == [f"impactwear {argv[0]}: error: {line}"]
    assert not out.exists()


def test_print_default_shows_only_the_fem_keys_indent_reads(capsys):
    """``indent --print-default`` prints the [fem] keys indent reads, no others (it says "every key it reads")."""
    assert main(["indent", "--print-default"]) == 0
    text = capsys.readouterr().out
    fem_table = text.split("[fem]")[1]
    keys = [line.split("=")[0].strip() for line in fem_table.splitlines() if "=" in line and not line.startswith("#")]
    assert sorted(keys) == sorted(JOBS["indent"].fem_keys)
