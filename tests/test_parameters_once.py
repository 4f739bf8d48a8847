"""Each parameter is checked once, where it enters, with one range and one name; options that travel together travel
as one frozen dataclass: the friction coefficient's one range at every entry point, the case's normal laws derived
from the engine's, the wall's law keys checked once on the command's path, the wall's options carried whole to the
worker processes, and the run's progress steps named apart from the sweep's stages."""

from __future__ import annotations

import dataclasses
import math
import pathlib
import re

import meshio
import numpy as np
import pytest
from wall_cases import flat_mesh, write_csv

import wear.chain.single as single
import wear.wall.case_keys as case_keys
from contact import Material, simulate_impact, simulate_impacts
from contact.checks import FRICTION_MAX, check_friction
from contact.impact import NORMAL_MODELS as ENGINE_NORMAL_MODELS
from fem import couple_solid, indent_solid
from fem.solid.plate import SolidPlate
from wear.app.cli import main
from wear.app.commands.run import BAR_STEPS
from wear.app.sweep.stages import STAGES
from wear.case import Case, default_case
from wear.case.choices import NORMAL_MODELS
from wear.case.impact_tables import ImpactSpec
from wear.erosion.response import ImpactResponse
from wear.law import WearLaw
from wear.wall import read_surface, wall_law
from wear.wall.engine import erode_wall
from wear.wall.options import NORMALS, WallOptions
from wear.wall.sources import plan_chunks

ROOT = pathlib.Path(__file__).resolve().parents[1]
STEEL = Material(E=200e9, nu=0.3, density=7800.0)
LAW = WearLaw(K=1e-12, alpha=1.0, beta=0.3)

# --- friction: one range, one check, one message ------------------------------------------------------------------

#: Every entry point that takes a friction coefficient, called with ``mu`` (the others valid).
ENTRIES = {
    "simulate_impact": lambda mu: simulate_impact(
        radius=1e-3, ball=STEEL, plate=STEEL, speed=3.0, angle=30.0, friction=mu
    ),
    "simulate_impacts": lambda mu: simulate_impacts(1e-3, STEEL, STEEL, [3.0, 3.0], [30.0, 30.0], [0.3, mu]),
    "indent_solid": lambda mu: indent_solid(0.01, STEEL, [1e-6], friction=mu),
    "indent_solid per step": lambda mu: indent_solid(0.01, STEEL, [1e-6, 2e-6], friction=[0.0, mu]),
    "SolidPlate": lambda mu: SolidPlate(0.01, STEEL, 1e-6, friction=mu),
    "couple_solid": lambda mu: couple_solid(None, None, 0.01, STEEL, mu),
    "ImpactResponse": lambda mu: ImpactResponse(1e-3, STEEL, STEEL, mu, LAW),
    "the case": lambda mu: Case().with_(impact={"friction": mu}),
}


@pytest.mark.parametrize("mu", [1.5, -0.1, 11.0])
@pytest.mark.parametrize("entry", list(ENTRIES))
def test_every_entry_point_refuses_friction_outside_the_one_range_in_the_same_words(entry, mu):
    with pytest.raises(ValueError) as err:
        ENTRIES[entry](mu)
    name = "impact.friction" if entry == "the case" else "friction"
    expected = f"{name}={mu:g} is out of range: Coulomb friction coefficient must be in [0, {FRICTION_MAX:g}]"
    assert str(err.value) == expected


def test_friction_at_the_bounds_is_taken_as_given():
    assert simulate_impact(radius=1e-3, ball=STEEL, plate=STEEL, speed=3.0, angle=30.0, friction=FRICTION_MAX)
    assert Case().with_(impact={"friction": 0.0}).impact.friction == 0.0
    assert check_friction("friction", np.float64(0.3)) == 0.3
    assert np.array_equal(check_friction("friction", [0.0, FRICTION_MAX]), [0.0, FRICTION_MAX])


def test_the_case_schema_reads_the_one_range_and_no_other_copy_is_left():
    spec = ImpactSpec.keys()["friction"]
    assert (spec.low, spec.high) == (0.0, FRICTION_MAX)
    sources = [p for folder in ("contact", "fem", "wear") for p in (ROOT / folder).rglob("*.py")]
    stale = [str(p) for p in sources if re.search(r"MAX_FRICTION|friction[^\n]*high=10\.0", p.read_text("utf-8"))]
    assert not stale


# --- the normal laws a case names ---------------------------------------------------------------------------------


def test_the_case_names_the_engine_normal_laws_but_the_tabulated_one():
    """A tabulated law is data (an FE plate's), which a case key cannot hold: the case's choices are the engine's
    others, in the engine's order, so that a law added to the engine is a case choice too."""
    assert NORMAL_MODELS == tuple(m for m in ENGINE_NORMAL_MODELS if m != "tabulated")
    assert "tabulated" in ENGINE_NORMAL_MODELS


# --- the run's steps are not the sweep's stages ---------------------------------------------------------------------


def test_the_run_progress_steps_are_named_apart_from_the_sweep_stages():
    assert not hasattr(single, "STAGES")
    assert BAR_STEPS[: len(single.STEPS)] == single.STEPS
    assert "impact" in single.STEPS and "surface" in single.STEPS
    assert "run" in STAGES and "run" not in single.STEPS  # a sweep's stage is a job; a run's steps its parts


# --- the wall: the law keys checked once, the options one frozen dataclass ------------------------------------------

HEADER = ["x_m", "y_m", "z_m", "u_m_s", "v_m_s", "w_m_s", "diameter_m", "density_kg_m3", "time_s"]


def _row(x=0.01, y=0.01, z=0.0, w=-10.0, time=0.0) -> list[str]:
    return [str(x), str(y), str(z), "3.0", "0.0", str(w), "3e-4", "2650.0", str(time)]


@pytest.fixture
def flat(tmp_path):
    path = tmp_path / "plate.stl"
    meshio.write(path, flat_mesh())
    return path


def test_the_wall_command_checks_the_law_keys_once(flat, tmp_path, monkeypatch, capsys):
    """Counted inside the check (its keys_read), so that a second check from any module counts too."""
    calls = []
    read = case_keys.keys_read
    monkeypatch.setattr(case_keys, "keys_read", lambda case: calls.append(case) or read(case))
    records = write_csv(tmp_path / "hits.csv", HEADER, [_row(), _row(x=0.02, time=1.0)])
    args = ["wall", str(records), str(flat), "--quiet", "--no-figures", "--out", str(tmp_path / "out")]
    assert main(args) == 0
    assert len(calls) == 1
    calls.clear()
    assert main([*args[:-1], str(tmp_path / "refused"), "--set", "impact.friction=0.5"]) == 2
    assert "impact.friction=0.5: the wall's wear.law=" in capsys.readouterr().err
    assert len(calls) == 1


def test_wall_options_are_frozen_and_each_field_is_checked_where_they_are_made():
    options = WallOptions()
    with pytest.raises(dataclasses.FrozenInstanceError):
        options.workers = 2  # type: ignore[misc]
    assert NORMALS == ("recorded", "face")
    for fields, says in [
        ({"workers": 0}, "workers=0 is out of range"),
        ({"normal": "wall"}, "normal='wall' is not a valid choice"),
        ({"tolerance": 0.0}, "tolerance=0 is out of range"),
        ({"tolerance": math.nan}, "tolerance=nan is not finite"),
        ({"skip_bad": "yes"}, "skip_bad='yes' is not a boolean"),
        ({"scheduler": 5}, "scheduler=5 is not a Dask scheduler"),
    ]:
        with pytest.raises(ValueError, match=re.escape(says)):
            WallOptions(**fields)


@pytest.mark.parametrize("workers", [1, 2])
def test_wall_options_reach_the_worker_processes(flat, tmp_path, workers):
    """The options go whole to the chunk of every worker: with skip_bad the record leaving the wall and the one
    far from it are counted, not refused; a tolerance past that distance keeps the far one on the wall; the face
    normal is the one measured against (the records carry none)."""
    rows = [_row(), _row(x=0.02, w=10.0), _row(x=0.03, y=0.02), _row(x=0.01, z=0.5), _row(x=0.02, y=0.02)]
    path = write_csv(tmp_path / "mixed.csv", HEADER, rows)
    wall = read_surface(flat)
    law = wall_law(default_case("wall"))
    chunks = plan_chunks(path, 1)  # a chunk a record: every worker sums some
    skipped = erode_wall(chunks, wall, law, WallOptions(workers=workers, skip_bad=True), progress=False)
    assert skipped.skipped == {"far_from_wall": 1, "leaving_wall": 1} and skipped.records.sum() == 3
    near = WallOptions(workers=workers, skip_bad=True, tolerance=1.0, normal="face")
    kept = erode_wall(chunks, wall, law, near, progress=False)
    assert kept.skipped == {"leaving_wall": 1} and kept.records.sum() == 4
    if workers == 1:  # the refusals, as the worker would raise them
        with pytest.raises(ValueError, match=r"^options=2 is not a wear\.wall\.options\.WallOptions"):
            erode_wall(chunks, wall, law, 2, progress=False)  # the workers in the options' place
        with pytest.raises(ValueError, match="--skip-bad"):
            erode_wall(chunks, wall, law, WallOptions(), progress=False)
        with pytest.raises(ValueError, match="normal='recorded': the records of .* carry no normal"):
            erode_wall(chunks, wall, law, WallOptions(normal="recorded"), progress=False)
