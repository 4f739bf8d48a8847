"""The names of the fields a user opens: the point and cell data of the meshes (``.vtu``), the columns of the tables
(``.csv``) and the arrays of ``.npz`` files.

Every name ends in its SI unit (:data:`UNIT_SUFFIXES`: ``_m``, ``_Pa``, ``_m_s`` for m/s, ...), as the fields of
``summary.json`` do; a quantity without a unit (a strain, a restitution, a count, a flag, a text) has none and is
listed in :data:`UNITLESS`. One quantity has one name in every file: the displacement is ``displacement_m`` in every
mesh, the worn depth ``wear_depth_m`` in the meshes and in ``wear_map.npz``.

The meshes are built with short names (``u``, ``von_mises``, ... as :mod:`fem` and :mod:`wear.surface` give them);
:func:`named_mesh` gives them their file names (:data:`MESH_FIELDS`) when they are written.
"""

from __future__ import annotations

import re

import meshio

__all__ = [
    "MESH_FIELDS",
    "UNITLESS",
    "UNIT_SUFFIXES",
    "named_mesh",
    "unit_of",
    "unit_suffix",
    "with_units",
]

#: SI unit (as the case schema and the summaries write it) → the suffix of a field name in that unit. Units with no
#: short suffix (a wear law's K, whose unit depends on the law's exponents) get ``SI``: the key's unit in the schema
#: (docs/keys.md).
UNIT_SUFFIXES = {
    "m": "m",
    "m^2": "m2",
    "m^3": "m3",
    "s": "s",
    "m/s": "m_s",
    "rad/s": "rad_s",
    "1/s": "per_s",
    "N": "N",
    "Pa": "Pa",
    "J": "J",
    "J/m^3": "J_m3",
    "kg": "kg",
    "kg/kg": "kg_per_kg",
    "kg/m^2": "kg_m2",
    "kg/m^3": "kg_m3",
    "kg/(m^2 s)": "kg_m2_s",
    "kg/s": "kg_s",
    "deg": "deg",
    "year": "year",
    "mm/year": "mm_year",
    "SI": "SI",
}

#: Names (or, for a dotted sweep column, the key after the last dot) of the fields without a unit: dimensionless
#: quantities, counts, flags (1/0) and texts.
UNITLESS = frozenset(
    {
        # dimensionless quantities
        "equivalent_plastic_strain",
        "max_equivalent_plastic_strain",
        "plastic_strain_increment",
        "normal_restitution",
        "tangential_restitution",
        "wear_peak_to_azimuthal_mean",
        "rms_slope",
        "log_residual",
        "s",
        # counts
        "step",
        "steps",
        "row",
        "impacts",
        "impact_first",
        "impact_last",
        "impacts_in_row",
        "particles",
        "face",
        "label",
        "rank",
        # flags (1/0 or true/false)
        "on_surface",
        "sliding",
        "computed",
        "shaken_down",
        "elastic_response",
        # a unit vector and a name
        "normal",
        "patch",
        "fitted",
        "fe3d_sticking",
        # texts
        "regime",
        "source",
        "about",
        "case_id",
        "status",
        "error",
    }
)

#: Mesh field as built (:mod:`fem`, :mod:`wear.surface`, the erosion's surface grid) → its name in the file.
MESH_FIELDS = {
    "u": "displacement_m",
    "displacement": "displacement_m",
    "wear_depth": "wear_depth_m",
    "dent_depth": "dent_depth_m",
    "total_depth": "total_depth_m",
    "pressure": "pressure_Pa",
    "max_pressure": "max_pressure_Pa",
    "von_mises": "von_mises_stress_Pa",
    "equivalent_plastic_strain": "equivalent_plastic_strain",
    "surface": "on_surface",
}

_UNITS = {suffix: units for units, suffix in UNIT_SUFFIXES.items()}
_SUFFIX = re.compile(r"_(" + "|".join(sorted(map(re.escape, set(UNIT_SUFFIXES.values())), key=len)[::-1]) + r")$")


def unit_suffix(units: str) -> str:
    """The name suffix of an SI unit (:data:`UNIT_SUFFIXES`; ``""`` for no unit, ``SI`` for a compound unit).

    >>> unit_suffix("m/s"), unit_suffix(""), unit_suffix("(kg/kg) (m/s)^-n")
    ('m_s', '', 'SI')
    """
    if not units:
        return ""
    return UNIT_SUFFIXES.get(units, "SI")


def with_units(name: str, units: str) -> str:
    """``name`` with the suffix of ``units`` (none for no unit; unchanged if it already ends in it).

    >>> with_units("impact.speed", "m/s"), with_units("max_depth_m", "m"), with_units("steps", "")
    ('impact.speed_m_s', 'max_depth_m', 'steps')
    """
    suffix = unit_suffix(units)
    return name if not suffix or name.endswith(f"_{suffix}") else f"{name}_{suffix}"


def unit_of(name: str) -> str:
    """The SI unit a field name ends in (``""`` if none).

    >>> unit_of("max_force_N"), unit_of("wear_volume_per_impact_m3"), unit_of("normal_restitution")
    ('N', 'm^3', '')
    """
    m = _SUFFIX.search(name)
    return "" if m is None else _UNITS[m.group(1)]


def named_mesh(mesh: meshio.Mesh) -> meshio.Mesh:
    """``mesh`` with its point and cell data under their file names (:data:`MESH_FIELDS`; other names, e.g. those
    of a user's own plate mesh, kept)."""
    return meshio.Mesh(
        mesh.points,
        mesh.cells,
        point_data={MESH_FIELDS.get(k, k): v for k, v in mesh.point_data.items()},
        cell_data={MESH_FIELDS.get(k, k): v for k, v in mesh.cell_data.items()},
    )
