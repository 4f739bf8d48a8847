"""The pipeline wear.run(case) and its output folder (issue 4 acceptance 6: mesh coherence)."""

import json
import math

import meshio
import numpy as np
import pytest

from wear import Case, run
from wear.app.outputs.run import write_run
from wear.surface import integrate_point_data

# a quick case: alumina on Ti-6Al-4V, 3 m/s at 30 deg (the default case's impact), Thornton pressure, no FE
QUICK = Case.default().with_(
    fem={"coupling": "none"}, wear={"pressure": "thornton", "speed": "sliding"}, output={"render": False}
)


def _check_folder(out, summary):
    """Acceptance 6: every file reads back; volume in summary.json = ∫ wear_depth dA over surface.vtu (1%);
    node z = −(dent + wear)."""
    on_disk = json.loads((out / "summary.json").read_text())
    assert on_disk["wear"]["volume_m3"] == pytest.approx(summary["wear"]["volume_m3"], rel=1e-12)
    for key in ("impact", "yield", "regime", "wear", "dent", "coupling", "case", "versions"):
        assert key in on_disk
    surf = meshio.read(out / "surface.vtu")
    volume = integrate_point_data(surf, "wear_depth_m")
    # the wear grid's own volume (helper's trapezoid/cell sum) and the bilinear mesh integral agree within 1%
    assert volume == pytest.approx(on_disk["wear"]["volume_m3"], rel=0.01)
    np.testing.assert_allclose(
        surf.points[:, 2], -(surf.point_data["dent_depth_m"] + surf.point_data["wear_depth_m"]), rtol=0, atol=1e-18
    )
    assert surf.point_data["wear_depth_m"].max() == pytest.approx(on_disk["wear"]["max_depth_m"], rel=1e-9)
    plate = meshio.read(out / "plate.vtu")
    assert "hexahedron" in plate.cells_dict
    for name in on_disk["files"]:
        path = out / name
        assert path.is_file(), name
        if path.suffix == ".vtu":
            meshio.read(path)
    with np.load(out / "pressure.npz") as npz:
        assert npz["pressure_Pa"].shape == (npz["time_s"].size, npz["s"].size)
    header = (out / "history.csv").read_text().splitlines()[0].split(",")
    assert header[:3] == ["time_s", "overlap_m", "normal_force_N"]
    return on_disk, surf


def test_run_without_fe_writes_coherent_folder(tmp_path):
    """Issue 4 acceptance 6 on the one-way chain without FE (no dent): mesh coherence and readable files; the
    impulse identity (acceptance 2 of the wear stage, K m V_n (1 + e) for alpha = 1, beta = 0) is not
    applicable with beta = 0.3, so the volume is checked against the mesh integral only."""
    result = run(QUICK)
    assert set(result.stage_times) == {"impact", "wear", "surface"}
    summary = write_run(result, tmp_path / "out")
    on_disk, surf = _check_folder(tmp_path / "out", summary)
    assert on_disk["dent"]["max_depth_m"] == 0.0
    assert on_disk["coupling"] is None
    # first yield numbers are the closed forms of errata Eq. 18 (C = 1.6) and the exact C(0.3x) (> Eq. 18 value)
    assert on_disk["yield"]["F_c_exact"] > on_disk["yield"]["F_y_paper"]
    assert on_disk["impact"]["max_force"] > on_disk["yield"]["F_c_exact"]


def test_impulse_identity_through_the_pipeline():
    """Wear impulse identity (issue 4 acceptance 2) through run(): for alpha = 1, beta = 0 the worn volume is
    K ∫F dt = K m V_n (1 + e_n) within 0.5% (momentum balance), here with the Thornton pressure and e_n < 1."""
    case = QUICK.with_(wear={"alpha": 1.0, "beta": 0.0, "K": 1e-13})
    result = run(case)
    imp = result.impact
    v_n = case.impact.speed * math.cos(math.radians(case.impact.angle))
    expected = 1e-13 * imp.mass * v_n * (1.0 + imp.normal_restitution)
    assert result.wear.volume_m3 == pytest.approx(expected, rel=0.005)


@pytest.mark.parametrize(
    "tables, key",
    [
        ({"wear": {"K": -1.0}}, "wear.K"),
        ({"wear": {"pressure": "magic"}}, "wear.pressure"),
        ({"impact": {"angle": 120.0}}, "impact.angle"),
        ({"fem": {"coupling": "both"}}, "fem.coupling"),
        ({"plate": {"E": 210.0}}, "plate.E"),
        ({"ball": {"radius": 0.0}}, "ball.radius"),
        ({"wear": {"Kw": 1.0}}, "wear.Kw"),
        ({"extra": {}}, "extra"),
    ],
)
def test_case_errors_name_the_key(tables, key):
    with pytest.raises(ValueError, match=key.replace(".", r"\.")):
        Case.from_dict(tables)


def test_fe_pressure_without_fe_is_an_error():
    with pytest.raises(ValueError, match="wear.pressure='fe'"):
        run(Case.default().with_(fem={"coupling": "none"}))


def test_user_plate_mesh_is_deformed_in_the_output(tmp_path):
    """A user's meshio plate block (output.plate_mesh) replaces the generated plate.vtu: its top nodes move to
    −(dent + wear) interpolated from surface.vtu's grid (here no dent: −wear; checked at the wear maximum)."""
    from wear.surface import DeformedSurface, plate_block_mesh

    flat = DeformedSurface.flat_dent(np.linspace(-5e-4, 5e-4, 41), np.linspace(-5e-4, 5e-4, 41), np.zeros((41, 41)))
    block = plate_block_mesh(flat, 1e-3, n_layers=3)
    user = meshio.Mesh(block.points, block.cells)  # an undeformed hexahedral block, top at z = 0
    path = tmp_path / "block.vtu"
    user.write(path)
    result = run(QUICK.with_(output={"plate_mesh": str(path), "figures": False}))
    write_run(result, tmp_path / "out")
    moved = meshio.read(tmp_path / "out" / "plate.vtu")
    assert moved.points.shape == user.points.shape
    top = user.points[:, 2] == 0.0
    expected = -result.surface.wear_at(user.points[top, 0], user.points[top, 1])
    np.testing.assert_allclose(moved.points[top, 2], expected, rtol=0, atol=1e-18)
    assert -moved.points[top, 2].min() <= result.wear.max_depth_m * (1 + 1e-12)


@pytest.mark.filterwarnings("ignore:elastic ball")
def test_one_way_fe_pressure_normal_impact(tmp_path):
    """One-way chain (impact → fem.indent_impact → "fe" pressure) on an elastic plate, normal impact, alpha = 1,
    beta = 0, kinematic speed: the worn volume is K ∫F_FE dt, and with the FE force within a few % of Hertz it
    equals the impulse identity K m V_n (1 + e) (issue 4 acceptance 2) within 3% (coarse FE mesh, 16 steps);
    plate_fe.vtu's surface nodes are moved down by the axisymmetric wear depth, whose maximum is the grid's."""
    case = QUICK.with_(
        plate={"yield_strength": None},
        impact={"angle": 0.0, "normal_model": "hertz"},
        wear={"pressure": "fe", "alpha": 1.0, "beta": 0.0, "K": 1e-13, "speed": "kinematic"},
        fem={"coupling": "one-way", "mesh_scale": 4.0, "load_steps": 10, "unload_steps": 6},
        output={"figures": False},
    )
    result = run(case)
    imp = result.impact
    expected = 1e-13 * imp.mass * case.impact.speed * (1.0 + imp.normal_restitution)
    assert result.wear.volume_m3 == pytest.approx(expected, rel=0.03)
    write_run(result, tmp_path / "out")
    fe_mesh = meshio.read(tmp_path / "out" / "plate_fe.vtu")
    assert fe_mesh.point_data["wear_depth_m"].max() == pytest.approx(result.wear.max_depth_m, rel=0.02)


@pytest.mark.filterwarnings("ignore:elastic ball")
def test_one_way_fe_pressure_plastic_impact():
    """One-way chain on a plate that yields (the default case, Thornton's rebound separates at a residual overlap
    above 0, so the FE unloading goes on below it after the ball has left): the run completes, and with alpha = 1,
    beta = 0 and the kinematic speed the worn volume is K ∫F_FE dt over the FE steps up to separation (the law's
    impulse identity, integrated by the trapezoid rule independently of the wear grid) within 3%."""
    case = Case.default().with_(
        wear={"pressure": "fe", "alpha": 1.0, "beta": 0.0, "K": 1e-13, "speed": "kinematic"},
        fem={"coupling": "one-way", "mesh_scale": 4.0, "load_steps": 10, "unload_steps": 6},
        output={"figures": False, "render": False},
    )
    result = run(case)
    fe = result.fe
    time, force = np.asarray(fe.time), np.asarray(fe.force)
    during = np.r_[True, np.diff(time) > 0.0]
    assert time[-1] == pytest.approx(result.impact.contact_time, rel=1e-9)
    assert np.count_nonzero(~during) >= 1  # steps after separation exist (the case is the one this test is for)
    impulse = np.trapezoid(force[during], time[during])
    assert result.wear.volume_m3 == pytest.approx(1e-13 * impulse, rel=0.03)


@pytest.mark.filterwarnings("ignore:elastic ball")
def test_two_way_run_with_dent_writes_coherent_folder(tmp_path):
    """Issue 4 acceptance 6 on the default case's two-way chain (coarse FE mesh): volume in summary.json equals
    ∫ wear_depth dA over surface.vtu within 1%, node z = −(dent + wear) with a real dent, every file reads back
    (plate_fe.vtu too). (The FE first yield is checked against F_c in tests/test_cli_run.py on the default mesh.)"""
    case = Case.default().with_(
        fem={"mesh_scale": 4.0, "load_steps": 10, "unload_steps": 6}, output={"render": False, "figures": False}
    )
    result = run(case)
    summary = write_run(result, tmp_path / "out")
    on_disk, surf = _check_folder(tmp_path / "out", summary)
    assert on_disk["dent"]["max_depth_m"] > 0.05 * on_disk["impact"]["max_overlap"]
    assert surf.point_data["dent_depth_m"].max() > 0
    assert on_disk["coupling"]["converged"] and on_disk["coupling"]["final_change"] < 0.005
    assert on_disk["regime"] in ("surface-plastic", "fully-plastic")
    meshio.read(tmp_path / "out" / "plate_fe.vtu")
