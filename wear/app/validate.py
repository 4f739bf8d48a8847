"""``impactwear validate``: the toolkit's validation cases, run at full resolution, as one table.

A *check* compares one quantity that the toolkit computes with an independent reference (a published number, a
closed form evaluated separately, a conservation law) and records: quantity, case, reference value and its
source, obtained value, error, tolerance, pass/fail (:class:`Check`). Checks come in groups: a group is a function
``group(quick: bool) -> list[Check]`` registered with :func:`register` under an area (``contact``, ``fem``,
``wear``); ``quick=True`` runs the same computation at reduced sizes (the test suite uses it), ``quick=False`` at
the full resolution of the report. A group that raises is recorded as one failed check carrying the error.

The groups live in ``wear/app/validation_*.py`` (one module per area); :func:`run_validation` imports them, runs
them and :func:`render_report` writes the Markdown report (``docs/validation.md`` is its committed output).
"""

from __future__ import annotations

import importlib
import math
import os
import tempfile
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

__all__ = [
    "Check",
    "relative",
    "absolute",
    "GROUPS",
    "register",
    "load_groups",
    "run_validation",
    "render_report",
    "write_report",
    "CHECK_MODULES",
]

#: Modules holding the check groups (imported by :func:`load_groups`).
CHECK_MODULES = ("wear.app.validation_contact", "wear.app.validation_wear", "wear.app.validation_fem")


@dataclass(frozen=True)
class Check:
    """One validation check.

    ``error`` is computed by the check: ``measure`` says how (``"relative"``: |obtained − reference|/|reference|;
    ``"absolute"``: |obtained − reference| in ``units``; or a stated measure such as ``"max |Δ| over table"``).
    ``units`` are those of reference and obtained, ``error_units`` those of error and tolerance. The check passes
    when ``error`` is finite and ≤ ``tolerance`` (same measure and units)."""

    area: str
    quantity: str
    case: str
    reference: float | str
    source: str
    obtained: float | str
    error: float
    tolerance: float
    measure: str = "relative"
    units: str = ""
    group: str = ""
    error_units: str = ""

    @property
    def passed(self) -> bool:
        return math.isfinite(self.error) and self.error <= self.tolerance


def relative(area, quantity, case, reference, source, obtained, tolerance, units="") -> Check:
    """A check of ``obtained`` against ``reference`` with the relative error |o − r|/|r| ≤ ``tolerance``."""
    reference, obtained = float(reference), float(obtained)
    error = abs(obtained - reference) / abs(reference) if reference != 0.0 else math.inf
    return Check(area, quantity, case, reference, source, obtained, error, tolerance, "relative", units)


def absolute(area, quantity, case, reference, source, obtained, tolerance, units="", measure="absolute") -> Check:
    """A check of ``obtained`` against ``reference`` with the absolute error |o − r| ≤ ``tolerance`` (``units``)."""
    reference, obtained = float(reference), float(obtained)
    error = abs(obtained - reference)
    return Check(area, quantity, case, reference, source, obtained, error, tolerance, measure, units, "", units)


@dataclass(frozen=True)
class Group:
    name: str
    area: str
    function: Callable[[bool], list[Check]]


#: name → :class:`Group`, in registration order.
GROUPS: dict[str, Group] = {}


def register(area: str, name: str | None = None):
    """Decorator: register ``function(quick) -> list[Check]`` as a group of ``area`` (contact, fem or wear)."""
    if area not in ("contact", "fem", "wear"):
        raise ValueError(f"area={area!r} is not a valid choice: must be one of 'contact', 'fem', 'wear'")

    def wrap(function):
        key = name or function.__name__
        GROUPS[key] = Group(key, area, function)
        return function

    return wrap


#: module → why it was not loaded (its stage is not in this build), filled by :func:`load_groups`.
SKIPPED: dict[str, str] = {}


def load_groups() -> dict[str, Group]:
    """Import every module of :data:`CHECK_MODULES` that exists (registering its groups); return :data:`GROUPS`.

    A module that raises ``ModuleNotFoundError`` naming itself (its stage is missing) is recorded in
    :data:`SKIPPED` and reported."""
    for module in CHECK_MODULES:
        try:
            importlib.import_module(module)
        except ModuleNotFoundError as exc:
            if exc.name != module:
                raise
            SKIPPED[module] = str(exc)
    return GROUPS


@dataclass
class Validation:
    """Result of :func:`run_validation`: the checks, the seconds per group, and the mode."""

    checks: list[Check] = field(default_factory=list)
    seconds: dict[str, float] = field(default_factory=dict)
    quick: bool = False

    @property
    def failed(self) -> list[Check]:
        return [c for c in self.checks if not c.passed]


def run_validation(*, quick: bool = False, only=None, progress=None) -> Validation:
    """Run the registered groups (all, or those whose name contains one of the strings in ``only``).

    ``progress(name)`` is called before each group. A group that raises becomes one failed check."""
    groups = load_groups()
    names = list(groups)
    if only:
        names = [n for n in names if any(s in n for s in only)]
        if not names:
            raise ValueError(f"only={list(only)!r} matches no check group: groups are {', '.join(groups)}")
    out = Validation(quick=quick)
    for name in names:
        group = groups[name]
        if progress is not None:
            progress(name)
        start = time.perf_counter()
        try:
            checks = [Check(**{**c.__dict__, "group": name}) for c in group.function(quick)]
        except Exception as exc:  # a crash is a failure of the whole group, reported with its cause
            last = traceback.extract_tb(exc.__traceback__)[-1]
            why = f"{type(exc).__name__}: {exc} ({Path(last.filename).name}:{last.lineno})"
            checks = [Check(group.area, f"group {name} ran", "", "no error", "", why, math.inf, 0.0, "error", "", name)]
        out.seconds[name] = time.perf_counter() - start
        out.checks.extend(checks)
    return out


def _num(x) -> str:
    if isinstance(x, str):
        return x
    x = float(x)
    if x == 0.0:
        return "0"
    if 1e-3 <= abs(x) < 1e5:
        return f"{x:.5g}"
    return f"{x:.4e}"


def _unit(value, unit: str) -> str:
    return "" if isinstance(value, str) else unit


def _error_text(c: Check) -> tuple[str, str]:
    if c.measure == "error":
        return "—", "—"
    if c.measure == "relative":
        return f"{100 * c.error:.2g}%" if c.error < 10 else f"{c.error:.3g}", f"{100 * c.tolerance:.2g}%"
    unit = f" {c.error_units}" if c.error_units else ""
    how = "" if c.measure == "absolute" else f" ({c.measure})"
    return f"{_num(c.error)}{unit}{how}", f"{_num(c.tolerance)}{unit}"


def render_report(result: Validation, command: str = "impactwear validate") -> str:
    """Markdown report: summary per area, then one row per check."""
    checks = result.checks
    failed = result.failed
    lines = [
        "# Validation report",
        "",
        f"Generated by `{command}` (do not edit by hand). "
        + ("**Quick mode (reduced sizes): not the full validation.** " if result.quick else "Full resolution. ")
        + f"{len(checks)} checks, {len(checks) - len(failed)} passed, {len(failed)} failed; "
        f"{sum(result.seconds.values()):.0f} s.",
        "",
        "Each row compares one quantity computed by the toolkit with an independent reference: a published "
        "number, a closed form evaluated separately, or a conservation law. Error and tolerance use the stated "
        "measure (relative unless units are given). SI units; angles in degrees from the plate normal.",
        "",
    ]
    if SKIPPED:
        lines += [f"**Not run:** `{m}` ({why})." for m, why in SKIPPED.items()] + [""]
    lines += [
        "| area | checks | passed | time (s) |",
        "|---|---|---|---|",
    ]
    for area in ("contact", "fem", "wear"):
        mine = [c for c in checks if c.area == area]
        secs = sum(t for g, t in result.seconds.items() if GROUPS.get(g) and GROUPS[g].area == area)
        lines.append(f"| {area} | {len(mine)} | {sum(c.passed for c in mine)} | {secs:.1f} |")
    lines += [
        "",
        "| # | area | quantity | case | reference | source | obtained | error | tolerance | result |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for i, c in enumerate(checks, 1):
        err, tol = _error_text(c)
        unit = f" {c.units}" if c.units else ""
        verdict = "pass" if c.passed else "**FAIL**"
        cells = [str(i), c.area, c.quantity, c.case, _num(c.reference) + _unit(c.reference, unit), c.source]
        cells += [_num(c.obtained) + _unit(c.obtained, unit), err, tol, verdict]
        lines.append("| " + " | ".join(x.replace("|", "\\|").replace("\n", " ") for x in cells) + " |")
    lines.append("")
    return "\n".join(lines)


def write_report(path: str | os.PathLike, text: str) -> Path:
    """Write ``text`` to ``path`` atomically (temporary file in the same folder, then ``os.replace``)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path
