"""Numbers that mean what they say: the reported peak pressure is a defined pressure (the FE's with the FE plate), the
impact history ends at the separation overlap, plate_fe.vtu carries no all-zero field, pressure.npz holds p(r, t)
as documented, and the notes a run prints are the notes of its summary."""

from __future__ import annotations

import json
import math

import meshio
import numpy as np
import pytest

from contact import simulate_impact
from contact.materials import Material
from contact.theory import effective_modulus, first_yield, hertz_peak_pressure
from wear.app.cli import main
from wear.case import default_case

ALUMINA = Material(E=380e9, nu=0.23, density=4000.0, name="alumina")
GLASS = Material(E=70e9, nu=0.25, density=2500.0, name="soda-lime glass")
STEEL = Material(E=210e9, nu=0.3, density=7850.0, yield_strength=500e6, name="steel")


@pytest.mark.parametrize("restitution", [1.0, 0.9, 0.5])
def test_max_peak_pressure_of_a_damped_hertz_impact_is_the_hertz_p0_at_the_largest_overlap(restitution):
    """With a dashpot the reported peak pressure was 3F/(2πa²) with the dashpot's force at first contact (a → 0):
    28.5 GPa (e 0.9) and 212 GPa (e 0.5) for a 3 GPa contact. Reference: Hertz (Johnson 1985, Eq. 4.23), p₀ =
    (2E*/π)(δ/R)^½ at the largest overlap δ_max, which for e = 1 is also the p₀ of the largest force."""
    radius = 2.5e-3
    res = simulate_impact(
        radius=radius, ball=ALUMINA, plate=GLASS, speed=3.9, angle=30.0, friction=0.092, restitution=restitution
    )
    e_star = effective_modulus(ALUMINA, GLASS)
    p0 = 2.0 * e_star / math.pi * math.sqrt(res.max_overlap / radius)
    assert res.max_peak_pressure == pytest.approx(p0, rel=1e-9)
    if restitution == 1.0:
        assert res.max_peak_pressure == pytest.approx(
            float(hertz_peak_pressure(res.max_force, radius, e_star)), rel=1e-6
        )
    assert res.max_peak_pressure < 3.3e9


def test_history_ends_at_the_separation_overlap_of_a_plastic_impact():
    """The last history row is the separation: force, radius and pressure 0, and the overlap the residual dent's
    (it was 0, which drew a false drop in force_overlap.png). Reference: Thornton (1997) unloading from δ*,
    F_p = F_y + π p_y R (δ* − δ_y), a_p² = (2F_p + F_y)/(2π p_y), R_p = 4E* a_p³/(3F_p), separation at
    δ_p = δ* − a_p²/R_p; within one time step of the rebound speed."""
    radius = 2.5e-3
    res = simulate_impact(
        radius=radius, ball=ALUMINA, plate=STEEL, speed=3.0, angle=0.0, friction=0.0, normal_model="thornton"
    )
    h = res.history
    assert h.normal_force[-1] == 0.0 and h.contact_radius[-1] == 0.0 and h.peak_pressure[-1] == 0.0
    e_star = effective_modulus(ALUMINA, STEEL)
    k = 4.0 / 3.0 * e_star * math.sqrt(radius)
    # Thornton's limiting pressure p_y = C(ν)·Y of the plate (the default): the Hertz p₀ at exact first yield;
    # it bounds the pressure of his model, loading and unloading
    p_y = first_yield(radius, e_star, STEEL.yield_strength, STEEL.nu).peak_pressure
    assert res.max_peak_pressure == pytest.approx(p_y, rel=1e-9)
    d_y = radius * (math.pi * p_y / (2.0 * e_star)) ** 2
    f_y = k * d_y**1.5
    d_star = res.max_overlap
    f_p = f_y + math.pi * p_y * radius * (d_star - d_y)
    a_p2 = (2.0 * f_p + f_y) / (2.0 * math.pi * p_y)
    r_p = 4.0 * e_star * a_p2**1.5 / (3.0 * f_p)
    separation = d_star - a_p2 / r_p
    assert separation > 0.1 * d_star  # a plastic impact: a real dent
    assert h.overlap[-1] == pytest.approx(separation, abs=1.5 * res.rebound_normal_velocity * res.time_step)


@pytest.fixture(scope="module")
def default_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("run") / "out"
    code = main(["run", "--out", str(out), "--quiet", "--set", "output.figures=false", "--set", "output.render=false"])
    assert code == 0
    return out


def test_reported_peak_pressure_is_the_fe_plates(default_run):
    """With the FE plate the summary's peak pressure is the FE contact pressure's maximum (it was the Hertz formula
    3F/(2πa²) of the force law, 2.74 GPa against the FE's 2.0). Reference: the pressure under an elastic–plastic
    contact is flatter than Hertz's (Johnson 1985, §6.2–6.3): its peak lies between the mean F/(πa²) and the
    Hertz peak 1.5 F/(πa²) at the largest force and contact radius."""
    summary = json.loads((default_run / "summary.json").read_text())
    imp = summary["impact"]
    assert imp["max_peak_pressure_source"] == "FE plate"
    mesh = meshio.read(default_run / "plate_fe.vtu")
    assert imp["max_peak_pressure"] == pytest.approx(float(mesh.point_data["max_pressure_Pa"].max()), rel=0.01)
    mean = imp["max_force"] / (math.pi * imp["max_contact_radius"] ** 2)
    assert 1.0 <= imp["max_peak_pressure"] / mean <= 1.5


def test_history_overlap_at_separation_is_the_fe_dent(default_run):
    """The impact's overlap at separation (the FE force law's unloading) against the FE plate's residual dent
    depth after the unloading (the surface the FE leaves): 3.63 against 3.66 µm; within 3%."""
    summary = json.loads((default_run / "summary.json").read_text())
    history = np.genfromtxt(default_run / "history.csv", delimiter=",", names=True)
    assert history["normal_force_N"][-1] == 0.0
    assert history["overlap_m"][-1] == pytest.approx(summary["dent"]["max_depth_m"], rel=0.03)


def test_plate_fe_fields_and_pressure_npz_mean_what_they_say(default_run):
    """plate_fe.vtu: every point field is non-zero somewhere (the old ``pressure`` after the rebound and the oblique
    impact's ``wear_depth`` were all zero); pressure.npz: p(r, t) with r_m[i, k] = extent_m[i]·√(1 − s_k²)."""
    mesh = meshio.read(default_run / "plate_fe.vtu")
    assert "pressure_Pa" not in mesh.point_data and "wear_depth_m" not in mesh.point_data  # 30°: not axisymmetric
    for name, values in mesh.point_data.items():
        assert np.any(np.asarray(values) != 0.0), name
    z = np.load(default_run / "pressure.npz")
    assert z["r_m"].shape == z["pressure_Pa"].shape
    np.testing.assert_allclose(z["r_m"][:, 0], z["extent_m"])
    np.testing.assert_allclose(z["r_m"][:, -1], 0.0, atol=1e-18)
    assert "p(r, t)" in str(z["about"])


def test_normal_impact_plate_fe_has_its_wear_depth(tmp_path):
    """A normal impact's wear is axisymmetric: plate_fe.vtu moves the surface down by it (non-zero field)."""
    out = tmp_path / "out"
    # β = 0: the wear rate K p^α does not need sliding (at normal incidence nothing slides)
    assert (
        main(
            [
                "run",
                "--out",
                str(out),
                "--quiet",
                "--set",
                "impact.angle=0",
                "--set",
                "wear.beta=0",
                "--set",
                "output.figures=false",
                "--set",
                "output.render=false",
                "--set",
                "fem.mesh_scale=3",
            ]
        )
        == 0
    )
    mesh = meshio.read(out / "plate_fe.vtu")
    assert mesh.point_data["wear_depth_m"].max() > 0.0 and mesh.point_data["max_pressure_Pa"].max() > 0.0


def test_notes_printed_are_the_notes_of_the_summary(tmp_path, capsys):
    """What a run prints as notes is in summary.json → notes (it said ``[]`` while the run printed a note)."""
    out = tmp_path / "out"
    case = default_case("run")
    assert case.ball.E < math.inf  # an elastic ball on the FE plate: the run notes how the FE represents it
    assert (
        main(
            [
                "run",
                "--out",
                str(out),
                "--quiet",
                "--set",
                "output.figures=false",
                "--set",
                "output.render=false",
                "--set",
                "fem.mesh_scale=3",
            ]
        )
        == 0
    )
    printed = [line.split("note: ", 1)[1] for line in capsys.readouterr().err.splitlines() if "note: " in line]
    assert printed and json.loads((out / "summary.json").read_text())["notes"] == printed
