"""Input checks shared by the whole toolkit.

Every public entry point validates its inputs with these helpers, so that a bad value fails
early with one line that names the parameter, repeats the value it got and states the valid
range with its SI unit, e.g.::

    ValueError: E=210.0 is out of range: Young's modulus must be in [1e+05, 1e+13] Pa (give Pa, not GPa)

`fem` and `wear` import from here too (the import direction contact <- fem <- wear allows it).
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

import numpy as np

__all__ = [
    "FRICTION_MAX",
    "check_friction",
    "check_number",
    "check_choice",
    "check_array",
    "check_bool",
    "check_count",
    "check_instance",
    "check_path",
    "fmt_argument",
    "fmt_value",
]


#: The largest Coulomb friction coefficient μ taken anywhere: the impact (:func:`contact.simulate_impacts`), the
#: case's ``impact.friction``, the erosion's response and the 3-D plate (:func:`fem.indent_solid`). Dry metal and
#: ceramic pairs in air reach about 1; a larger ratio of tangential to normal force is adhesion (clean metals in
#: vacuum, junction growth), not the load-proportional law μ stands for. The bound is the law's, not a solver's: the
#: 3-D plate's Newton converges on an elastic plate in full slip at μ = 1.5 too
#: (measured).
FRICTION_MAX = 1.0
_FRICTION = "Coulomb friction coefficient"


def fmt_value(value: Any) -> str:
    """Short, unambiguous text of a value for an error message."""
    if isinstance(value, str):
        return repr(value)
    if isinstance(value, float):
        return f"{value:.6g}"
    return repr(value)


def _interval(low: float | None, high: float | None, low_open: bool, high_open: bool) -> str:
    if low is not None and high is not None:
        return f"in {'(' if low_open else '['}{low:g}, {high:g}{')' if high_open else ']'}"
    if low is not None:
        return f"{'>' if low_open else '>='} {low:g}"
    if high is not None:
        return f"{'<' if high_open else '<='} {high:g}"
    return "finite"


def check_number(
    name: str,
    value: Any,
    *,
    low: float | None = None,
    high: float | None = None,
    low_open: bool = False,
    high_open: bool = False,
    units: str = "",
    what: str = "",
    allow_inf: bool = False,
    hint: str = "",
) -> float:
    """Return ``value`` as a float, or raise ``ValueError`` naming ``name``.

    ``low``/``high`` bound the valid range (closed unless ``low_open``/``high_open``);
    ``units`` is the SI unit shown in the message; ``what`` says what the quantity is;
    ``hint`` is appended (e.g. "give Pa, not GPa"). NaN is always rejected; +inf only
    with ``allow_inf`` (a rigid body's modulus).
    """
    label = f"{what} " if what else ""
    unit = f" {units}" if units else ""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise ValueError(f"{name}={fmt_value(value)} is not a number: {label}must be a number{unit}")
    x = float(value)
    rng = _interval(low, high, low_open, high_open)
    tail = f" ({hint})" if hint else ""
    if math.isnan(x) or (math.isinf(x) and not (allow_inf and x > 0)):
        raise ValueError(f"{name}={fmt_value(x)} is not finite: {label}must be {rng}{unit}{tail}")
    if math.isinf(x):
        return x
    bad = (low is not None and (x < low or (low_open and x == low))) or (
        high is not None and (x > high or (high_open and x == high))
    )
    if bad:
        raise ValueError(f"{name}={fmt_value(x)} is out of range: {label}must be {rng}{unit}{tail}")
    return x


def check_friction(name: str, value: Any) -> Any:
    """``value`` as a Coulomb friction coefficient μ in [0, :data:`FRICTION_MAX`] (dimensionless): a float for a
    number, a float array of its shape for an array (every entry checked), else a one-line ``ValueError`` naming
    ``name`` and the first bad value, worded alike for both."""
    if np.ndim(value) == 0:
        scalar = value[()] if isinstance(value, np.ndarray) else value
        return check_number(name, scalar, low=0.0, high=FRICTION_MAX, what=_FRICTION)
    array = check_array(name, value, what=_FRICTION, ndim=np.ndim(value))
    bad = np.flatnonzero((array < 0.0) | (array > FRICTION_MAX))
    if len(bad):
        check_number(name, float(array.flat[bad[0]]), low=0.0, high=FRICTION_MAX, what=_FRICTION)
    return array


def check_choice(name: str, value: Any, choices: Iterable[str]) -> str:
    """Return ``value`` if it is one of ``choices``, else raise ``ValueError`` naming ``name``."""
    options = tuple(choices)
    if not isinstance(value, str) or value not in options:
        listed = ", ".join(repr(c) for c in options)
        raise ValueError(f"{name}={fmt_value(value)} is not a valid choice: must be one of {listed}")
    return value


def check_bool(name: str, value: Any) -> bool:
    """Return ``value`` if it is a bool, else raise ``ValueError`` naming ``name``."""
    if not isinstance(value, (bool, np.bool_)):
        raise ValueError(f"{name}={fmt_value(value)} is not a boolean: must be true or false")
    return bool(value)


def fmt_argument(value: Any) -> str:
    """An argument of any type for a message: its value if a scalar or a path, else its type."""
    if isinstance(value, (list, tuple)) and not value:
        return repr(value)
    if value is None or isinstance(value, (str, int, float, bool, os.PathLike)):
        return fmt_value(str(value) if isinstance(value, os.PathLike) else value)
    return f"<{type(value).__name__}>"


def check_count(name: str, value: Any, *, low: int = 0, what: str = "") -> int:
    """Return ``value`` if it is an integer >= ``low`` (a count, an index, a number of workers), else raise
    ``ValueError`` naming ``name``; ``what`` says what it counts."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < low:
        tail = f" ({what})" if what else ""
        raise ValueError(f"{name}={fmt_argument(value)} is out of range: give an integer >= {low}{tail}")
    return int(value)


def check_instance(name: str, value: Any, kind: type | tuple[type, ...], what: str) -> Any:
    """Return ``value`` if it is a ``kind``, else raise ``ValueError`` naming ``name``; ``what``: what to give
    (e.g. "a wear.Case: wear.case.default_case('wall') or wear.case.load_case(path)")."""
    if not isinstance(value, kind):
        raise ValueError(f"{name}={fmt_argument(value)} is not {what}")
    return value


def check_path(name: str, value: Any, what: str = "a file or folder") -> Path:
    """Return ``value`` as a ``Path`` if it is a non-empty ``str`` or path, else raise ``ValueError`` naming
    ``name``."""
    if not isinstance(value, (str, os.PathLike)) or not str(value):
        raise ValueError(f"{name}={fmt_argument(value)} is not a path: give {what} (str or pathlib.Path)")
    return Path(value)


def check_array(
    name: str,
    values: Any,
    *,
    low: float | None = None,
    high: float | None = None,
    low_open: bool = False,
    units: str = "",
    what: str = "",
    ndim: int = 1,
    min_size: int = 1,
) -> np.ndarray:
    """Return ``values`` as a float array of dimension ``ndim`` with every entry checked.

    The message names the parameter, the first offending index and its value.
    """
    try:
        arr = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} is not an array of numbers: {what or 'values'} in {units or 'SI units'}") from None
    if arr.ndim == 0 and ndim == 1:
        arr = arr.reshape(1)
    if arr.ndim != ndim:
        raise ValueError(f"{name} has {arr.ndim} dimension(s): must have {ndim}")
    if arr.size < min_size:
        raise ValueError(f"{name} has {arr.size} entries: must have at least {min_size}")
    flat = arr.ravel()
    bad = ~np.isfinite(flat)
    if low is not None:
        bad |= (flat <= low) if low_open else (flat < low)
    if high is not None:
        bad |= flat > high
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        rng = _interval(low, high, low_open, False)
        unit = f" {units}" if units else ""
        label = f"{what} " if what else ""
        raise ValueError(
            f"{name}[{i}]={fmt_value(float(flat[i]))} is out of range: {label}must be finite and {rng}{unit}"
        )
    return arr
