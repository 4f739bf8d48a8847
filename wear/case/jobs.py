"""The jobs of the toolkit (one per command that reads a case) and each job's default case, defined here once.

A job reads some of the case's tables; its default case is the schema's defaults (:class:`wear.case.Case`, the
default of ``impactwear run``) with the values below laid over them. Whichever way a case reaches a job — empty
tables in a file, no file, ``--print-default`` fed back, :func:`default_case` in Python — keys left out take the
job's default.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from wear.case.tables import FEM_MODELS, Case

__all__ = ["Job", "JOBS", "default_case"]

#: The Kharaz, Gorham & Salman (2001) experiment as used by Chung & Ooi (2011): an alumina ball (R 2.5 mm) on a
#: soda-lime glass plate at 3.9 m/s, 30° from the normal, μ 0.092, elastic (Hertz).
KHARAZ_2001 = {
    "ball": {"density": 4000.0},
    "plate": {"E": 70e9, "nu": 0.25, "density": 2500.0, "yield_strength": None, "name": "soda-lime glass"},
    "impact": {"speed": 3.9, "friction": 0.092, "normal_model": "hertz"},
}


#: Silica sand on a plain carbon steel (the assumptions of examples/fig10_stream.toml), elastic–plastic impacts on
#: Thornton's law and pressure without the FE plate: the erosion setting of the calibration.
SAND_ON_STEEL = {
    "ball": {"radius": 150e-6, "E": 94e9, "nu": 0.17, "density": 2650.0, "name": "silica sand"},
    "plate": {"E": 200e9, "nu": 0.3, "density": 7850.0, "yield_strength": 350e6, "name": "carbon steel"},
    "impact": {"speed": 20.0, "friction": 0.3, "normal_model": "thornton"},
    "wear": {"pressure": "thornton"},
    "fem": {"coupling": "none"},
}


@dataclass(frozen=True)
class Job:
    """A job: ``name`` (its command), the ``tables`` it reads (what ``--print-default`` prints and
    ``summary.json`` records), the tables a case file must hold (``required``), the ``overlay`` of values that
    differ from the schema's defaults, a one-line ``doc`` of its default case, and the plate models it runs
    (``fem_models``, for a job that reads ``[fem]``; :func:`wear.case.check.check_job_case`)."""

    name: str
    tables: tuple[str, ...]
    doc: str
    overlay: dict[str, dict[str, Any]] = field(default_factory=dict)
    required: tuple[str, ...] = ()
    fem_models: tuple[str, ...] = FEM_MODELS

    def default_case(self) -> Case:
        """This job's default case."""
        return Case.from_dict(self.overlay)


_RUN_TABLES = ("ball", "plate", "impact", "wear", "fem", "output")

JOBS: dict[str, Job] = {
    job.name: job
    for job in (
        Job("run", _RUN_TABLES, "an alumina ball (R 2.5 mm) on a Ti-6Al-4V plate at 3 m/s, 30° from the normal, "
            "μ 0.3, on the FE plate's own force law", required=("ball", "plate", "impact", "wear")),
        Job("repeat", (*_RUN_TABLES, "repeat"), "the run's default case, 100 impacts at one site",
            required=("ball", "plate", "impact", "wear"), fem_models=("axisymmetric",)),
        Job("impact", ("ball", "plate", "impact"), "Kharaz, Gorham & Salman (2001): an alumina ball (R 2.5 mm) on "
            "soda-lime glass at 3.9 m/s, 30° from the normal, μ 0.092", KHARAZ_2001),
        Job("indent", ("ball", "plate", "fem"), "a rigid ball (R 10 mm) pressed into a steel plate (E 210 GPa, "
            "ν 0.3, Y 210 MPa)", {
                "ball": {"radius": 10e-3, "E": float("inf"), "nu": 0.3, "density": 7850.0, "name": "rigid"},
                "plate": {"E": 210e9, "nu": 0.3, "density": 7850.0, "yield_strength": 210e6, "name": "steel"},
                "fem": {"load_steps": 40, "unload_steps": 20, "mesh_scale": 1.0},
            }, fem_models=("axisymmetric",)),
        Job("calibrate", ("ball", "plate", "impact", "wear", "fem", "calibration"), "silica sand (R 150 µm) on a "
            "carbon steel (Y 350 MPa) at 20 m/s, Thornton's normal law and pressure, no FE", SAND_ON_STEEL,
            fem_models=("axisymmetric",)),
        Job("erode", ("ball", "plate", "impact", "wear", "erosion"), "a stream of the Kharaz (2001) alumina balls on "
            "soda-lime glass at 3.9 m/s, 30° from the normal, 0.464 kg/m³ for 52 min, Eq. 15 on the Hertz pressure",
            {**KHARAZ_2001, "wear": {"pressure": "hertz"}}),
    )
}  # fmt: skip


def default_case(job: str = "run") -> Case:
    """The default case of ``job`` (one of :data:`JOBS`: "run", "repeat", "impact", "indent", "erode")."""
    if job not in JOBS:
        raise ValueError(f"job={job!r} is not a valid choice: must be one of {', '.join(map(repr, JOBS))}")
    return JOBS[job].default_case()
