"""Repeated oblique impacts with friction at one site on the 3-D plate (``fem.model = "3d"``,
:mod:`wear.chain.solid_repeat`): what the second and third impacts do to a dented plate, and the repeat's outputs.
The reduced 3-D plate of ``tests/solid_cases.py`` at 3 elements across the contact radius (``mesh_scale`` 2.6: per
impact the dent 3.74, 4.67, 5.07 µm and the plastic work 0.332, 0.163, 0.087 mJ, against 3.80, 4.67, 5.07 µm and
0.328, 0.163, 0.088 mJ with 4 elements). One coupling cycle an impact is not enough here: the second impact's cycle
along the first impact's path, pressed into the dent, dissipated 1.4 times the first's plastic work."""

import csv
import math
from dataclasses import replace

import meshio
import numpy as np
import pytest
from solid_cases import repeat_case, repeat_table

from wear import repeat
from wear.app.outputs.repeat import RepeatWriter

pytestmark = pytest.mark.filterwarnings("ignore:elastic ball", "ignore:contact radius")


@pytest.fixture(scope="module")
def oblique_3d():
    result = repeat(repeat_case(30.0, 0.3, 3, mesh_scale=2.6))
    print(repeat_table(result))
    return result


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
