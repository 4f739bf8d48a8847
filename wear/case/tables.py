"""The case: every table and key, defined once (type, units, default, valid range, one-line doc).

A :class:`wear.case.Case` holds tables ``[ball]``, ``[plate]``, ``[impact]``, ``[wear]``, ``[fem]``, ``[output]``,
``[erosion]``, ``[repeat]``, ``[calibration]`` and ``[wall]``; each job reads the tables it needs
(:mod:`wear.case.jobs`). The tables' defaults are those of the main job, ``impactwear run``: a hard alumina ball
(R 2.5 mm) hitting a Ti-6Al-4V plate at 3 m/s, 30° from the normal, μ 0.3 — about 12 times Thornton's yield speed in
the normal direction, so first yield is far exceeded and the plastic zone reaches the surface — on the FE plate's own
force law (two-way coupling), with the paper's wear law (Eq. 15, α = 1, β = 0.3, K = 1e-11 m^0.7 s^-0.7 Pa^-1). SI
units; angles in degrees from the plate normal.

The tables are defined by concept, each key once (type, units, default, valid range, one-line doc): one impact's
(:mod:`wear.case.impact_tables`), the models and outputs of a run (:mod:`wear.case.model_tables`), the jobs beyond
one impact (:mod:`wear.case.job_tables`), with the choices of the string keys that name a model
(:mod:`wear.case.choices`); this module gathers them, in order, as :data:`TABLES`.
"""

from __future__ import annotations

from wear.case.impact_tables import BallSpec, ImpactSpec, PlateSpec
from wear.case.job_tables import CalibrationSpec, ErosionSpec, RepeatSpec, WallSpec
from wear.case.model_tables import FemSpec, OutputSpec, WearSpec
from wear.case.schema import Table

__all__ = ["TABLES"]

#: The case tables, in order: TOML name → table class.
TABLES: dict[str, type[Table]] = {
    t.table: t
    for t in (
        BallSpec,
        PlateSpec,
        ImpactSpec,
        WearSpec,
        FemSpec,
        OutputSpec,
        ErosionSpec,
        RepeatSpec,
        CalibrationSpec,
        WallSpec,
    )
}
