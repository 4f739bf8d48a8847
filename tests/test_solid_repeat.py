"""Repeated impacts at one site on the 3-D plate (``fem.model = "3d"``, :mod:`wear.chain.solid_repeat`): the dent of
each normal frictionless impact against the axisymmetric repeat (the peer model), its energy balance, and the
refused settings (the oblique repeat with friction: ``tests/test_solid_repeat_oblique.py``). The reduced 3-D plate
of ``tests/solid_cases.py``."""

import math

import meshio
import numpy as np
import pytest
from solid_cases import repeat_case, repeat_table

from wear import repeat
from wear.case.check import on_plate

pytestmark = pytest.mark.filterwarnings("ignore:elastic ball", "ignore:contact radius")


@pytest.fixture(scope="module")
def normal_3d():
    # the repeat as given: the wear moves the 3-D surface between impacts (its peer, the axisymmetric repeat, too)
    result = repeat(repeat_case(0.0, 0.0, 3, geometry_update=True))
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
        ({"geometry_update": False, "surface_fraction": 0.2}, "repeat.surface_fraction=0.2"),
        ({"geometry_update": False, "elastic_after_shakedown": False}, "repeat.elastic_after_shakedown=False"),
    ],
)
def test_3d_repeat_refuses_axisymmetric_only_settings(repeat_keys, text):
    """Cycle jump and the elastic shortcut are not measured on the 3-D plate: their keys are refused (one line naming
    the key and its value), before any impact is run."""
    case = repeat_case(30.0, 0.3, 2).with_(repeat=repeat_keys)
    with pytest.raises(ValueError, match=text):
        repeat(case)


def test_normal_repeat_moves_and_writes_the_worn_3d_surface(normal_3d, tmp_path):
    """With ``repeat.geometry_update`` (the default) the wear of each impact lowers the 3-D plate's surface: the depth
    the plate's surface lost, integrated over the whole plate (its surface nodes, linear over their triangles,
    mirrored), is the run's worn volume within 2% (each impact's map read at the nodes; at normal incidence without
    friction the local slip wears, so it is not zero), and the frames written after the saved impacts carry it
    (``wear_depth_m``, the surface vertices lowered by it)."""
    from wear.app.outputs.repeat import RepeatWriter

    plate = normal_3d.plate
    disc = plate.solver.disc
    corners = plate.surface_xy[disc.surface_node_triangles]
    edges = corners[:, 1:] - corners[:, :1]
    areas = 0.5 * np.abs(edges[:, 0, 0] * edges[:, 1, 1] - edges[:, 0, 1] * edges[:, 1, 0])
    removed = 2.0 * float(np.sum(areas * plate.wear_depth[disc.surface_node_triangles].mean(axis=1)))
    print(f"removed from the plate {removed:.4e} m^3, worn {normal_3d.wear.volume_m3:.4e} m^3")
    assert normal_3d.wear.volume_m3 > 0.0
    assert removed == pytest.approx(normal_3d.wear.volume_m3, rel=0.02)
    writer = RepeatWriter(tmp_path, save_every=1)
    writer.finish(normal_3d, [])
    frame = meshio.read(tmp_path / writer.entries[-1][1])
    worn = frame.point_data["wear_depth_m"]
    on_surface = frame.point_data["on_surface"] > 0.0
    assert worn.max() > 0.0 and np.all(worn[~on_surface] == 0.0)
    np.testing.assert_allclose(frame.points[on_surface, 2], -worn[on_surface], rtol=0.0, atol=1e-15)
