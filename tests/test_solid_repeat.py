"""Repeated impacts at one site on the 3-D plate (``fem.model = "3d"``, :mod:`wear.chain.solid_repeat`): the dent of
each normal frictionless impact against the axisymmetric repeat (the peer model), its energy balance, and the
refused settings (the oblique repeat with friction: ``tests/test_solid_repeat_oblique.py``). The reduced 3-D plate
of ``tests/solid_cases.py``."""

import math

import pytest
from solid_cases import repeat_case, repeat_table

from wear import repeat
from wear.case.check import on_plate

pytestmark = pytest.mark.filterwarnings("ignore:elastic ball", "ignore:contact radius")


@pytest.fixture(scope="module")
def normal_3d():
    result = repeat(repeat_case(0.0, 0.0, 3))
    print(repeat_table(result))
    return result


def test_normal_frictionless_dent_of_each_impact_matches_the_axisymmetric_repeat(normal_3d):
    """Reference: the axisymmetric repeat of the same case (its own (r, z) mesh, solver and stateful plate,
    ``fem.Plate``), every impact computed (a shakedown tolerance of 1e-9 Y/E keeps it from cycle-jumping). At normal
    incidence without friction the 3-D half plate is the same axisymmetric problem: the dent after each of 3
    impacts within 3% (the 3-D mesh has 4 elements across the contact radius), and the first-contact overlap of
    the re-impacts (the dent the ball meets) within 3% too."""
    axisymmetric_case = on_plate(normal_3d.case, "axisymmetric", "repeat").with_(repeat={"shakedown_tolerance": 1e-9})
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
    case = repeat_case(30.0, 0.3, 2).with_(repeat=repeat_keys)
    with pytest.raises(ValueError, match=text):
        repeat(case)
