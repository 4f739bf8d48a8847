"""Erosion of a steel plate by a stream of sand particles
======================================================

Erosion of a steel plate by a stream of sand particles, with surface feedback (public API of wear.erosion).

Builds the response table of one particle impact over normal speed x local angle (H-DD impact + the wear law,
errata Eq. 15), erodes a periodic patch for a few seconds of the paper's Fig. 10 stream (20 m/s, 464 g/m^3) at
three angles, prints the erosion rate, and writes ``erosion_stream.csv`` (time series at 45 deg) and
``erosion_angles.csv`` into ``erosion_stream/`` of the folder named by the environment variable
``IMPACTWEAR_EXAMPLE_OUT`` (default: the current folder). SI units; angles in degrees from the plate normal.
For the full case and the CLI see
``impactwear erode examples/fig10_stream.toml``.
"""

# %%
# Particle, plate and wear law
# ----------------------------

import os
from pathlib import Path

import matplotlib.pyplot as plt

from contact import Material
from wear import WearLaw
from wear.app.outputs.writer import write_csv
from wear.erosion import ImpactResponse, Stream, build_response_table, erode, table_axes

# where the outputs go
OUT = Path(os.environ.get("IMPACTWEAR_EXAMPLE_OUT", ".")) / "erosion_stream"
OUT.mkdir(parents=True, exist_ok=True)
# IMPACTWEAR_QUICK=1 (as on this page): a coarser table, a smaller patch
quick = os.environ.get("IMPACTWEAR_QUICK") == "1"

sand = Material(E=94e9, nu=0.17, density=2650.0, name="silica sand")
steel = Material(
    E=200e9, nu=0.3, density=7850.0, yield_strength=350e6, name="carbon steel"
)
law = WearLaw(K=1e-11, alpha=1.0, beta=0.3, K_units="m^(0.7) s^(-0.7) Pa^(-1)")
response = ImpactResponse(
    radius=150e-6, ball=sand, plate=steel, friction=0.3, law=law, pressure="paper"
)
grid = 128 if quick else 256
exposure = 2.0 if quick else 20.0  # s

# %%
# Erode a patch at three angles
# -----------------------------
# One response table per stream angle (the local angles around it), then the stream's impacts on the patch.

rates, losses, series = [], [], {}
angles = (30.0, 45.0, 60.0)
for angle in angles:
    vn, local_angles = table_axes(
        20.0, angle, angle_margin=10.0, angle_step=5.0 if quick else 2.5, speeds=3
    )
    table = build_response_table(
        response, vn, local_angles, points_per_length=8 if quick else 12
    )
    result = erode(
        table, Stream(20.0, angle, exposure, concentration=0.464), grid=grid, seed=1
    )
    print(
        f"{angle:4.0f} deg: {result.n_impacts:7d} impacts on a "
        f"{result.patch_size * 1e3:.3g} mm patch, "
        f"mass loss {result.mass_loss_kg[-1]:.4g} kg, erosion rate "
        f"{result.final_erosion_rate:.4g} kg/kg, "
        f"deepest {result.max_depth_m[-1] * 1e6:.3g} um"
    )
    print(f"          table: {table.resolution}")
    rates.append(result.final_erosion_rate)
    losses.append(float(result.mass_loss_kg[-1]))
    series[angle] = result
    if angle == 45.0:
        write_csv(
            OUT / "erosion_stream.csv",
            {
                "time_s": result.time,
                "impacts": result.impacts,
                "mass_loss_kg": result.mass_loss_kg,
                "erosion_rate_kg_per_kg": result.erosion_rate,
            },
        )
write_csv(
    OUT / "erosion_angles.csv",
    {"angle_deg": angles, "erosion_rate_kg_per_kg": rates, "mass_loss_kg": losses},
)

# %%
# Mass loss against time
# ----------------------

fig, ax = plt.subplots(figsize=(6.0, 3.6))
for angle, result in series.items():
    ax.plot(result.time, result.mass_loss_kg * 1e12, label=f"{angle:g}°")
ax.set(
    xlabel="exposure time (s)",
    ylabel="mass loss of the patch (ng)",
    title="sand on steel, 20 m/s",
)
ax.legend(title="angle from the normal")
fig.tight_layout()
