"""Repeated normal impacts at one spot: shakedown
==============================================

Repeated normal impacts of an alumina ball at one spot on a Ti-6Al-4V plate, below the shakedown limit.

At V_n = 2.2 V_y (Thornton's yield speed) the first impact yields the plate; the dent it leaves and its residual
stresses make the later impacts elastic (shakedown). Prints one line per computed impact (restitution, peak
force and pressure, plastic strain increment, dent) and the impact at which the plate shook down, and writes
repeat.csv and repeat.png into ``repeated_impacts/`` of the folder named by the environment variable
``IMPACTWEAR_EXAMPLE_OUT`` (default: the current folder).
"""

# %%
# Impacts at one site, wear off
# -----------------------------
# The toolkit's statements of its modelling assumptions (Python warnings) are collected and printed as notes, as
# ``impactwear repeat`` does.

import os
import warnings
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import MaxNLocator

from contact.theory import yield_velocity
from wear import Case, repeat
from wear.app.figures.repeat import plot_repeat
from wear.app.outputs.writer import write_csv

# where the outputs go
OUT = Path(os.environ.get("IMPACTWEAR_EXAMPLE_OUT", ".")) / "repeated_impacts"
OUT.mkdir(parents=True, exist_ok=True)
# IMPACTWEAR_QUICK=1 (as on this page): a coarser FE mesh, 4 impacts (seconds per
# impact, not validation quality)
quick = os.environ.get("IMPACTWEAR_QUICK") == "1"

case = Case()
v_y = yield_velocity(case.ball.radius, case.ball.material(), case.plate.material())
case = case.with_(
    impact={"speed": 2.2 * v_y, "angle": 0.0},
    # wear off: only the dent and the residual stresses change the plate
    wear={"K": 0.0},
    fem={"mesh_scale": 4.0 if quick else 2.0},
    output={"figures": False, "render": False},
    repeat={
        "impacts": 4 if quick else 8,
        "geometry_update": True,
        "max_plastic_impacts": 4 if quick else 8,
    },
)
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    result = repeat(case)
for note in dict.fromkeys(str(w.message) for w in caught):
    print(f"note: {note}")

print(f"V_y = {v_y:.4g} m/s, V_n = {2.2 * v_y:.4g} m/s")
for row in result.records:
    if row.kind == "computed":
        print(
            f"impact {row.first:3d}: e_n {row.normal_restitution:.4f}, F_max "
            f"{row.max_force:.4g} N, "
            f"p_max {row.max_pressure / 1e9:.3f} GPa, Δᾱ "
            f"{row.plastic_strain_increment:.2e}, "
            f"dent {row.dent_depth * 1e6:.3f} µm"
        )
print(
    f"shakedown at impact {result.shakedown_impact}"
    if result.shakedown_impact
    else "no shakedown"
)
columns = result.columns()
write_csv(OUT / "repeat.csv", columns)
plot_repeat(
    columns,
    OUT / "repeat.png",
    title=f"{case.repeat.impacts} impacts at one site (no wear)",
    shakedown_impact=result.shakedown_impact,
)

# %%
# Dent and restitution per impact
# -------------------------------
# The first impact dents the plate; each of the next ones adds less plastic strain, until the plate shakes down: the
# impacts rebound elastically (normal restitution near 1) and the dent stops growing. ``repeat.png`` in the output
# folder has these and the plastic work, pressure and worn volume.

n = np.asarray(columns["impact_last"])
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9.0, 3.4))
ax1.plot(n, np.asarray(columns["dent_depth_m"]) * 1e6, "o-")
ax1.set(xlabel="impact", ylabel="dent depth (µm)")
ax2.plot(n, columns["normal_restitution"], "o-")
ax2.set(xlabel="impact", ylabel="normal restitution $e_n$")
for ax in (ax1, ax2):
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))  # impact 1, 2, 3: no 1.5
fig.tight_layout()
