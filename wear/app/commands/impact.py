"""``impactwear impact``: simulate one oblique impact (H-DD model) and print the results.

With no arguments it runs the default case of ``impactwear impact --print-default`` (an alumina ball, R 2.5 mm, on
soda-lime glass at 3.9 m/s, 30° from the normal, μ = 0.092; Kharaz, Gorham & Salman 2001). ``--config CASE.toml``
reads a case file (any case file: the tables ``[ball]``, ``[plate]``, ``[impact]`` are read); the options below
override single keys; ``--set table.key=value`` overrides any key.
"""

from __future__ import annotations

import argparse
import math

from contact import simulate_impact
from wear.app.commands.common import add_case_options, case_from_args, case_json, print_default, print_json
from wear.case import Case
from wear.case.choices import NORMAL_MODELS, SCHEMES, TANGENTIAL_MODELS

HELP = "simulate one oblique ball-on-plate impact (H-DD model) and print rebound, forces and timings"


def _one_of(choices: tuple[str, ...]) -> str:
    """The case schema's choices as help text: "a, b or c"."""
    return f"{', '.join(choices[:-1])} or {choices[-1]}"


# option -> case key (values are checked by the case schema, so errors name the key)
_OPTIONS = {
    "radius": ("ball.radius", float, "ball radius (m)"),
    "speed": ("impact.speed", float, "impact speed (m/s)"),
    "angle": ("impact.angle", float, "impact angle from the plate normal (deg)"),
    "friction": ("impact.friction", float, "Coulomb friction coefficient"),
    "restitution": ("impact.restitution", float, "normal restitution setting the Hertz dashpot"),
    "normal_model": ("impact.normal_model", str, _one_of(NORMAL_MODELS)),
    "tangential_model": ("impact.tangential_model", str, _one_of(TANGENTIAL_MODELS)),
    "limiting_pressure": ("impact.limiting_pressure", float, "Thornton limiting pressure (Pa)"),
    "scheme": ("impact.scheme", str, _one_of(SCHEMES)),
    "time_step": ("impact.time_step", float, "time step (s); default Hertz contact time / 2000"),
}

# (label, attribute, unit, scale) rows of the human-readable table
_ROWS = (
    ("normal restitution", "normal_restitution", "", 1.0),
    ("tangential restitution", "tangential_restitution", "", 1.0),
    ("rebound angle (centre)", "rebound_angle", "deg", 1.0),
    ("rebound angle (contact point)", "contact_point_rebound_angle", "deg", 1.0),
    ("spin after impact", "spin", "rad/s", 1.0),
    ("contact time", "contact_time", "us", 1e6),
    ("sliding time", "sliding_time", "us", 1e6),
    ("max normal force", "max_force", "N", 1.0),
    ("max tangential force", "max_tangential_force", "N", 1.0),
    ("max overlap", "max_overlap", "um", 1e6),
    ("max contact radius", "max_contact_radius", "um", 1e6),
    ("max peak pressure", "max_peak_pressure", "MPa", 1e-6),
    ("kinetic energy in", "energy_in", "mJ", 1e3),
    ("kinetic energy out", "energy_out", "mJ", 1e3),
    ("normal work (dissipated)", "normal_work", "mJ", 1e3),
    ("friction work", "friction_work", "mJ", 1e3),
    ("time step", "time_step", "ns", 1e9),
    ("steps in contact", "steps", "", 1.0),
)


def configure(parser: argparse.ArgumentParser) -> None:
    add_case_options(parser, "impact", flag=True)
    for name, (key, kind, doc) in _OPTIONS.items():
        parser.add_argument(f"--{name.replace('_', '-')}", dest=name, type=kind, metavar="X", help=f"{doc} [{key}]")
    parser.add_argument("--json", action="store_true", help="print JSON (case and results) instead of a table")


def build_case(args: argparse.Namespace) -> Case:
    """The checked case from ``--config``, the named options and ``--set`` (in that order of precedence)."""
    named: dict[str, dict[str, object]] = {}
    for name, (key, _kind, _doc) in _OPTIONS.items():
        value = getattr(args, name, None)
        if value is not None:
            table, _, k = key.partition(".")
            named.setdefault(table, {})[k] = value
    return case_from_args(args, "impact", named)


def main(args: argparse.Namespace) -> int:
    case = build_case(args)
    if args.print_default:
        return print_default(args, "impact", case)
    result = simulate_impact(**case.impact_arguments(), history=False)
    if args.json:
        print_json({"case": case_json(case, "impact"), "result": result.to_dict()})
        return 0
    ball, plate, imp = case.ball, case.plate, case.impact
    plate_text = "rigid" if plate.rigid else f"{plate.name} (E {plate.E / 1e9:g} GPa, nu {plate.nu:g})"
    print(
        f"impact: {ball.name} ball R {ball.radius * 1e3:g} mm (E {ball.E / 1e9:g} GPa, nu {ball.nu:g}) on {plate_text}"
    )
    print(
        f"        {imp.speed:g} m/s at {imp.angle:g} deg from the normal, mu {imp.friction:g}, "
        f"e {imp.restitution:g}, {imp.normal_model} / {imp.tangential_model}, {imp.scheme} scheme"
    )
    width = max(len(r[0]) for r in _ROWS)
    for label, attr, unit, scale in _ROWS:
        value = getattr(result, attr)
        text = "n/a" if isinstance(value, float) and math.isnan(value) else f"{value * scale:.6g}"
        print(f"  {label:<{width}}  {text:>12} {unit}")
    return 0
