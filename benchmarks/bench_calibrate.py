"""Benchmark of ``impactwear calibrate`` (not a timed test): ``python benchmarks/bench_calibrate.py``.

3 constants (K, β of Eq. 15 and Bitter's ε: the combined law) fitted to 50 rows (5 speeds × 10 angles of Oka et
al.'s 2005 carbon-steel curve, silica sand R 150 µm on carbon steel, Thornton's law and pressure), then the same
with α free too (each new α re-integrates every row's pressure history: the slow part) and Eq. 15 alone with K
and α free, side by side with the fit of one constant of a closed-form law (DNV). Prints the time to compute the 50
impacts (the first includes numba's compilation), the forward-model evaluations (all rows) per second, the number
of evaluations and the fit time. Target: ≤ 2 min.
"""

from __future__ import annotations

import os
import time
import warnings

import numpy as np

from wear.app.validation.laws import CASE
from wear.chain.calibrate import calibrate
from wear.chain.calibration_data import CalibrationData
from wear.laws.oka import oka_erosion_ratio

TARGET_S = 120.0


def main() -> None:
    angles = np.tile([0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 75.0, 80.0], 5)
    speeds = np.repeat([20.0, 30.0, 40.0, 50.0, 60.0], 10)
    data = CalibrationData(
        angles, speeds, "erosion_kg_per_kg", oka_erosion_ratio(speeds, angles, 1.4e9, 300e-6, 6.154e-4), {}
    )
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs; {angles.size} rows")
    for label, keys, free in (
        ("combined (K, beta, epsilon)", {"law": "combined"}, ("K", "beta", "deformation_factor")),
        ("combined (K, alpha, beta, eps)", {"law": "combined"}, ("K", "alpha", "beta", "deformation_factor")),
        ("local (K, alpha)", {"law": "local"}, ("K", "alpha")),
        ("dnv (K)", {"law": "dnv"}, ("dnv_K",)),
    ):
        t0 = time.perf_counter()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = calibrate(CASE.with_(wear=keys), data, free)
        total = time.perf_counter() - t0
        s = result.seconds
        verdict = "meets" if total <= TARGET_S else "MISSES"
        print(
            f"{label:30s} impacts {s['impacts']:6.2f} s, fit {s['fit']:6.2f} s ({result.fit.evaluations} "
            f"evaluations, {result.evaluations_per_s:8.1f}/s), total {total:6.2f} s: {verdict} the target "
            f"{TARGET_S:.0f} s; RMS log error {result.fit.rms_log_error:.3f}"
        )


if __name__ == "__main__":
    main()
