"""Repeated impacts at one site on the 3-D plate (``fem.model = "3d"``, :mod:`wear.chain.solid_repeat`): the dent of
each normal frictionless impact against the axisymmetric repeat (the peer model), an oblique repeat with friction,
the stateful plate's bookkeeping, and the refused settings. Reduced meshes (3–4 elements across the contact) and few
increments."""

import csv
import math
from dataclasses import replace

import meshio
import numpy as np
import pytest

from wear import repeat
from wear.app.outputs.repeat import RepeatWriter
from wear.case import JOBS

pytestmark = pytest.mark.filterwarnings("ignore:elastic ball", "ignore:contact radius")

#: The reduced 3-D plate: 4 elements across the contact radius, 5 + 3 increments, two coupling cycles.
REDUCED = {"model": "3d", "mesh_scale": 2.0, "solid_load_steps": 5, "solid_unload_steps": 3, "solid_iterations": 2}


def _case(angle: float, friction: float, impacts: int, **fem):
    base = JOBS["repeat"].default_case()
    return base.with_(
        impact={"angle": angle, "friction": friction},
        fem={**REDUCED, **fem},
        repeat={"impacts": impacts, "geometry_update": False},
        output={"render": False, "figures": False},
    )


def _table(result) -> str:
    """The per-impact numbers (for the log of a run with ``-rA``)."""
    lines = ["impact dent_m pile_up_m plastic_work_J wear_m3 e_n e_t wall_s"]
    for r in result.records:
        lines.append(
            f"{r.first} {r.dent_depth:.5g} {r.pile_up_height:.5g} {r.plastic_work:.5g} {r.wear_volume:.5g} "
            f"{r.normal_restitution:.5g} {r.tangential_restitution:.5g} {r.wall_time:.1f}"
        )
    return "\n".join(lines)


@pytest.fixture(scope="module")
def normal_3d():
    result = repeat(_case(0.0, 0.0, 3))
    print(_table(result))
    return result


@pytest.fixture(scope="module")
def oblique_3d():
    result = repeat(_case(30.0, 0.3, 3))
    print(_table(result))
    return result


def test_normal_frictionless_dent_of_each_impact_matches_the_axisymmetric_repeat(normal_3d):
    """Reference: the axisymmetric repeat of the same case (its own (r, z) mesh, solver and stateful plate,
    ``fem.Plate``), every impact computed (a shakedown tolerance of 1e-9 Y/E keeps it from cycle-jumping). At normal
    incidence without friction the 3-D half plate is the same axisymmetric problem: the dent after each of 3
    impacts within 3% (the 3-D mesh has 4 elements across the contact radius), and the first-contact overlap of
    the re-impacts (the dent the ball meets) within 3% too."""
    axisymmetric_case = normal_3d.case.with_(fem={"model": "axisymmetric"}, repeat={"shakedown_tolerance": 1e-9})
    axisymmetric = repeat(axisymmetric_case)
    assert [r.kind for r in axisymmetric.records] == ["computed"] * 3
    solid, peer = normal_3d.records, axisymmetric.records
    print("axisymmetric dent_m", [r.dent_depth for r in peer], "δ₀_m", [r.first_contact_overlap for r in peer])
    print("3-D dent_m", [r.dent_depth for r in solid], "δ₀_m", [r.first_contact_overlap for r in solid])
    for mine, theirs in zip(solid, peer, strict=True):
        assert mine.dent_depth == pytest.approx(theirs.dent_depth, rel=0.03), (mine.first, mine.dent_depth)
    for mine, theirs in zip(solid[1:], peer[1:], strict=True):
        assert mine.first_contact_overlap == pytest.approx(theirs.first_contact_overlap, rel=0.03)


def test_normal_repeat_plastic_work_is_the_impact_energy_lost(normal_3d):
    """Energy balance at normal incidence without friction: the ball's kinetic energy lost in an impact (the impact
    engine's, from its velocities) is the plate's plastic dissipation (the 3-D plate's ᾱ integrated over its
    elements) plus the elastic energy the residual stress stores; the stored part is a small share, so the plastic
    work lies within 0.6–1.02 of the loss for each impact (a first impact of this case: ~0.85), and falls from
    impact to impact as the dent conforms."""
    case = normal_3d.case
    ball = case.ball.material()
    mass = ball.density * 4.0 / 3.0 * math.pi * case.ball.radius**3
    work = [r.plastic_work for r in normal_3d.records]
    for r in normal_3d.records:
        lost = 0.5 * mass * case.impact.speed**2 * (1.0 - r.normal_restitution**2)
        assert 0.6 * lost < r.plastic_work <= 1.02 * lost, (r.first, r.plastic_work, lost)
    assert work[1] < work[0] and work[2] < work[1]


def test_oblique_repeat_with_friction_dissipates_less_and_digs_deeper(oblique_3d):
    """Three oblique impacts (30°, μ = 0.3) at one site. The first impact plastically deforms a virgin plate; the
    second meets a conforming dent whose residual stresses oppose yielding (Johnson, Contact Mechanics §9.2:
    protective residual stress and a conforming seat, the mechanism of shakedown), so it dissipates less plastic
    work, by a clear margin (< 0.7 ×). Plastic strain only accumulates under a repeated load in one direction, so
    the dent after the third impact is at least that after the first, the lip of the dent rises above the original
    plane (pile-up), and every impact wears the plate."""
    r = oblique_3d.records
    assert [x.kind for x in r] == ["computed"] * 3
    assert r[1].plastic_work < 0.7 * r[0].plastic_work
    assert r[2].dent_depth >= r[0].dent_depth
    assert all(x.pile_up_height > 0.0 for x in r)
    assert r[1].first_contact_overlap > 0.0
    assert np.all(np.diff([x.total_wear_volume for x in r]) > 0.0)
    assert all(math.isfinite(x.tangential_restitution) for x in r)


@pytest.mark.parametrize(
    ("repeat_keys", "text"),
    [
        ({"geometry_update": True}, "repeat.geometry_update=true"),
        ({"geometry_update": False, "surface_fraction": 0.2}, "repeat.surface_fraction=0.2"),
        ({"geometry_update": False, "elastic_after_shakedown": False}, "repeat.elastic_after_shakedown=False"),
    ],
)
def test_3d_repeat_refuses_axisymmetric_only_settings(repeat_keys, text):
    """Cycle jump, the elastic shortcut and the moved surface are not measured on the 3-D plate: their keys are
    refused (one line naming the key and its value), before any impact is run."""
    case = _case(30.0, 0.3, 2).with_(repeat=repeat_keys)
    with pytest.raises(ValueError, match=text):
        repeat(case)


def test_3d_repeat_outputs(oblique_3d, tmp_path):
    """The one writer of ``impactwear repeat`` on the 3-D result: repeat.csv carries the records (dent, pile-up,
    plastic work, e_t per impact), summary.json has no half-space check (the 3-D dent is not axisymmetric), the
    frame of the last impact is the whole 3-D plate, and the figure is written."""
    out = tmp_path / "out"
    out.mkdir()
    result = replace(oblique_3d, case=oblique_3d.case.with_(output={"figures": True}))
    summary = RepeatWriter(out, save_every=1).finish(result, [])
    with open(out / "repeat.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 3
    for row, record in zip(rows, oblique_3d.records, strict=True):
        assert float(row["dent_depth_m"]) == pytest.approx(record.dent_depth)
        assert float(row["pile_up_height_m"]) == pytest.approx(record.pile_up_height)
        assert float(row["plastic_work_per_impact_J"]) == pytest.approx(record.plastic_work)
    assert summary["halfspace_check"] is None and summary["fem_model"] == "3d"
    mesh = meshio.read(out / "frames" / "plate_000003.vtu")
    assert mesh.points.shape[0] == 2 * oblique_3d.plate.solver.disc.mesh.p.shape[1]
    assert (out / "repeat.png").stat().st_size > 0
