"""A wear coefficient far too large for its case: the repeat runs (its first impact alone wears past the FE mesh's
valid depth) and a run says, in its notes, when one impact wears deeper than its contact radius or more mass than
the ball has (:func:`wear.integrate.implausible_wear`)."""

import json
import math

import numpy as np
import pytest

from contact.theory import sphere_mass
from wear import Case, repeat, run
from wear.app.cli import main
from wear.integrate import WearMap, implausible_wear

# the default case's impact (alumina R 2.5 mm on Ti-6Al-4V, 3 m/s at 30 deg), Thornton pressure, no FE: quick
QUICK = Case.default().with_(
    fem={"coupling": "none"}, wear={"pressure": "thornton", "speed": "sliding"}, output={"render": False}
)
pytestmark = pytest.mark.filterwarnings("ignore:elastic ball")


def _map(depth: float, mass: float) -> WearMap:
    x = np.linspace(-1e-4, 1e-4, 5)
    grid = np.zeros((5, 5))
    grid[2, 2] = depth
    return WearMap(x, x, grid, mass / 4430.0, mass, depth, 0.0, 0.0, 4430.0)


def test_implausible_wear_names_depth_beyond_the_contact_radius_and_mass_beyond_the_ball():
    assert implausible_wear(_map(0.9e-4, 1e-5), 1e-4, 2e-5) == []
    (depth,) = implausible_wear(_map(1.1e-4, 1e-5), 1e-4, 2e-5)
    assert "0.00011 m, exceeds the contact radius 0.0001 m" in depth
    (mass,) = implausible_wear(_map(0.9e-4, 3e-5), 1e-4, 2e-5)
    assert "3e-05 kg, exceeds the ball's mass 2e-05 kg" in mass


@pytest.mark.parametrize("factor, warned", [(0.95, False), (1.05, True)])
def test_worn_mass_note_at_the_impulse_identity_threshold(factor, warned):
    """For alpha = 1, beta = 0 the worn volume of one impact is K m V_n (1 + e_n) (momentum balance; the impulse
    identity of tests/test_pipeline.py), so the worn mass ρ_plate K m V_n (1 + e_n) reaches the ball's mass m at
    K* = 1 / (ρ_plate V_n (1 + e_n)): 5% below it no mass note, 5% above it one."""
    probe = run(QUICK.with_(wear={"alpha": 1.0, "beta": 0.0, "K": 1e-13}))
    v_n = QUICK.impact.speed * math.cos(math.radians(QUICK.impact.angle))
    k_star = 1.0 / (QUICK.plate.material().density * v_n * (1.0 + probe.impact.normal_restitution))
    with pytest.warns(UserWarning) as record:
        run(QUICK.with_(wear={"alpha": 1.0, "beta": 0.0, "K": factor * k_star}))
    messages = [str(w.message) for w in record]
    assert any("exceeds the contact radius" in m for m in messages)  # far deeper than a long before the mass
    assert any("exceeds the ball's mass" in m for m in messages) is warned


def test_run_with_the_largest_wear_coefficient_says_so_in_its_notes_and_summary(tmp_path, capsys):
    """wear.K = 1e-3 (the top of its range): metres of wear from one 0.26 g ball; stderr and summary.json say so."""
    out = tmp_path / "out"
    argv = ["run", "--set", "wear.K=1e-3", "--set", "fem.coupling='none'", "--set", "wear.pressure='thornton'"]
    argv += ["--set", "wear.speed='sliding'"]
    assert main([*argv, "--set", "output.render=false", "--out", str(out), "--quiet"]) == 0
    err = capsys.readouterr().err
    notes = json.loads((out / "summary.json").read_text())["notes"]
    ball = sphere_mass(QUICK.ball.radius, QUICK.ball.material().density)
    for text in ("exceeds the contact radius", f"exceeds the ball's mass {ball:.3g} kg"):
        assert sum(text in n for n in notes) == 1
        assert sum(text in line for line in err.splitlines()) == 1


def test_repeat_whose_first_impact_wears_past_the_mesh_reports_that_impact():
    """wear.K = 1e-7 (every K from here up crashed): the first impact wears deeper than half the FE mesh's taper
    depth; it is reported (one record, its wear the total), the run stops with a note, and the plate's surface is
    left as that impact met it."""
    case = Case().with_(
        wear={"K": 1e-7}, repeat={"impacts": 5}, fem={"mesh_scale": 4.0}, output={"figures": False, "render": False}
    )
    result = repeat(case)
    assert [(r.first, r.last) for r in result.records] == [(1, 1)]
    assert result.wear.volume_m3 == pytest.approx(result.records[0].wear_volume, rel=1e-12)
    assert result.wear_depth_over_taper == 0.0
    assert any(n.startswith("stopped after impact 1: the worn depth would exceed") for n in result.notes)
