"""The whole chain on the default case
===================================

The whole chain on the default case through the public API: impact → FE plate (two-way) → wear → meshes.

Equivalent to ``impactwear run`` (an alumina ball, R 2.5 mm, on a Ti-6Al-4V plate at 3 m/s, 30° from the
normal); prints the main results and writes the output folder (summary.json, history.csv, pressure.npz,
surface.vtu, plate.vtu, plate_fe.vtu, figures) into ``default_run/`` of the folder named by the environment variable
``IMPACTWEAR_EXAMPLE_OUT`` (default: the current folder). SI units.
"""

# %%
# Run the default case
# --------------------
# The toolkit states its modelling assumptions as Python warnings (here: the elastic ball enters the FE plate
# through the effective modulus E*); like ``impactwear run``, this example collects them and prints each as a note.

import os
import warnings
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from wear import Case, run
from wear.app.outputs.run import write_run

# where the outputs go
OUT = Path(os.environ.get("IMPACTWEAR_EXAMPLE_OUT", ".")) / "default_run"

case = Case()
# IMPACTWEAR_QUICK=1 (as on this page): coarser FE mesh, fewer steps, no 3-D render
if os.environ.get("IMPACTWEAR_QUICK") == "1":
    case = case.with_(
        fem={"mesh_scale": 4.0, "load_steps": 10, "unload_steps": 6},
        wear={"points_across": 40},
        output={"render": False},
    )
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    result = run(case, progress=lambda stage: print(f"stage: {stage}", flush=True))
for note in dict.fromkeys(str(w.message) for w in caught):
    print(f"note: {note}")
summary = write_run(result, OUT)
imp, wear = result.impact, result.wear
print(
    f"normal restitution e_n = {imp.normal_restitution:.4f}, max force "
    f"{imp.max_force:.4g} N"
)
print(
    f"coupling: {result.coupling.iterations} impact runs, final change "
    f"{result.coupling.change:.2e}"
)
print(
    f"regime: {result.regime}; FE first yield "
    f"{result.yield_info['fe_first_yield_force']:.4g} N "
    f"(Eq. 18, C = 1.6: {result.yield_info['F_y_paper']:.4g} N)"
)
print(
    f"worn volume {wear.volume_m3:.4g} m^3, max wear depth {wear.max_depth_m:.4g} m, "
    f"dent depth {result.surface.max_dent_depth:.4g} m"
)
print("stage times (s):", {k: round(v, 2) for k, v in summary["stage_times_s"].items()})

# %%
# The impact's force history
# --------------------------
# The normal force on the FE plate's force law (two-way coupling) and the tangential force, against time.

h = imp.history
fig, ax = plt.subplots(figsize=(6.0, 3.6))
ax.plot(h.t * 1e6, h.normal_force, label="normal force")
ax.plot(h.t * 1e6, h.tangential_force, label="tangential force")
ax.set(
    xlabel="time (µs)", ylabel="force (N)", title="alumina on Ti-6Al-4V, 3 m/s at 30°"
)
ax.legend()
fig.tight_layout()

# %%
# The worn and dented surface
# ---------------------------
# The wear depth on the plate's surface (the output folder's ``wear_map.png`` draws the same map).

fig, ax = plt.subplots(figsize=(6.0, 4.2))
mesh = ax.pcolormesh(
    wear.x * 1e6, wear.y * 1e6, wear.depth * 1e9, shading="auto", cmap="viridis"
)
fig.colorbar(mesh, ax=ax, label="wear depth (nm)")
ax.set(xlabel="x along the impact (µm)", ylabel="y (µm)", aspect="equal")
ax.set_title(
    f"worn volume {wear.volume_m3:.3g} m³, deepest {np.max(wear.depth) * 1e9:.3g} nm",
    fontsize=10,
)
fig.tight_layout()
