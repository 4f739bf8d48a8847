"""Benchmark of the 3-D plate in the chain: the default oblique impact (``impactwear run``'s default case, 30° from
the normal, μ = 0.3) coupled to the 3-D half plate with friction (``fem.model = "3d"``).

Prints, side by side in one run: the wall time of the 3-D coupling (its plate cycles, increments, Newton
iterations, factorisations and factor applications), the time of one linear elastic solve on the same mesh
(assembly of the stiffness, the clamped DOFs removed, PARDISO/SuperLU factorisation and one solve), and the cost per
increment in units of that solve. Goals (the issue): the whole 3-D impact ≤ 10 min and ≤ 5 solve-equivalents per
increment on 2 cores.

Run: ``python benchmarks/bench_solid.py`` (``--quick``: 3 elements across the contact, 4 + 2 increments, one cycle;
``--friction 0``: the frictionless oblique impact).
"""

from __future__ import annotations

import argparse
import time
import warnings

import numpy as np

from fem.core.assembly import assemble
from fem.core.linear import BACKEND, factorise
from wear.case import JOBS
from wear.case.check import on_plate
from wear.chain.single import run
from wear.chain.solid import solid_case, solid_impact, solid_settings


def one_elastic_solve(solver, repeats: int = 3) -> float:
    """Best-of-``repeats`` time (s) of one linear elastic solve on the 3-D plate ``solver``'s mesh."""
    d = solver.disc
    free = np.setdiff1d(np.arange(d.ndofs), d.fixed_dofs)
    rhs = np.ones(free.size)
    best = np.inf
    for _ in range(repeats):
        t0 = time.perf_counter()
        K = assemble(d, solver.elastic_element_matrices)
        factor = factorise(K[free][:, free].tocsr())
        factor.solve(rhs)
        factor.free()
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="reduced mesh and path")
    parser.add_argument("--friction", type=float, default=None, help="the impact's μ (default: the case's, 0.3)")
    args = parser.parse_args()
    warnings.simplefilter("ignore")  # the elastic-ball note: the benchmark measures time
    case = JOBS["run"].default_case().with_(fem={"model": "3d"})
    if args.friction is not None:
        case = case.with_(impact={"friction": args.friction})
    if args.quick:
        case = case.with_(
            fem={
                "model": "3d",
                "mesh_scale": 2.6,
                "solid_load_steps": 4,
                "solid_unload_steps": 2,
                "solid_iterations": 1,
            }
        )
    case = solid_case(case)  # the impact's tangential law the plate's, as in the chain
    t0 = time.perf_counter()
    start = run(on_plate(case, "axisymmetric")).impact
    t_start = time.perf_counter() - t0
    t0 = time.perf_counter()
    coupled = solid_impact(case, start)
    t_solid = time.perf_counter() - t0
    solid, stats = coupled.solid, coupled.work  # all cycles
    solve = one_elastic_solve(solid.solver)
    per_increment = t_solid / stats.increments
    settings = solid_settings(case)
    print(
        f"3-D plate benchmark: default oblique impact, μ = {case.impact.friction:g} "
        f"({case.impact.tangential_model}), "
        f"{settings.contact_elements} elements across the contact, "
        f"{solid.final.u.size} DOFs, solver {BACKEND}"
    )
    print(f"  axisymmetric start (whole chain):      {t_start:8.1f} s")
    print(f"  3-D coupling:                          {t_solid:8.1f} s   ({t_solid / 60:.2f} min; goal <= 10 min)")
    print(f"  plate cycles / converged:              {coupled.iterations:8d}   {coupled.converged}")
    print(f"  increments:                            {stats.increments:8d}")
    print(f"  Newton iterations:                     {stats.iterations:8d}")
    print(f"  factorisations / factor applications:  {stats.factorisations:8d} / {stats.solves}")
    print(f"  factorisation time:                    {stats.factor_time:8.1f} s")
    print(f"  set rounds / cut increments:           {stats.set_updates:8d} / {stats.cuts}")
    print(f"  line-search backtracks / elastic retries: {stats.backtracks:5d} / {stats.elastic_retries}")
    print(f"  one linear elastic solve, same mesh:   {solve:8.2f} s")
    print(
        f"  cost per increment:                    {per_increment:8.2f} s = {per_increment / solve:.1f} "
        "solve-equivalents (goal <= 5)"
    )
    print(
        f"  e_n {coupled.impact.normal_restitution:.4f} (axisymmetric {start.normal_restitution:.4f}), "
        f"e_t {coupled.impact.tangential_restitution:.4f} (axisymmetric {start.tangential_restitution:.4f})"
    )


if __name__ == "__main__":
    main()
