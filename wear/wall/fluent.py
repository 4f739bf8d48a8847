r"""Ansys Fluent's DPM sample files (Report > Discrete Phase > Sample on a wall zone) as an impact table
(:class:`wear.wall.records.ImpactRecords`).

**The format, as found** (no Fluent was run here: Fluent 6.3 User's Guide §22.16.6 "Sampling of Trajectories",
https://www.sharcnet.ca/Software/Fluent6/html/ug/node867.htm, and public readers and writers of the files, see
``docs/wall-records.md``). Fluent writes one text file per sampled surface, named after it with ``.dpm`` appended;
in unsteady tracking the header is written when sampling starts and one row per particle parcel crossing or
hitting the surface is appended as the run goes. The file is

.. code-block:: text

    (wall-plate 13)
    (    x    y    z    u    v    w diameter    t parcel-mass mass n-in-parcel time flow-time name)
    ((-1.2e-02 3.4e-03 0.0e+00 ... 2.1e-03) injection-0:17)

a first line naming the surface and a count, a line of column names in parentheses, then one row per parcel:
the values in an inner pair of parentheses, followed by the parcel's name (``injection:number``) and a closing
parenthesis. The columns found are ``x y z`` (m, the sample point), ``u v w`` (m/s), ``diameter`` (m), ``t`` (K,
the particle temperature), ``parcel-mass`` (kg, the parcel: ``n-in-parcel`` particles), ``mass`` (kg, one
particle), ``n-in-parcel``, ``time`` (s, the particle's time since injection) and, in unsteady tracking,
``flow-time`` (s, the flow time of the sample). Variants seen: with and without ``flow-time`` (unsteady/steady
tracking), with and without the ``name`` column in the header line, rows with or without the name.

**What is read.** The columns are found by name in the header line (any order; other columns are ignored); the
count on the first line is not used. Required: ``x y z u v w diameter`` and two of ``parcel-mass``, ``mass``,
``n-in-parcel``. The particles per record are ``n-in-parcel`` (or ``parcel-mass / mass``); one particle's mass is
``mass`` (or ``parcel-mass / n-in-parcel``); the particle density is

.. math:: \rho_p = \frac{m}{\pi d^3 / 6},

the sample file having no density column. When all three are given, a row whose ``parcel-mass`` differs from
``n-in-parcel × mass`` by more than the printed digits allow (:math:`1.5 \cdot 10^{1-s}` relative, s the fewest
significant digits of the three) is bad input. The hit's time is ``flow-time`` (0 without it: a steady run's samples
have no flow time). Fluent gives the hit point, not the face: every record's face is −1, found from the position
by :func:`wear.wall.hits.hits_on_wall`. The velocity is taken as the incident one (the found sources do not say
whether a wall sample is written before or after the rebound: a rebound velocity points out of the wall and is
refused there, naming the row). Units are SI (m, m/s, kg, s): no source found states a sample file's units, but
Fluent stores and computes in SI and converts only at its interface (Fluent 6.3 User's Guide, Chapter 5, "Unit
Systems"), and the public readers take the values as SI; a diameter in mm or µm fails the diameter range check.

Rows are counted from 1 after the header lines (the r-th row of parcels; blank lines and a closing ``)`` line are
not rows); bad input is a ``ValueError`` naming the file, the row and the column.
"""

from __future__ import annotations

import gzip
import io
import math
from collections.abc import Iterator
from pathlib import Path

import numpy as np

from contact.checks import check_path
from wear.wall.mesh import Wall
from wear.wall.records import DENSITY_RANGE, ImpactRecords, check_rows, numbers, where

__all__ = ["read_fluent_dpm", "count_fluent_rows", "FLUENT_COLUMNS", "FLUENT_MASS_COLUMNS", "FLUENT_TIME"]

#: The columns read (Fluent's names), by impact-table field; all required.
FLUENT_COLUMNS = {"position": ("x", "y", "z"), "velocity": ("u", "v", "w"), "diameter": ("diameter",)}
#: Parcel mass (kg), one particle's mass (kg), particles in the parcel: two of the three are required.
FLUENT_MASS_COLUMNS = ("parcel-mass", "mass", "n-in-parcel")
#: The flow time of the sample (s), written in unsteady tracking only.
FLUENT_TIME = "flow-time"
#: The header's name of the parcel-name column, which closes a row after the values.
_NAME = "name"
#: A density for records whose diameter is not > 0, so that ImpactRecords reports the diameter, not a density
#: derived from it.
_PLACEHOLDER_DENSITY = 1000.0


def read_fluent_dpm(
    path: str | Path, wall: Wall | None = None, start_row: int = 0, max_rows: int | None = None
) -> ImpactRecords:
    """The impact table of a Fluent DPM sample file ``path`` (``.dpm``, gzipped or not; see the module docstring):
    rows ``start_row + 1`` to ``start_row + max_rows`` (all the rest when ``max_rows`` is None), the rows before
    skipped unparsed. ``wall`` is not needed (every record's face is −1, found from its position by
    :func:`wear.wall.hits.hits_on_wall`); it is accepted so that all readers are called alike."""
    name = str(check_path("path", path, "a Fluent DPM sample file"))
    check_rows(start_row, max_rows)
    header, lines = _header(name, _lines(Path(path)))
    columns = [c for c in header if c != _NAME]
    rows: list[int] = []
    cells: list[list[str]] = []
    r = 0
    for text in lines:
        if not text or text == ")":
            continue
        r += 1
        if r <= start_row:
            continue
        if max_rows is not None and len(rows) == max_rows:
            break
        rows.append(r)
        cells.append(_row(name, r, text, columns))
    table = dict(zip(columns, zip(*cells, strict=True), strict=True)) if cells else {c: () for c in columns}
    return _records(name, table, np.array(rows, dtype=np.int64))


def count_fluent_rows(path: str | Path) -> int:
    """The number of parcel rows of a Fluent DPM sample file (its header checked, the rows not parsed)."""
    _, lines = _header(str(path), _lines(Path(path)))
    return sum(1 for text in lines if text and text != ")")


def _lines(path: Path) -> Iterator[str]:
    """The stripped lines of a text file, gzipped or not, or ValueError naming it."""
    try:
        raw = gzip.open(path, "rb") if path.suffix == ".gz" else path.open("rb")
        with raw, io.TextIOWrapper(raw, encoding="utf-8") as text:
            for line in text:
                yield line.strip()
    except (OSError, UnicodeDecodeError, EOFError) as err:
        raise ValueError(f"{path} is not a Fluent DPM sample text file ({err})") from None


def _header(name: str, lines: Iterator[str]) -> tuple[list[str], Iterator[str]]:
    """The column names of the header line, checked, and the lines after it."""
    header = None
    for text in lines:
        if not text:
            continue
        if not text.startswith("(") or text.startswith("(("):
            break  # a row or other text before any column line
        names = text.replace("(", " ").replace(")", " ").split()
        if "x" in names:
            header = names
            break
    if header is None:
        raise ValueError(
            f"{name}, header: no column line '(x y z u v w diameter ...)': give a Fluent DPM sample file "
            "(Report > Discrete Phase > Sample)"
        )
    for c in header:
        if header.count(c) > 1:
            raise ValueError(f"{name}, header: column {c!r} appears {header.count(c)} times: give each column once")
    required = [c for cs in FLUENT_COLUMNS.values() for c in cs]
    missing = [c for c in required if c not in header]
    if missing:
        raise ValueError(
            f"{name}, header: no column {missing[0]} (a required column; the header names {' '.join(header)})"
        )
    if sum(c in header for c in FLUENT_MASS_COLUMNS) < 2:
        raise ValueError(
            f"{name}, header: give two of the columns {', '.join(FLUENT_MASS_COLUMNS)} (the header names "
            f"{' '.join(header)})"
        )
    if _NAME in header and header[-1] != _NAME:
        raise ValueError(f"{name}, header: column {_NAME!r} is not the last: the parcel's name closes a row")
    return header, lines


def _row(name: str, r: int, text: str, columns: list[str]) -> list[str]:
    """The values (text) of row ``r``, ``((v1 v2 ...) name)``, one per numeric column, or ValueError."""
    close = text.find(")")
    if not text.startswith("((") or close < 0 or "(" in text[close:] or text[close + 1 :].count(")") > 1:
        raise ValueError(f"{where(name, r, columns[0])}: {text[:60]!r} is not a sample row '((value value ...) name)'")
    values = text[2:close].split()
    if len(values) != len(columns):
        column = columns[min(len(values), len(columns) - 1)]
        raise ValueError(
            f"{where(name, r, column)}: the row has {len(values)} values for the header's {len(columns)} columns "
            f"({' '.join(columns)})"
        )
    return values


def _digits(texts: list[str]) -> np.ndarray:
    """Significant digits of printed numbers: their mantissas' digits without sign, point and leading zeros (≥ 1)."""
    mantissa = np.char.partition(np.char.lower(np.asarray(texts, dtype=str)), "e")[:, 0]
    bare = np.char.lstrip(np.char.replace(np.char.lstrip(mantissa, "+-"), ".", ""), "0")
    return np.maximum(np.char.str_len(bare), 1)


def _records(name: str, table: dict[str, tuple[str, ...]], rows: np.ndarray) -> ImpactRecords:
    """The impact table of the rows' text ``table`` (column → values)."""

    def column(c: str) -> np.ndarray:
        return numbers(table[c], name, rows, c) if len(rows) else np.zeros(0)

    def vector(cs: tuple[str, ...]) -> np.ndarray:
        return np.column_stack([column(c) for c in cs]) if len(rows) else np.zeros((0, 3))

    diameter = column("diameter")
    given = {c: column(c) for c in FLUENT_MASS_COLUMNS if c in table}
    if "n-in-parcel" in given:
        count, count_column = given["n-in-parcel"], "n-in-parcel"
    else:
        with np.errstate(divide="ignore", invalid="ignore"):
            count, count_column = given["parcel-mass"] / given["mass"], "parcel-mass"
    if "mass" in given:
        mass, mass_column = given["mass"], "mass"
    else:
        with np.errstate(divide="ignore", invalid="ignore"):
            mass, mass_column = given["parcel-mass"] / given["n-in-parcel"], "parcel-mass"
    if len(given) == 3:
        _check_parcel_mass(name, table, rows, given)
    with np.errstate(divide="ignore", invalid="ignore"):
        density = np.where(diameter > 0.0, mass / (math.pi * diameter**3 / 6.0), _PLACEHOLDER_DENSITY)
    lo, hi = DENSITY_RANGE
    bad = np.flatnonzero((density <= lo) | (density > hi))  # NaN is left to ImpactRecords' finite check
    if len(bad):
        i = bad[0]
        raise ValueError(
            f"{where(name, int(rows[i]), mass_column)}: {mass[i]:.6g} kg with diameter {diameter[i]:.6g} m gives a "
            f"particle density m / (π d³ / 6) = {density[i]:.6g} kg/m^3, out of ({lo:g}, {hi:g}]: give the masses "
            "in kg and the diameter in m"
        )
    return ImpactRecords(
        position=vector(FLUENT_COLUMNS["position"]),
        velocity=vector(FLUENT_COLUMNS["velocity"]),
        diameter=diameter,
        density=density,
        count=count,
        time=column(FLUENT_TIME) if FLUENT_TIME in table else np.zeros(len(rows)),
        face=np.full(len(rows), -1),
        files=(name,),
        row=rows,
        columns={**FLUENT_COLUMNS, "density": (mass_column,), "count": (count_column,), "time": (FLUENT_TIME,)},
    )


def _check_parcel_mass(
    name: str, table: dict[str, tuple[str, ...]], rows: np.ndarray, given: dict[str, np.ndarray]
) -> None:
    """Raise naming the first row whose parcel mass is not n-in-parcel × mass within the printed digits."""
    parcel, n, mass = given["parcel-mass"], given["n-in-parcel"], given["mass"]
    with np.errstate(divide="ignore", invalid="ignore"):
        difference = np.abs(parcel - n * mass) / np.abs(parcel)
    finite = np.isfinite(parcel) & np.isfinite(n) & np.isfinite(mass) & (parcel != 0.0)
    suspects = np.flatnonzero(finite & (difference > 1e-15))
    if not len(suspects):
        return
    digits = np.min([_digits([table[c][i] for i in suspects]) for c in FLUENT_MASS_COLUMNS], axis=0)
    tolerances = 1.5 * 10.0 ** (1.0 - digits)
    bad = np.flatnonzero(difference[suspects] > tolerances)
    if len(bad):
        i, digits, tolerance = suspects[bad[0]], digits[bad[0]], tolerances[bad[0]]
        raise ValueError(
            f"{where(name, int(rows[i]), 'parcel-mass')}: {parcel[i]:.6g} kg is not n-in-parcel × mass = "
            f"{n[i]:.6g} × {mass[i]:.6g} kg = {n[i] * mass[i]:.6g} kg (relative difference {difference[i]:.2g}, "
            f"more than the {tolerance:.2g} that {digits} printed digits allow)"
        )
