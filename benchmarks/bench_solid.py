"""Benchmark of the 3-D plate in the chain: the default oblique impact (``impactwear run``'s default case, 30° from
the normal, μ = 0.3) coupled to the 3-D half plate with friction (``fem.model = "3d"``).

Prints, side by side in one run, each factorisation analysed anew (as before) and PARDISO's analysis reused for
every factor of a sparsity pattern already analysed (:attr:`fem.core.kept_factor.KeptFactor.reuse_analysis`): the
wall time of the 3-D coupling (its plate cycles, increments, Newton iterations, factorisations and their analyses,
factor applications), the cost per increment in units of one linear elastic solve on the same mesh (assembly of the
stiffness, the clamped DOFs removed, PARDISO/SuperLU factorisation and one solve), and the results. Goals (the
issue): the default 3-D impact ≤ 4 min and ≤ 5 solve-equivalents per increment on 2 cores.

Run: ``python benchmarks/bench_solid.py`` (``--quick``: 3 elements across the contact, 4 + 2 increments, one cycle;
``--friction 0``: the frictionless oblique impact).
"""

from __future__ import annotations

import argparse
import time
import warnings

import numpy as np

from fem.core.assembly import assemble
from fem.core.kept_factor import KeptFactor
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


def measure(case, reuse_analysis: bool) -> dict:
    """The 3-D coupling of ``case`` from its axisymmetric start, with or without the reuse of PARDISO's analysis
    (:attr:`fem.core.kept_factor.KeptFactor.reuse_analysis`): its times, work and results."""
    KeptFactor.reuse_analysis = reuse_analysis
    try:
        t0 = time.perf_counter()
        start = run(on_plate(case, "axisymmetric")).impact
        t_start = time.perf_counter() - t0
        t0 = time.perf_counter()
        coupled = solid_impact(case, start)
        t_solid = time.perf_counter() - t0
    finally:
        KeptFactor.reuse_analysis = True
    stats = coupled.work
    return {
        "start": t_start,
        "solid": t_solid,
        "coupled": coupled,
        "stats": stats,
        "per_increment": t_solid / stats.increments,
        "axisymmetric": start,
    }


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
    before, after = measure(case, reuse_analysis=False), measure(case, reuse_analysis=True)
    solid = after["coupled"].solid
    solve = one_elastic_solve(solid.solver)
    settings = solid_settings(case)
    print(
        f"3-D plate benchmark: default oblique impact, μ = {case.impact.friction:g} "
        f"({case.impact.tangential_model}), "
        f"{settings.contact_elements} elements across the contact, "
        f"{solid.final.u.size} DOFs, solver {BACKEND}; one linear elastic solve on the same mesh {solve:.2f} s"
    )
    print(f"  {'':44s} {'each factor analysed':>22s} {'analysis reused':>18s}")
    rows = [
        ("axisymmetric start (whole chain), s", lambda m: f"{m['start']:.1f}"),
        ("3-D coupling, s", lambda m: f"{m['solid']:.1f}"),
        ("plate cycles / converged", lambda m: f"{m['coupled'].iterations} / {m['coupled'].converged}"),
        ("increments", lambda m: f"{m['stats'].increments}"),
        ("Newton iterations", lambda m: f"{m['stats'].iterations}"),
        ("factorisations (analyses)", lambda m: f"{m['stats'].factorisations} ({m['stats'].analyses})"),
        ("factorisation time, s", lambda m: f"{m['stats'].factor_time:.1f}"),
        ("factor applications", lambda m: f"{m['stats'].solves}"),
        ("set rounds / cut increments", lambda m: f"{m['stats'].set_updates} / {m['stats'].cuts}"),
        ("solve-equivalents per increment", lambda m: f"{m['per_increment'] / solve:.1f}"),
        ("e_n", lambda m: f"{m['coupled'].impact.normal_restitution:.5f}"),
        ("e_t", lambda m: f"{m['coupled'].impact.tangential_restitution:.5f}"),
        ("largest normal force, N", lambda m: f"{m['coupled'].impact.max_force:.5g}"),
    ]
    for name, value in rows:
        print(f"  {name:44s} {value(before):>22s} {value(after):>18s}")
    speed_up = before["solid"] / after["solid"]
    print(f"  speed-up of the 3-D coupling: {speed_up:.2f}x (goal: 4 min, 2.2x the 528 s of 2026-11-24)")


if __name__ == "__main__":
    main()
