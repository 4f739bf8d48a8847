"""Published reference data shared by the validation, the reproduced figures and the tests, with their sources.

Kharaz, Gorham & Salman (2001), Powder Technol. 120:281: an alumina ball R = 2.5 mm (E 380 GPa, ν 0.23,
4000 kg/m³) on soda-lime glass (E 70 GPa, ν 0.25) at 3.9 m/s, μ = 0.092, normal restitution 0.98 (the value
commonly used with this experiment, e.g. Chung & Ooi 2011); the digitised points ship as package data
(``wear/app/data/kharaz2001.csv``).
"""

from __future__ import annotations

from importlib import resources

import numpy as np

from contact import BatchResult, Material, simulate_impacts
from wear.chain.calibration_data import CalibrationData
from wear.laws.oka import oka_erosion_ratio

__all__ = [
    "KHARAZ",
    "KHARAZ_SOURCE",
    "MEASURED_EROSION",
    "OKA_CARBON_STEEL",
    "kharaz_batch",
    "kharaz_data",
    "kharaz_rms",
    "oka_curve",
    "unloading_path_w",
]

#: Kharaz, Gorham & Salman (2001) setup (see the module docstring).
KHARAZ = dict(
    radius=2.5e-3,
    ball=Material(E=380e9, nu=0.23, density=4000.0, name="alumina"),
    plate=Material(E=70e9, nu=0.25, density=2500.0, name="soda-lime glass"),
    speed=3.9,
    friction=0.092,
    restitution=0.98,
)
KHARAZ_SOURCE = "Kharaz, Gorham & Salman (2001) Powder Technol. 120:281 (digitised points)"


def kharaz_data() -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """The Kharaz, Gorham & Salman (2001) points shipped as package data: quantity → (angles deg, values).

    Quantities: ``tangential_restitution``, ``spin_rad_per_s``, ``centre_rebound_angle_deg``."""
    text = resources.files("wear.app").joinpath("data/kharaz2001.csv").read_text(encoding="utf-8")
    out: dict[str, list] = {}
    for line in text.splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        quantity, angle, value = line.split(",")
        out.setdefault(quantity, []).append((float(angle), float(value)))
    return {q: (np.array([a for a, _ in v]), np.array([x for _, x in v])) for q, v in out.items()}


def kharaz_batch(angles, tangential_model: str = "hdd") -> BatchResult:
    """The Kharaz setup simulated at ``angles`` (deg from the normal) with the engine's ``tangential_model``."""
    k = KHARAZ
    return simulate_impacts(
        k["radius"],
        k["ball"],
        k["plate"],
        k["speed"],
        angles,
        k["friction"],
        k["restitution"],
        tangential_model=tangential_model,
    )


def _rms(model, data) -> float:
    return float(np.sqrt(np.mean((np.asarray(model) - np.asarray(data)) ** 2)))


def kharaz_rms(tangential_model: str = "hdd") -> dict[str, float]:
    """RMS differences between the model (simulated at the measured angles with ``tangential_model``) and the
    Kharaz et al. 2001 points: centre rebound angle (deg), spin (rad/s), tangential restitution."""
    data = kharaz_data()
    out = {}
    for quantity, attr in (
        ("centre_rebound_angle_deg", "rebound_angle"),
        ("spin_rad_per_s", "spin"),
        ("tangential_restitution", "tangential_restitution"),
    ):
        angles, values = data[quantity]
        out[quantity] = _rms(getattr(kharaz_batch(angles, tangential_model), attr), values)
    return out


def unloading_path_w(quick: bool) -> tuple[np.ndarray, np.ndarray]:
    """The load–unload path of the Kogut–Etsion and Mesarovic–Johnson checks, in w = δ/δ_c: (loading, unloading).

    Loading through w = 2, 6, 20 to 50 in increments of at most 0.25 δ_c up to w = 2 (the radial return integrates
    the path: with one increment from w = 0.5 to 1 the fine-mesh FE flags a spurious surface-plastic point), then
    unloading in steps of ~1 w (a/a* ≈ 0.5, the second Mesarovic–Johnson point, is reached near w ≈ 30)."""
    if quick:
        w_load = np.array([0.25, 0.5, 0.75, 1, 1.25, 1.5, 2, 3, 4, 5, 6, 8, 10, 14, 20, 30, 40, 50], dtype=float)
        w_unload = np.concatenate([[50.0 * 0.995], np.linspace(49.0, 29.0, 11)])
    else:
        w_load = np.unique(
            np.concatenate(
                [np.linspace(0.25, 2, 8), np.linspace(2.5, 6, 8), np.linspace(7, 20, 14), np.linspace(22, 50, 15)]
            )
        )
        w_unload = np.concatenate([[50.0 * 0.995], np.linspace(49.0, 28.0, 22)])
    return w_load, w_unload


#: Oka, Okamura & Yoshida (2005, Wear 259: 95–101, Part 1) for silica sand (D 300 µm) on a plain carbon steel (H_v
#: 1.4 GPa): their correlation's angle and speed dependence (n₁ = 0.71 H_v^0.14, n₂ = 2.4 H_v^−0.94, k₂ = 2.3
#: H_v^0.038). Its scale E90 (kg/kg at 104 m/s, 326 µm) is the Ansys Fluent Theory Guide's example value for sand on
#: a steel of H_v 1.8 GPa (6.154e-4; Oka & Yoshida's own E90, Part 2, Wear 259: 102–109, gives 4.9e-4 for this
#: steel, :func:`wear.laws.oka.oka_e90`): it only scales the curve, which every law is calibrated to.
OKA_CARBON_STEEL = {
    "hardness": 1.4e9,
    "diameter": 300e-6,
    "e90": 6.154e-4,
    "angles": (0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 55.0, 60.0, 65.0, 70.0, 75.0, 80.0),
}
OKA_SOURCE = "Oka, Okamura & Yoshida 2005, Wear 259: 95-101 (their correlation, carbon steel Hv 1.4 GPa, SiO2 300 um)"

#: The measured ranges of ductile metals: velocity exponent (Finnie; Oka et al. 2005; DNV-RP-O501 n = 2.6), the angle
#: of maximum erosion from the surface (Hutchings 1981: 20–30°; Oka: ~30° for steels), and the erosion at normal
#: incidence over the maximum (Hutchings 1981: about a third; Oka's correlation: up to ~0.7 for hard steels).
MEASURED_EROSION = {"velocity_exponent": (2.3, 2.9), "peak_angle_deg": (15.0, 35.0), "normal_to_max": (0.25, 0.7)}


def oka_curve(speeds) -> CalibrationData:
    """The :data:`OKA_CARBON_STEEL` erosion ratio (kg/kg) at its angles (deg from the normal) and ``speeds`` (m/s),
    as calibration data."""
    o = OKA_CARBON_STEEL
    angles = np.tile(np.asarray(o["angles"]), len(speeds))
    speed = np.repeat(np.asarray(speeds, float), len(o["angles"]))
    ratio = oka_erosion_ratio(speed, angles, o["hardness"], o["diameter"], o["e90"])
    return CalibrationData(angles, speed, "erosion_kg_per_kg", ratio, {}, OKA_SOURCE)
