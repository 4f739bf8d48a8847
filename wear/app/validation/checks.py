"""The validation's building blocks: a :class:`Check` (one quantity against an independent reference) and a
:class:`Group` of checks.

A *check* compares one quantity that the toolkit computes with an independent reference (a published number, a
closed form evaluated separately, a conservation law) and records: quantity, case, reference value and its
source, obtained value, error, tolerance, pass/fail. Checks come in groups: a group is a function
``group(quick: bool) -> list[Check]`` of an area (``contact``, ``fem``, ``wear``); ``quick=True`` runs the same
computation at reduced sizes (the test suite uses it), ``quick=False`` at the full resolution of the report. The
groups live in :mod:`wear.app.validation.chung_ooi`, ``.contact``, ``.fem``, ``.laws``, ``.wall`` and ``.wear``,
and :mod:`wear.app.validation.groups` lists them by area.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

__all__ = ["AREAS", "Check", "Group", "absolute", "relative"]

#: The areas of the validation, in the report's order.
AREAS = ("contact", "fem", "wear")


@dataclass(frozen=True)
class Check:
    """One validation check.

    ``error`` is computed by the check: ``measure`` says how (``"relative"``: ``|obtained − reference|/|reference|``;
    ``"absolute"``: ``|obtained − reference|`` in ``units``; or a stated measure such as ``"max |Δ| over table"``).
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
    """A check of ``obtained`` against ``reference`` with the relative error ``|o − r|/|r|`` ≤ ``tolerance``."""
    reference, obtained = float(reference), float(obtained)
    error = abs(obtained - reference) / abs(reference) if reference != 0.0 else math.inf
    return Check(area, quantity, case, reference, source, obtained, error, tolerance, "relative", units)


def absolute(area, quantity, case, reference, source, obtained, tolerance, units="", measure="absolute") -> Check:
    """A check of ``obtained`` against ``reference`` with the absolute error ``|o − r|`` ≤ ``tolerance`` (``units``)."""
    reference, obtained = float(reference), float(obtained)
    error = abs(obtained - reference)
    return Check(area, quantity, case, reference, source, obtained, error, tolerance, measure, units, "", units)


@dataclass(frozen=True)
class Group:
    """A group of checks: its ``name``, its ``area`` (one of :data:`AREAS`) and its ``function(quick) -> list[Check]``
    (``quick``: reduced sizes)."""

    name: str
    area: str
    function: Callable[[bool], list[Check]]

    def __post_init__(self) -> None:
        if self.area not in AREAS:
            raise ValueError(f"area={self.area!r} is not a valid choice: must be one of {', '.join(map(repr, AREAS))}")
