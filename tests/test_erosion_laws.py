"""The stream erosion (wear.erosion, what `impactwear erode --angles` runs) against the closed-form wear laws: on a
nearly flat plate every particle hits at the stream's angle and speed, so the erosion rate (kg/kg) is the law's own
erosion ratio at (V, θ). The references are the laws' formulas written out here from their papers, independent of
wear.laws and of the response table."""

import math

import numpy as np
import pytest

from wear.case import default_case
from wear.erosion.run import erode_angles

ANGLES = (0.0, 30.0, 55.0, 70.0, 75.0, 80.0, 83.0, 85.0)
SPEED, RADIUS, SAND_DENSITY = 20.0, 150e-6, 2650.0
HARDNESS, STEEL_DENSITY = 1.4e9, 7850.0
CUTTING_FRACTION, FORCE_RATIO, DEPTH_RATIO = 0.1, 2.0, 2.0


def _finnie(theta: float) -> float:
    """Finnie (1960, Wear 3: 87-103): volume c m V² / (p ψ K) (sin 2α − 6/K sin²α) for tan α ≤ K/6, else
    c m V² / (p ψ K) · K cos²α / 6 (α from the surface); as a mass ratio, volume · ρ_plate / m."""
    a = math.radians(90.0 - theta)
    k = FORCE_RATIO
    if math.tan(a) <= k / 6.0:
        shape = math.sin(2.0 * a) - 6.0 / k * math.sin(a) ** 2
    else:
        shape = k * math.cos(a) ** 2 / 6.0
    return CUTTING_FRACTION * SPEED**2 / (HARDNESS * DEPTH_RATIO * k) * shape * STEEL_DENSITY


def _oka(theta: float) -> float:
    """Oka, Okamura & Yoshida (2005, Wear 259: 95-101) with E90 of Oka & Yoshida (2005, Wear 259: 102-109),
    65 H_v^-0.12 mm³/kg × ρ (H_v in GPa): E = E90 (V/104)^k2 (D/326 µm)^0.19 sin^n1 α (1 + H_v (1 − sin α))^n2,
    n1 = 0.71 H_v^0.14, n2 = 2.4 H_v^-0.94, k2 = 2.3 H_v^0.038."""
    hv = HARDNESS / 1e9
    s = math.sin(math.radians(90.0 - theta))
    e90 = 65e-9 * hv**-0.12 * STEEL_DENSITY
    n1, n2, k2 = 0.71 * hv**0.14, 2.4 * hv**-0.94, 2.3 * hv**0.038
    return e90 * (SPEED / 104.0) ** k2 * (2 * RADIUS / 326e-6) ** 0.19 * s**n1 * (1.0 + hv * (1.0 - s)) ** n2


def _dnv(theta: float) -> float:
    """DNV-RP-O501 (2015): E = K U^n F(α), F(α) = 0.6 (sin α + 7.2 (sin α − sin²α))^0.6 (1 − e^(−20α)), α in rad
    from the surface; K = 2e-9, n = 2.6 (steel)."""
    a = math.radians(90.0 - theta)
    s = math.sin(a)
    return 2e-9 * SPEED**2.6 * 0.6 * (s + 7.2 * (s - s * s)) ** 0.6 * (1.0 - math.exp(-20.0 * a))


@pytest.mark.filterwarnings("ignore:elastic ball")
@pytest.mark.parametrize("law, formula", [("finnie", _finnie), ("oka", _oka), ("dnv", _dnv)])
def test_erode_follows_each_closed_form_law_from_normal_to_grazing(law, formula):
    """Silica sand (R 150 µm) on carbon steel (H_v 1.4 GPa) at 20 m/s, 0–85° from the normal: the stream's erosion
    rate is the law's erosion ratio within 0.5% at every angle (measured ≤ 0.24%, at 80°: the slight roughening of
    8–90 impacts). Before the table was interpolated as a power law of the normal speed along the particle's speed,
    this table gave DNV's rate 0.8% high at 55°, 2.4% at 75°, 23% at 80° and 63% at 83° (that angle off the angle
    axis; the default table: 2.4% at 55°, 11% at 75°, 36% at 83°). A table of 3 speeds and 5° steps keeps the test
    short: a power-law volume is exact for any number of speeds, and the stream's angle is a node of any table."""
    case = default_case("erode").with_(
        ball={"radius": RADIUS, "E": 94e9, "nu": 0.17, "density": SAND_DENSITY, "name": "silica sand"},
        plate={"E": 200e9, "nu": 0.3, "density": STEEL_DENSITY, "yield_strength": 350e6, "hardness": HARDNESS},
        impact={"speed": SPEED, "friction": 0.3},
        wear={"law": law, "cutting_fraction": CUTTING_FRACTION, "force_ratio": FORCE_RATIO, "depth_ratio": DEPTH_RATIO},
        erosion={
            "grid": 192,
            "patch_size": 6e-4,
            "exposure_time": 1.0,
            "samples": 2,
            "frames": 1,
            "table_speeds": 3,
            "angle_step": 5.0,
            "angle_margin": 10.0,
        },
    )
    runs = erode_angles(case, list(ANGLES))
    rates = np.array([r.result.final_erosion_rate for r in runs])
    expected = np.array([formula(a) for a in ANGLES])
    for angle, run in zip(ANGLES, runs, strict=True):
        assert run.result.n_impacts >= 8 and run.result.rms_slope[-1] < 0.01, angle  # a nearly flat plate
    if law == "finnie":  # nothing at normal incidence (round-off of cos²90°)
        assert rates[0] <= 1e-12 * rates.max() and expected[0] <= 1e-12 * expected.max()
        rates, expected = rates[1:], expected[1:]
    np.testing.assert_allclose(rates, expected, rtol=5e-3)
