"""Benchmark of the 3-D plate in the chain: the default oblique impact (``impactwear run``'s default case, 30° from
the normal, μ = 0.3) coupled to the 3-D half plate with friction (``fem.model = "3d"``), on the default mesh (4
elements across the contact) and on the mesh 4× finer at the surface (8 across: ``fem.mesh_scale`` = 1).

Prints, side by side in one run, the code before its speed-ups (main at :data:`BEFORE`, extracted with ``git
archive``) and this tree with each step added: PARDISO's analysis reused for every factor of a sparsity pattern
already analysed (:attr:`fem.core.kept_factor.KeptFactor.reuse_analysis`), and the solves without MKL's two steps of
iterative refinement (:attr:`fem.core.linear.Factorisation.refinement_steps`), and OpenBLAS on one thread beside
PARDISO's (:data:`fem.core.linear.OPENBLAS_THREADS_BESIDE_PARDISO`). This tree's first column has none of them (MKL's
defaults, each factor analysed, OpenBLAS's threads as they are): against the before column it measures the rest of the
work (the tangent assembled on the yielding elements only, the constrained and augmented matrices on patterns found
once, the slip coupling on the contact rows only). Each column runs in a process of its own: its wall time, its work
(plate cycles, increments, Newton iterations, factorisations and their analyses, factor applications), the cost per
increment in units of one linear elastic solve on the same mesh (assembly of the stiffness, the clamped DOFs removed,
a PARDISO factorisation and one solve, measured in this process as the solver runs it: within
:func:`fem.core.linear.pardiso_threads`), its peak memory (resident set), and its results (e_n, e_t, F_max, the dent
and the local law's wear) with their relative change from the before column. Goals (the issue): the default 3-D impact
≤ 4 min and ≤ 5 solve-equivalents per increment on 2 cores, the results within 0.5%, ≤ 4 GB.

Run: ``python benchmarks/bench_solid.py`` (both meshes, about an hour; ``--mesh default`` or ``--mesh fine`` for
one; ``--quick``: 3 elements across the contact, 4 + 2 increments, one cycle; ``--no-before``: without the before
column, e.g. outside a git clone).
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tarfile
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

from fem.core import linear
from fem.core.assembly import assemble
from fem.core.kept_factor import KeptFactor
from fem.core.linear import Factorisation, factorise
from fem.solid.indentation import solid_solver
from fem.solid_coupling import impact_path
from wear.case import JOBS
from wear.case.check import on_plate
from wear.chain.single import run
from wear.chain.solid import solid_case, solid_impact, solid_settings, solid_surface, solid_wear

#: main before the speed-ups of the 3-D plate (each factor analysed, MKL's refinement on every solve).
BEFORE = "0c54ec7"

ROOT = Path(__file__).resolve().parent.parent

#: This tree's columns: (title, KeptFactor.reuse_analysis, Factorisation.refinement_steps,
#: OPENBLAS_THREADS_BESIDE_PARDISO).
STEPS = (
    ("this tree, MKL defaults", False, 2, None),
    ("+ analysis reused", True, 2, None),
    ("+ no refinement", True, 0, None),
    ("+ OpenBLAS on 1 thread", True, 0, 1),
)

#: The fine mesh: this tree as it runs by default only (the before column on it too, for the speed-up).
FINE_STEPS = STEPS[-1:]


def case_of(mesh: str, quick: bool, friction: float | None):
    """The benchmark's case: ``run``'s default with the 3-D plate on the ``mesh`` ("default" or "fine")."""
    fem = {"model": "3d"}
    if mesh == "fine":
        fem["mesh_scale"] = 1.0
    if quick:
        fem.update(mesh_scale=2.6, solid_load_steps=4, solid_unload_steps=2, solid_iterations=1)
    case = JOBS["run"].default_case().with_(fem=fem)
    if friction is not None:
        case = case.with_(impact={"friction": friction})
    return solid_case(case)  # the impact's tangential law the plate's, as in the chain


def measure(settings: dict) -> dict:
    """One column, in its own process: the 3-D coupling of the case from its axisymmetric start with the
    ``settings``' switches (those this tree has), its work, peak memory and results (every name used here exists
    in the :data:`BEFORE` tree too)."""
    if settings.get("reuse_analysis") is not None:
        KeptFactor.reuse_analysis = settings["reuse_analysis"]
    if settings.get("refinement_steps") is not None:
        Factorisation.refinement_steps = settings["refinement_steps"]
    if "openblas_threads" in settings:
        linear.OPENBLAS_THREADS_BESIDE_PARDISO = settings["openblas_threads"]
    case = case_of(settings["mesh"], settings["quick"], settings["friction"])
    t0 = time.perf_counter()
    start = run(on_plate(case, "axisymmetric")).impact
    t_start = time.perf_counter() - t0
    t0 = time.perf_counter()
    coupled = solid_impact(case, start)
    t_solid = time.perf_counter() - t0
    _, wm, _ = solid_wear(case, coupled)
    dent = solid_surface(coupled, wm).dent_grid
    work = coupled.work
    return {
        "start_s": t_start,
        "solid_s": t_solid,
        "cycles": coupled.iterations,
        "converged": bool(coupled.converged),
        "increments": work.increments,
        "iterations": work.iterations,
        "factorisations": work.factorisations,
        "analyses": getattr(work, "analyses", work.factorisations),
        "factor_s": work.factor_time,
        "solves": work.solves,
        "set_updates": work.set_updates,
        "cuts": work.cuts,
        "dofs": int(coupled.solid.final.u.size),
        "peak_GB": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20,
        "e_n": coupled.impact.normal_restitution,
        "e_t": coupled.impact.tangential_restitution,
        "F_max_N": coupled.impact.max_force,
        "dent_m": float(np.max(dent)),
        "pile_up_m": float(-np.min(dent)),
        "wear_m3": wm.volume_m3,
        "wear_depth_m": float(np.max(wm.depth)),
    }


def one_elastic_solve(mesh: str, quick: bool, repeats: int = 3) -> float:
    """Best-of-``repeats`` time (s) of one linear elastic solve on the 3-D plate of the case's first cycle."""
    case = case_of(mesh, quick, None)
    settings = solid_settings(case)
    path = impact_path(run(on_plate(case, "axisymmetric")).impact, settings.load_steps, settings.unload_steps)
    ball, plate = case.ball.material(), case.plate.material()
    solver = solid_solver(
        case.ball.radius,
        plate,
        (1.0 + settings.overshoot) * float(path.overlap[path.peak]),
        path.centre,
        case.impact.friction,
        None if ball.is_rigid else ball,
        0.0,
        settings.contact_elements,
        settings.box_depth,
    )
    d = solver.disc
    free = np.setdiff1d(np.arange(d.ndofs), d.fixed_dofs)
    rhs = np.ones(free.size)
    best = np.inf
    with linear.pardiso_threads():
        for _ in range(repeats):
            t0 = time.perf_counter()
            K = assemble(d, solver.elastic_element_matrices)
            factor = factorise(K[free][:, free].tocsr())
            factor.solve(rhs)
            factor.free()
            best = min(best, time.perf_counter() - t0)
    return best


def run_column(tree: Path, settings: dict) -> dict:
    """:func:`measure` in a new process on the package ``tree`` (its modules first on the path)."""
    env = dict(os.environ, PYTHONPATH=str(tree))
    out = subprocess.run(
        [sys.executable, str(Path(__file__).resolve()), "--child", json.dumps(settings)],
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )
    if out.returncode != 0:
        raise RuntimeError(f"the column {settings} failed:\n{out.stderr[-3000:]}")
    return json.loads(out.stdout.strip().splitlines()[-1])


def before_tree(workdir: Path) -> Path | None:
    """The :data:`BEFORE` commit's packages extracted into ``workdir`` (None outside a git clone)."""
    archive = workdir / "before.tar"
    made = subprocess.run(
        ["git", "-C", str(ROOT), "archive", "--format=tar", "-o", str(archive), BEFORE, "contact", "fem", "wear"],
        capture_output=True,
        check=False,
    )
    if made.returncode != 0:
        return None
    with tarfile.open(archive) as tar:
        tar.extractall(workdir / "before", filter="data")
    return workdir / "before"


ROWS = (
    ("axisymmetric start, s", lambda m: f"{m['start_s']:.1f}"),
    ("3-D coupling, s", lambda m: f"{m['solid_s']:.1f}"),
    ("plate cycles / converged", lambda m: f"{m['cycles']} / {m['converged']}"),
    ("increments (cut)", lambda m: f"{m['increments']} ({m['cuts']})"),
    ("Newton iterations", lambda m: f"{m['iterations']}"),
    ("set rounds", lambda m: f"{m['set_updates']}"),
    ("factorisations (analyses)", lambda m: f"{m['factorisations']} ({m['analyses']})"),
    ("factorisation time, s", lambda m: f"{m['factor_s']:.1f}"),
    ("factor applications", lambda m: f"{m['solves']}"),
    ("solve-equivalents per increment", lambda m: f"{m['per_increment']:.1f}"),
    ("peak memory, GB", lambda m: f"{m['peak_GB']:.2f}"),
)
RESULTS = (
    ("e_n", "e_n", "{:.5f}"),
    ("e_t", "e_t", "{:.5f}"),
    ("largest normal force, N", "F_max_N", "{:.5g}"),
    ("dent depth, m", "dent_m", "{:.5g}"),
    ("pile-up, m", "pile_up_m", "{:.5g}"),
    ("worn volume (local law), m³", "wear_m3", "{:.5g}"),
    ("deepest wear, m", "wear_depth_m", "{:.5g}"),
)


def table(title: str, columns: dict[str, dict]) -> None:
    """Print the columns side by side; the results with their change (%) from the first column."""
    names = list(columns)
    width = max(22, *(len(n) + 2 for n in names))
    print(title)
    print(f"  {'':34s}" + "".join(f"{n:>{width}s}" for n in names))
    for name, value in ROWS:
        print(f"  {name:34s}" + "".join(f"{value(columns[n]):>{width}s}" for n in names))
    first = columns[names[0]]
    for name, key, fmt in RESULTS:
        cells = []
        for n in names:
            x = columns[n][key]
            change = 100.0 * (x - first[key]) / abs(first[key]) if first[key] else 0.0
            cells.append(fmt.format(x) + ("" if n == names[0] else f" ({change:+.2f}%)"))
        print(f"  {name:34s}" + "".join(f"{c:>{width}s}" for c in cells))
    last = columns[names[-1]]
    print(f"  speed-up of the 3-D coupling, first column to last: {first['solid_s'] / last['solid_s']:.2f}x")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="reduced mesh and path")
    parser.add_argument("--friction", type=float, default=None, help="the impact's μ (default: the case's, 0.3)")
    parser.add_argument("--mesh", choices=("default", "fine", "both"), default="both")
    parser.add_argument("--no-before", action="store_true", help="without the before column")
    parser.add_argument("--child", help=argparse.SUPPRESS)
    args = parser.parse_args()
    warnings.simplefilter("ignore")  # the elastic-ball note: the benchmark measures time
    if args.child:
        print(json.dumps(measure(json.loads(args.child))))
        return
    meshes = ("default", "fine") if args.mesh == "both" else (args.mesh,)
    with tempfile.TemporaryDirectory() as workdir:
        before = None if args.no_before else before_tree(Path(workdir))
        for mesh in meshes:
            solve = one_elastic_solve(mesh, args.quick)
            common = {"mesh": mesh, "quick": args.quick, "friction": args.friction}
            columns = {}
            if before is not None:
                columns[f"before ({BEFORE})"] = run_column(before, common)
            for title, reuse, refinement, openblas in STEPS if mesh == "default" else FINE_STEPS:
                settings = dict(common, reuse_analysis=reuse, refinement_steps=refinement, openblas_threads=openblas)
                columns[title] = run_column(ROOT, settings)
            for m in columns.values():
                m["per_increment"] = m["solid_s"] / m["increments"] / solve
            last = columns[list(columns)[-1]]
            table(
                f"3-D plate benchmark, {mesh} mesh: oblique impact at 30°, μ = "
                f"{0.3 if args.friction is None else args.friction:g}, {last['dofs']} DOFs; one linear elastic "
                f"solve on the same mesh {solve:.2f} s",
                columns,
            )
            sys.stdout.flush()


if __name__ == "__main__":
    main()
