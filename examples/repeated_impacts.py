"""Repeated normal impacts at one spot: shakedown
==============================================

Repeated normal impacts of an alumina ball at one spot on a Ti-6Al-4V plate, below the shakedown limit.

At V_n = 2.2 V_y (Thornton's yield speed) the first impact yields the plate; the dent it leaves and its residual
stresses make the later impacts elastic (shakedown). Prints one line per computed impact (restitution, peak
force and pressure, plastic strain increment, dent) and the impact at which the plate shook down, and writes
repeat.csv and repeat.png into --out. IMPACTWEAR_QUICK=1 uses a coarser FE mesh (seconds per impact, not
validation quality).
"""

import argparse
import os
from pathlib import Path

from contact.theory import yield_velocity
from wear import Case, repeat
from wear.app.figures.repeat import plot_repeat
from wear.app.outputs.writer import write_csv

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--out", default="repeated-impacts-example", help="output folder")
args = parser.parse_args()
quick = os.environ.get("IMPACTWEAR_QUICK") == "1"
out = Path(args.out)
out.mkdir(parents=True, exist_ok=True)

case = Case()
v_y = yield_velocity(case.ball.radius, case.ball.material(), case.plate.material())
case = case.with_(
    impact={"speed": 2.2 * v_y, "angle": 0.0},
    wear={"K": 0.0},  # wear off: only the dent and the residual stresses change the plate
    fem={"mesh_scale": 4.0 if quick else 2.0},
    output={"figures": False, "render": False},
    repeat={"impacts": 4 if quick else 8, "geometry_update": True, "max_plastic_impacts": 4 if quick else 8},
)
result = repeat(case)

print(f"V_y = {v_y:.4g} m/s, V_n = {2.2 * v_y:.4g} m/s")
for row in result.records:
    if row.kind == "computed":
        print(
            f"impact {row.first:3d}: e_n {row.normal_restitution:.4f}, F_max {row.max_force:.4g} N, "
            f"p_max {row.max_pressure / 1e9:.3f} GPa, Δᾱ {row.plastic_strain_increment:.2e}, "
            f"dent {row.dent_depth * 1e6:.3f} µm"
        )
print(f"shakedown at impact {result.shakedown_impact}" if result.shakedown_impact else "no shakedown")
write_csv(out / "repeat.csv", result.columns())
plot_repeat(
    result.columns(),
    out / "repeat.png",
    title=f"{case.repeat.impacts} impacts at one site (no wear)",
    shakedown_impact=result.shakedown_impact,
)
