r"""The estimated work of a case's axisymmetric FE plate and wear grid, from its keys and closed forms only, refused
before any work past the budget of :mod:`wear.case.budget` (one line naming the key, its value and the value that
fits).

FE wall time: :math:`c\,N_e\,(n_{load} + n_{unload})\,n_{pass}` with :math:`N_e` the plate's elements
(:func:`fe_elements`), :math:`c` = :data:`SECONDS_PER_ELEMENT_STEP` and :math:`n_{pass}` the FE passes: a run's
two-way coupling at most ``fem.max_iterations``, a one-way run or an indentation one, a repeat one per impact computed
one by one before the blocks (at most ``repeat.max_plastic_impacts`` of the ``repeat.impacts``; the blocks after them
are bounded by the worn depth, which stops the run: ``impactwear repeat --impacts 1e9`` on the default case stopped
at impact 77,114 after 309 computed impacts, 16 min and 0.7 GB on 2 shared cores). FE memory: :data:`FE_MEMORY`. Wear
grid memory: :data:`BYTES_PER_WEAR_CELL` per cell of a grid of ``wear.points_across`` across the Hertz contact diameter
and, along the impact, that plus the travel :math:`V_t t_c` (Hertz contact time: an upper bound of the contact centre's
travel while sliding).

The 3-D plate (``fem.model = "3d"``) is not estimated here.
"""

from __future__ import annotations

import math
from collections.abc import Callable

from contact import effective_modulus
from contact.theory import hertz_impact, speed_components, sphere_mass
from wear.case.budget import check_budget
from wear.case.case import Case
from wear.case.jobs import default_case

__all__ = [
    "BYTES_PER_WEAR_CELL",
    "FE_MEMORY",
    "MESH_ELEMENTS",
    "SECONDS_PER_ELEMENT_STEP",
    "check_work",
    "fe_elements",
    "fe_memory",
    "fe_seconds",
    "wear_grid_memory",
]

#: Elements of the axisymmetric plate's mesh at ``fem.mesh_scale`` s: A / s² + B (the refined contact and yield
#: boxes are 2-D: their elements grow as 1/s²). Fitted to the default case's meshes at s = 2 (2789 elements) and
#: 0.5 (24077); it overestimates those at 0.25 (86642) by 6%, 1 (5120, fem's default mesh) by 38% and 8 (1160) by 26%.
MESH_ELEMENTS = (5677.0, 1370.0)
#: FE wall time per element and load increment of one FE pass (s): the larger of two measurements on 2 shared cores,
#: indent's default path (5120 elements, 60 increments, plastic to δ = 20 δ_c: 157 s, 5.1e-4 s) and the default
#: run's two-way coupling (2789 elements, 24 increments, 2 passes: 21.5 s, 1.6e-4 s); the default repeat's impacts
#: took 6.1 s each (estimate 33 s).
SECONDS_PER_ELEMENT_STEP = 5.1e-4
#: FE peak memory (B): base + per element; measured on indent, 0.36 GB at 5120 elements, 0.74 GB (still growing) at
#: 24077; the issue's 0.25 mesh scale (86642 elements) was at 1.9 GB after 120 s.
FE_MEMORY = (2.6e8, 2.0e4)
#: Peak memory per wear-grid cell (B), the run and its output folder with the rendered figures: 2.6 GB measured at
#: ``wear.points_across = 2000`` on the default run (4.2 million cells, 620 B each, over the run's 0.3 GB).
BYTES_PER_WEAR_CELL = 620.0


def fe_elements(mesh_scale: float) -> float:
    """Estimated elements of the axisymmetric plate's mesh at ``mesh_scale`` (:data:`MESH_ELEMENTS`)."""
    a, b = MESH_ELEMENTS
    return a / mesh_scale**2 + b


def fe_memory(mesh_scale: float) -> float:
    """Estimated peak memory (B) of an FE plate at ``mesh_scale`` (:data:`FE_MEMORY`)."""
    base, per_element = FE_MEMORY
    return base + per_element * fe_elements(mesh_scale)


def fe_seconds(mesh_scale: float, steps: int, passes: int) -> float:
    """Estimated FE wall time (s) of ``passes`` passes of ``steps`` increments at ``mesh_scale``."""
    return SECONDS_PER_ELEMENT_STEP * fe_elements(mesh_scale) * steps * passes


def wear_grid_memory(case: Case, points_across: int) -> float:
    """Estimated peak memory (B) of the wear grid of ``case``'s impact at ``points_across`` (module docstring)."""
    ball, plate = case.ball.material(), case.plate.material()
    v_n, v_t = speed_components(case.impact.speed, case.impact.angle)
    if v_n <= 0.0 or math.isinf(ball.density):
        return 0.0
    mass = sphere_mass(case.ball.radius, ball.density)
    hertz = hertz_impact(mass, case.ball.radius, effective_modulus(ball, plate), v_n)
    diameter = 2.0 * hertz.max_contact_radius
    if not math.isfinite(hertz.contact_time) or diameter <= 0.0:
        return 0.0
    along = 1.0 + v_t * hertz.contact_time / diameter
    return BYTES_PER_WEAR_CELL * float(points_across) ** 2 * along


def _passes(case: Case, job: str) -> tuple[int, str]:
    """(FE passes, what they are) of ``job`` on ``case``'s axisymmetric plate; 0 where there is no FE plate."""
    if job == "indent":
        return 1, "one FE pass"
    if job == "repeat":
        return min(case.repeat.impacts, case.repeat.max_plastic_impacts), "impacts computed one by one"
    if case.fem.coupling == "two-way":
        return case.fem.max_iterations, "passes of the two-way coupling at most"
    return (1, "one FE pass") if case.fem.coupling == "one-way" else (0, "")


def check_work(case: Case, job: str) -> None:
    """Refuse ``case`` for ``job`` (``run``, ``repeat`` or ``indent``; other jobs are not estimated here) if its wear
    grid or its axisymmetric FE plate would need more memory or time than the budget: a one-line ``ValueError``
    naming the key, its value, the estimate and the value of the key that fits (of the keys behind the FE time, the
    first the case changed from the job's default)."""
    if job in ("run", "repeat"):
        points = case.wear.points_across
        check_budget(
            "wear.points_across",
            points,
            lambda n: wear_grid_memory(case, int(n)),
            what="the wear grid and its outputs",
            valid=(40, points),
        )
    if job not in ("run", "repeat", "indent") or case.fem.model != "axisymmetric":
        return
    passes, how = _passes(case, job)
    if passes == 0:
        return
    f = case.fem
    scale, load, unload = f.mesh_scale, f.load_steps, f.unload_steps
    elements = fe_elements(scale)
    check_budget(
        "fem.mesh_scale",
        scale,
        fe_memory,
        what=f"~{elements:.3g} FE elements",
        valid=(scale, 8.0),
        increasing=False,
        integer=False,
    )
    # (key, value, FE time as a function of it, cheap end of its range)
    keys: list[tuple[str, float, Callable[[float], float], float]] = [
        ("fem.load_steps", load, lambda n: fe_seconds(scale, int(n) + unload, passes), 2),
        ("fem.unload_steps", unload, lambda n: fe_seconds(scale, load + int(n), passes), 1),
        ("fem.mesh_scale", scale, lambda s: fe_seconds(s, load + unload, passes), 8.0),
    ]
    if job == "repeat":
        impacts, most = case.repeat.impacts, case.repeat.max_plastic_impacts
        keys[:0] = [
            ("repeat.max_plastic_impacts", most, lambda n: fe_seconds(scale, load + unload, min(impacts, int(n))), 1),
            ("repeat.impacts", impacts, lambda n: fe_seconds(scale, load + unload, min(int(n), most)), 1),
        ]
    elif job == "run" and f.coupling == "two-way":
        keys.insert(0, ("fem.max_iterations", passes, lambda n: fe_seconds(scale, load + unload, int(n)), 1))
    default = default_case(job).to_dict()
    keys.sort(key=lambda k: k[1] == default[k[0].split(".")[0]][k[0].split(".")[1]])
    what = f"~{elements:.3g} FE elements x {load + unload} increments x {passes} {how}"
    for name, value, need, cheap in keys:
        increasing = name != "fem.mesh_scale"
        valid = (cheap, value) if increasing else (value, cheap)
        check_budget(name, value, need, what=what, valid=valid, memory=False, increasing=increasing, integer=increasing)
