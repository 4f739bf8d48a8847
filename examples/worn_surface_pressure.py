"""Pressure of a ball on a worn surface
====================================

Pressure of a ball on a worn surface: the FE plate against the half-space solution of the same gap.

A steel plate worn into a smooth pit w(r) = D (1 − r²/a₀²)² (a₀ the flat Hertz contact radius, D = 0.5 a₀²/R) is
pressed by a rigid 10 mm ball (fem.Plate.move_surface, then Plate.load). The same gap is solved on a 2-D grid by
contact.halfspace_contact (boundary elements). Prints both peak pressures, where they sit, and Hertz on the flat
at the same force; writes the radial profiles to ``profiles.csv`` in ``worn_surface_pressure/`` of the folder named by
the environment variable ``IMPACTWEAR_EXAMPLE_OUT`` (default: the current folder).
"""

# %%
# The worn plate and the same gap on the half-space
# -------------------------------------------------

import os
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import fem
from contact import Material, sphere_on_axisymmetric_surface
from contact.theory import hertz_peak_pressure

# where the outputs go
OUT = Path(os.environ.get("IMPACTWEAR_EXAMPLE_OUT", ".")) / "worn_surface_pressure"
OUT.mkdir(parents=True, exist_ok=True)
# IMPACTWEAR_QUICK=1 (as on this page): a coarser FE mesh
quick = os.environ.get("IMPACTWEAR_QUICK") == "1"

radius = 10e-3  # m
# elastic: no yield strength
steel = Material(E=210e9, nu=0.3, density=7850.0, name="steel")
e_star = steel.E / (1.0 - steel.nu**2)
a0 = 0.01 * radius  # m
d0 = a0**2 / radius  # m


def pit(r):
    return 0.5 * d0 * np.clip(1.0 - (r / a0) ** 2, 0.0, None) ** 2


mesh = fem.plate_mesh(
    radius, steel, 2.0 * d0, contact_elements=12 if quick else 32, yield_elements=8
)
plate = fem.Plate(radius, steel, 2.0 * d0, mesh=mesh)
r = plate.surface_r
plate.move_surface(pit(r))
first = plate.first_contact_overlap()
res = plate.load(first + np.linspace(0.0, 1.0, 5)[1:] * d0)
force = float(res.force[-1])
p_fe = res.pressure[-1]

cells = 128
bem, rho = sphere_on_axisymmetric_surface(radius, pit, force, e_star, 3.2 * a0, cells)
row = bem.pressure[cells // 2, cells // 2 :]
# a row through the centre (half a cell off the axis)
x_row = rho[cells // 2, cells // 2 :]

print(
    f"first contact at δ = {first:.4g} m (closed form 0.375 a0²/R = {0.375 * d0:.4g} m)"
)
print(
    f"force {force:.4g} N at δ = {res.overlap[-1]:.4g} m (half-space approach "
    f"{bem.approach:.4g} m)"
)
print(
    f"peak pressure: FE {p_fe.max():.4g} Pa at r = {r[np.argmax(p_fe)] / a0:.2f} a0; "
    "half-space "
    f"{bem.max_pressure:.4g} Pa at r = {x_row[np.argmax(row)] / a0:.2f} a0; Hertz on "
    "the flat "
    f"{hertz_peak_pressure(force, radius, e_star):.4g} Pa on the axis"
)
inside = r < 1.5 * a0
np.savetxt(
    OUT / "profiles.csv",
    np.column_stack([r[inside], p_fe[inside], np.interp(r[inside], x_row, row)]),
    delimiter=",",
    header="r_m,pressure_fe_Pa,pressure_halfspace_Pa",
    comments="",
)

# %%
# The two pressure profiles
# -------------------------
# The pit moves the pressure off the axis: both solutions put the peak on a ring.

fig, ax = plt.subplots(figsize=(6, 4))
ax.plot(r[inside] / a0, p_fe[inside] / 1e9, "o-", ms=3, label="FE plate (fem.Plate)")
ax.plot(
    x_row / a0,
    row / 1e9,
    "-",
    label="half-space (contact.sphere_on_axisymmetric_surface)",
)
ax.set_xlim(0, 1.5)
ax.set_xlabel("r / a0")
ax.set_ylabel("contact pressure (GPa)")
ax.legend()
fig.tight_layout()
