"""The jobs of the toolkit, defined once as data: each job's name (its command), the case tables it reads, its
default case and the plate models it runs.

A job reads some of the case's tables; its default case is the schema's defaults (:class:`wear.case.Case`, the
default of ``impactwear run``) with the values below laid over them. Whichever way a case reaches a job — empty
tables in a file, no file, ``--print-default`` fed back, :func:`default_case` in Python — keys left out take the
job's default.

The case schema (:mod:`wear.case.toml`), the checks of a case against its job (:mod:`wear.case.check`) and the
command line read :data:`JOBS`. What runs a job sits above the case: its command is a module of
:mod:`wear.app.commands` (listed in :data:`wear.app.cli.JOB_COMMANDS`) and its sweep stages are listed in
:data:`wear.app.sweep.stages.STAGES`; the case names neither.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from wear.case.case import Case
from wear.case.choices import FEM_MODELS

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
    "wear": {"pressure": "thornton", "speed": "sliding"},
    "fem": {"coupling": "none"},
}


@dataclass(frozen=True)
class Job:
    """A job: ``name`` (its command), the ``tables`` it reads (what ``--print-default`` prints and
    ``summary.json`` records), a one-line ``doc`` of its default case, the ``overlay`` of values that differ from
    the schema's defaults, the tables a case file must hold (``required``) and the plate models it runs
    (``fem_models``, for a job that reads ``[fem]``; :func:`wear.case.check.check_job_case`), with why it runs no
    other (``fem_models_why``), and for a job that reads a fixed part of ``[fem]`` those keys (``fem_keys``; empty:
    the keys its plate and its coupling read) or the one coupling it always runs (``fem_coupling``; empty:
    ``fem.coupling``'s)."""

    name: str
    tables: tuple[str, ...]
    doc: str
    overlay: dict[str, dict[str, Any]] = field(default_factory=dict)
    required: tuple[str, ...] = ()
    fem_models: tuple[str, ...] = FEM_MODELS
    fem_models_why: str = ""
    fem_keys: tuple[str, ...] = ()
    fem_coupling: str = ""

    def default_case(self) -> Case:
        """This job's default case."""
        return Case.from_dict(self.overlay)


_RUN_TABLES = ("ball", "plate", "impact", "wear", "fem", "output")

#: The jobs by name (each an ``impactwear`` command): the tables it reads, its default case, its plate models.
JOBS: dict[str, Job] = {
    job.name: job
    for job in (
        Job(
            "run",
            _RUN_TABLES,
            "an alumina ball (R 2.5 mm) on a Ti-6Al-4V plate at 3 m/s, 30° from the normal, μ 0.3, on the FE plate's "
            "own force law",
            required=("ball", "plate", "impact", "wear"),
        ),
        Job(
            "impact",
            ("ball", "plate", "impact"),
            "Kharaz, Gorham & Salman (2001): an alumina ball (R 2.5 mm) on soda-lime glass at 3.9 m/s, 30° from the "
            "normal, μ 0.092",
            KHARAZ_2001,
        ),
        Job(
            "indent",
            ("ball", "plate", "fem"),
            "a rigid ball (R 10 mm) pressed into a steel plate (E 210 GPa, ν 0.3, Y 210 MPa)",
            {
                "ball": {"radius": 10e-3, "E": float("inf"), "nu": 0.3, "density": 7850.0, "name": "rigid"},
                "plate": {"E": 210e9, "nu": 0.3, "density": 7850.0, "yield_strength": 210e6, "name": "steel"},
                "fem": {"load_steps": 40, "unload_steps": 20, "mesh_scale": 1.0},
            },
            fem_models=("axisymmetric",),
            fem_models_why="a normal press is axisymmetric: the axisymmetric plate is the 3-D plate's exact reduction, "
            "the same dent within 1.5 % at about a hundredth of its cost",
            fem_keys=("model", "load_steps", "unload_steps", "mesh_scale"),
        ),
        Job(
            "repeat",
            (*_RUN_TABLES, "repeat"),
            "the run's default case, 100 impacts at one site",
            required=("ball", "plate", "impact", "wear"),
            fem_coupling="two-way",
        ),
        Job(
            "erode",
            ("ball", "plate", "impact", "wear", "erosion"),
            "a stream of the Kharaz (2001) alumina balls on soda-lime glass at 3.9 m/s, 30° from the normal, "
            "0.464 kg/m³ for 52 min, Eq. 15 on the Hertz pressure",
            {**KHARAZ_2001, "wear": {"pressure": "hertz", "speed": "sliding"}},
        ),
        Job(
            "calibrate",
            ("ball", "plate", "impact", "wear", "fem", "calibration"),
            "silica sand (R 150 µm) on a carbon steel (Y 350 MPa) at 20 m/s, Thornton's normal law and pressure, no FE",
            SAND_ON_STEEL,
            fem_models=("axisymmetric",),
            fem_models_why="a fit runs the FE-informed law at every data point and every optimiser step, and one "
            "3-D impact takes about 10 minutes",
        ),
        Job(
            "wall",
            ("ball", "plate", "impact", "wear", "wall"),
            "silica sand on a carbon steel wall (7850 kg/m³), DNV-RP-O501's law for steel (K 2e-9, n 2.6)",
            {**SAND_ON_STEEL, "wear": {**SAND_ON_STEEL["wear"], "law": "dnv"}},
        ),
    )
}


def default_case(job: str = "run") -> Case:
    """The default case of ``job`` (a name of :data:`JOBS`)."""
    if job not in JOBS:
        raise ValueError(f"job={job!r} is not a valid choice: must be one of {', '.join(map(repr, JOBS))}")
    return JOBS[job].default_case()
