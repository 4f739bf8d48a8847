"""A sweep's tables: ``results.csv`` (one row per case: inputs, results, error, in expansion order; every name with
its SI unit, :func:`column_names`) and the 1-D or 2-D figure of its grid (SI units from the case schema).

The cases' records (``cases/<case-id>.json``) hold each stage's results under the stage's own names, and the units
join them only in ``results.csv``: a sweep folder of an earlier version is resumed as it is, its table rewritten
with the names of this one.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Iterable
from pathlib import Path

from wear.app.figures.sweep import plot_sweep
from wear.app.outputs.fields import with_units
from wear.app.outputs.writer import write_text
from wear.app.sweep.spec import SweepSpec, flatten
from wear.app.sweep.stages import STAGES
from wear.case import TABLES

__all__ = ["column_names", "results_table", "write_outputs"]


def _csv_text(value) -> str:
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)  # shortest text that reads back to the same float
    return str(value)


def results_table(spec: SweepSpec, records: dict[str, dict]) -> tuple[list[str], list[dict], list[str]]:
    """The ``results.csv`` table: (header, rows as dicts column → value, result column names).

    Columns: ``case_id``, ``status``, the swept inputs, the other inputs (dotted keys), the results (union over
    cases, first-seen order; a name clashing with an input gets ``result.``) and ``error``. Rows in expansion
    order; a case without a record has status ``pending``."""
    swept = spec.swept_keys
    others: dict[str, None] = {}
    for sc in spec.cases:
        others.update(dict.fromkeys(k for k in flatten(sc.case) if k not in swept))
    inputs = swept + list(others)
    result_keys: dict[str, None] = {}
    for sc in spec.cases:
        result_keys.update(dict.fromkeys((records.get(sc.case_id) or {}).get("results") or {}))
    named = {k: (f"result.{k}" if k in inputs else k) for k in result_keys}
    header = ["case_id", "status", *inputs, *named.values(), "error"]
    rows = []
    for sc in spec.cases:
        record = records.get(sc.case_id) or {"status": "pending"}
        results = record.get("results") or {}
        row = {"case_id": sc.case_id, "status": record["status"]}
        row.update(flatten(sc.case))
        row.update(sc.inputs)  # the values as written in the sweep file (the figure's axis values)
        row.update({named[k]: results.get(k) for k in result_keys})
        row["error"] = record.get("error")
        rows.append(row)
    return header, rows, list(named.values())


def column_names(spec: SweepSpec, header: list[str]) -> list[str]:
    """The names of ``results.csv``'s columns ``header`` (of :func:`results_table`) with their SI units
    (:func:`wear.app.outputs.fields.with_units`): an input's from the case schema, a result's from its stage."""
    results = STAGES[spec.stage].result_units()
    units = _input_units(header)
    return [with_units(k, units.get(k) or results.get(k.removeprefix("result."), "")) for k in header]


def write_outputs(spec: SweepSpec, out: Path, records: dict[str, dict]) -> None:
    header, rows, results = results_table(spec, records)
    buf = io.StringIO()
    writer = csv.writer(buf, lineterminator="\n")
    writer.writerow(column_names(spec, header))
    writer.writerows([[_csv_text(row.get(k)) for k in header] for row in rows])
    write_text(out / "results.csv", buf.getvalue(), fsync=True)
    if spec.axes is not None:
        units = {**_input_units(spec.axes), **STAGES[spec.stage].result_units()}
        plot_sweep(spec.axes, rows, results, out, units=units)


def _input_units(keys: Iterable[str]) -> dict[str, str]:
    """SI units of dotted case keys, from the case schema."""
    units = {}
    for dotted in keys:
        table, _, name = dotted.partition(".")
        key = TABLES[table].keys().get(name) if table in TABLES else None
        if key is not None and key.units:
            units[dotted] = key.units
    return units
