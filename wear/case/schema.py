"""The building blocks of the case schema: a :class:`Key` per case key, and :class:`Table`, the base of the frozen
dataclasses that hold one case table.

A case key is a dataclass field whose metadata holds its :class:`Key` (type, default, units, valid range, one-line
doc), written with :func:`key`::

    @dataclass(frozen=True)
    class ImpactSpec(Table):
        table: ClassVar[str] = "impact"
        speed: float = key(float, 3.0, "impact speed", "m/s", low=0.0, low_open=True, high=1000.0)

Constructing a table checks every key (one-line ``ValueError`` naming ``table.key``, its value and the valid range
with units) and converts it to its type (a TOML integer given for a float key becomes a float). Loading, checking,
``--print-default``, the sweep-key checks and the docs' key reference all read the same :class:`Key`.
"""

from __future__ import annotations

import math
from collections.abc import Collection
from dataclasses import dataclass, field, fields
from typing import Any, ClassVar

import numpy as np

from contact.checks import check_bool, check_choice, check_number, fmt_value

__all__ = ["Key", "Table", "key"]


def _integral_float(value: Any) -> bool:
    """True for a finite float with no fractional part (``1e6``, ``5.0``), which an integer key accepts."""
    return isinstance(value, (float, np.floating)) and math.isfinite(value) and float(value).is_integer()


@dataclass(frozen=True)
class Key:
    """One case key: ``type`` (float, int, str or bool), ``default``, one-line ``doc`` (what the quantity is),
    ``units`` (SI), valid range ``[low, high]`` (open ends with ``low_open``/``high_open``), ``choices`` for strings,
    ``optional`` (None = absent is allowed: ``absent`` says what absent means) and ``inf_is_absent`` (``inf`` in a
    file means absent, e.g. a yield strength: never yields)."""

    type: type
    default: Any
    doc: str
    units: str = ""
    low: float | None = None
    high: float | None = None
    low_open: bool = False
    high_open: bool = False
    allow_inf: bool = False
    #: read at each check: a registry's live mapping (e.g. :data:`wear.laws.registry.LAWS`) takes the entries added
    #: to it
    choices: Collection[str] = ()
    optional: bool = False
    absent: str = ""
    inf_is_absent: bool = False

    def check(self, name: str, value: Any) -> Any:
        """The checked ``value`` of key ``name`` ("table.key") in its type, or a one-line ``ValueError``."""
        if value is None and self.optional:
            return None
        if self.type is bool:
            return check_bool(name, value)
        if self.type is str:
            if self.choices:
                return check_choice(name, value, self.choices)
            if not isinstance(value, str):
                raise ValueError(f"{name}={fmt_value(value)} is not a string: {self.doc}")
            return value
        if self.type is int and _integral_float(value):
            # TOML reads 1e6 as a float; a whole number written so is the integer the user meant
            value = int(value)
        if self.type is int and (isinstance(value, bool) or not isinstance(value, (int, np.integer))):
            raise ValueError(
                f"{name}={fmt_value(value)} is not an integer: {self.doc} must be an integer {self.valid_range()}"
            )
        if self.inf_is_absent and isinstance(value, (int, float)) and value == math.inf:
            return None
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

    def valid_range(self) -> str:
        """The valid values as text: ``one of 'a', 'b'``, ``true or false``, ``in [0, 90) deg``, ``> 0 m``."""
        if self.choices:
            return "one of " + ", ".join(repr(c) for c in self.choices)
        if self.type is bool:
            return "true or false"
        if self.type is str:
            return "text"
        lo, hi = "(" if self.low_open else "[", ")" if self.high_open else "]"
        if self.low is not None and self.high is not None:
            text = f"in {lo}{self.low:g}, {self.high:g}{hi}"
        elif self.low is not None:
            text = f"{'>' if self.low_open else '>='} {self.low:g}"
        elif self.high is not None:
            text = f"{'<' if self.high_open else '<='} {self.high:g}"
        else:
            text = "any number"
        text = f"{text} {self.units}".rstrip()
        if self.inf_is_absent:
            return f"{text}, or inf ({self.absent})"
        return f"{text} or inf" if self.allow_inf else text


def key(type: type, default: Any, doc: str, units: str = "", **limits: Any) -> Any:
    """A dataclass field holding a case key (see :class:`Key` for ``limits``: low, high, low_open, high_open,
    allow_inf, choices, optional, absent, inf_is_absent)."""
    spec = Key(type, default, doc, units, **limits)
    if default is None and not spec.optional:
        raise TypeError(f"key {doc!r}: a default of None needs optional=True")
    return field(default=default, metadata={"key": spec})


class Table:
    """Base of the frozen dataclasses holding one case table (``table`` is its TOML name). Construction checks every
    key against its :class:`Key` and converts it to the key's type; subclasses add cross-key checks in
    :meth:`check`."""

    table: ClassVar[str] = ""

    def __post_init__(self) -> None:
        for f in fields(self):
            value = f.metadata["key"].check(f"{self.table}.{f.name}", getattr(self, f.name))
            object.__setattr__(self, f.name, value)
        self.check()

    def check(self) -> None:
        """Checks across keys (one-line ``ValueError`` naming the key); none by default."""

    @classmethod
    def keys(cls) -> dict[str, Key]:
        """Key name → :class:`Key`, in the table's order."""
        return {f.name: f.metadata["key"] for f in fields(cls)}  # type: ignore[arg-type]

    def values(self) -> dict[str, Any]:
        """Key name → value (None for an absent optional key)."""
        return {f.name: getattr(self, f.name) for f in fields(self)}  # type: ignore[arg-type]
