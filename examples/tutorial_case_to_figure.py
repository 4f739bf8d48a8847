"""Tutorial: from a case file to a figure
======================================

The path a study takes in Python: write a case file (TOML), load it, run the chain, read the output files back and
draw a figure. The case is an elastic one, so the result can be checked against Hertz's closed form: an alumina
ball (R 2.5 mm) on soda-lime glass at 3.9 m/s, 30° from the normal (Kharaz, Gorham & Salman 2001). SI units;
angles in degrees from the plate normal.
"""

# %%
# 1. Write a case file
# --------------------
# A run case has the tables ``[ball]``, ``[plate]``, ``[impact]`` and ``[wear]``; a key left out takes its default
# (``impactwear keys`` lists every key, its default, units and range). Here: an alumina ball, the glass plate (it
# does not yield: ``yield_strength = inf``), the impact, Hertz's normal law without the FE plate (an elastic impact
# needs none), and the wear law on the Hertz pressure.

import csv
import json
import math
import os
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from wear import load_case, run
from wear.app.outputs.run import write_run

# where the outputs go
OUT = Path(os.environ.get("IMPACTWEAR_EXAMPLE_OUT", ".")) / "tutorial_case_to_figure"
OUT.mkdir(parents=True, exist_ok=True)

CASE = """\
[ball]
name = "alumina"
radius = 2.5e-3       # m
E = 380e9             # Pa
nu = 0.23
density = 3950.0      # kg/m^3

[plate]
name = "soda-lime glass"
E = 70e9              # Pa
nu = 0.25
density = 2500.0      # kg/m^3
yield_strength = inf  # elastic

[impact]
speed = 3.9           # m/s
angle = 30.0          # deg from the normal
friction = 0.092
normal_model = "hertz"

[fem]
coupling = "none"     # no FE plate: the impact's own Hertz law

[wear]
pressure = "hertz"
# the contact point's slip: without the FE plate there is no surface slip of its own
speed = "sliding"

[output]
figures = false       # this tutorial draws its own
render = false
"""
(OUT / "glass.toml").write_text(CASE, encoding="utf-8")

# %%
# 2. Load and run it
# ------------------
# :func:`wear.load_case` reads the file over the defaults of ``impactwear run`` and checks every key (a wrong one
# is a one-line error naming it). :func:`wear.run` is ``impactwear run`` in Python; :func:`write_run` writes its
# output folder (``summary.json``, ``history.csv``, ``pressure.npz``, the meshes).

case = load_case(OUT / "glass.toml", "run")
print(
    f"ball: {case.ball.name}, R {case.ball.radius:g} m; plate: {case.plate.name}, E "
    f"{case.plate.E:g} Pa"
)
result = run(case)
write_run(result, OUT / "run")
print(sorted(p.name for p in (OUT / "run").iterdir() if not p.name.startswith(".")))

# %%
# 3. Read the outputs
# -------------------
# ``summary.json`` holds the numbers of the impact and the wear (``impactwear run`` prints its main lines);
# ``history.csv`` the time history of the contact, one row per saved time step, the units in the column names.

summary = json.loads((OUT / "run" / "summary.json").read_text(encoding="utf-8"))
print({k: v for k, v in summary["impact"].items() if not isinstance(v, (dict, list))})
with open(OUT / "run" / "history.csv", newline="", encoding="utf-8") as f:
    rows = list(csv.DictReader(f))
history = {name: np.array([float(r[name]) for r in rows]) for name in rows[0]}
print(f"{len(rows)} time steps; columns: {', '.join(history)}")

# %%
# 4. A figure, and a check against Hertz
# --------------------------------------
# Hertz's closed form for the normal part of the impact (Johnson 1985, §11.4): the largest force
# :math:`F_{max} = \frac{4}{3} E^* \sqrt{R}\, \delta_{max}^{3/2}` at the overlap
# :math:`\delta_{max} = \left(\frac{15 m V_n^2}{16 E^* \sqrt{R}}\right)^{2/5}`, and the contact time
# :math:`t_c = 2.868 \left(\frac{m^2}{R E^{*2} V_n}\right)^{1/5}`.

ball, plate = case.ball, case.plate
e_star = 1.0 / ((1 - ball.nu**2) / ball.E + (1 - plate.nu**2) / plate.E)
mass = 4.0 / 3.0 * math.pi * ball.radius**3 * ball.density
v_n = case.impact.speed * math.cos(math.radians(case.impact.angle))
d_max = (15.0 * mass * v_n**2 / (16.0 * e_star * math.sqrt(ball.radius))) ** 0.4
f_max = 4.0 / 3.0 * e_star * math.sqrt(ball.radius) * d_max**1.5
t_c = 2.868 * (mass**2 / (ball.radius * e_star**2 * v_n)) ** 0.2
print(
    f"largest normal force: run {history['normal_force_N'].max():.4g} N, Hertz "
    f"{f_max:.4g} N"
)
in_contact = history["time_s"][history["overlap_m"] > 0.0]
print(f"contact time: run {in_contact[-1] - in_contact[0]:.4g} s, Hertz {t_c:.4g} s")

t = history["time_s"] * 1e6
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9.0, 3.6))
ax1.plot(t, history["normal_force_N"], label="normal force")
ax1.plot(t, history["tangential_force_N"], label="tangential force")
ax1.axhline(f_max, color="0.5", ls="--", lw=0.8, label="Hertz $F_{max}$")
ax1.axvline(t_c * 1e6, color="0.5", ls=":", lw=0.8, label="Hertz $t_c$")
ax1.set(xlabel="time (µs)", ylabel="force (N)", ylim=(None, 1.45 * f_max))
ax1.legend(fontsize=8, loc="upper left", ncols=2)
# the tangential force opposes the slip (negative here): its size against μ times the
# normal force
ax2.plot(
    t,
    np.abs(history["tangential_force_N"])
    / np.maximum(history["normal_force_N"], 1e-30),
)
ax2.axhline(
    case.impact.friction, color="0.5", ls="--", lw=0.8, label="friction coefficient μ"
)
ax2.set(xlabel="time (µs)", ylabel="|tangential| / normal force", ylim=(0.0, 0.15))
ax2.legend(fontsize=8, loc="upper right")
fig.suptitle("alumina on glass, 3.9 m/s at 30°", fontsize=10)
fig.tight_layout()
