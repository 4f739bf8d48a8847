"""``impactwear indent``: press the ball into the FE plate (:func:`fem.indent`) and unload; write F–δ, pressures,
first yield, the deformed mesh and figures.

The ball, the plate and the FE increments come from the case (``--config CASE.toml``, any case file; keys left out
take ``impactwear indent --print-default``'s: a rigid ball R 10 mm on a steel plate E 210 GPa, ν 0.3, Y 210 MPa,
40 + 20 increments); the flags below override single keys. The path loads to ``--max-overlap`` (m), or to
``--max-force`` (N), or by default to w = δ/δ_c = 20 (plastic plate) or a = 0.05 R (elastic), then unloads to zero.
The plate is the axisymmetric one: ``fem.model = "3d"`` is refused before any work (:func:`wear.case.check_job_case`).
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

from contact.checks import check_number
from fem import load_mesh
from wear.app.commands.common import (
    add_case_options,
    add_out_option,
    case_from_args,
    collect_notes,
    print_default,
    print_json,
    print_notes,
)
from wear.app.outputs.folder import check_output_folder
from wear.app.outputs.indent import ENTRIES, write_indent
from wear.chain.indent import indent_case, largest_force

HELP = "press the ball into the axisymmetric FE plate and unload; write F-δ, pressures, first yield, mesh, figures"

DEFAULT_OUT = "impactwear-indent"
#: Largest hardening modulus (Pa): the case schema's largest Young's modulus.
MAX_HARDENING = 1e13

# option -> case key (checked by the case schema, so errors name the key)
_OPTIONS = {
    "radius": ("ball.radius", "ball radius R (m)"),
    "E": ("plate.E", "plate Young's modulus (Pa)"),
    "nu": ("plate.nu", "plate Poisson's ratio"),
    "yield_strength": ("plate.yield_strength", "plate yield strength Y (Pa; inf: never yields, as in case files)"),
    "load_steps": ("fem.load_steps", "loading increments"),
    "unload_steps": ("fem.unload_steps", "unloading increments"),
}


def configure(parser: argparse.ArgumentParser) -> None:
    add_case_options(parser, "indent", flag=True)
    group = parser.add_mutually_exclusive_group()
    group.add_argument(
        "--max-overlap",
        type=float,
        metavar="M",
        help="largest overlap δ_max (m); with neither this nor --max-force the path loads to "
        "w = δ/δ_c = 20 (plastic plate) or to a contact radius a = 0.05 R (elastic), then "
        "unloads",
    )
    group.add_argument("--max-force", type=float, metavar="N", help="largest force (N): δ_max found by the FE")
    for name, (key, doc) in _OPTIONS.items():
        kind = int if name.endswith("steps") else float
        parser.add_argument(f"--{name.replace('_', '-')}", dest=name, type=kind, metavar="X", help=f"{doc} [{key}]")
    parser.add_argument("--hardening", type=float, default=0.0, help="linear isotropic hardening modulus H (Pa)")
    parser.add_argument("--mesh", default=None, help="plate mesh file (m; boundaries axis, surface, bottom)")
    add_out_option(parser, DEFAULT_OUT)
    parser.add_argument("--no-figures", action="store_true", help="skip the PNG figures")
    parser.add_argument("--quiet", action="store_true", help="no summary lines")
    parser.add_argument("--json", action="store_true", help="print summary.json to stdout instead of the lines")


def main(args: argparse.Namespace) -> int:
    named: dict[str, dict[str, object]] = {}
    for name, (key, _doc) in _OPTIONS.items():
        value = getattr(args, name)
        if value is not None:
            table, _, k = key.partition(".")
            named.setdefault(table, {})[k] = value
    case = case_from_args(args, "indent", named)
    if args.print_default:
        return print_default(args, "indent", case)
    check_output_folder(args.out, "indent", ENTRIES)
    # named as the user gave them (indent_case checks its own arguments again, named as in Python)
    if args.max_overlap is not None:
        check_number("--max-overlap", args.max_overlap, low=0.0, low_open=True, high=case.ball.radius, units="m")
    if args.max_force is not None:
        check_number("--max-force", args.max_force, low=0.0, low_open=True, high=largest_force(case), units="N")
    check_number("--hardening", args.hardening, low=0.0, high=MAX_HARDENING, units="Pa")
    mesh = None
    if args.mesh is not None:
        # meshio warns in raw lines on files it half-reads (an STL: "overflow encountered in scalar multiply"): a
        # refused file's one line says what is wrong, a read one's warnings are notes
        with collect_notes() as read_notes:
            try:  # read before any work: its errors name mesh=PATH, the option is --mesh
                mesh = load_mesh(args.mesh)
            except ValueError as exc:
                raise ValueError(f"--{exc}") from None
        print_notes("indent", [f"--mesh={args.mesh!r}: {note}" for note in read_notes])
    with collect_notes() as notes:
        run = indent_case(
            case, max_overlap=args.max_overlap, max_force=args.max_force, hardening=args.hardening, mesh=mesh
        )
        out = Path(args.out)
        summary = write_indent(run, out, figures=not args.no_figures, notes=notes)
    print_notes("indent", summary["notes"])
    if args.json:
        print_json(summary)
    elif not args.quiet:
        fy = summary["fe_first_yield"]
        ex = summary["first_yield_exact_C"]
        print(
            f"max overlap {summary['max_overlap_m']:.4g} m, max force {summary['max_force_N']:.4g} N, "
            f"contact radius {summary['max_contact_radius_m']:.4g} m, regime {summary['regime_at_max']}"
        )
        if fy is not None and ex is not None:
            paper = summary["first_yield_paper_C_1.6"]["force_N"]
            print(
                f"first yield: FE {fy['force_N']:.4g} N at depth {fy['depth_m']:.3g} m; exact C={ex['C']:.4f} "
                f"{ex['force_N']:.4g} N; paper C=1.6 {paper:.4g} N"
            )
        print(
            f"residual dent on the axis {summary['residual_depth_on_axis_m']:.4g} m; "
            f"{summary['steps']} steps in {summary['wall_time_s']:.1f} s; outputs in {out}"
        )
    return 0 if math.isfinite(summary["max_force_N"]) else 1
