"""The oblique impact on the 3-D plate in the chain (``fem.model = "3d"``): the frictionless oblique impact against the
axisymmetric chain, its outputs, the dent's dimensions against closed forms, and the bad-input errors.

Reduced path (CI): the default 3-D mesh (4 elements across the contact radius), 5 + 3 increments.
"""

import json

import meshio
import numpy as np
import pytest
from solid_cases import REDUCED_3D

import fem.core.increments
import fem.solid.solver
from contact import effective_modulus
from contact.theory import first_yield
from wear import run
from wear.app.cli import main
from wear.case import JOBS
from wear.chain.solid_run import SOLID_PLASTIC_REGIME
from wear.surface import DeformedSurface

REDUCED = REDUCED_3D


@pytest.fixture(scope="module")
def frictionless():
    case = JOBS["run"].default_case().with_(impact={"friction": 0.0}, fem=REDUCED, output={"render": False})
    return run(case)


def test_frictionless_oblique_impact_equals_the_axisymmetric_chain(frictionless):
    """Reference: the axisymmetric plate's chain of the same case (the (r, z) model, its own mesh and solver), which
    the 3-D run starts from and keeps in ``coupling``/``fe``: without friction the half block must give the same
    impact and dent (issue acceptance: within 2 %)."""
    r = frictionless
    axisymmetric = r.coupling.impact
    assert r.solid.converged
    assert r.impact.normal_restitution == pytest.approx(axisymmetric.normal_restitution, rel=0.02)
    assert r.impact.max_force == pytest.approx(axisymmetric.max_force, rel=0.02)
    assert r.surface.max_dent_depth == pytest.approx(float(np.max(r.fe.residual_depth)), rel=0.02)
    # no friction, no tangential traction on the plate (the impact's own tangential force is 0 too)
    assert np.max(np.abs(r.solid.solid.tangential_force)) < 1e-6 * r.impact.max_force
    assert r.impact.spin == 0.0


def test_frictionless_worn_volume_near_the_axisymmetric_chain(frictionless):
    """Reference: the axisymmetric chain's local wear law over its FE pressure p(r/a, t) and its surface's local slip
    (the ball's slip less the surface's radial motion, the same physics as the 3-D plate's vertex slip at μ = 0).
    The 3-D wear interpolates its fields linearly in time at fixed plate points (wear.solid_wear), which loses p^α at
    the growing contact edge between steps: within 10 % on the reduced path."""
    from wear.chain.axisymmetric_run import impact_wear

    r = frictionless
    c = r.coupling
    ph, wm, worn = impact_wear(r.case, c.impact, c.pressure_table, c.plastic_work, c.radial_table)
    print(f"worn volume 3-D {r.wear.volume_m3:.4e} m^3, axisymmetric {wm.volume_m3:.4e} m^3")
    assert r.wear.volume_m3 == pytest.approx(wm.volume_m3, rel=0.10)


def test_3d_outputs(frictionless, tmp_path):
    """plate_fe.vtu is the whole 3-D plate (mirrored half block) with its plastic strain; the summary reports the
    3-D plate and the dent's length, width and pile-up."""
    from wear.app.outputs.run import write_run

    summary = write_run(frictionless, tmp_path / "out")
    mesh = meshio.read(tmp_path / "out" / "plate_fe.vtu")
    assert mesh.cells[0].type == "tetra"
    y = mesh.points[:, 1]
    assert y.min() == pytest.approx(-y.max())
    assert np.max(mesh.cell_data["equivalent_plastic_strain"][0]) > 0.0
    assert (tmp_path / "out" / "plastic_zone.png").is_file()
    with np.load(tmp_path / "out" / "pressure.npz") as fields:
        # the slip field beside the pressure: one (x, y) slip per step and surface vertex
        steps, vertices = fields["fe3d_pressure_Pa"].shape
        assert fields["fe3d_slip_m"].shape == (steps, vertices, 2)
    saved = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert saved["plate_3d"]["increments"] == summary["plate_3d"]["increments"] > 0
    # the impact ran on the plate's tangential law, and the case written with the run says so
    assert saved["plate_3d"]["tangential_model"] == "mindlin_deresiewicz"
    assert frictionless.case.impact.tangential_model == "mindlin_deresiewicz"
    # the slip traction's limit is the shear yield stress of the perfectly plastic plate's surface, Y/√3 (von Mises)
    plate_yield = frictionless.case.plate.material().yield_strength
    assert saved["plate_3d"]["surface_shear_strength_Pa"] == pytest.approx(plate_yield / np.sqrt(3.0), rel=1e-12)
    dent = saved["dent"]
    assert dent["model"] == "3d"
    # the dent is wider than deep by far, and a plastic dent has a lip above the original plane
    assert dent["length_m"] > 10 * dent["max_depth_m"] and dent["width_m"] > 10 * dent["max_depth_m"]
    assert dent["pile_up_m"] > 0.0


def test_dent_dimensions_of_a_closed_form_profile():
    """A paraboloidal dent h = d (1 − r²/c²) for r < c, rising to a lip of height L at r = 1.2 c and back to 0 at
    r = 1.4 c: length = width = 2c, pile-up L (closed form)."""
    depth, c, lip = 2e-6, 150e-6, 0.3e-6
    r = np.linspace(0.0, 2.0 * c, 2001)
    h = np.where(r < c, depth * (1 - r**2 / c**2), -lip * np.clip(1 - np.abs(r - 1.2 * c) / (0.2 * c), 0, 1))
    grid = np.linspace(-3 * c, 3 * c, 7)
    dims = DeformedSurface(grid, grid, np.zeros((7, 7)), r, h, (10e-6, 0.0)).dent_dimensions()
    assert dims.length == pytest.approx(2 * c, rel=1e-3)
    assert dims.width == pytest.approx(2 * c, rel=1e-3)
    assert dims.pile_up == pytest.approx(lip, rel=1e-3)
    # the same dent as a field on a fine grid (the 3-D plate's form): the same dimensions within a grid cell
    x = np.linspace(-3 * c, 3 * c, 301)
    gx, gy = np.meshgrid(x, x, indexing="ij")
    field = np.interp(np.hypot(gx, gy), r, h, right=0.0)
    on_grid = DeformedSurface(x, x, np.zeros_like(field), r, h, dent_grid=field).dent_dimensions()
    cell = x[1] - x[0]
    assert abs(on_grid.length - 2 * c) < cell and abs(on_grid.width - 2 * c) < cell
    assert on_grid.pile_up == pytest.approx(lip, rel=0.05)


@pytest.mark.parametrize(
    "sets, expected",
    [
        (['fem.coupling="one-way"'], "fem.model='3d' needs fem.coupling='two-way'"),
        (["impact.friction=1.5"], "impact.friction=1.5"),
        (["fem.mesh_scale=4.0"], "fem.mesh_scale=4.0: the 3-D plate would have 2 elements across"),
    ],
)
def test_3d_bad_input_one_line_exit_2_nothing_written(sets, expected, tmp_path, capsys):
    args = ["run", "--out", str(tmp_path / "out"), "--quiet", "--set", 'fem.model="3d"']
    for s in sets:
        args += ["--set", s]
    status = main(args)
    err = capsys.readouterr().err.strip()
    assert status == 2
    assert len(err.splitlines()) == 1, err
    assert expected in err, err
    assert not (tmp_path / "out").exists()


def test_3d_non_converging_increment_one_line_nothing_written(tmp_path, capsys, monkeypatch):
    """An increment that does not converge (here forced: every Newton solve fails) ends the run with one line naming
    the overlap where it failed, and no output folder."""

    def fails(self, *args, **kwargs):
        raise fem.core.increments.NotConverged(1.0)

    monkeypatch.setattr(fem.solid.solver.SolidSolver, "_newton", fails)
    args = ["run", "--out", str(tmp_path / "out"), "--quiet", "--set", 'fem.model="3d"', "--set", "fem.mesh_scale=2.6"]
    status = main(args)
    err = capsys.readouterr().err.strip()
    assert status == 1
    assert len(err.splitlines()) == 1, err
    assert "3-D plate: Newton did not converge at overlap=" in err, err
    assert not (tmp_path / "out").exists()


def test_3d_run_summary_describes_the_3d_plate(frictionless, tmp_path):
    """``regime``, ``yield.fe_first_yield_force`` and ``coupling`` of a 3-D run are the 3-D plate's, each naming its
    plate; the axisymmetric plate it started from is kept under keys that say so. Reference for the first yield:
    the closed form F_c = (π C Y)³ R² / (6 E*²) with the exact C(ν) (Johnson 1985 §6.2, contact.theory): the 3-D
    plate's step before its first plastic step carries less (within 5 %: the plate's mesh), its first plastic step
    more."""
    from wear.app.outputs.run import write_run

    summary = write_run(frictionless, tmp_path / "out")
    saved = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert saved["fem_model"] == saved["regime_plate"] == "3d"
    solid = frictionless.solid
    # coupling: the 3-D coupling's cycles and convergence, the axisymmetric start inside
    coupling = saved["coupling"]
    assert coupling["plate"] == "3d"
    assert coupling["iterations"] == solid.iterations == len(coupling["max_overlaps_m"]) - 1
    assert coupling["converged"] == solid.converged
    assert coupling["max_overlaps_m"][-1] == pytest.approx(frictionless.impact.max_overlap, rel=1e-12)
    assert coupling["axisymmetric_start"]["plate"] == "axisymmetric"
    assert coupling["start_max_overlap_m"] == pytest.approx(frictionless.coupling.impact.max_overlap, rel=1e-12)
    # regime: from the 3-D plate's plastic strain (the default case yields well past first yield)
    assert np.max(solid.solid.max_equivalent_plastic_strain) > 0.0
    assert saved["regime"] == SOLID_PLASTIC_REGIME
    assert saved["axisymmetric_start_regime"] in ("surface-plastic", "fully-plastic")
    # first yield: the 3-D plate's, bracketed by the closed form
    y = saved["yield"]
    assert y["fe_first_yield_plate"] == "3d"
    case = frictionless.case
    plate = case.plate.material()
    f_c = first_yield(
        case.ball.radius, effective_modulus(case.ball.material(), plate), plate.yield_strength, plate.nu
    ).force
    assert y["F_c_exact"] == pytest.approx(f_c, rel=1e-12)
    forces = solid.solid.normal_force
    k = int(np.flatnonzero(solid.solid.max_equivalent_plastic_strain > 0.0)[0])
    assert y["fe_first_yield_force"] == forces[k] >= f_c
    assert k == 0 or forces[k - 1] <= 1.05 * f_c
    assert y["axisymmetric_first_yield_force"] == pytest.approx(f_c, rel=0.03)
    assert summary["yield"] == saved["yield"]
