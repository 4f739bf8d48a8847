"""Sweep files (``SWEEP.toml``): parsing, expansion into validated cases, stable case ids.

A sweep file has three parts::

    [sweep]
    stage = "impact"                 # a stage of wear.app.sweep.stages.STAGES: "impact", "indent", "run", ...

    [base]                           # optional: a case, same tables as a case file; keys left out take
    impact.speed = 3.9               # the stage's default case's values (see wear.app.sweep.stages)

    [grid]                           # dotted keys to lists: the Cartesian product, first key slowest
    "impact.angle" = [10, 30, 50]
    "plate.E" = [70e9, 210e9]

or, instead of ``[grid]``, an explicit list::

    [[cases]]
    impact.angle = 10
    [[cases]]
    impact.angle = 40
    impact.speed = 2.0

Every expanded case is validated through the case schema (:mod:`wear.case`) before anything runs; a bad
file raises ``ValueError`` with one line naming the key (the CLI turns it into exit status 2).

The case id is the first 16 hex digits of the SHA-256 of the canonical JSON of ``{"stage", "case"}``, where
``case`` holds only the tables the stage reads (so adding, say, a ``[wear]`` key to the schema does not
invalidate finished ``impact`` sweeps). Canonical means: keys sorted, integers written as floats (``30`` and
``30.0`` are the same input), ``-0.0`` as ``0.0``, floats in shortest round-trip form. It depends neither on dict
order nor on the Python hash seed.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from wear.app.sweep.stages import STAGES, check_stage_case
from wear.case import read_toml, read_toml_text

__all__ = ["SweepSpec", "SweepCase", "load_sweep", "parse_sweep", "case_id", "flatten", "MAX_CASES"]

#: A sweep larger than this is almost certainly a typo (and its manifest would not fit in memory comfortably).
MAX_CASES = 100_000

_TOP_LEVEL = ("sweep", "base", "grid", "cases")
_SWEEP_KEYS = ("stage", "description")


@dataclass(frozen=True)
class SweepCase:
    """One expanded case: ``case_id``, the full validated ``case`` restricted to the stage's tables (nested dict
    of JSON values, SI units) and ``inputs``, the swept keys and their values (dotted key → value)."""

    case_id: str
    case: dict
    inputs: dict


@dataclass(frozen=True)
class SweepSpec:
    """A parsed sweep: ``stage`` name, ``cases`` in expansion order, ``axes`` (dotted key → list of values) for a
    ``[grid]`` sweep (``None`` for ``[[cases]]``), ``description`` and the ``source`` text it came from."""

    stage: str
    cases: tuple[SweepCase, ...]
    axes: dict | None
    description: str = ""
    source: str = ""

    @property
    def swept_keys(self) -> list[str]:
        """Dotted keys that vary across cases, in first-seen order."""
        keys: dict[str, None] = {}
        for c in self.cases:
            keys.update(dict.fromkeys(c.inputs))
        return list(keys)


def flatten(table: Mapping, prefix: str = "") -> dict[str, Any]:
    """Nested dict → ``{"table.key": value}`` (TOML dotted keys and quoted keys with dots give the same result)."""
    out: dict[str, Any] = {}
    for key, value in table.items():
        name = f"{prefix}{key}"
        if isinstance(value, Mapping):
            out.update(flatten(value, f"{name}."))
        else:
            out[name] = value
    return out


def _nest(flat: Mapping[str, Any], where: str) -> dict:
    """``{"a.b": 1}`` → ``{"a": {"b": 1}}``; a key that is both a value and a table is an error."""
    root: dict = {}
    for dotted, value in flat.items():
        parts = dotted.split(".")
        if any(not p for p in parts):
            raise ValueError(f"{where}{dotted!r} is not a valid key: write table.key, e.g. 'impact.angle'")
        node = root
        for i, part in enumerate(parts[:-1]):
            nxt = node.setdefault(part, {})
            if not isinstance(nxt, dict):
                raise ValueError(f"{where}{'.'.join(parts[: i + 1])} is given both as a value and as a table")
            node = nxt
        if isinstance(node.get(parts[-1]), dict):
            raise ValueError(f"{where}{dotted} is given both as a value and as a table")
        node[parts[-1]] = value
    return root


def _merge(base: Mapping, override: Mapping) -> dict:
    """Deep merge: ``override``'s values replace ``base``'s key by key (tables merged, not replaced)."""
    out = {k: (_merge(v, {}) if isinstance(v, Mapping) else v) for k, v in base.items()}
    for key, value in override.items():
        if isinstance(value, Mapping) and isinstance(out.get(key), Mapping):
            out[key] = _merge(out[key], value)
        else:
            out[key] = _merge(value, {}) if isinstance(value, Mapping) else value
    return out


def _canonical(value: Any) -> Any:
    """JSON-ready value whose text is the same for equal inputs (ints as floats, -0.0 as 0.0)."""
    if isinstance(value, Mapping):
        return {str(k): _canonical(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_canonical(v) for v in value]
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, (int, float)):
        x = float(value)
        return 0.0 if x == 0.0 else x
    if hasattr(value, "item"):  # numpy scalar
        return _canonical(value.item())
    raise ValueError(f"value {value!r} of type {type(value).__name__} cannot be part of a case")


def canonical_json(value: Any) -> str:
    """The canonical text hashed by :func:`case_id` (sorted keys, no spaces, infinities as ``Infinity``)."""
    return json.dumps(_canonical(value), sort_keys=True, separators=(",", ":"), allow_nan=True)


def case_id(stage: str, case: Mapping) -> str:
    """Stable id of ``case`` run by ``stage``: 16 hex digits of SHA-256 of the canonical JSON (see module doc)."""
    text = canonical_json({"stage": stage, "case": case})
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


def _check_table(name: str, value: Any) -> dict:
    if not isinstance(value, Mapping):
        raise ValueError(f"{name} must be a table ([{name}]), got {type(value).__name__}")
    return dict(value)


def _value_text(value: Any) -> str:
    """A value as the user wrote it (TOML-like JSON), for messages and labels."""
    return json.dumps(value, allow_nan=True, default=str)


def _expand_grid(grid: Mapping) -> tuple[dict[str, list], list[dict[str, Any]]]:
    """``[grid]`` → (axes, list of flat overrides) in Cartesian order, first axis slowest."""
    axes: dict[str, list] = {}
    for key, values in flatten(grid).items():
        where = f"grid.{key}"
        if not isinstance(values, list):
            raise ValueError(f"{where}={_value_text(values)} is not a list: give the values to sweep, e.g. [10, 30]")
        if not values:
            raise ValueError(f"{where}=[] is empty: give at least one value")
        seen: dict[str, int] = {}
        for i, v in enumerate(values):
            text = canonical_json(v)
            if text in seen:
                raise ValueError(f"{where}[{i}]={_value_text(v)} repeats {where}[{seen[text]}]: each value once")
            seen[text] = i
        axes[key] = list(values)
    if not axes:
        raise ValueError('grid is empty: give at least one dotted key with a list, e.g. "impact.angle" = [10, 30]')
    size = math.prod(len(v) for v in axes.values())
    if size > MAX_CASES:
        raise ValueError(f"grid expands to {size} cases: at most {MAX_CASES} per sweep file")
    overrides = [dict(zip(axes, combo, strict=True)) for combo in itertools.product(*axes.values())]
    return axes, overrides


def _explicit_cases(cases: Any) -> list[dict[str, Any]]:
    if not isinstance(cases, list) or not cases:
        raise ValueError("cases must be a non-empty array of tables: write [[cases]] blocks")
    if len(cases) > MAX_CASES:
        raise ValueError(f"cases has {len(cases)} entries: at most {MAX_CASES} per sweep file")
    out = []
    for i, entry in enumerate(cases):
        if not isinstance(entry, Mapping):
            raise ValueError(f"cases[{i}] is a {type(entry).__name__}: each entry must be a table ([[cases]])")
        if not entry:
            raise ValueError(f"cases[{i}] is empty: give the keys that differ from [base]")
        out.append(flatten(entry))
    return out


def _validated(stage: str, merged: dict) -> dict:
    """Full, validated, normalised case (tables of values) restricted to the stage's tables."""
    st = STAGES[stage]
    # checked as the stage's function will check it (e.g. indent's plate model, the wall's files), before any work
    return check_stage_case(stage, merged, st.job).to_dict(st.tables)


def _blame(stage: str, base: dict, exc: ValueError, label: str) -> str:
    """Where an invalid case's error comes from: ``base`` if the base alone fails the same way, else ``label``."""
    try:
        _validated(stage, _merge(base, {}))
    except ValueError as base_exc:
        if str(base_exc) == str(exc):
            return "base"
    return label


def parse_sweep(data: Mapping, *, source: str = "") -> SweepSpec:
    """Parse a sweep given as a dict (the TOML document); see the module doc. Raises ``ValueError``."""
    unknown = [k for k in data if k not in _TOP_LEVEL]
    if unknown:
        raise ValueError(f"{unknown[0]}: unknown table: a sweep file has [sweep], [base], and [grid] or [[cases]]")
    if "sweep" not in data:
        raise ValueError(f"sweep: missing table [sweep] with stage = one of {', '.join(map(repr, STAGES))}")
    head = _check_table("sweep", data["sweep"])
    for key in head:
        if key not in _SWEEP_KEYS:
            raise ValueError(f"sweep.{key}: unknown key: [sweep] takes {', '.join(_SWEEP_KEYS)}")
    if "stage" not in head:
        raise ValueError(f"sweep.stage: missing: give stage = one of {', '.join(map(repr, STAGES))}")
    stage = head["stage"]
    if not isinstance(stage, str) or stage not in STAGES:
        listed = ", ".join(repr(s) for s in STAGES)
        raise ValueError(f"sweep.stage={_value_text(stage)} is not a valid choice: must be one of {listed}")
    description = head.get("description", "")
    if not isinstance(description, str):
        raise ValueError(f"sweep.description={_value_text(description)} is not a string")
    base = _merge(STAGES[stage].defaults(), _check_table("base", data.get("base", {})))
    if ("grid" in data) == ("cases" in data):
        raise ValueError("grid/cases: give exactly one of [grid] (a Cartesian product) or [[cases]] (a list)")
    if "grid" in data:
        axes, overrides = _expand_grid(_check_table("grid", data["grid"]))
        labels = [
            f"grid case {i} ({', '.join(f'{k}={_value_text(v)}' for k, v in o.items())})"
            for i, o in enumerate(overrides)
        ]
    else:
        axes, overrides = None, _explicit_cases(data["cases"])
        labels = [f"cases[{i}]" for i in range(len(overrides))]

    tables = STAGES[stage].tables
    for flat, label in zip(overrides, labels, strict=True):
        for key in flat:
            if tables is not None and key.split(".")[0] not in tables:
                where = f"grid.{key}" if axes is not None else f"{label}.{key}"
                raise ValueError(
                    f"{where}: the {stage} stage does not read [{key.split('.')[0]}]; it reads "
                    f"{', '.join(f'[{t}]' for t in tables)}"
                )
    cases: list[SweepCase] = []
    seen: dict[str, int] = {}
    for i, (flat, label) in enumerate(zip(overrides, labels, strict=True)):
        try:
            merged = _merge(base, _nest(flat, ""))
            case = _validated(stage, merged)
        except ValueError as exc:
            raise ValueError(f"{_blame(stage, base, exc, label)}: {exc}") from None
        cid = case_id(stage, case)
        if cid in seen:
            raise ValueError(f"{label} is the same case as {labels[seen[cid]]}: remove the duplicate")
        seen[cid] = i
        cases.append(SweepCase(case_id=cid, case=case, inputs=dict(flat)))
    return SweepSpec(stage=stage, cases=tuple(cases), axes=axes, description=description, source=source)


def load_sweep(path: str | Path) -> SweepSpec:
    """Read and validate a sweep file (see the module doc). Raises ``ValueError`` naming the key at fault."""
    text = read_toml_text(path, "sweep")
    return parse_sweep(read_toml(text, str(path), "sweep"), source=text)
