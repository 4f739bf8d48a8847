"""A sweep over the impact angle
=============================

Run a sweep spec (the impact stage at 17 angles: ``examples/sweep_angles.toml``) and read the rebound angles from
its ``results.csv``. Equivalent to ``impactwear sweep examples/sweep_angles.toml --out sweep_angles``; rerunning
skips finished cases. Writes into ``sweep_angles/`` of the folder named by the environment variable
``IMPACTWEAR_EXAMPLE_OUT`` (default: the current folder). SI units; angles in degrees from the plate normal.
"""

# %%
# The sweep spec and the run
# --------------------------
# A sweep spec names the stage, the base case (keys left out come from the default case) and the grid of keys.
# The sweep runs its cases in worker processes: here it is run as the command ``impactwear sweep`` would be, in a
# process of its own (a script that starts the workers itself must guard its code with
# ``if __name__ == "__main__":``, as the workers import the script again).

import csv
import os
import subprocess
import sys
from pathlib import Path

import matplotlib.pyplot as plt

# where the outputs go
OUT = Path(os.environ.get("IMPACTWEAR_EXAMPLE_OUT", ".")) / "sweep_angles"
OUT.mkdir(parents=True, exist_ok=True)

SPEC = """\
[sweep]
stage = "impact"
description = "rebound angle, spin and sliding time vs impact angle, Kharaz et al. 2001"

[base]
impact.speed = 3.9           # m/s
impact.friction = 0.092

[grid]
# deg from the normal
"impact.angle" = [5, 10, 15, 20, 25, 30, 35, 40, 45, 50, 55, 60, 65, 70, 75, 80, 85]
"""
(OUT / "sweep_angles.toml").write_text(SPEC, encoding="utf-8")
command = [
    "sweep",
    str(OUT / "sweep_angles.toml"),
    "--out",
    str(OUT / "run"),
    "--workers",
    "2",
    "--quiet",
]
subprocess.run([sys.executable, "-m", "wear.app.cli", *command], check=True)

# %%
# The results table
# -----------------
# ``results.csv``: one row per case, its grid keys and the stage's numbers.

with open(OUT / "run" / "results.csv", newline="", encoding="utf-8") as f:
    rows = list(csv.DictReader(f))
print(
    f"{'angle (deg)':>12} {'rebound (deg)':>14} {'contact pt (deg)':>17} "
    f"{'spin (rad/s)':>13}"
)
for r in rows:
    print(
        f"{float(r['impact.angle_deg']):12.1f} {float(r['rebound_angle_deg']):14.3f} "
        f"{float(r['contact_point_rebound_angle_deg']):17.3f} "
        f"{float(r['spin_rad_s']):13.2f}"
    )

angle = [float(r["impact.angle_deg"]) for r in rows]
fig, ax = plt.subplots(figsize=(5.5, 3.8))
curves = (
    ("rebound_angle_deg", "o-", "centre of the ball"),
    ("contact_point_rebound_angle_deg", "s-", "contact point"),
)
for column, style, label in curves:
    ax.plot(angle, [float(r[column]) for r in rows], style, ms=3, label=label)
ax.plot([0, 90], [0, 90], "k:", lw=0.8, label="rebound = impact angle")
ax.set(xlabel="impact angle from the normal (deg)", ylabel="rebound angle (deg)")
ax.legend()
fig.tight_layout()
