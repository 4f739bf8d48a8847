"""Validation checks of the wear laws side by side (:mod:`wear.laws`) and of their calibration
(:mod:`wear.chain.calibrate`), for ``impactwear validate``.

References: the laws' closed forms evaluated by hand from the papers' formulas (Finnie 1960's angle of maximum
tan 2α = K/3; DNV-RP-O501's F(α); Oka et al. 2005 at its reference point); Thornton's (1997) yield speed as the onset
of Bitter's deformation wear; round trips (data made by each law with known constants and 10% log-normal noise);
and the measured trends of ductile metals (:data:`wear.app.validation.references.MEASURED_EROSION`) after a
calibration on Oka et al.'s carbon-steel curve.
"""

from __future__ import annotations

import math

import numpy as np

from contact.theory import yield_velocity
from wear.app.validation.checks import Check, absolute, relative
from wear.app.validation.references import MEASURED_EROSION, OKA_CARBON_STEEL, OKA_SOURCE, oka_curve
from wear.case import default_case
from wear.chain.calibrate import calibrate
from wear.chain.calibration_data import CalibrationData
from wear.chain.forward_model import ForwardModel
from wear.chain.trends import law_trends
from wear.laws.dnv import dnv_angle_function
from wear.laws.finnie import finnie_volume
from wear.laws.oka import oka_erosion_ratio

#: The calibration case: silica sand on carbon steel (impactwear calibrate's default) of Oka's hardness.
CASE = default_case("calibrate").with_(
    plate={"hardness": OKA_CARBON_STEEL["hardness"]}, wear={"deformation_factor": 1e10}
)
CASE_TEXT = "silica sand R 150 um on carbon steel (Y 350 MPa, H 1.4 GPa), Thornton"


def wear_law_closed_forms(quick: bool) -> list[Check]:
    """Finnie's maximum at tan 2α = K/3 (16.85° from the surface for K = 2), found numerically on the law; DNV's
    F(α) at normal incidence and at 30° from the surface, and Oka's ratio at its reference point (104 m/s, 326 µm,
    normal incidence: E90) and at 30° from the surface, against values computed by hand from the papers' formulas."""
    theta = np.linspace(0.0, 89.99, 200_001)
    v = finnie_volume(1e-9, 20.0, theta, 1e9)
    peak = 90.0 - float(theta[np.argmax(v)])
    s30 = 0.5  # sin 30°
    dnv30 = 0.6 * (s30 + 7.2 * (s30 - s30**2)) ** 0.6 * (1.0 - math.exp(-20.0 * math.pi / 6.0))
    hv = 1.8  # GPa
    n1, n2 = 0.71 * hv**0.14, 2.4 * hv**-0.94
    oka30 = 6.154e-4 * s30**n1 * (1.0 + hv * (1.0 - s30)) ** n2
    return [
        absolute("wear", "Finnie angle of maximum", "K = 2", 16.8450, "Finnie 1960: tan 2a = K/3", peak, 0.01, "deg"),
        absolute("wear", "Finnie at normal incidence", "K = 2", 0.0, "Finnie 1960", float(v[0] / v.max()), 1e-12),
        relative(
            "wear",
            "DNV F(a), normal incidence",
            "ductile",
            0.6,
            "DNV-RP-O501 (2015) Eq. 3.3",
            float(dnv_angle_function(0.0)),
            1e-9,
        ),
        relative(
            "wear",
            "DNV F(a), 30 deg from the surface",
            "ductile",
            dnv30,
            "DNV-RP-O501 (2015), by hand",
            float(dnv_angle_function(60.0)),
            1e-9,
        ),
        relative(
            "wear",
            "Oka E at the reference point",
            "Hv 1.8 GPa, 104 m/s, 326 um, 90 deg",
            6.154e-4,
            "Oka et al. 2005 (E = E90 there)",
            float(oka_erosion_ratio(104.0, 0.0, 1.8e9, 326e-6, 6.154e-4)),
            1e-12,
        ),
        relative(
            "wear",
            "Oka E at 30 deg from the surface",
            "Hv 1.8 GPa, 104 m/s, 326 um",
            oka30,
            "Oka et al. 2005, by hand",
            float(oka_erosion_ratio(104.0, 60.0, 1.8e9, 326e-6, 6.154e-4)),
            1e-12,
        ),
    ]


def deformation_wear_onset(quick: bool) -> list[Check]:
    """Bitter's deformation wear is the impact's plastic work / ε: nothing below the speed at which the plate first
    yields, Thornton's (1997) V_y (normal impacts on Thornton's law just below and above it)."""
    case = CASE.with_(wear={"law": "deformation"})
    ball, plate = case.ball.material(), case.plate.material()
    v_y = yield_velocity(case.ball.radius, ball, plate)
    data = CalibrationData(np.zeros(2), np.array([0.95 * v_y, 1.2 * v_y]), "volume_per_impact_m3", np.ones(2), {})
    below, above = ForwardModel(case, data).predict({})
    return [
        absolute(
            "wear",
            "deformation wear below V_y",
            CASE_TEXT,
            0.0,
            "Thornton 1997: no plastic work below V_y",
            below,
            0.0,
            "m^3",
        ),
        Check(
            "wear",
            "deformation wear above V_y",
            CASE_TEXT,
            "> 0",
            "Thornton 1997: plastic work above V_y",
            f"{above:.3e}",
            0.0 if above > 0 else math.inf,
            0.0,
            "error",
        ),
    ]


_ROUND_TRIP = (
    ("dnv", {}, {"dnv_K": 3e-9, "dnv_n": 2.4}),
    ("local", {}, {"K": 2e-12, "beta": 0.5}),
    ("finnie", {}, {"cutting_fraction": 0.3}),
    ("deformation", {}, {"deformation_factor": 2e10}),
    ("oka", {}, {"oka_e90": 5e-4}),
    ("combined", {"cutting": "finnie"}, {"cutting_fraction": 0.2, "deformation_factor": 3e10}),
)


def _inside(quantity: str, truth: float, value: float, interval: tuple[float, float] | None) -> Check:
    """A check that ``truth`` lies inside the 95% ``interval`` of a fitted ``value``: error |fitted − true| over the
    interval's half width (in log coordinates for a positive scale constant), tolerance 1."""
    error = math.inf
    if interval is not None:
        lo, hi = interval
        if lo > 0 and value > 0:  # a scale: the interval is multiplicative
            error = abs(math.log(value / truth)) / (0.5 * math.log(hi / lo))
        else:
            error = abs(value - truth) / (0.5 * (hi - lo))
    return Check(
        "wear",
        quantity,
        "data made by the law, 10% log-normal noise",
        truth,
        "the constant the data were made with",
        value,
        error,
        1.0,
        "|fitted - true| / 95% half-width",
    )


def calibration_round_trip(quick: bool) -> list[Check]:
    """Data made by each law with known constants at 3 speeds × 10 angles, with 10% log-normal noise (seeded): the
    calibration recovers every constant inside its 95% interval; and a speed exponent from a single speed is
    reported as not determined."""
    angles = np.array([0.0, 15.0, 30.0, 45.0, 55.0, 60.0, 65.0, 70.0, 75.0, 80.0])
    speeds = (30.0, 50.0) if quick else (20.0, 40.0, 60.0)
    a, v = np.tile(angles, len(speeds)), np.repeat(speeds, angles.size)
    rng = np.random.default_rng(2005)
    out = []
    for law, extra, truth in _ROUND_TRIP:
        case = CASE.with_(wear={"law": law, **extra})
        clean = ForwardModel(case, CalibrationData(a, v, "erosion_kg_per_kg", np.ones(a.size), {})).predict(truth)
        keep = clean > 1e-12 * clean.max()
        noisy = clean[keep] * np.exp(0.1 * rng.standard_normal(int(keep.sum())))
        result = calibrate(case, CalibrationData(a[keep], v[keep], "erosion_kg_per_kg", noisy, {}), tuple(truth))
        for name, value, interval in zip(result.fit.names, result.fit.values, result.fit.intervals, strict=True):
            out.append(_inside(f"calibrated {name} ({law})", truth[name], value, interval))
    single = CalibrationData(
        angles,
        np.full(angles.size, 50.0),
        "erosion_kg_per_kg",
        ForwardModel(
            CASE.with_(wear={"law": "dnv"}),
            CalibrationData(angles, np.full(angles.size, 50.0), "erosion_kg_per_kg", angles, {}),
        ).predict({}),
        {},
    )
    result = calibrate(CASE.with_(wear={"law": "dnv"}), single, ("dnv_K", "dnv_n"))
    out.append(
        Check(
            "wear",
            "dnv_n from a single speed",
            "50 m/s, 10 angles",
            "not determined",
            "identifiability (the exponent trades off against K)",
            "not determined" if not result.fit.determined[1] else f"{result.fit.values[1]:.4g}",
            0.0 if not result.fit.determined[1] else math.inf,
            0.0,
            "error",
        )
    )
    return out


def laws_against_measured_trends(quick: bool) -> list[Check]:
    """Calibrated on Oka et al.'s (2005) carbon-steel curve at two speeds (30, 60 m/s), the combined law (equation 15 +
    Bitter's deformation wear; K, β, ε free) falls inside the measured ranges of ductile metals: velocity exponent
    2.3–2.9, maximum 15–35° from the surface, normal incidence / maximum 0.25–0.7; and DNV's exponent fitted to
    Oka's curve is Oka's k₂ = 2.3 H_v^0.038."""
    fit = calibrate(CASE.with_(wear={"law": "combined"}), oka_curve((30.0, 60.0)), ("K", "beta", "deformation_factor"))
    trends = law_trends(fit.case)
    out = []
    for name, value in (
        ("velocity_exponent", trends.velocity_exponent),
        ("peak_angle_deg", trends.peak_angle),
        ("normal_to_max", trends.normal_to_max),
    ):
        lo, hi = MEASURED_EROSION[name]
        out.append(
            absolute(
                "wear",
                f"combined law: {name.replace('_', ' ')}",
                "calibrated on Oka's curve, 2 speeds",
                0.5 * (lo + hi),
                f"measured range [{lo:g}, {hi:g}] (Finnie; Oka 2005; DNV; Hutchings 1981)",
                value,
                0.5 * (hi - lo),
            )
        )
    dnv = calibrate(CASE.with_(wear={"law": "dnv"}), oka_curve((30.0, 60.0)), ("dnv_K", "dnv_n"))
    k2 = 2.3 * (OKA_CARBON_STEEL["hardness"] / 1e9) ** 0.038
    out.append(
        relative("wear", "DNV exponent fitted to Oka's curve", "2 speeds", k2, OKA_SOURCE, dnv.fit.values[1], 0.01)
    )
    return out
