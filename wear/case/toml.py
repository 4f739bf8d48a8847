"""Case files: TOML ⇄ :class:`~wear.case.Case`, command-line overrides, and the key reference of the docs.

A case file holds any of the case tables (``[ball]``, ``[plate]``, ``[impact]``, ``[wear]``, ``[fem]``,
``[output]``, ``[erosion]``, ``[repeat]``); keys left out take the job's default (:mod:`wear.case.jobs`), so a
file written for one command can be given to another. Unknown tables and keys and bad values are one-line
``ValueError`` naming the key, e.g. ``impact.angle=120 is out of range: impact angle from the plate normal must be
in [0, 90) deg``. SI units throughout.
"""

from __future__ import annotations

import math
import os
import sys
from pathlib import Path
from typing import Any

from wear.case.case import Case
from wear.case.jobs import JOBS, default_case
from wear.case.schema import Key
from wear.case.tables import TABLES

if sys.version_info >= (3, 11):
    import tomllib
else:  # Python 3.10
    import tomli as tomllib

__all__ = [
    "parse_case",
    "load_case",
    "dump_case",
    "apply_override",
    "override_tables",
    "key_reference",
    "read_toml",
    "read_toml_text",
    "toml_value",
]


def parse_case(text: str, job: str = "run", source: str = "case", name: str = "case") -> Case:
    r"""The case in the TOML ``text`` laid over ``job``'s default case (``name``=``source`` names the text in
    errors).

    Examples
    --------
    The keys given replace those of the job's default case (``impactwear impact``'s here), the text written by
    :func:`dump_case` reads back as the same case, and a mistyped key or a table a job needs is named:

    >>> case = parse_case("[impact]\nspeed = 2.0  # m/s\n", job="impact")
    >>> case.impact.speed, case.impact.angle == default_case("impact").impact.angle
    (2.0, True)
    >>> parse_case(dump_case(case), job="impact") == case
    True
    >>> parse_case("[impact]\nsped = 2.0\n", job="impact")
    Traceback (most recent call last):
    ...
    ValueError: impact.sped is not a known key (did you mean impact.speed?): keys of [impact] are speed, ...
    >>> parse_case("[impact]\nspeed = 2.0\n")  # job="run"
    Traceback (most recent call last):
    ...
    ValueError: [ball] is missing from case='case': a run case needs [ball], [plate], [impact], [wear]
    """
    data = read_toml(text, source, name)
    # every key is checked before a missing table is named: a mistyped table or key would otherwise be reported
    # as the table it was meant to be
    base = default_case(job)
    tables = Case.tables_from_dict(data, base)
    for table in JOBS[job].required:
        if table not in data:
            need = ", ".join(f"[{t}]" for t in JOBS[job].required)
            raise ValueError(f"[{table}] is missing from {name}={source!r}: a {job} case needs {need}")
    return base.with_tables(tables)


def read_toml(text: str, source: str, name: str) -> dict[str, Any]:
    """The TOML ``text`` as a dict; ValueError naming ``name``=``source`` and, for a key or table given twice, that
    key (tomllib names only the line)."""
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        twice = _given_twice(text)
        if twice:
            raise ValueError(f"{name}={source!r}: {twice}; give each once") from None
        raise ValueError(f"{name}={source!r} is not valid TOML: {exc}") from None


def _given_twice(text: str) -> str:
    """What the TOML ``text`` gives twice, as ``impact.angle is given twice (lines 3 and 5)`` (``[impact] is
    declared twice`` for a table), or "" if no key or table is repeated; a plain line scan (tomllib names only the
    line, not the key)."""
    seen: dict[str, int] = {}
    table = ""
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if line.startswith("[") and not line.startswith("[["):
            table = line.strip("[] ")
            what, shown = f"[{table}]", f"[{table}] is declared"
        elif "=" in line:
            key = line.split("=", 1)[0].strip().strip("\"'")
            what = f"{table}.{key}" if table else key
            shown = f"{what} is given"
        else:
            continue
        if what in seen:
            return f"{shown} twice (lines {seen[what]} and {number})"
        seen[what] = number
    return ""


def load_case(path: str | os.PathLike | None, job: str = "run", name: str = "case") -> Case:
    r"""The case in the TOML file ``path`` (None: ``job``'s default case); ``name`` names the file in errors.

    Examples
    --------
    A case file written in a temporary folder reads back as the case it holds; no file is the job's default case:

    >>> import tempfile
    >>> from pathlib import Path
    >>> with tempfile.TemporaryDirectory() as folder:
    ...     path = Path(folder) / "case.toml"
    ...     _ = path.write_text("[impact]\nangle = 30.0  # deg\n", encoding="utf-8")
    ...     case = load_case(path, job="impact")
    >>> case == default_case("impact").with_(impact={"angle": 30.0}), load_case(None) == default_case("run")
    (True, True)
    >>> load_case("no-such-case.toml")
    Traceback (most recent call last):
    ...
    ValueError: case='no-such-case.toml': no such file
    """
    if path is None:
        return default_case(job)
    return parse_case(read_toml_text(path, name), job, str(Path(path)), name)


def read_toml_text(path: str | os.PathLike, name: str) -> str:
    """The text of the TOML file ``path``; ValueError naming ``name``=``path`` when there is no such file, it is a
    folder, or it is not UTF-8 text."""
    p = Path(path)
    shown = f"{name}={str(p)!r}"
    if not p.exists():
        raise ValueError(f"{shown}: no such file")
    if not p.is_file():
        raise ValueError(f"{shown} is not a file")
    try:
        # utf-8-sig: a byte-order mark (Notepad's and Excel's "UTF-8") is not part of the TOML, as for the CSV files
        text = p.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        text = "\x00"
    except OSError as exc:
        raise ValueError(f"{shown} cannot be read: {exc.strerror}") from None
    if "\x00" in text:  # no text file holds a NUL
        raise ValueError(f"{shown} is not a UTF-8 text (TOML) file")
    return text


def toml_value(value: Any) -> str:
    """A value as TOML text (floats in a short exponent form: ``3.8e11``, not ``380000000000.0``)."""
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
            text = f"{mantissa.rstrip('0').rstrip('.')}e{int(exponent)}"
        return text
    return str(value)


def _comment(spec: Key) -> str:
    return f"{spec.doc}; {spec.valid_range()}"


def dump_case(
    case: Case,
    tables: tuple[str, ...] | None = None,
    comments: bool = True,
    only: dict[str, tuple[str, ...]] | None = None,
) -> str:
    """TOML text of ``case`` (all tables, or ``tables``). Every key is written (of a table in ``only``, its keys
    listed there); an absent optional key is written as a comment saying what absent means, except where ``inf``
    states it (a yield strength: never yields). With ``comments`` each key carries its doc, valid range and units."""
    lines: list[str] = []
    only = only or {}
    for name, values in case.to_dict(tables).items():
        lines.append(f"[{name}]")
        for k, spec in TABLES[name].keys().items():
            if name in only and k not in only[name]:
                continue
            value = values[k]
            note = f"  # {_comment(spec)}" if comments else ""
            if value is None and spec.inf_is_absent:
                value = math.inf
            if value is None:
                lines.append(f"# {k} =  # absent: {spec.absent}; {_comment(spec)}" if comments else f"# {k} =")
            else:
                lines.append(f"{k} = {toml_value(value)}{note}")
        lines.append("")
    return "\n".join(lines)


def override_tables(items: list[str]) -> dict[str, dict[str, Any]]:
    """Command-line ``--set TABLE.KEY=VALUE`` items as tables of values (later items win). VALUE is read as TOML
    (``3.9``, ``true``, ``"x"``); a bare word that is not TOML is taken as a string (``impact.normal_model=hertz``)."""
    tables: dict[str, dict[str, Any]] = {}
    for item in items:
        dotted, sep, text = item.partition("=")
        table, dot, name = dotted.strip().partition(".")
        if not sep or not dot:
            raise ValueError(f"--set {item!r} is not TABLE.KEY=VALUE")
        try:
            value = tomllib.loads(f"v = {text}")["v"]
        except tomllib.TOMLDecodeError:
            value = text
        tables.setdefault(table, {})[name] = value
    return tables


def apply_override(case: Case, item: str) -> Case:
    """``case`` with one command-line ``--set TABLE.KEY=VALUE`` applied (:func:`override_tables`)."""
    return Case.from_dict(override_tables([item]), base=case)


def key_reference() -> str:
    """Markdown reference of every case key: table, key, valid values, units, meaning, and the default of each job
    where it differs from ``impactwear run``'s."""
    defaults = {job: default_case(job).to_dict() for job in JOBS}
    rows = ["| key | run default | valid | meaning | other jobs' defaults |", "|---|---|---|---|---|"]
    for name, table in TABLES.items():
        for k, spec in table.keys().items():
            run = defaults["run"][name][k]
            other = [
                f"{job}: {_shown(v[name][k], spec)}"
                for job, v in defaults.items()
                if name in JOBS[job].tables and v[name][k] != run
            ]
            doc = spec.doc + (f" (absent: {spec.absent})" if spec.optional else "")
            rows.append(
                f"| `{name}.{k}` | {_shown(run, spec)} | {spec.valid_range().replace('|', '/')} | {doc} | "
                f"{'; '.join(other)} |"
            )
    return "\n".join(rows)


def _shown(value: Any, spec: Key) -> str:
    if value is None:
        return "inf" if spec.inf_is_absent else "(absent)"
    return f"`{toml_value(value)}`"
