"""Benchmark of the FE plate (issue 3): the standard cycle on the default mesh.

Steel plate E 210 GPa, ν 0.3, Y 210 MPa, rigid ball R 10 mm; load to w = δ/δ_c = 20 in 40 increments,
unload to zero in 20. Prints the wall time, Newton iterations and LU factorisations per increment, and —
measured in the same run on the same mesh — the time of one linear elastic solve (assembly of the
stiffness, reduction to the free DOFs, SuperLU factorisation and solve). Targets: total time /
(increments × one solve) ≤ 4, whole cycle ≤ 60 s on 2 cores.

Run: ``python benchmarks/bench_fem.py`` (``--quick`` for a reduced mesh).
"""

from __future__ import annotations

import argparse
import time

import numpy as np
import scipy.sparse.linalg as spla

import fem
from contact.materials import Material, effective_modulus
from contact.theory import first_yield
from fem.axisymmetric.forms import discretise
from fem.core.assembly import assemble, element_matrices
from fem.core.plasticity import J2Material

R = 10e-3
PLATE = Material(E=210e9, nu=0.3, density=7850.0, yield_strength=210e6)


def one_elastic_solve(mesh, repeats: int = 3) -> float:
    """Best-of-``repeats`` time (s) of one linear elastic solve on ``mesh``."""
    disc = discretise(mesh)
    tangent = J2Material(PLATE.E, PLATE.nu).elastic_tangent
    fixed = np.unique(np.concatenate([disc.axis_dofs, disc.bottom_dofs]))
    free = np.setdiff1d(np.arange(disc.ndofs), fixed)
    rhs = np.ones(free.size)
    best = np.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        K = assemble(disc, element_matrices(disc, tangent))
        K_ff = K[free][:, free]
        lu = spla.splu(K_ff.tocsc(), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True})
        lu.solve(rhs)
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="reduced mesh (16 elements across a_max)")
    args = parser.parse_args()
    e_star = effective_modulus(Material.rigid(), PLATE)
    fy = first_yield(R, e_star, PLATE.yield_strength, PLATE.nu)
    d_max = 20.0 * fy.overlap
    path = np.r_[np.linspace(0.0, d_max, 41)[1:], np.linspace(d_max, 0.0, 21)[1:]]
    if args.quick:
        mesh = fem.plate_mesh(R, PLATE, d_max, contact_elements=16, yield_elements=10)
    else:
        mesh = fem.plate_mesh(R, PLATE, d_max)
    solve = one_elastic_solve(mesh)
    t0 = time.perf_counter()
    res = fem.indent(R, PLATE, path, mesh=mesh)
    total = time.perf_counter() - t0
    stats = res.run.solver.stats
    n = path.size
    ndofs = res.run.solver.disc.ndofs
    print(f"mesh: {mesh.t.shape[1]} P2 triangles, {ndofs} DOFs")
    print(f"one linear elastic solve (assemble + factorise + solve): {solve:.3f} s")
    print(f"standard cycle: {n} increments in {total:.2f} s (target <= 60 s)")
    print(f"Newton iterations per increment: {res.newton_iterations.mean():.2f} (max {res.newton_iterations.max()})")
    print(
        f"LU factorisations per increment: {stats.factorisations / n:.2f}; step cuts: {stats.cuts}; "
        f"elastic-stiffness retries: {stats.elastic_retries}; relaxed contact sets: {stats.relaxed}"
    )
    print(f"time in assembly {stats.assembly_time:.2f} s, in factorisation+solve {stats.factor_time:.2f} s")
    print(
        f"solve-equivalents per increment: total / (increments x one solve) = {total / (n * solve):.2f} (target <= 4)"
    )
    print(f"max force {res.force.max():.4g} N (F_c = {fy.force:.4g} N), residual dent {res.residual_depth[0]:.3e} m")


if __name__ == "__main__":
    main()
