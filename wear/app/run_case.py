"""Run case files: the ``[wear]``, ``[fem]`` and ``[output]`` tables and the embedded default run case.

A run case (``impactwear run CASE.toml``) has the tables ``[ball]``, ``[plate]``, ``[impact]`` (documented in
:mod:`wear.app.case`), ``[wear]``, ``[fem]`` and ``[output]`` (below). ``[ball]``, ``[plate]``, ``[impact]`` and
``[wear]`` are required — a run must say what hits what and how it wears; absent keys take their defaults.
The tables are registered in the declarative case schema, so errors read like every other case error
(``wear.K=-1 is out of range: wear coefficient must be >= 0 ...``). The embedded default run case is
``wear/app/default_run.toml`` (see :class:`wear.pipeline.Case`).
"""

from __future__ import annotations

import os
from dataclasses import fields
from importlib import resources
from pathlib import Path

from wear.pipeline import COUPLINGS, Case, FemSpec, OutputSpec, WearSpec
from wear.pressure import PRESSURE_SOURCES, SPEED_MODELS

from . import case as case_module
from .case import Key

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

__all__ = ["RUN_TABLES", "REQUIRED_TABLES", "parse_run_case", "load_run_case", "default_run_text"]

#: Tables of a run case, in order; the first four must be present in a case file.
RUN_TABLES = ("ball", "plate", "impact", "wear", "fem", "output")
REQUIRED_TABLES = ("ball", "plate", "impact", "wear")


def _defaults(spec) -> dict:
    return {f.name: f.default for f in fields(spec)}


_W, _F, _O = _defaults(WearSpec), _defaults(FemSpec), _defaults(OutputSpec)

WEAR_TABLE = {
    "K": Key(float, _W["K"], "wear coefficient of Eq. 15 in m^(1-beta) s^(beta-1) Pa^(-alpha)", "SI", low=0.0,
             high=1e-3),
    "alpha": Key(float, _W["alpha"], "pressure exponent of Eq. 15", low=0.0, high=4.0),
    "beta": Key(float, _W["beta"], "sliding-speed exponent of Eq. 15", low=0.0, high=4.0),
    "pressure": Key(str, _W["pressure"], "contact pressure source", choices=PRESSURE_SOURCES),
    "speed": Key(str, _W["speed"], "sliding speed of the contact points", choices=SPEED_MODELS),
    "points_across": Key(int, _W["points_across"], "wear grid points across the largest contact diameter",
                         low=40, high=2000),
}  # fmt: skip
FEM_TABLE = {
    "coupling": Key(str, _F["coupling"], "impact-FE coupling (two-way = FE normal law)", choices=COUPLINGS),
    "tolerance": Key(float, _F["tolerance"], "coupling tolerance on the max overlap change (relative)", low=1e-6,
                     high=0.2),
    "max_iterations": Key(int, _F["max_iterations"], "most impact runs of the coupling", low=2, high=50),
    "load_steps": Key(int, _F["load_steps"], "FE increments of the loading", low=4, high=1000),
    "unload_steps": Key(int, _F["unload_steps"], "FE increments of the unloading", low=2, high=1000),
    "overshoot": Key(float, _F["overshoot"], "FE loading past the estimated max overlap (relative)", low=0.02,
                     high=2.0),
    "mesh_scale": Key(float, _F["mesh_scale"], "FE element size factor (> 1 coarser)", low=0.25, high=8.0),
}  # fmt: skip
OUTPUT_TABLE = {
    "figures": Key(bool, _O["figures"], "write the PNG figures"),
    "render": Key(bool, _O["render"], "write the rendered 3-D view (needs EGL or OSMesa)"),
    "plate_mesh": Key(str, _O["plate_mesh"], "meshio plate block to deform instead of the generated one"),
    "block_thickness": Key(float, _O["block_thickness"], "thickness of the generated plate block", "m", low=0.0,
                           low_open=True, high=1.0),
}  # fmt: skip

case_module.register_table("wear", WEAR_TABLE)
case_module.register_table("fem", FEM_TABLE)
case_module.register_table("output", OUTPUT_TABLE)


def default_run_text() -> str:
    """TOML text of the embedded default run case."""
    return resources.files("wear.app").joinpath("default_run.toml").read_text(encoding="utf-8")


def parse_run_case(text: str, source: str = "case") -> Case:
    """A checked :class:`wear.pipeline.Case` from TOML text; one-line ``ValueError`` naming the key if malformed."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise ValueError(f"case={source!r} is not valid TOML: {exc}") from None
    for table in data:
        if table not in RUN_TABLES:
            raise ValueError(f"[{table}] is not a run case table: the tables are {', '.join(RUN_TABLES)}")
    for table in REQUIRED_TABLES:
        if table not in data:
            need = ", ".join(f"[{t}]" for t in REQUIRED_TABLES)
            raise ValueError(f"[{table}] is missing from case={source!r}: a run case needs {need}")
    checked = case_module.check_case(data)
    return Case.from_dict({table: checked[table] for table in RUN_TABLES})


def load_run_case(path: str | os.PathLike | None = None) -> Case:
    """The run case in the TOML file ``path``, or the embedded default run case when ``path`` is None."""
    if path is None:
        return parse_run_case(default_run_text(), "default")
    p = Path(path)
    if not p.is_file():
        raise ValueError(f"case={str(p)!r} is not a file")
    try:
        text = p.read_text(encoding="utf-8")
    except UnicodeDecodeError:
        raise ValueError(f"case={str(p)!r} is not a UTF-8 text (TOML) file") from None
    return parse_run_case(text, str(p))
