"""The case keys a wall's wear law reads (:func:`wear.wall.per_record.wall_law`; a law's own from its declaration,
:data:`wear.laws.registry.LAWS`), and the refusal of the others: a key
a wall run accepts is used or refused, never silently ignored. The wall command adds the ``[wall]`` keys it reads
itself (thickness, exposure, service time, sand rates)."""

from __future__ import annotations

from wear.case import Case
from wear.laws.registry import law_named, wear_keys

__all__ = ["WALL_TABLE_KEYS", "check_law_keys", "keys_read"]

#: The ``[wall]`` keys of the response table (the others are the wall command's: thickness, exposure, rates).
WALL_TABLE_KEYS = ("table_speed_min", "table_speed_max", "table_speeds", "table_angles", "table_angle_max")
_TABLE_KEYS = {
    "ball": ("radius", "E", "nu", "density", "yield_strength", "name"),
    "plate": ("rigid", "E", "nu", "density", "yield_strength", "hardness", "name"),
    "impact": (
        "friction",
        "restitution",
        "normal_model",
        "tangential_model",
        "limiting_pressure",
        "scheme",
        "time_step",
    ),
    "wall": WALL_TABLE_KEYS,
}


def keys_read(case: Case) -> dict[str, tuple[str, ...]]:
    """The keys of the ``[ball]``, ``[plate]``, ``[impact]``, ``[wear]`` tables and the table keys of ``[wall]``
    that :func:`wall_law` reads for ``case`` (table → keys): a command refuses the others at a value other than
    its default, so that no key is silently ignored. The closed forms read no particle key (the records carry
    the particles) and of the plate what their formula takes (hardness or yield strength), its density (the wall's
    eroded mass), whether it is rigid, and its name; the table laws read the
    particle's material and the impact's models and integration, but neither its speed nor its angle (the
    records')."""
    law = law_named(case.wear.law)
    wear = wear_keys(law.name, case.wear.values())
    if law.per_record is not None:
        # the density always: the wall's eroded mass and erosion rate are ρ V (wear.wall.worn)
        return {"ball": (), "plate": law.plate_keys, "impact": (), "wear": wear, "wall": ()}
    return {**_TABLE_KEYS, "wear": wear}


def check_law_keys(case: Case, default: Case) -> Case:
    """``case`` if every key of ``[ball]``, ``[plate]``, ``[impact]``, ``[wear]`` and the table keys of ``[wall]``
    (:data:`WALL_TABLE_KEYS`) that the law does not read (:func:`keys_read`) is at its ``default`` (the command's
    default case), else a one-line ``ValueError`` naming the first other one."""
    read = keys_read(case)
    for table, keys in read.items():
        given, base = getattr(case, table).values(), getattr(default, table).values()
        candidates = WALL_TABLE_KEYS if table == "wall" else tuple(given)
        for key in candidates:
            if key not in keys and given[key] != base[key]:
                raise ValueError(
                    f"{table}.{key}={given[key]!r}: the wall's wear.law={case.wear.law!r} does not read it (of "
                    f"[{table}] it reads {', '.join(keys) if keys else 'nothing'}); leave it out (default "
                    f"{base[key]!r})"
                )
    return case
