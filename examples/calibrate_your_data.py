"""Calibrate a wear law to your own data
=====================================

Fit the constants of a wear law to measured erosion rates (:func:`wear.chain.calibrate.calibrate`, the Python side
of ``impactwear calibrate``), check the fit, and draw the fitted curves over the data.

The data here are the sample file shipped with the toolkit, ``wear/app/data/calibration_sample.csv``: 24 erosion
ratios of silica sand on carbon steel at 8 angles (10-80° from the normal) and 3 speeds (15, 30, 60 m/s). They are
not measurements: they were drawn from the DNV-RP-O501 (2015) law for ductile materials,

.. math::

    E = K U^n F(\\alpha), \\qquad
    F(\\alpha) = 0.6\\,\\bigl(\\sin\\alpha + 7.2(\\sin\\alpha - \\sin^2\\alpha)\\bigr)^{0.6}\\,(1 - e^{-20\\alpha}),

(α from the surface, in radians) with K = 3.0e-9 (kg/kg)(m/s)^-n and n = 2.3, each value multiplied by
exp(0.10 z), z standard normal (NumPy ``default_rng(2026)``, rows in file order), rounded to 4 significant digits.
So the fit can be checked: it must recover K and n within the noise. With your own data, replace ``DATA`` by the
path of your CSV (columns ``angle_deg``, ``speed_m_s`` and one measured quantity, here ``erosion_kg_per_kg``).
SI units; angles in degrees from the plate normal.
"""

# %%
# The data
# --------
# A CSV file with a header row and one row per measurement. :func:`~wear.chain.calibration_data.read_data` reads
# and checks it (an error names the column and the row).

import os
from importlib import resources
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from wear.app.outputs.calibration import write_calibration
from wear.case import default_case
from wear.chain.calibrate import calibrate
from wear.chain.calibration_data import read_data

# where the outputs go
OUT = Path(os.environ.get("IMPACTWEAR_EXAMPLE_OUT", ".")) / "calibrate_your_data"

with resources.as_file(
    resources.files("wear.app").joinpath("data/calibration_sample.csv")
) as DATA:
    data = read_data(DATA)
    print(DATA.read_text(encoding="utf-8").splitlines()[:4])
print(
    f"{data.angle.size} rows of {data.quantity} at speeds "
    f"{', '.join(f'{v:g}' for v in np.unique(data.speed))} m/s"
)

# %%
# The fit
# -------
# The case says what hits what (``impactwear calibrate``'s default: silica sand, R 150 µm, on carbon steel) and
# which law is fitted; ``free`` names the constants to fit (the others keep the case's values). The DNV law's
# defaults, K = 2e-9 and n = 2.6, are the start of the fit, not the answer.

case = default_case("calibrate").with_(wear={"law": "dnv"})
result = calibrate(case, data, free=("dnv_K", "dnv_n"))
# calibration.json, calibration.csv, calibrated.toml, a figure
summary = write_calibration(result, OUT)
for name, c in summary["constants"].items():
    lo, hi = c["interval_95"]
    print(
        f"{name} = {c['value']:.4g} (95% interval {lo:.4g} .. {hi:.4g}; start "
        f"{c['start']:.4g}) {c['units']}"
    )
print(
    f"rms log error {summary['rms_log_error']:.3f} over {summary['fitted_rows']} rows"
)

# %%
# The same from the command line (the output folder is the same)::
#
#     impactwear calibrate calibration_sample.csv --law dnv --free dnv_K,dnv_n \
#         --out calibrate_your_data
#
# ``calibrated.toml`` in the output folder is the case with the fitted constants: ``impactwear run``, ``erode``
# and ``repeat`` read it as it is.
#
# Does the fit recover the law the data were drawn from?
# ------------------------------------------------------
# The true constants lie inside the 95% intervals, and the rms log error is the noise drawn: 0.068 for these 24
# draws of a standard deviation 0.10 (the scatter of ln(data / true law)).

truth = {"dnv_K": 3.0e-9, "dnv_n": 2.3}
for name, value in truth.items():
    lo, hi = summary["constants"][name]["interval_95"]
    print(f"{name}: true {value:g}, inside the 95% interval: {lo <= value <= hi}")

# %%
# The fitted curves over the data
# -------------------------------
# One curve per speed (the fitted law through the calibration's own impacts), the data as markers.

fig, ax = plt.subplots(figsize=(7.0, 4.0))
for speed in np.unique(data.speed):
    rows = np.flatnonzero(data.speed == speed)
    order = rows[np.argsort(data.angle[rows])]
    (line,) = ax.plot(
        data.angle[order], result.predicted[order], label=f"fitted, {speed:g} m/s"
    )
    ax.plot(data.angle[order], data.measured[order], "o", color=line.get_color(), ms=4)
ax.set_yscale("log")
ax.set_xlabel("impact angle from the normal (deg)")
ax.set_ylabel("erosion ratio (kg/kg)")
ax.set_title("DNV law fitted to the sample data (markers)", fontsize=10)
ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.0, 1.0))
fig.tight_layout()
