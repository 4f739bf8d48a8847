"""A ball sliding on the 3-D plate: where the surface yields first
=================================================================

A rigid 10 mm ball is pressed into an elastic steel plate without friction, then slid to gross sliding with
μ = 0.5 (fem.indent_solid, the plate refined around the contact edge). Hamilton (1983) puts first yield for
μ > 0.3 at the surface, at the trailing edge, with p0/Y = 1.045 (ν = 0.3) — for the Hertz pressure and a traction
μp. On a compressible plate the solved contact's pressure shifts towards the trailing edge, in proportion to the
coupling β = (1 − 2ν)/(2(1 − ν)) (Johnson 1985 §7), and the surface yields earlier. Prints, for ν = 0.3 and 0.45,
the pressure's centroid, its shift per unit β, and the p0/Y of the largest surface von Mises stress
(fem.solid.surface_stress); writes the surface von Mises stress along the plane of incidence to ``surface.csv`` in
``sliding_surface_yield/`` of the folder named by the environment variable ``IMPACTWEAR_EXAMPLE_OUT`` (default: the
current folder).
"""

# %%
# Press, then slide, on two plates
# --------------------------------

import math
import os
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

import fem
from contact import Material
from fem.core.plasticity import von_mises

# where the outputs go
OUT = Path(os.environ.get("IMPACTWEAR_EXAMPLE_OUT", ".")) / "sliding_surface_yield"
OUT.mkdir(parents=True, exist_ok=True)
# IMPACTWEAR_QUICK=1 (as on this page): no edge band (coarser, faster)
quick = os.environ.get("IMPACTWEAR_QUICK") == "1"

radius, mu, a_max = 10e-3, 0.5, 1e-4  # m, -, m
overlap = a_max**2 / radius  # m
rows, profiles = [], {}
for nu in (0.3, 0.45):
    # elastic: no yield strength
    steel = Material(E=210e9, nu=nu, density=7850.0, name="steel")
    e_star = steel.E / (1.0 - nu**2)
    shear_modulus = steel.E / (2.0 * (1.0 + nu))
    hertz_force = 4.0 / 3.0 * e_star * math.sqrt(radius) * overlap**1.5
    hertz_radius = math.sqrt(radius * overlap)
    # twice the Cattaneo-Mindlin slide of gross sliding, 3 mu P (2 - nu) / (16 G a)
    slide = (
        2.0
        * 3.0
        * mu
        * hertz_force
        * (2.0 - nu)
        / (16.0 * shear_modulus * hertz_radius)
    )
    result = fem.indent_solid(
        radius,
        steel,
        [overlap, overlap],
        slides=[0.0, slide],
        friction=[0.0, mu],
        box_depth=0.3,
        edge_elements=None if quick else 16,
    )
    force = result.normal_force[-1]
    a = (3.0 * force * radius / (4.0 * e_star)) ** (1.0 / 3.0)
    p0 = 3.0 * force / (2.0 * math.pi * a**2)
    x, y = result.surface_vertices[:, 0] / a, result.surface_vertices[:, 1] / a
    pressure = result.pressure[-1]
    # the hats' areas weight the vertex pressures into the half plate's force
    area = result.solver.disc.surface_area
    centroid = float((x * pressure * area).sum() / (pressure * area).sum())
    beta = (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))
    surface = von_mises(result.surface_stress()) / p0
    worst = int(np.argmax(surface))
    rows.append((nu, beta, centroid, 1.0 / surface[worst], x[worst], y[worst]))
    line = np.flatnonzero(np.abs(y) < 1e-9)
    line = line[np.argsort(x[line])]
    profiles[nu] = (x[line], surface[line])

print(
    "  nu    beta   pressure centroid x/a   per unit beta   p0/Y of the largest "
    "surface stress   at x/a, y/a"
)
for nu, beta, centroid, ratio, xw, yw in rows:
    print(
        f"  {nu:.2f}  {beta:.3f}  {centroid:+.4f}                "
        f"{centroid / beta:+.4f}         "
        f"{ratio:.3f}                                {xw:+.2f}, {yw:.2f}"
    )
print(
    "  Hamilton (1983), nu = 0.3, the Hertz pressure and traction mu p: p0/Y = 1.045 "
    "at x = -a, y = 0"
)

# %%
# The surface stress along the plane of incidence
# -----------------------------------------------
# Largest at the trailing edge (x = −a), where the surface yields first.

with open(OUT / "surface.csv", "w") as fh:
    fh.write(
        "# surface von Mises stress / p0 along y = 0 after sliding at mu = 0.5 (rigid "
        "ball, elastic plate)\n"
    )
    fh.write("nu,x_over_a,von_mises_over_p0\n")
    for nu, (xs, vm) in profiles.items():
        for xv, v in zip(xs, vm, strict=True):
            fh.write(f"{nu},{xv:.5f},{v:.5f}\n")
fig, ax = plt.subplots(figsize=(5.5, 3.5))
for nu, (xs, vm) in profiles.items():
    ax.plot(xs, vm, marker="o", markersize=3, label=f"ν = {nu}")
ax.axvline(-1.0, color="0.6", lw=0.8)
ax.set(
    xlabel="x / a (sliding towards +x)",
    ylabel="surface von Mises / p0",
    xlim=(-1.5, 1.5),
)
ax.legend()
fig.tight_layout()
