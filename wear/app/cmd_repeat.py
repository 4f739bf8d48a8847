"""``impactwear repeat [CASE.toml] --impacts N [--out DIR] [--quiet] [--json]``: N impacts at one site.

The case is a run case (``impactwear run``'s tables ``[ball]``, ``[plate]``, ``[impact]``, ``[wear]``, ``[fem]``,
``[output]``; with no CASE the embedded default run case) plus an optional ``[repeat]`` table (below);
``--impacts`` overrides ``repeat.impacts``. See :mod:`wear.repeat` for the physics (plate state kept, dented and
worn surface, shakedown, cycle jump). Output folder (written atomically, see :mod:`wear.app.outputs`):

- ``repeat.csv``: one row per computed impact or cycle-jump block (columns with units, see
  :data:`wear.repeat_records.CSV_COLUMNS`); ``summary.json`` (case, [repeat], results, notes, wall time, and
  ``halfspace_check``: the last pressure against the half-space solution, :mod:`wear.repeat_check`);
- ``repeat.pvd`` + ``frames/plate_NNNNNN.vtu``: the FE mesh after each saved computed impact (time = impact
  number; point data ``u``, ``wear_depth``, ``surface``; cell data ``equivalent_plastic_strain``, ``von_mises``);
- ``wear_map.npz``: the cumulative 2-D wear map (``x``, ``y``, ``depth``, m); ``repeat.png`` (with
  ``output.figures``): dent, wear, restitution, pressure and Δᾱ against the impact number.
"""

from __future__ import annotations

import argparse
import json
import sys
import warnings
from dataclasses import fields

from . import case as case_module
from .case import Key

HELP = "N impacts of the same ball at one site on the plate the previous ones left: dent, wear, shakedown"

DEFAULT_OUT = "impactwear-repeat"


def _repeat_table() -> dict[str, Key]:
    from wear.repeat import RepeatSpec

    d = {f.name: f.default for f in fields(RepeatSpec)}
    return {
        "impacts": Key(int, d["impacts"], "number of impacts at the site", low=1, high=1e9),
        "geometry_update": Key(bool, d["geometry_update"], "the wear of each impact moves the FE surface nodes"),
        "shakedown_tolerance": Key(float, d["shakedown_tolerance"],
                                   "largest plastic strain increment of a shaken-down impact, over Y/E", low=0.0,
                                   low_open=True, high=1.0),
        "surface_fraction": Key(float, d["surface_fraction"],
                                "surface change per cycle-jump block, fraction of the impact's approach (max "
                                "overlap from first contact)",
                                low=0.0, low_open=True, high=1.0),
        "max_plastic_impacts": Key(int, d["max_plastic_impacts"],
                                   "impacts computed one by one before blocks go on without shakedown", low=1,
                                   high=100000),
        "save_every": Key(int, d["save_every"], "save the FE mesh of every k-th computed impact (0 = none)", low=0,
                          high=1e9),
        "wear_smoothing": Key(float, d["wear_smoothing"],
                              "width of the filter of the wear profile on the FE surface, fraction of the contact "
                              "radius (0 = off)", low=0.0, high=1.0),
        "elastic_after_shakedown": Key(bool, d["elastic_after_shakedown"],
                                       "after a shaken-down impact, solve the next on the plate's elastic response "
                                       "unless its elastic field yields"),
    }  # fmt: skip


case_module.register_table("repeat", _repeat_table())


def load_repeat_case(path=None, impacts: str | int | None = None):
    """(Case, RepeatSpec, checked [repeat] table) from a TOML case file (None = the embedded default run case)."""
    from pathlib import Path

    from wear.pipeline import Case
    from wear.repeat import RepeatSpec

    from .run_case import REQUIRED_TABLES, RUN_TABLES, default_run_text

    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10
        import tomli as tomllib

    if path is None:
        text, source = default_run_text(), "default"
    else:
        p = Path(path)
        if not p.is_file():
            raise ValueError(f"case={str(p)!r} is not a file")
        try:
            text, source = p.read_text(encoding="utf-8"), str(p)
        except UnicodeDecodeError:
            raise ValueError(f"case={str(p)!r} is not a UTF-8 text (TOML) file") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"case={source!r} is not valid TOML: {exc}") from None
    for table in data:
        if table not in RUN_TABLES + ("repeat",):
            raise ValueError(f"[{table}] is not a repeat case table: the tables are {', '.join(RUN_TABLES)}, repeat")
    for table in REQUIRED_TABLES:
        if table not in data:
            raise ValueError(f"[{table}] is missing from case={source!r}: a repeat case needs "
                             f"{', '.join(f'[{t}]' for t in REQUIRED_TABLES)}")  # fmt: skip
    checked = case_module.check_case(data)
    if impacts is not None:
        case_module.set_value(checked, "repeat.impacts", _integer("impacts", impacts))
    case = Case.from_dict({table: checked[table] for table in RUN_TABLES})
    return case, RepeatSpec(**checked["repeat"]), checked["repeat"]


def _integer(name: str, text) -> int:
    if isinstance(text, int):
        return text
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"--{name}={text!r} is not a number: the number of impacts must be an integer in "
                         "[1, 1e9]") from None  # fmt: skip
    if not value.is_integer():
        raise ValueError(f"--{name}={text} is not an integer: the number of impacts must be an integer in [1, 1e9]")
    return int(value)


def configure(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("case", nargs="?", metavar="CASE.toml", help="run case file with an optional [repeat] table "
                        "(default: the embedded run case)")  # fmt: skip
    parser.add_argument("--impacts", metavar="N", help="number of impacts (overrides repeat.impacts)")
    parser.add_argument("--out", default=DEFAULT_OUT, metavar="DIR", help=f"output folder (default: {DEFAULT_OUT})")
    parser.add_argument("--quiet", action="store_true", help="no progress bar and no table")
    parser.add_argument("--json", action="store_true", help="print summary.json to stdout instead of a table")


def _table(summary: dict, out: str) -> str:
    first, last = summary["first_impact"], summary["last_computed_impact"]
    after = summary["after_last_impact"]
    check = summary["halfspace_check"]
    rows = [
        ("impacts (computed; of them elastic)",
         f"{summary['impacts']} ({summary['computed_impacts']}; {summary['elastic_computed_impacts']})", ""),
        ("shakedown at impact", str(summary["shakedown_impact"]), ""),
        ("normal restitution first / last computed", f"{first['normal_restitution']:.4g} / "
                                                      f"{last['normal_restitution']:.4g}", ""),
        ("max pressure first / last computed", f"{first['max_pressure'] / 1e9:.4g} / "
                                                f"{last['max_pressure'] / 1e9:.4g}", "GPa"),
        ("last computed: max pressure FE / half-space",
         f"{check['fe_max_pressure_Pa'] / 1e9:.4g} / {check['halfspace_max_pressure_Pa'] / 1e9:.4g}", "GPa"),
        ("dent depth after the last impact", f"{after['dent_depth_m'] * 1e6:.4g}", "um"),
        ("wear: max depth / volume", f"{after['total_wear_max_depth_m'] * 1e6:.4g} um / "
                                     f"{after['total_wear_volume_m3']:.4g}", "m^3"),
        ("wall time", f"{summary['wall_time_s']:.1f}", "s"),
    ]  # fmt: skip
    width = max(len(r[0]) for r in rows)
    lines = [f"{label:<{width}}  {value} {unit}".rstrip() for label, value, unit in rows]
    lines.append(f"output: {out}")
    return "\n".join(lines)


def main(args: argparse.Namespace) -> int:
    case, spec, table = load_repeat_case(args.case, args.impacts)  # bad input raises here, before any output

    from wear.repeat import repeat
    from wear.repeat_check import halfspace_check

    from .cmd_erode import write_pvd
    from .outputs import atomic_output_dir, to_jsonable, versions, write_csv, write_json, write_npz

    show = not args.quiet and sys.stderr.isatty()
    bar = None
    if show:
        from tqdm import tqdm

        bar = tqdm(total=spec.impacts, desc="impactwear repeat", unit="impact", file=sys.stderr, leave=False)

    def progress(done: int, total: int) -> None:
        if bar is not None:
            bar.update(done - bar.n)

    try:
        with atomic_output_dir(args.out) as out, warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            frames = out / "frames"
            frames.mkdir()
            entries: list[tuple[float, str]] = []
            saved = [0]

            def on_computed(impact: int, plate) -> None:
                saved[0] += 1
                if spec.save_every and (saved[0] == 1 or saved[0] % spec.save_every == 0):
                    name = f"frames/plate_{impact:06d}.vtu"
                    plate.write(out / name)
                    entries.append((float(impact), name))

            result = repeat(case, spec, progress=progress, on_computed=on_computed)
            if spec.save_every and (not entries or entries[-1][0] != result.records[-1].last):
                name = f"frames/plate_{result.records[-1].last:06d}.vtu"
                result.plate.write(out / name)
                entries.append((float(result.records[-1].last), name))
            if entries:
                write_pvd(out / "repeat.pvd", entries)
            columns = result.columns()
            write_csv(out / "repeat.csv", columns)
            wm = result.wear
            write_npz(out / "wear_map.npz", {"x": wm.x, "y": wm.y, "depth": wm.depth})
            summary = {"case": case.to_dict(), "repeat": table, "versions": versions(), **result.summary()}
            summary["halfspace_check"] = halfspace_check(result)
            notes = list(dict.fromkeys(str(w.message) for w in caught)) + list(result.notes)
            summary["notes"] = notes
            write_json(out / "summary.json", summary)
            if case.output.figures:
                from .figures.repeat import plot_repeat

                tol = summary["shakedown_tolerance_strain"]
                plot_repeat(columns, out / "repeat.png", title=f"{spec.impacts} impacts at one site",
                            shakedown_impact=result.shakedown_impact, tolerance=tol)  # fmt: skip
    finally:
        if bar is not None:
            bar.close()
    for note in notes:
        print(f"impactwear repeat: note: {note}", file=sys.stderr)
    if args.json:
        print(json.dumps(to_jsonable(summary), indent=2))
    elif not args.quiet:
        print(_table(summary, args.out))
    return 0
