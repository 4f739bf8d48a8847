"""A wear law is one module and one registry entry: a toy law declared below the way each law of ``wear/laws/``
declares itself, added to :data:`wear.laws.registry.LAWS` for one test, is run, calibrated, eroded with and put on a
wall by the commands, end to end, on the fast inputs of the output-folder tests. Its one constant is a key the
case schema has (``wear.cutting_fraction``, its c): a constant of its own would be a field of ``[wear]`` too."""

from __future__ import annotations

import csv
import json
from dataclasses import dataclass

import numpy as np
import pytest
from output_commands import command_args

from contact.theory import sphere_mass
from wear.app.cli import main
from wear.case import default_case
from wear.laws.declaration import Law, flow_pressure_of, need
from wear.laws.records import particle_mass, record_arrays
from wear.laws.registry import LAWS, closed_form_laws, law_named

#: The plate's hardness (Pa) of every toy run: the flow pressure p.
HARDNESS = 2e9


# --- the toy law's module: the fraction c of the normal kinetic energy over the flow pressure -------------------
def toy_volume(mass, speed, angle, flow_pressure: float, fraction: float) -> np.ndarray:
    """c ½ m (V cos θ)² / p (m³) of particles of ``mass`` (kg) at ``speed`` (m/s), ``angle`` (deg from the normal)."""
    normal = np.asarray(speed, float) * np.cos(np.radians(angle))
    return fraction * 0.5 * np.asarray(mass, float) * normal**2 / flow_pressure


def _closed_form(constants, radius, ball_density, plate, speed, angle):
    (c,) = need(constants, "toy", "cutting_fraction")
    return toy_volume(sphere_mass(radius, ball_density), speed, angle, flow_pressure_of(constants, plate), c)


def _volumes(constants, impact, *, local, plate_work):
    return {
        "toy": float(
            _closed_form(constants, impact.radius, impact.ball.density, impact.plate, impact.speed, impact.angle)
        )
    }


@dataclass(frozen=True)
class ToyLaw:
    flow_pressure: float
    fraction: float
    name: str = "toy"
    description: str = "toy law per record"

    def volume(self, angle_deg, speed_m_s, diameter_m, density_kg_m3, count):
        theta, speed, d, rho, n = record_arrays(angle_deg, speed_m_s, diameter_m, density_kg_m3, count)
        return n * toy_volume(particle_mass(d, rho), speed, theta, self.flow_pressure, self.fraction)


TOY = Law(
    name="toy",
    description="a toy: the fraction c of the normal kinetic energy over the flow pressure",
    volumes=_volumes,
    constants=("cutting_fraction",),
    scale="cutting_fraction",
    log_constants=("cutting_fraction",),
    closed_form=_closed_form,
    per_record=lambda constants, plate: ToyLaw(flow_pressure_of(constants, plate), constants["cutting_fraction"]),
    plate_keys=("rigid", "density", "hardness", "yield_strength", "name"),
)
# --- end of the toy law's module ----------------------------------------------------------------------------------


@pytest.fixture
def toy(monkeypatch):
    """The toy law in the registry: its one line."""
    monkeypatch.setitem(LAWS, TOY.name, TOY)
    return TOY


def _summary(folder) -> dict:
    return json.loads((folder / "summary.json").read_text())


def _toy_args(command: str, tmp_path) -> list[str]:
    """``command``'s fast arguments with the toy law on a plate of hardness :data:`HARDNESS`."""
    args = command_args(command, tmp_path)
    return [*args, "--set", 'wear.law="toy"', "--set", f"plate.hardness={HARDNESS}", "--out", str(tmp_path / "out")]


def test_the_registry_lists_the_toy_law(toy):
    assert law_named("toy") is toy and "toy" in closed_form_laws()


def test_run_wears_by_the_toy_law(toy, tmp_path):
    """One impact of the run's ball at its speed and angle wears c ½ m V_n² / p."""
    assert main(_toy_args("run", tmp_path)) == 0
    wear = _summary(tmp_path / "out")["wear"]
    case = default_case("run")
    mass = sphere_mass(case.ball.radius, case.ball.density)
    expected = toy_volume(mass, case.impact.speed, case.impact.angle, HARDNESS, case.wear.cutting_fraction)
    assert wear["parts_m3"] == {"toy": pytest.approx(float(expected), rel=1e-12)}


def test_erode_erodes_by_the_toy_law(toy, tmp_path):
    """The stream's response table holds the toy law's volume of each normal speed, c ½ m V_n² / p at every angle."""
    assert main(_toy_args("erode", tmp_path)) == 0
    out = tmp_path / "out"
    assert _summary(out)["results"]["mass_loss_kg"] > 0.0
    case = default_case("erode")
    mass = sphere_mass(case.ball.radius, case.ball.density)
    with (out / "response_table.csv").open() as f:
        rows = list(csv.DictReader(f))
    assert len(rows) > 1
    for row in rows:
        expected = toy_volume(mass, float(row["normal_speed_m_s"]), 0.0, HARDNESS, case.wear.cutting_fraction)
        assert float(row["volume_m3"]) == pytest.approx(float(expected), rel=1e-9)


def test_calibrate_fits_the_toy_laws_scale(toy, tmp_path):
    """Erosion ratios made by the toy law at c = 0.3 give back c = 0.3 (its scale, fitted when none is named)."""
    density = default_case("calibrate").plate.density
    rows = [(a, v) for a in (15, 45, 75) for v in (20, 40)]
    ratio = [0.3 * 0.5 * (v * np.cos(np.radians(a))) ** 2 * density / HARDNESS for a, v in rows]
    data = tmp_path / "toy.csv"
    lines = "".join(f"{a},{v},{float(e)!r}\n" for (a, v), e in zip(rows, ratio, strict=True))
    data.write_text("angle_deg,speed_m_s,erosion_kg_per_kg\n" + lines)
    argv = ["calibrate", str(data), "--law", "toy", "--set", f"plate.hardness={HARDNESS}", "--quiet"]
    assert main([*argv, "--out", str(tmp_path / "out")]) == 0
    fitted = json.loads((tmp_path / "out" / "calibration.json").read_text())
    assert fitted["law"] == "toy" and list(fitted["constants"]) == ["cutting_fraction"]
    assert fitted["constants"]["cutting_fraction"]["value"] == pytest.approx(0.3, rel=1e-9)


def test_wall_erodes_by_the_toy_law_per_record(toy, tmp_path):
    """The one record of the fast wall input, 5 m/s along the wall and 10 m/s into it, erodes c ½ m V_n² / p."""
    assert main([*_toy_args("wall", tmp_path), "--no-figures"]) == 0
    out = tmp_path / "out"
    assert _summary(out)["law"]["name"] == "toy"
    with (out / "faces.csv").open() as f:
        face = next(csv.DictReader(f))
    mass = float(particle_mass(3e-4, 2650.0))
    assert float(face["eroded_volume_m3"]) == pytest.approx(0.5 * 0.5 * mass * 10.0**2 / HARDNESS, rel=1e-9)
