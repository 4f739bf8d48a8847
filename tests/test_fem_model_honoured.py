"""``fem.model`` is honoured or refused by every command that reads ``[fem]``, never ignored.

``impactwear run`` runs either plate; ``repeat``, ``calibrate`` and ``indent`` run the axisymmetric plate only and
refuse ``fem.model = "3d"`` in one line naming the key, before any work (exit 2, no output folder); ``impact`` and
``erode`` do not read ``[fem]`` and refuse ``--set fem.model``. Every summary.json a plate produced names its plate
model; a 3-D run's ``regime``, ``yield`` and ``coupling`` describe the 3-D plate the impact ran on.
"""

import json

import numpy as np
import pytest

from contact import effective_modulus
from contact.theory import first_yield
from wear import run
from wear.app.cli import main
from wear.app.outputs.run import write_run
from wear.app.sweep.spec import parse_sweep
from wear.case import JOBS, Case, dump_case
from wear.chain.calibrate import calibrate, read_data
from wear.chain.repeat import repeat
from wear.chain.single import SOLID_PLASTIC_REGIME

AXISYMMETRIC_ONLY = ("repeat", "calibrate", "indent")
REDUCED_3D = {"model": "3d", "mesh_scale": 2.0, "solid_load_steps": 5, "solid_unload_steps": 3, "solid_iterations": 2}


def test_every_job_that_reads_fem_says_which_plates_it_runs():
    """The jobs that read [fem] are exactly run (both plates) and the axisymmetric-only ones."""
    reads_fem = {name for name, job in JOBS.items() if "fem" in job.tables}
    assert reads_fem == {"run", *AXISYMMETRIC_ONLY}
    assert JOBS["run"].fem_models == ("axisymmetric", "3d")
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
        f"impactwear {command}: error: fem.model='3d': impactwear {command} runs the axisymmetric plate only; "
        "set fem.model='axisymmetric'"
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
    case = JOBS["repeat"].default_case().with_(fem={"model": "3d"})
    with pytest.raises(ValueError, match=r"^fem.model='3d': impactwear repeat runs the axisymmetric plate only"):
        repeat(case)
    data = tmp_path / "data.csv"
    data.write_text("angle_deg,speed_m_s,erosion_kg_per_kg\n30,20,1e-4\n")
    with pytest.raises(ValueError, match=r"^fem.model='3d': impactwear calibrate runs the axisymmetric plate only"):
        calibrate(JOBS["calibrate"].default_case().with_(fem={"model": "3d"}), read_data(str(data)))
    sweep = {"sweep": {"stage": "repeat"}, "base": {"fem": {"model": "3d"}}, "grid": {"impact.angle": [30.0, 45.0]}}
    with pytest.raises(ValueError, match="fem.model='3d': impactwear repeat runs the axisymmetric plate only"):
        parse_sweep(sweep)


def test_indent_and_repeat_summaries_name_the_plate(tmp_path, capsys):
    """Tiny elastic runs (the plumbing: the physics is in test_fem_cli and test_repeat): each summary names its
    plate; the indent's force is Hertz's (Johnson 1985 Eq. 4.23: F = 0.9730 N at δ = 1e-7 m, R = 10 mm,
    E* = 230.8 GPa) within 2 %."""
    out = tmp_path / "indent"
    argv = ["indent", "--yield-strength", "inf", "--max-overlap", "1e-7", "--load-steps", "3", "--unload-steps", "2"]
    assert main([*argv, "--no-figures", "--out", str(out), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["fem_model"] == "axisymmetric"
    assert summary["max_force_N"] == pytest.approx(0.97301, rel=0.02)
    elastic = Case().with_(plate={"yield_strength": None}, fem={"mesh_scale": 4.0}, output={"render": False})
    case = tmp_path / "case.toml"
    case.write_text(dump_case(elastic, JOBS["run"].tables) + "\n[repeat]\nimpacts = 1\nsave_every = 0\n")
    assert main(["repeat", str(case), "--out", str(tmp_path / "repeat"), "--json"]) == 0
    saved = json.loads((tmp_path / "repeat" / "summary.json").read_text())
    assert saved["fem_model"] == "axisymmetric"


@pytest.fixture(scope="module")
def run_3d():
    """The default run case, frictionless, on the reduced 3-D path (as tests/test_solid_chain.py)."""
    case = JOBS["run"].default_case().with_(impact={"friction": 0.0}, fem=REDUCED_3D, output={"render": False})
    return run(case)


def test_3d_run_summary_describes_the_3d_plate(run_3d, tmp_path):
    """``regime``, ``yield.fe_first_yield_force`` and ``coupling`` of a 3-D run are the 3-D plate's, each naming its
    plate; the axisymmetric plate it started from is kept under keys that say so. Reference for the first yield:
    the closed form F_c = (π C Y)³ R² / (6 E*²) with the exact C(ν) (Johnson 1985 §6.2, contact.theory): the 3-D
    plate's step before its first plastic step carries less (within 5 %: the plate's mesh), its first plastic step
    more."""
    summary = write_run(run_3d, tmp_path / "out")
    saved = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert saved["fem_model"] == saved["regime_plate"] == "3d"
    solid = run_3d.solid
    # coupling: the 3-D coupling's cycles and convergence, the axisymmetric start inside
    coupling = saved["coupling"]
    assert coupling["plate"] == "3d"
    assert coupling["iterations"] == solid.iterations == len(coupling["max_overlaps_m"]) - 1
    assert coupling["converged"] == solid.converged
    assert coupling["max_overlaps_m"][-1] == pytest.approx(run_3d.impact.max_overlap, rel=1e-12)
    assert coupling["axisymmetric_start"]["plate"] == "axisymmetric"
    assert coupling["start_max_overlap_m"] == pytest.approx(run_3d.coupling.impact.max_overlap, rel=1e-12)
    # regime: from the 3-D plate's plastic strain (the default case yields well past first yield)
    assert np.max(solid.solid.max_equivalent_plastic_strain) > 0.0
    assert saved["regime"] == SOLID_PLASTIC_REGIME
    assert saved["axisymmetric_start_regime"] in ("surface-plastic", "fully-plastic")
    # first yield: the 3-D plate's, bracketed by the closed form
    y = saved["yield"]
    assert y["fe_first_yield_plate"] == "3d"
    case = run_3d.case
    plate = case.plate.material()
    f_c = first_yield(case.ball.radius, effective_modulus(case.ball.material(), plate), plate.yield_strength,
                      plate.nu).force  # fmt: skip
    assert y["F_c_exact"] == pytest.approx(f_c, rel=1e-12)
    forces = solid.solid.normal_force
    k = int(np.flatnonzero(solid.solid.max_equivalent_plastic_strain > 0.0)[0])
    assert y["fe_first_yield_force"] == forces[k] >= f_c
    assert k == 0 or forces[k - 1] <= 1.05 * f_c
    assert y["axisymmetric_first_yield_force"] == pytest.approx(f_c, rel=0.03)
    assert summary["yield"] == saved["yield"]
