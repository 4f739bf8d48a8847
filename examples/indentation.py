"""Indentation of a steel plate past first yield
=============================================

Press a rigid 10 mm ball into a steel plate past first yield and unload (fem.indent).

Prints the FE first yield against F_c (errata Eq. 18, exact C(ν) and the paper's C = 1.6), the force at the
maximum, the residual dent, and writes the F–δ table, the figures and the deformed mesh into ``indentation/`` of the
folder named by the environment variable ``IMPACTWEAR_EXAMPLE_OUT`` (default: the current folder).
"""

# %%
# Load and unload the plate
# -------------------------

import os
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import fem
from contact.materials import Material, effective_modulus
from contact.theory import PAPER_YIELD_COEFFICIENT, first_yield
from wear.app.figures.indent import write_figures
from wear.app.outputs.writer import write_mesh

# where the outputs go
OUT = Path(os.environ.get("IMPACTWEAR_EXAMPLE_OUT", ".")) / "indentation"
OUT.mkdir(parents=True, exist_ok=True)
# IMPACTWEAR_QUICK=1 (as on this page): a coarse mesh, few increments (seconds, not
# validation quality)
quick = os.environ.get("IMPACTWEAR_QUICK") == "1"

radius = 10e-3  # m
plate = Material(E=210e9, nu=0.3, density=7850.0, yield_strength=210e6, name="steel")
e_star = effective_modulus(Material.rigid(), plate)
exact = first_yield(radius, e_star, plate.yield_strength, plate.nu)
paper = first_yield(
    radius, e_star, plate.yield_strength, plate.nu, coefficient=PAPER_YIELD_COEFFICIENT
)

w_max = 6.0  # δ_max / δ_c
load, unload = (6, 8) if quick else (24, 12)
overlaps = (
    exact.overlap
    * np.r_[np.linspace(0, w_max, load + 1)[1:], np.linspace(w_max, 0, unload + 1)[1:]]
)
mesh = (
    fem.plate_mesh(radius, plate, overlaps.max(), contact_elements=12, yield_elements=8)
    if quick
    else None
)
res = fem.indent(radius, plate, overlaps, mesh=mesh)

fy = res.first_yield
print(f"FE first yield {fy.force:.4g} N at depth {fy.depth / fy.contact_radius:.3f} a")
print(
    f"F_c exact C={exact.coefficient:.4f}: {exact.force:.4g} N; paper C=1.6: "
    f"{paper.force:.4g} N"
)
k = int(np.argmax(res.overlap))
print(
    f"at w = {w_max}: F = {res.force[k]:.4g} N, a = {res.contact_radius[k]:.4g} m, "
    f"regime {res.regime[k]}"
)
print(f"residual dent on the axis {res.residual_depth[0]:.3e} m")
law = res.force_law()
print(
    f"force law: residual overlap {law.residual_overlap[0]:.3e} m after δ_max "
    f"{law.unloading_max_overlap[0]:.3e} m"
)

# %%
# Write the outputs
# -----------------
# The F–δ table, the plate mesh with its fields (open it in ParaView) and the toolkit's figures (PNG files:
# pressure, force–overlap, plastic zone).

np.savetxt(
    OUT / "force_overlap.csv",
    np.column_stack([res.overlap, res.force, res.contact_radius]),
    delimiter=",",
    header="overlap_m,force_N,contact_radius_m",
    comments="",
)
# field names with units, as impactwear indent writes them
write_mesh(OUT / "plate.vtu", res.to_meshio())
print([p.name for p in write_figures(res, OUT)])

# %%
# Force against overlap
# ---------------------
# The FE loading and unloading against Hertz's elastic curve F = (4/3) E* √R δ^(3/2) (errata Eq. 4); the plate
# leaves Hertz's curve after first yield and unloads to a residual overlap (the dent).

d = np.r_[0.0, res.overlap]
dd = np.linspace(0.0, res.overlap.max(), 200)
fig, ax = plt.subplots(figsize=(5.5, 4.0))
ax.plot(d * 1e6, np.r_[0.0, res.force], "o-", ms=3, label="FE plate")
ax.plot(
    dd * 1e6,
    4.0 / 3.0 * e_star * np.sqrt(radius) * dd**1.5,
    "--",
    label="Hertz (elastic)",
)
ax.plot(fy.overlap * 1e6, fy.force, "k*", ms=9, label="FE first yield")
ax.set(
    xlabel="overlap δ (µm)",
    ylabel="normal force F (N)",
    ylim=(0.0, 1.1 * res.force.max()),
)
ax.legend()
fig.tight_layout()
