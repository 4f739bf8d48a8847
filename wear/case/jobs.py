"""The jobs of the toolkit, registered once: each job's name (its command), the case tables it reads, its default
case, its command-line help and command, and the sweep stages it offers.

A job reads some of the case's tables; its default case is the schema's defaults (:class:`wear.case.Case`, the
default of ``impactwear run``) with the values below laid over them. Whichever way a case reaches a job — empty
tables in a file, no file, ``--print-default`` fed back, :func:`default_case` in Python — keys left out take the
job's default.

The command line (:mod:`wear.app.cli`), the sweeps (:mod:`wear.app.sweep.stages`) and the case schema
(:mod:`wear.case.toml`) read :data:`JOBS`. The command and the stage functions live above the case (in
:mod:`wear.app`), so they are named here as ``"module"`` / ``"module:attribute"`` and imported on use: importing
the case imports neither.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

from wear.case.case import Case
from wear.case.tables import FEM_MODELS

__all__ = ["Job", "JOBS", "STAGES", "Stage", "default_case"]

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


def resolve(reference: str) -> Any:
    """The object named by ``"module:attribute"`` (or the module named by ``"module"``), imported now."""
    module, _, attribute = reference.partition(":")
    found = importlib.import_module(module)
    return getattr(found, attribute) if attribute else found


@dataclass(frozen=True)
class Stage:
    """A sweep stage of a job (``impactwear sweep``, :mod:`wear.app.sweep`): ``name`` (``[sweep] stage``), the
    ``tables`` its results depend on (only those enter the case id), a one-line ``description``, ``function``
    (``"module:attribute"`` of a function: case as tables of values → flat dict of JSON scalars), ``units``
    (``"module:attribute"`` of a dict: result name → SI unit, for the sweep's figures; None: none given) and
    ``job``, the job that holds it (set by :class:`Job`): a sweep's ``[base]`` is laid over its default case."""

    name: str
    tables: tuple[str, ...]
    description: str
    function: str
    units: str | None = None
    job: str = ""

    def run(self, case: dict) -> dict:
        """The stage's results for ``case`` (a full case as tables of values, SI units)."""
        function: Callable[[dict], dict] = resolve(self.function)
        return function(case)

    def result_units(self) -> dict[str, str]:
        """Result name → SI unit, for the results that have one."""
        return {} if self.units is None else dict(resolve(self.units))

    def defaults(self) -> dict:
        """The default case of the stage's job, as tables of values (the tables the stage reads)."""
        return default_case(self.job).to_dict(self.tables)


@dataclass(frozen=True)
class Job:
    """A job: ``name`` (its command), the ``tables`` it reads (what ``--print-default`` prints and
    ``summary.json`` records), a one-line ``doc`` of its default case, the ``help`` line of its command, its
    ``command`` (the module of :mod:`wear.app.commands` with ``configure(parser)`` and ``main(args)``), the
    ``overlay`` of values that differ from the schema's defaults, the tables a case file must hold
    (``required``), the sweep ``stages`` it offers and the plate models it runs (``fem_models``, for a job that
    reads ``[fem]``; :func:`wear.case.check.check_job_case`), with why it runs no other (``fem_models_why``), and
    for a job that reads a fixed part of ``[fem]`` those keys (``fem_keys``; empty: the keys its plate and its
    coupling read) or the one coupling it always runs (``fem_coupling``; empty: ``fem.coupling``'s)."""

    name: str
    tables: tuple[str, ...]
    doc: str
    help: str
    command: str
    overlay: dict[str, dict[str, Any]] = field(default_factory=dict)
    required: tuple[str, ...] = ()
    stages: tuple[Stage, ...] = ()
    fem_models: tuple[str, ...] = FEM_MODELS
    fem_models_why: str = ""
    fem_keys: tuple[str, ...] = ()
    fem_coupling: str = ""

    def __post_init__(self) -> None:
        object.__setattr__(self, "stages", tuple(replace(stage, job=self.name) for stage in self.stages))

    def default_case(self) -> Case:
        """This job's default case."""
        return Case.from_dict(self.overlay)

    def command_module(self) -> Any:
        """The module of this job's command (imported now)."""
        return resolve(self.command)


_RUN_TABLES = ("ball", "plate", "impact", "wear", "fem", "output")

_STAGES = "wear.app.sweep.stages"

#: The jobs by name (each an ``impactwear`` command): the tables it reads, its default case, its plate models.
JOBS: dict[str, Job] = {
    job.name: job
    for job in (
        Job(
            "run",
            _RUN_TABLES,
            "an alumina ball (R 2.5 mm) on a Ti-6Al-4V plate at 3 m/s, 30° from the normal, μ 0.3, on the FE plate's "
            "own force law",
            "run one impact case through impact, FE plate, coupling and wear; write meshes, numbers and figures",
            "wear.app.commands.run",
            required=("ball", "plate", "impact", "wear"),
            stages=(
                Stage(
                    "run",
                    ("ball", "plate", "impact", "wear", "fem"),
                    "the whole chain impact -> FE -> coupling -> wear (wear.run)",
                    f"{_STAGES}:run_stage",
                    f"{_STAGES}:RUN_UNITS",
                ),
                Stage(
                    "indent",
                    ("ball", "plate", "impact", "fem"),
                    "the FE plate along the impact's overlap history (fem.indent_impact)",
                    f"{_STAGES}:indent_stage",
                    f"{_STAGES}:INDENT_UNITS",
                ),
            ),
        ),
        Job(
            "impact",
            ("ball", "plate", "impact"),
            "Kharaz, Gorham & Salman (2001): an alumina ball (R 2.5 mm) on soda-lime glass at 3.9 m/s, 30° from the "
            "normal, μ 0.092",
            "simulate one oblique ball-on-plate impact (H-DD model) and print rebound, forces and timings",
            "wear.app.commands.impact",
            KHARAZ_2001,
            stages=(
                Stage(
                    "impact",
                    ("ball", "plate", "impact"),
                    "one H-DD impact (contact.simulate_impact)",
                    f"{_STAGES}:impact_stage",
                    "contact.results:OUTPUT_UNITS",
                ),
            ),
        ),
        Job(
            "indent",
            ("ball", "plate", "fem"),
            "a rigid ball (R 10 mm) pressed into a steel plate (E 210 GPa, ν 0.3, Y 210 MPa)",
            "press the ball into the axisymmetric FE plate and unload; write F-δ, pressures, first yield, mesh, "
            "figures",
            "wear.app.commands.indent",
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
            "N impacts of the same ball at one site on the plate the previous ones left: dent, wear, shakedown",
            "wear.app.commands.repeat",
            required=("ball", "plate", "impact", "wear"),
            fem_coupling="two-way",
            stages=(
                Stage(
                    "repeat",
                    ("ball", "plate", "impact", "wear", "fem", "repeat"),
                    "repeated impacts at one site (wear.repeat)",
                    f"{_STAGES}:repeat_stage",
                    f"{_STAGES}:REPEAT_UNITS",
                ),
            ),
        ),
        Job(
            "erode",
            ("ball", "plate", "impact", "wear", "erosion"),
            "a stream of the Kharaz (2001) alumina balls on soda-lime glass at 3.9 m/s, 30° from the normal, "
            "0.464 kg/m³ for 52 min, Eq. 15 on the Hertz pressure",
            "erode a plate patch by a stream of particles (surface feedback); mass loss and erosion rate vs time or "
            "angle",
            "wear.app.commands.erode",
            {**KHARAZ_2001, "wear": {"pressure": "hertz", "speed": "sliding"}},
            stages=(
                Stage(
                    "erode",
                    ("ball", "plate", "impact", "wear", "erosion"),
                    "particle-stream erosion of a plate patch (wear.erode_case)",
                    f"{_STAGES}:erode_stage",
                    f"{_STAGES}:ERODE_UNITS",
                ),
            ),
        ),
        Job(
            "calibrate",
            ("ball", "plate", "impact", "wear", "fem", "calibration"),
            "silica sand (R 150 µm) on a carbon steel (Y 350 MPa) at 20 m/s, Thornton's normal law and pressure, no FE",
            "fit a wear law's constants to measured wear (least squares on logs, with intervals); write "
            "calibrated.toml",
            "wear.app.commands.calibrate",
            SAND_ON_STEEL,
            stages=(
                Stage(
                    "calibrate",
                    ("ball", "plate", "impact", "wear", "fem", "calibration"),
                    "a calibration of the wear law to measured wear (wear.chain.calibrate)",
                    f"{_STAGES}:calibrate_stage",
                    f"{_STAGES}:CALIBRATE_UNITS",
                ),
            ),
            fem_models=("axisymmetric",),
            fem_models_why="a fit runs the FE-informed law at every data point and every optimiser step, and one "
            "3-D impact takes about 10 minutes",
        ),
        Job(
            "wall",
            ("ball", "plate", "impact", "wear", "wall"),
            "silica sand on a carbon steel wall (7850 kg/m³), DNV-RP-O501's law for steel (K 2e-9, n 2.6)",
            "erode a component's wall from CFD or DEM impact records: per-face rates (mm/year), remaining life, hot "
            "spots and the worn wall",
            "wear.app.commands.wall",
            {**SAND_ON_STEEL, "wear": {**SAND_ON_STEEL["wear"], "law": "dnv"}},
            stages=(
                Stage(
                    "wall",
                    ("ball", "plate", "impact", "wear", "wall"),
                    "the erosion of a component's wall from CFD or DEM impact records (wear.wall.erode_component)",
                    f"{_STAGES}:wall_stage",
                    f"{_STAGES}:WALL_UNITS",
                ),
            ),
        ),
    )
}

#: The sweep stages of all jobs, by name (``[sweep] stage``).
STAGES: dict[str, Stage] = {stage.name: stage for job in JOBS.values() for stage in job.stages}


def default_case(job: str = "run") -> Case:
    """The default case of ``job`` (a name of :data:`JOBS`)."""
    if job not in JOBS:
        raise ValueError(f"job={job!r} is not a valid choice: must be one of {', '.join(map(repr, JOBS))}")
    return JOBS[job].default_case()
