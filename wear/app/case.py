"""Case files: a declarative schema of TOML tables and keys, TOML ⇄ case, and the embedded default case.

A case is a ``dict`` of tables (``{"ball": {...}, "plate": {...}, "impact": {...}}``), every key present
(defaults filled in) and checked. The schema maps table → key → :class:`Key` (type, default, valid range,
units, doc). Other stages add their tables with :func:`register_table` (e.g. ``[wear]``, ``[fem]``,
``[output]``); loading, checking, rendering and the CLI overrides then work for them unchanged.

Errors are one line naming the key, e.g. ``impact.angle=120 is out of range: impact angle from the plate
normal must be in [0, 90) deg``. Unknown tables and keys are rejected. SI units throughout.

The default case (every default below) is the Kharaz, Gorham & Salman (2001) experiment as used by
Chung & Ooi (2011): an alumina ball (R = 2.5 mm) on a soda-lime glass plate at 3.9 m/s, 30° from the
normal, μ = 0.092.
"""

from __future__ import annotations

import math
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from contact.validation import check_bool, check_choice, check_number, fmt_value

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

__all__ = [
    "Key",
    "SCHEMA",
    "register_table",
    "default_case",
    "check_case",
    "parse_case",
    "load_case",
    "dump_case",
    "write_case",
    "set_value",
    "apply_override",
    "render_defaults",
    "impact_arguments",
]


@dataclass(frozen=True)
class Key:
    """One key of a case table: ``type`` (float, int, str or bool), ``default`` (None = optional, absent),
    valid range ``[low, high]`` (open ends with ``low_open``/``high_open``; ``allow_inf`` accepts +inf),
    ``choices`` for strings, ``units`` (SI) and a one-line ``doc`` (what the quantity is)."""

    type: type
    default: Any
    doc: str
    units: str = ""
    low: float | None = None
    high: float | None = None
    low_open: bool = False
    high_open: bool = False
    allow_inf: bool = False
    choices: tuple[str, ...] = ()

    def check(self, name: str, value: Any) -> Any:
        """Return the checked ``value`` of key ``name`` ("table.key"), or raise a one-line ValueError."""
        if self.type is bool:
            return check_bool(name, value)
        if self.type is str:
            if self.choices:
                return check_choice(name, value, self.choices)
            if not isinstance(value, str):
                raise ValueError(f"{name}={fmt_value(value)} is not a string: {self.doc}")
            return value
        if self.type is int:
            if isinstance(value, bool) or not isinstance(value, int):
                raise ValueError(f"{name}={fmt_value(value)} is not an integer: {self.doc} must be an integer")
        x = check_number(
            name,
            value,
            low=self.low,
            high=self.high,
            low_open=self.low_open,
            high_open=self.high_open,
            units=self.units,
            what=self.doc,
            allow_inf=self.allow_inf,
        )
        return int(x) if self.type is int else x


_MATERIAL = {
    "E": dict(type=float, doc="Young's modulus", units="Pa", low=1e5, high=1e13, allow_inf=True),
    "nu": dict(type=float, doc="Poisson's ratio", low=0.0, high=0.5, high_open=True),
    "density": dict(type=float, doc="density", units="kg/m^3", low=0.0, low_open=True, high=1e5),
    "yield_strength": dict(type=float, doc="yield strength (absent: never yields)", units="Pa", low=1e3, high=1e11),
}

#: table -> key -> Key. Extend with :func:`register_table`, never by editing other stages' tables.
SCHEMA: dict[str, dict[str, Key]] = {
    "ball": {
        "radius": Key(float, 2.5e-3, "ball radius", "m", low=0.0, low_open=True, high=10.0),
        "E": Key(default=380e9, **_MATERIAL["E"]),
        "nu": Key(default=0.23, **_MATERIAL["nu"]),
        "density": Key(default=4000.0, **_MATERIAL["density"]),
        "yield_strength": Key(default=None, **_MATERIAL["yield_strength"]),
        "name": Key(str, "alumina", "label of the ball material"),
    },
    "plate": {
        "rigid": Key(bool, False, "rigid plate (E, nu, density ignored)"),
        "E": Key(default=70e9, **_MATERIAL["E"]),
        "nu": Key(default=0.25, **_MATERIAL["nu"]),
        "density": Key(default=2500.0, **_MATERIAL["density"]),
        "yield_strength": Key(default=None, **_MATERIAL["yield_strength"]),
        "name": Key(str, "soda-lime glass", "label of the plate material"),
    },
    "impact": {
        "speed": Key(float, 3.9, "impact speed", "m/s", low=0.0, low_open=True, high=1000.0),
        "angle": Key(float, 30.0, "impact angle from the plate normal", "deg", low=0.0, high=90.0, high_open=True),
        "friction": Key(float, 0.092, "Coulomb friction coefficient", low=0.0, high=10.0),
        "restitution": Key(
            float, 1.0, "normal restitution setting the Hertz dashpot", low=0.0, low_open=True, high=1.0
        ),
        "normal_model": Key(str, "hertz", "normal force law", choices=("hertz", "thornton")),
        "tangential_model": Key(str, "hdd", "tangential force law", choices=("hdd", "mindlin")),
        "limiting_pressure": Key(float, None, "Thornton limiting pressure (absent: C(nu)*Y)", "Pa", low=1e3, high=1e12),
        "scheme": Key(str, "verlet", "time integration scheme", choices=("verlet", "paper")),
        "time_step": Key(float, None, "time step (absent: Hertz contact time / 2000)", "s", low=0.0, low_open=True),
    },
}


def register_table(table: str, keys: dict[str, Key]) -> None:
    """Add a table to :data:`SCHEMA` (idempotent for the same keys; a different redefinition is an error)."""
    if table in SCHEMA and SCHEMA[table] != keys:
        raise ValueError(f"case table [{table}] is already registered with other keys")
    SCHEMA[table] = dict(keys)


def default_case() -> dict[str, dict[str, Any]]:
    """The embedded default case (a fresh copy; absent optional keys are None)."""
    return {table: {k: key.default for k, key in keys.items()} for table, keys in SCHEMA.items()}


def check_case(data: dict[str, Any]) -> dict[str, dict[str, Any]]:
    """Check a (partial) case dict against the schema and fill in the defaults; raises a one-line ValueError."""
    if not isinstance(data, dict):
        raise ValueError(f"case={fmt_value(data)} is not a table of tables")
    case = default_case()
    for table, values in data.items():
        if table not in SCHEMA:
            raise ValueError(f"[{table}] is not a known case table: known tables are {', '.join(SCHEMA)}")
        if not isinstance(values, dict):
            raise ValueError(f"{table}={fmt_value(values)} is not a table: write it as [{table}]")
        for name, value in values.items():
            set_value(case, f"{table}.{name}", value)
    return case


def set_value(case: dict[str, dict[str, Any]], dotted: str, value: Any) -> None:
    """Set ``case[table][key]`` from ``"table.key"`` after checking ``value`` against the schema."""
    table, _, name = dotted.partition(".")
    if table not in SCHEMA:
        raise ValueError(f"[{table}] is not a known case table: known tables are {', '.join(SCHEMA)}")
    if name not in SCHEMA[table]:
        raise ValueError(f"{dotted} is not a known key: keys of [{table}] are {', '.join(SCHEMA[table])}")
    key = SCHEMA[table][name]
    # None (absent) is allowed for optional keys only: a Python-built case may carry it; TOML cannot
    case[table][name] = None if value is None and key.default is None else key.check(dotted, value)


def apply_override(case: dict[str, dict[str, Any]], item: str) -> None:
    """Apply one command-line ``--set TABLE.KEY=VALUE`` to ``case``.

    VALUE is read as TOML (``3.9``, ``true``, ``"x"``); a bare word that is not TOML is taken as a string
    (``--set impact.normal_model=thornton``). The value is checked against the schema.
    """
    dotted, sep, text = item.partition("=")
    if not sep:
        raise ValueError(f"--set {item!r} is not TABLE.KEY=VALUE")
    try:
        value = tomllib.loads(f"v = {text}")["v"]
    except tomllib.TOMLDecodeError:
        value = text
    set_value(case, dotted.strip(), value)


def parse_case(text: str, source: str = "case") -> dict[str, dict[str, Any]]:
    """Parse TOML text into a checked case (``source`` names it in errors)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"config={source!r} is not valid TOML: {exc}") from None
    return check_case(data)


def load_case(path: str | os.PathLike) -> dict[str, dict[str, Any]]:
    """Read and check a TOML case file."""
    p = Path(path)
    if not p.is_file():
        raise ValueError(f"config={str(p)!r} is not a file")
    return parse_case(p.read_text(encoding="utf-8"), str(p))


def _toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(value, float):
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        text = repr(value)
        if value != 0.0 and not 1e-3 <= abs(value) < 1e6 and "e" not in text:
            mantissa, exponent = f"{value:.15e}".split("e")
            text = f"{mantissa.rstrip('0').rstrip('.')}e{int(exponent)}"  # 3.8e11, not 380000000000.0
        return text
    return str(value)


def dump_case(case: dict[str, dict[str, Any]], comments: bool = False) -> str:
    """TOML text of a case (optional keys that are None are left out; with ``comments``, documented)."""
    lines: list[str] = []
    for table, values in case.items():
        lines.append(f"[{table}]")
        for name, value in values.items():
            key = SCHEMA[table][name]
            note = ""
            if comments:
                rng = ""
                if key.choices:
                    rng = " one of " + ", ".join(key.choices)
                elif key.low is not None or key.high is not None:
                    lo = "(" if key.low_open else "["
                    hi = ")" if key.high_open else "]"
                    low = f"{key.low:g}" if key.low is not None else "-inf"
                    high = f"{key.high:g}" if key.high is not None else "inf"
                    rng = f" in {lo}{low}, {high}{hi}"
                note = f"  # {key.doc}{rng}{' ' + key.units if key.units else ''}"
            if value is None:
                if comments:
                    lines.append(f"# {name} ={note[1:]}")
                continue
            lines.append(f"{name} = {_toml_value(value)}{note}")
        lines.append("")
    return "\n".join(lines)


def write_case(path: str | os.PathLike, case: dict[str, dict[str, Any]]) -> None:
    """Write a case as TOML atomically (temporary file in the same folder, then ``os.replace``)."""
    p = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{p.name}.", dir=p.parent or ".")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(dump_case(case, comments=True))
        os.replace(tmp, p)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def render_defaults(tables: list[str] | None = None) -> str:
    """Markdown table of every key (table, key, default, valid range, units, meaning) for the README."""
    rows = ["| key | default | valid | units | meaning |", "|---|---|---|---|---|"]
    for table in tables or list(SCHEMA):
        for name, key in SCHEMA[table].items():
            if key.choices:
                valid = " / ".join(key.choices)
            elif key.type is bool:
                valid = "true / false"
            elif key.low is not None or key.high is not None:
                lo = "(" if key.low_open else "["
                hi = ")" if key.high_open else "]"
                low = f"{key.low:g}" if key.low is not None else "−∞"
                high = f"{key.high:g}" if key.high is not None else "∞"
                valid = f"{lo}{low}, {high}{hi}"
                if key.allow_inf:
                    valid += " or inf"
            else:
                valid = "text"
            default = "(absent)" if key.default is None else _toml_value(key.default)
            rows.append(f"| `{table}.{name}` | {default} | {valid} | {key.units} | {key.doc} |")
    return "\n".join(rows)


def impact_arguments(case: dict[str, dict[str, Any]]) -> dict[str, Any]:
    """Keyword arguments of :func:`contact.simulate_impact` for a checked case."""
    from contact import Material

    def material(table: str) -> Material:
        t = case[table]
        if t.get("rigid"):
            return Material.rigid(name=t["name"])
        try:
            return Material(
                E=t["E"], nu=t["nu"], density=t["density"], yield_strength=t["yield_strength"], name=t["name"]
            )
        except ValueError as exc:
            raise ValueError(f"{table}.{exc}") from None

    imp = case["impact"]
    return dict(
        radius=case["ball"]["radius"],
        ball=material("ball"),
        plate=material("plate"),
        speed=imp["speed"],
        angle=imp["angle"],
        friction=imp["friction"],
        restitution=imp["restitution"],
        normal_model=imp["normal_model"],
        tangential_model=imp["tangential_model"],
        limiting_pressure=imp["limiting_pressure"],
        scheme=imp["scheme"],
        time_step=imp["time_step"],
    )
