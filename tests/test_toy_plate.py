"""A third plate model added as one module (here, this test's half-space plate) and one line of the plate registry
(:data:`wear.chain.plates.PLATES`): ``impactwear run`` and ``impactwear repeat`` run it end to end through the
command line's entry (:func:`wear.app.cli.main`), asking the plate, never which plate it is.

The plate is the elastic half-space of Hertz's closed forms (Johnson 1985, §4.2 and §11.4): the impact on the
Hertz law is its coupled impact (no dent, restitution 1), and every impact of a repetition is the first one again,
so that the n-th impact's total wear is n times the first's. The case schema sits below the chains and cannot read
their registry: the plate declares what the case reads of it (its name, its ``[fem]`` keys and its work check: a
:class:`wear.case.plate_cases.PlateCase`) beside its run, and the fixture lists it in the case's registry of the
plates' declarations and gives the schema's lists of the model names (``fem.model``'s choices, each job's models)
the new name too.
"""

from __future__ import annotations

import dataclasses
import json
import math
from collections.abc import Mapping
from dataclasses import dataclass

import meshio
import numpy as np
import pytest

import contact.checks
import wear.case.plate_cases
import wear.case.schema
from contact import ImpactResult, effective_modulus
from contact.theory import hertz_impact, sphere_mass
from wear.app.cli import main
from wear.case import JOBS, Case, dump_case
from wear.case.plate_cases import PlateCase
from wear.chain.axisymmetric_run import impact_wear
from wear.chain.estimate import estimate_impact
from wear.chain.plate_model import PlateModel, Timed, Wear
from wear.chain.plates import PLATES
from wear.chain.records import ImpactRecord, RepeatResult
from wear.integrate import WearMap
from wear.pressure import PressureHistory
from wear.surface import DeformedSurface

NAME = "halfspace"


def _flat(impact: ImpactResult, wm: WearMap) -> DeformedSurface:
    """The wear map on the undented half-space, centred at the contact of maximum overlap."""
    h = impact.history
    centre = (float(h.contact_x[int(np.argmax(h.overlap))]), 0.0)
    return DeformedSurface(wm.x, wm.y, wm.depth.T, np.array([0.0, 1.0]), np.zeros(2), centre)


def _hertz_peak(impact: ImpactResult) -> float:
    """Hertz's peak pressure 3F/(2πa²) at the largest force (Pa)."""
    return 1.5 * impact.max_force / (math.pi * impact.max_contact_radius**2)


@dataclass(frozen=True, eq=False)
class HalfSpaceRun:
    """The elastic half-space plate of a run: the impact on the Hertz law is the coupled one."""

    impact: ImpactResult
    model: str | None = NAME

    @property
    def fields(self) -> Mapping[str, object]:
        return {}

    def wear(self, case: Case) -> Wear:
        return impact_wear(case, self.impact)

    def surface(self, wm: WearMap) -> DeformedSurface:
        return _flat(self.impact, wm)

    def yield_info(self, info: dict) -> dict:
        return info

    def regime(self, info: dict) -> str:
        return "elastic"

    def peak_pressure(self) -> tuple[float, str]:
        return _hertz_peak(self.impact), "elastic half-space (Hertz)"

    def summary_blocks(self, estimate: ImpactResult) -> dict[str, object]:
        return {}

    def pressure_arrays(self) -> dict[str, np.ndarray]:
        return {}

    def meshes(self, case: Case, pressure: PressureHistory) -> dict[str, meshio.Mesh]:
        return {}

    def force_steps(self) -> list[tuple[np.ndarray, np.ndarray, str]]:
        return []


def _prepare(case: Case) -> Case:
    if case.plate.yield_strength:
        raise ValueError(f"plate.yield_strength={case.plate.yield_strength!r}: the half-space plate is elastic")
    return case


def _couple(case: Case, estimate: ImpactResult, timed: Timed) -> HalfSpaceRun:
    timed("coupling", lambda: None)
    return HalfSpaceRun(estimate)


@dataclass(frozen=True)
class HalfSpaceState:
    """The half-space after an impact: as it was (a patch of its surface, for the frames)."""

    def to_meshio(self) -> meshio.Mesh:
        points = np.array([[0.0, 0.0, 0.0], [1e-3, 0.0, 0.0], [0.0, 1e-3, 0.0]])
        return meshio.Mesh(points, [("triangle", np.array([[0, 1, 2]]))])


def _repeat(case, progress=None, on_computed=None) -> RepeatResult:
    case = _prepare(case)
    n = case.repeat.impacts
    impact = estimate_impact(case)
    _, wm, _ = impact_wear(case, impact)
    total = dataclasses.replace(wm, depth=n * wm.depth, volume_m3=n * wm.volume_m3, max_depth_m=n * wm.max_depth_m)
    common = dict(
        kind="computed",
        normal_restitution=impact.normal_restitution,
        max_force=impact.max_force,
        max_pressure=_hertz_peak(impact),
        contact_radius=impact.max_contact_radius,
        max_overlap=impact.max_overlap,
        first_contact_overlap=impact.max_overlap,
        plastic_strain_increment=0.0,
        wear_volume=wm.volume_m3,
        wear_max_depth=wm.max_depth_m,
        max_plastic_strain=0.0,
        dent_depth=0.0,
        wear_peak_to_mean=1.0,
        shaken_down=True,
    )
    first = ImpactRecord(
        first=1,
        last=1,
        count=1,
        total_wear_volume=wm.volume_m3,
        total_wear_max_depth=wm.max_depth_m,
        surface_depth=wm.max_depth_m,
        **common,
    )
    records = [first]
    if on_computed is not None:
        on_computed(1, HalfSpaceState())
    if n > 1:
        block = {**common, "kind": "block"}
        records.append(
            ImpactRecord(
                first=2,
                last=n,
                count=n - 1,
                total_wear_volume=total.volume_m3,
                total_wear_max_depth=total.max_depth_m,
                surface_depth=total.max_depth_m,
                **block,
            )
        )
    if progress is not None:
        progress(n, n)
    return RepeatResult(case, records, HalfSpaceState(), total, 1, 1, 0.0)


def _no_fe_work(case: Case, job: str) -> None:
    """The closed forms: no FE work to refuse."""


#: The half-space plate model: its one line in the registry, and what the case reads of it (no ``[fem]`` key of its
#: own, no FE work).
HALFSPACE = PlateModel(PlateCase(NAME, (), _no_fe_work), _prepare, _couple, _repeat)


@pytest.fixture
def halfspace(monkeypatch):
    """The half-space plate in the registry, and its name in the case schema's lists of the plate models."""
    monkeypatch.setitem(PLATES, NAME, HALFSPACE)
    check_choice = contact.checks.check_choice

    def with_halfspace(name, value, choices):
        return check_choice(name, value, (*choices, NAME) if name == "fem.model" else choices)

    monkeypatch.setattr(wear.case.schema, "check_choice", with_halfspace)
    for job in ("run", "repeat"):
        monkeypatch.setitem(JOBS, job, dataclasses.replace(JOBS[job], fem_models=(*JOBS[job].fem_models, NAME)))
    monkeypatch.setitem(wear.case.plate_cases.PLATE_CASES, NAME, HALFSPACE.declaration)


def _case(tmp_path, repeat: str = "") -> str:
    case = Case().with_(
        plate={"yield_strength": None},
        impact={"angle": 30.0},
        wear={"pressure": "hertz", "speed": "sliding"},
        fem={"model": NAME},
        output={"figures": False, "render": False},
    )
    path = tmp_path / "case.toml"
    path.write_text(dump_case(case, JOBS["run"].tables) + repeat)
    return str(path)


def _hertz(case: Case):
    """Hertz's impact of the case's normal approach (Johnson 1985 §11.4)."""
    ball, plate = case.ball.material(), case.plate.material()
    v_n = case.impact.speed * math.cos(math.radians(case.impact.angle))
    mass = sphere_mass(case.ball.radius, ball.density)
    return hertz_impact(mass, case.ball.radius, effective_modulus(ball, plate), v_n)


def test_a_third_plate_is_one_module_and_one_registry_line(halfspace, tmp_path):
    """``run`` on the half-space: its force and overlap are Hertz's closed forms (within the time step's 1e-3), it
    rebounds elastically with no dent; ``repeat`` of 5 impacts: 5 times the first impact's wear, no dent."""
    case = _case(tmp_path)
    assert main(["run", case, "--out", str(tmp_path / "run")]) == 0
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert summary["fem_model"] == NAME
    hertz = _hertz(Case.from_dict(summary["case"]))
    assert summary["impact"]["max_force"] == pytest.approx(hertz.max_force, rel=1e-3)
    assert summary["impact"]["max_overlap"] == pytest.approx(hertz.max_overlap, rel=1e-3)
    assert summary["impact"]["normal_restitution"] == pytest.approx(1.0, abs=1e-3)
    assert summary["impact"]["max_peak_pressure_source"] == "elastic half-space (Hertz)"
    assert summary["regime"] == "elastic"
    assert summary["dent"]["max_depth_m"] == 0.0
    assert summary["plate_3d"] is None and summary["coupling"] is None
    volume = summary["wear"]["volume_m3"]
    assert volume > 0.0

    case = _case(tmp_path, "\n[repeat]\nimpacts = 5\nsave_every = 1\n")
    assert main(["repeat", case, "--out", str(tmp_path / "repeat")]) == 0
    repeated = json.loads((tmp_path / "repeat" / "summary.json").read_text())
    assert repeated["fem_model"] == NAME
    after = repeated["after_last_impact"]
    assert after["total_wear_volume_m3"] == pytest.approx(5 * volume, rel=1e-12)
    assert after["dent_depth_m"] == 0.0
    assert (tmp_path / "repeat" / "frames" / "plate_000001.vtu").exists()
