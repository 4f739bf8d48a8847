"""Repeated oblique impacts with friction at one site on the 3-D plate (``fem.model = "3d"``,
:mod:`wear.chain.solid_repeat`): what the second and third impacts do to a dented plate, and the repeat's outputs.
The reduced 3-D plate of ``tests/solid_cases.py`` at 3 elements across the contact radius (``mesh_scale`` 2.6) and
at most 3 coupling cycles: per impact the dent 3.74, 4.65, 5.06 µm and the plastic work 0.332, 0.164, 0.089 mJ
(2026-11-27, each later impact started on the reloading law; from the previous impact and at most 2 cycles: 3.74,
4.67, 5.07 µm and 0.332, 0.163, 0.087 mJ). One coupling cycle an impact is not enough here: the second impact's
cycle along the first impact's path, pressed into the dent, dissipated 1.4 times the first's plastic work."""

import copy
import csv
import math
from dataclasses import replace

import meshio
import numpy as np
import pytest
from solid_cases import repeat_case, repeat_table

import wear.chain.solid_repeat as solid_repeat
from wear import repeat
from wear.app.outputs.repeat import RepeatWriter
from wear.chain.solid import solid_wear

pytestmark = pytest.mark.filterwarnings("ignore:elastic ball", "ignore:contact radius")


def _repeat_with_couplings(case):
    """``repeat(case)``, each impact's coupling call (positional arguments of
    :func:`fem.solid_coupling.couple_solid_plate`), its :class:`fem.solid_coupling.SolidCoupledImpact`, and a copy of
    the plate after each (:class:`fem.solid.plate.SolidPlate` commits by rebinding its frozen state)."""
    calls, couplings, plates = [], [], []
    couple = solid_repeat.couple_solid_plate

    def recorded(*args):
        calls.append(args)
        couplings.append(couple(*args))
        plates.append(copy.copy(args[2]))
        return couplings[-1]

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(solid_repeat, "couple_solid_plate", recorded)
        result = repeat(case)
    print(repeat_table(result))
    print("plate cycles", [c.iterations for c in couplings], "converged", [c.converged for c in couplings])
    return result, calls, couplings, plates


@pytest.fixture(scope="module")
def oblique_couplings():
    return _repeat_with_couplings(repeat_case(30.0, 0.3, 3, mesh_scale=2.6, solid_iterations=3))


@pytest.fixture(scope="module")
def oblique_3d(oblique_couplings):
    return oblique_couplings[0]


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


def test_second_impact_reaches_the_same_answer_from_the_reloading_law_in_fewer_cycles(oblique_couplings):
    """The second impact's coupling does not depend on its start (the fixed point of the 3-D plate's cycles): on the
    plate the first impact left, started from the first impact (run on the virgin plate) instead of the impact on
    the dented plate's reloading law (:func:`fem.force_law.reloading_law`), it converges to the same δ_max and e_t
    within the coupling's tolerance (0.005: relative for δ_max, absolute for e_t), e_n and the dent within 0.5%, the
    wear (not in the coupling's measure: it follows the slip history) within 5%; the reloading start needs fewer 3-D
    plate cycles (here 2 against 3, e_n 0.9140 against 0.9144, e_t 0.6216 against 0.6218; docs/repeat-record.md for the
    default mesh)."""
    result, calls, couplings, plates = oblique_couplings
    on_law, _, _, settings, offset = calls[1]
    plate = copy.copy(plates[0])
    theirs = solid_repeat.couple_solid_plate(on_law, couplings[0].impact, plate, settings, offset)
    mine = couplings[1]
    print("from the first impact:", theirs.iterations, "cycles, e_n", theirs.impact.normal_restitution)
    assert mine.converged and theirs.converged
    assert mine.iterations < theirs.iterations
    tolerance = settings.tolerance
    assert mine.impact.max_overlap == pytest.approx(theirs.impact.max_overlap, rel=tolerance)
    assert mine.impact.tangential_restitution == pytest.approx(theirs.impact.tangential_restitution, abs=tolerance)
    assert mine.impact.normal_restitution == pytest.approx(theirs.impact.normal_restitution, rel=0.005)
    assert result.records[1].dent_depth == pytest.approx(plate.dent_depth, rel=0.005)
    wear = solid_wear(result.case, theirs)[1].volume_m3
    assert result.records[1].wear_volume == pytest.approx(wear, rel=0.05)
