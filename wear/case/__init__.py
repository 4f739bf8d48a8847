"""The case: every table and key defined once (gathered by :mod:`wear.case.tables`), the whole case
(:mod:`wear.case.case`), each job's default case (:mod:`wear.case.jobs`) and case files (:mod:`wear.case.toml`).

>>> from wear.case import Case, default_case, dump_case
>>> Case().impact.speed                      # impactwear run's default (m/s)
3.0
>>> default_case("impact").plate.name        # impactwear impact's default: Kharaz et al. (2001)
'soda-lime glass'
>>> Case().with_(impact={"angle": 120.0})
Traceback (most recent call last):
...
ValueError: impact.angle=120 is out of range: impact angle from the plate normal must be in [0, 90) deg
"""

from wear.case.case import Case
from wear.case.check import check_job_case
from wear.case.choices import COUPLINGS, FEM_MODELS
from wear.case.impact_tables import BallSpec, ImpactSpec, PlateSpec
from wear.case.job_tables import CalibrationSpec, ErosionSpec, RepeatSpec, WallSpec
from wear.case.jobs import JOBS, Job, default_case
from wear.case.model_tables import FemSpec, OutputSpec, WearSpec
from wear.case.schema import Key, Table, key
from wear.case.tables import TABLES
from wear.case.toml import (
    apply_override,
    dump_case,
    key_reference,
    load_case,
    override_tables,
    parse_case,
    read_toml,
    read_toml_text,
    toml_value,
)

__all__ = [
    "COUPLINGS",
    "FEM_MODELS",
    "JOBS",
    "TABLES",
    "BallSpec",
    "CalibrationSpec",
    "Case",
    "ErosionSpec",
    "FemSpec",
    "ImpactSpec",
    "Job",
    "Key",
    "OutputSpec",
    "PlateSpec",
    "RepeatSpec",
    "Table",
    "WallSpec",
    "WearSpec",
    "apply_override",
    "check_job_case",
    "default_case",
    "dump_case",
    "key",
    "key_reference",
    "load_case",
    "override_tables",
    "parse_case",
    "read_toml",
    "read_toml_text",
    "toml_value",
]
