"""``impactwear indent``: press the ball into the FE plate (fem.indent) and unload; write F–δ, pressures,
first yield, the deformed mesh and figures.

Without ``--config`` the plate and ball come from flags (defaults: steel plate E 210 GPa, ν 0.3,
Y 210 MPa, rigid ball R 10 mm). With ``--config case.toml`` they come from its [ball] and [plate] tables
(an elastic ball enters through E*, see fem.indent). The path loads to ``--max-overlap`` (m), or to
``--max-force`` (N), or by default to w = δ/δ_c = 20 (plastic plate) or a = 0.05 R (elastic), in
``--load-steps`` increments, then unloads to zero in ``--unload-steps``. Every file is written atomically.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
import os
import sys
import time
from pathlib import Path

import numpy as np

HELP = "press the ball into the axisymmetric FE plate and unload; write F-δ, pressures, first yield, mesh, figures"

DEFAULT_OUT = "impactwear-indent"


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--config", metavar="CASE.toml", help="case file: ball and plate from [ball], [plate]")
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--max-overlap", type=float, metavar="M", help="largest overlap δ_max (m)")
    group.add_argument("--max-force", type=float, metavar="N", help="largest force (N): δ_max found by the FE")
    parser.add_argument("--radius", type=float, default=None, help="ball radius R (m, default 10e-3)")
    parser.add_argument("--E", type=float, default=None, help="plate Young's modulus (Pa, default 210e9)")
    parser.add_argument("--nu", type=float, default=None, help="plate Poisson's ratio (default 0.3)")
    parser.add_argument(
        "--yield-strength", type=float, default=None, help="plate yield strength Y (Pa, default 210e6; 0 = elastic)"
    )
    parser.add_argument("--hardening", type=float, default=0.0, help="linear isotropic hardening modulus H (Pa)")
    parser.add_argument("--load-steps", type=int, default=40, help="loading increments (default 40)")
    parser.add_argument("--unload-steps", type=int, default=20, help="unloading increments (default 20)")
    parser.add_argument("--mesh", default=None, help="plate mesh file (m; boundaries axis, surface, bottom)")
    parser.add_argument("--out", default=DEFAULT_OUT, metavar="DIR", help=f"output folder (default {DEFAULT_OUT})")
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    parser.add_argument("--json", action="store_true", help="print summary.json to stdout")


def _materials(args):
    from contact.materials import Material

    ball = None
    if args.config:
        from wear.app import case as case_module

        case = case_module.load_case(args.config)
        b, p = case["ball"], case["plate"]
        radius = b["radius"]
        ball_material = Material(E=b["E"], nu=b["nu"], density=b["density"], yield_strength=None, name=b["name"])
        ball = None if ball_material.is_rigid else ball_material
        plate = dict(E=p["E"], nu=p["nu"], density=p["density"], yield_strength=p["yield_strength"], name=p["name"])
    else:
        radius = 10e-3
        plate = dict(E=210e9, nu=0.3, density=7850.0, yield_strength=210e6, name="steel")
    if args.radius is not None:
        radius = args.radius
    for key, value in (("E", args.E), ("nu", args.nu)):
        if value is not None:
            plate[key] = value
    if args.yield_strength is not None:
        plate["yield_strength"] = None if args.yield_strength == 0 else args.yield_strength
    return radius, Material(**plate), ball


def _atomic_text(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.tmp{os.getpid()}")
    tmp.write_text(text)
    os.replace(tmp, path)


def _csv(rows: list[list], header: list[str]) -> str:
    buf = io.StringIO()
    writer = csv.writer(buf)
    writer.writerow(header)
    writer.writerows(rows)
    return buf.getvalue()


def run_indent(args) -> tuple[object, dict]:
    import fem
    from contact.materials import effective_modulus
    from contact.theory import PAPER_YIELD_COEFFICIENT, first_yield, hertz_overlap
    from contact.validation import check_number

    radius, plate, ball = _materials(args)
    check_number("--load-steps", args.load_steps, low=2, high=2000)
    check_number("--unload-steps", args.unload_steps, low=1, high=2000)
    e_star = effective_modulus(ball if ball is not None else plate.rigid(), plate)
    exact = paper = None
    if plate.yield_strength is not None:
        exact = first_yield(radius, e_star, plate.yield_strength, plate.nu)
        paper = first_yield(radius, e_star, plate.yield_strength, plate.nu, coefficient=PAPER_YIELD_COEFFICIENT)
    if args.max_overlap is not None:
        d_max = check_number("--max-overlap", args.max_overlap, low=0.0, low_open=True, high=radius, units="m")
    elif args.max_force is not None:
        f_max = check_number("--max-force", args.max_force, low=0.0, low_open=True, units="N")
        d_max = float(hertz_overlap(f_max, radius, e_star))
        if exact is not None and f_max > exact.force:
            # Kogut & Etsion (2002) P/P_c = 1.03 w^1.425 / 1.40 w^1.263, inverted, +25% margin
            ratio = f_max / exact.force
            w = (ratio / 1.03) ** (1 / 1.425)
            if w > 6.0:
                w = (ratio / 1.40) ** (1 / 1.263)
            d_max = 1.25 * w * exact.overlap
    else:
        d_max = 20.0 * exact.overlap if exact is not None else 0.0025 * radius
    started = time.perf_counter()
    loading = d_max * np.linspace(0.0, 1.0, args.load_steps + 1)[1:] ** 1.5
    mesh = args.mesh
    if args.max_force is not None:
        load = fem.indent(radius, plate, loading, ball=ball, mesh=mesh, hardening=args.hardening, keep_states=True)
        if load.force.max() < f_max:
            raise ValueError(
                f"--max-force={f_max:g} is out of reach of the estimated path (max {load.force.max():g} N)"
            )
        d_max = float(np.interp(f_max, load.force, load.overlap))
        unload = load.unload_from(d_max, args.unload_steps)
        keep = load.overlap < d_max
        res = _concatenate(load, keep, unload)
    else:
        path = np.r_[loading, d_max * np.linspace(1.0, 0.0, args.unload_steps + 1)[1:]]
        res = fem.indent(radius, plate, path, ball=ball, mesh=mesh, hardening=args.hardening)
    elapsed = time.perf_counter() - started
    peak = int(np.argmax(res.overlap))
    fy = res.first_yield
    summary = {
        "radius_m": radius,
        "effective_modulus_Pa": e_star,
        "plate": {"E_Pa": plate.E, "nu": plate.nu, "yield_strength_Pa": plate.yield_strength},
        "ball": "rigid" if ball is None else {"E_Pa": ball.E, "nu": ball.nu},
        "max_overlap_m": float(res.overlap[peak]),
        "max_force_N": float(res.force[peak]),
        "max_contact_radius_m": float(res.contact_radius[peak]),
        "max_pressure_Pa": float(res.max_pressure.max()),
        "regime_at_max": res.regime[peak],
        "max_equivalent_plastic_strain": float(res.max_equivalent_plastic_strain.max()),
        "residual_depth_on_axis_m": float(res.residual_depth[0]),
        "fe_first_yield": None
        if fy is None
        else {"force_N": fy.force, "overlap_m": fy.overlap, "depth_m": fy.depth, "radius_m": fy.radius},
        "first_yield_exact_C": None
        if exact is None
        else {"C": exact.coefficient, "force_N": exact.force, "overlap_m": exact.overlap, "depth_m": exact.depth},
        "first_yield_paper_C_1.6": None if paper is None else {"force_N": paper.force, "overlap_m": paper.overlap},
        "steps": int(res.overlap.size),
        "newton_iterations": int(res.newton_iterations.sum()),
        "wall_time_s": elapsed,
    }
    return res, summary


def _concatenate(load, keep, unload):
    from fem.result import IndentationResult

    def cat(name):
        return np.concatenate([np.asarray(getattr(load, name))[keep], np.asarray(getattr(unload, name))])

    return IndentationResult(
        overlap=cat("overlap"),
        force=cat("force"),
        contact_radius=cat("contact_radius"),
        max_pressure=cat("max_pressure"),
        mean_pressure=cat("mean_pressure"),
        surface_r=unload.surface_r,
        pressure=np.concatenate([load.pressure[keep], unload.pressure]),
        first_yield=load.first_yield,
        residual_depth=unload.residual_depth,
        max_equivalent_plastic_strain=cat("max_equivalent_plastic_strain"),
        regime=[r for r, k in zip(load.regime, keep, strict=True) if k] + list(unload.regime),
        newton_iterations=cat("newton_iterations"),
        radius=load.radius,
        effective_modulus=load.effective_modulus,
        _run=unload._run,
    )


def write_outputs(res, summary: dict, out: Path, figures: bool = True) -> None:
    out.mkdir(parents=True, exist_ok=True)
    rows = [
        [k, res.overlap[k], res.force[k], res.contact_radius[k], res.max_pressure[k], res.mean_pressure[k],
         res.max_equivalent_plastic_strain[k], res.regime[k]]
        for k in range(res.overlap.size)
    ]  # fmt: skip
    header = ["step", "overlap_m", "force_N", "contact_radius_m", "max_pressure_Pa", "mean_pressure_Pa",
              "max_equivalent_plastic_strain", "regime"]  # fmt: skip
    _atomic_text(out / "force_overlap.csv", _csv(rows, header))
    prow = [[r] + list(res.pressure[:, i]) for i, r in enumerate(res.surface_r)]
    _atomic_text(out / "pressure.csv", _csv(prow, ["r_m"] + [f"step{k}_Pa" for k in range(res.overlap.size)]))
    dent = [[r, z] for r, z in zip(res.surface_r, res.residual_depth, strict=True)]
    _atomic_text(out / "residual_depth.csv", _csv(dent, ["r_m", "residual_depth_m"]))
    res.write(out / "plate.vtu")
    if figures:
        from wear.app.figures.indent import write_figures

        write_figures(res, out)
    _atomic_text(out / "summary.json", json.dumps(summary, indent=2, default=float) + "\n")


def main(args) -> int:
    res, summary = run_indent(args)
    out = Path(args.out)
    write_outputs(res, summary, out, figures=not args.no_figures)
    if args.json:
        json.dump(summary, sys.stdout, indent=2, default=float)
        print()
    else:
        fy = summary["fe_first_yield"]
        ex = summary["first_yield_exact_C"]
        print(f"max overlap {summary['max_overlap_m']:.4g} m, max force {summary['max_force_N']:.4g} N, "
              f"contact radius {summary['max_contact_radius_m']:.4g} m, regime {summary['regime_at_max']}")  # fmt: skip
        if fy is not None and ex is not None:
            paper = summary["first_yield_paper_C_1.6"]["force_N"]
            print(f"first yield: FE {fy['force_N']:.4g} N at depth {fy['depth_m']:.3g} m; exact C={ex['C']:.4f} "
                  f"{ex['force_N']:.4g} N; paper C=1.6 {paper:.4g} N")  # fmt: skip
        print(f"residual dent on the axis {summary['residual_depth_on_axis_m']:.4g} m; "
              f"{summary['steps']} steps in {summary['wall_time_s']:.1f} s; outputs in {out}")  # fmt: skip
    return 0 if all(math.isfinite(v) for v in (summary["max_force_N"],)) else 1
