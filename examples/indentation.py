"""Indentation of a steel plate past first yield
=============================================

Press a rigid 10 mm ball into a steel plate past first yield and unload (fem.indent).

Prints the FE first yield against F_c (errata Eq. 18, exact C(ν) and the paper's C = 1.6), the force at the
maximum, the residual dent, and writes the F–δ table, the figures and the deformed mesh into --out.
IMPACTWEAR_QUICK=1 uses a coarse mesh and few increments (seconds, not validation quality).
"""

import argparse
import os
from pathlib import Path

import numpy as np

import fem
from contact.materials import Material, effective_modulus
from contact.theory import PAPER_YIELD_COEFFICIENT, first_yield
from wear.app.figures.indent import write_figures
from wear.app.outputs.writer import write_mesh

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--out", default="indentation-example", help="output folder")
args = parser.parse_args()
quick = os.environ.get("IMPACTWEAR_QUICK") == "1"
out = Path(args.out)
out.mkdir(parents=True, exist_ok=True)

radius = 10e-3  # m
plate = Material(E=210e9, nu=0.3, density=7850.0, yield_strength=210e6, name="steel")
e_star = effective_modulus(Material.rigid(), plate)
exact = first_yield(radius, e_star, plate.yield_strength, plate.nu)
paper = first_yield(radius, e_star, plate.yield_strength, plate.nu, coefficient=PAPER_YIELD_COEFFICIENT)

w_max = 6.0  # δ_max / δ_c
load, unload = (6, 8) if quick else (24, 12)
overlaps = exact.overlap * np.r_[np.linspace(0, w_max, load + 1)[1:], np.linspace(w_max, 0, unload + 1)[1:]]
mesh = fem.plate_mesh(radius, plate, overlaps.max(), contact_elements=12, yield_elements=8) if quick else None
res = fem.indent(radius, plate, overlaps, mesh=mesh)

fy = res.first_yield
print(f"FE first yield {fy.force:.4g} N at depth {fy.depth / fy.contact_radius:.3f} a")
print(f"F_c exact C={exact.coefficient:.4f}: {exact.force:.4g} N; paper C=1.6: {paper.force:.4g} N")
k = int(np.argmax(res.overlap))
print(f"at w = {w_max}: F = {res.force[k]:.4g} N, a = {res.contact_radius[k]:.4g} m, regime {res.regime[k]}")
print(f"residual dent on the axis {res.residual_depth[0]:.3e} m")
law = res.force_law()
print(f"force law: residual overlap {law.residual_overlap[0]:.3e} m after δ_max {law.unloading_max_overlap[0]:.3e} m")

np.savetxt(
    out / "force_overlap.csv",
    np.column_stack([res.overlap, res.force, res.contact_radius]),
    delimiter=",",
    header="overlap_m,normal_force_N,contact_radius_m",
    comments="",
)
write_mesh(out / "plate.vtu", res.to_meshio())  # field names with units, as impactwear indent writes them
write_figures(res, out)
print(f"outputs in {out}")
