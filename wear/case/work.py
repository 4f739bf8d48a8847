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

The 3-D plate (``fem.model = "3d"``): wall time :math:`c_3\,N_3\,(n_{load} + n_{unload})\,n_{cycle}\,n_{impact}`
with :math:`N_3` its elements (:func:`solid_elements`), :math:`c_3` = :data:`SOLID_SECONDS_PER_ELEMENT_STEP`, the
``solid_load_steps`` and ``solid_unload_steps`` increments, :math:`n_{cycle}` = min(``fem.solid_iterations``,
:data:`SOLID_CYCLES`) 3-D plate cycles and one impact for a run, ``repeat.impacts`` for a repeat (every impact is
computed). It is linear in the elements, while the sparse factorisations grow faster than that, so it is a low
estimate for meshes much finer than the default: it refuses what would run for hours, not what would take 70 min.
Its memory is not estimated.
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
    "REPEAT_BLOCK_PASS",
    "REPEAT_SEAT_FACTOR",
    "SECONDS_PER_ELEMENT_STEP",
    "check_axisymmetric_work",
    "check_solid_work",
    "check_wear_grid",
    "fe_elements",
    "fe_memory",
    "fe_seconds",
    "repeat_block_impacts",
    "SOLID_CYCLES",
    "SOLID_ELEMENTS",
    "SOLID_SECONDS_PER_ELEMENT_STEP",
    "solid_elements",
    "solid_seconds",
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


#: Elements of the 3-D half plate with k = round(8 / ``fem.mesh_scale``) elements across the contact radius: c k².
#: Counted on the oblique block (contact centre's track ±0.3 a_max): 7324, 10196, 13416, 20416, 32088, 88176 and
#: 158992 elements at k = 3, 4, 5, 6, 8, 12 and 16; 640 k² is within -21% (k = 3) to +28% (k = 8) of them.
SOLID_ELEMENTS = 640.0
#: 3-D plate wall time per element and planned increment of one plate cycle (s): the default oblique impact (μ 0.3,
#: 30°, k = 4: 10196 elements, 10 + 6 increments) took 528 s on idle cores for two cycles, 1.6e-3 s
#: (docs/benchmarks-record.md); its repeated impacts 391 s each (1.2e-3 s). With μ = 0.5 a cycle took 3–7 times as long
#: (docs/fem-record.md).
SOLID_SECONDS_PER_ELEMENT_STEP = 1.6e-3
#: 3-D plate cycles counted per impact: the most measured over 0/30/60° × μ 0/0.3/0.5 (docs/fem-record.md), whatever
#: larger ``fem.solid_iterations`` allows.
SOLID_CYCLES = 2


def solid_elements(mesh_scale: float) -> float:
    """Estimated elements of the 3-D half plate at ``mesh_scale`` (:data:`SOLID_ELEMENTS`)."""
    across = max(round(8.0 / mesh_scale), 1)
    return SOLID_ELEMENTS * across**2


def solid_seconds(mesh_scale: float, steps: int, cycles: int, impacts: int) -> float:
    """Estimated wall time (s) of ``impacts`` impacts of ``cycles`` 3-D plate cycles of ``steps`` increments."""
    return SOLID_SECONDS_PER_ELEMENT_STEP * solid_elements(mesh_scale) * steps * min(cycles, SOLID_CYCLES) * impacts


def fe_elements(mesh_scale: float) -> float:
    """Estimated elements of the axisymmetric plate's mesh at ``mesh_scale`` (:data:`MESH_ELEMENTS`)."""
    a, b = MESH_ELEMENTS
    return a / mesh_scale**2 + b


def fe_memory(mesh_scale: float) -> float:
    """Estimated peak memory (B) of an FE plate at ``mesh_scale`` (:data:`FE_MEMORY`)."""
    base, per_element = FE_MEMORY
    return base + per_element * fe_elements(mesh_scale)


def fe_seconds(mesh_scale: float, steps: int, passes: float) -> float:
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


#: After the impacts computed one by one, a repeat computes one impact between cycle-jump blocks until the worn depth
#: reaches half the contact radius a: a block and its computed impact move the surface by about
#: ``repeat.surface_fraction`` f times the approach δ, so about a / (2 f δ) of them (module docstring). With Hertz's
#: δ and a = √(R δ (1 + overshoot)) that is 82 on the default repeat, which computed 214 (``--impacts 1e9``, stopped
#: at impact 13,309): its approach fell from 10.8 to 4.1 µm as the seat conformed. Counted this many times over.
REPEAT_SEAT_FACTOR = 3.0
#: The FE time of an impact computed between blocks over that of one computed one by one (:func:`fe_seconds`): the
#: same run took 4.7 s for each of those 214 (an estimate of 34 s), 21 s for each of its first 20.
REPEAT_BLOCK_PASS = 0.25


def repeat_block_impacts(case: Case, impacts: int) -> float:
    """Estimated impacts a repeat of ``impacts`` computes between cycle-jump blocks (:data:`REPEAT_SEAT_FACTOR`):
    none within ``repeat.max_plastic_impacts``, one when the wear does not move the surface (one block), else at
    most every other one of the rest."""
    spec = case.repeat
    rest = impacts - spec.max_plastic_impacts
    if rest <= 0:
        return 0.0
    if not spec.geometry_update:
        return 1.0
    ball, plate = case.ball.material(), case.plate.material()
    v_n, _ = speed_components(case.impact.speed, case.impact.angle)
    if v_n <= 0.0 or math.isinf(ball.density) or plate.is_rigid:
        return 0.0
    mass = sphere_mass(case.ball.radius, ball.density)
    approach = hertz_impact(mass, case.ball.radius, effective_modulus(ball, plate), v_n).max_overlap
    if not approach > 0.0:
        return 0.0
    radius = math.sqrt(case.ball.radius * approach * (1.0 + case.fem.overshoot))
    pairs = REPEAT_SEAT_FACTOR * 0.5 * radius / (spec.surface_fraction * approach) + 1.0
    return min(math.ceil(rest / 2.0), pairs)


def _passes(case: Case, job: str) -> tuple[int, str]:
    """(FE passes, what they are) of ``job`` on ``case``'s axisymmetric plate; 0 where there is no FE plate."""
    if job == "indent":
        return 1, "one FE pass"
    if job == "repeat":
        return min(case.repeat.impacts, case.repeat.max_plastic_impacts), "impacts computed one by one"
    if case.fem.coupling == "two-way":
        return case.fem.max_iterations, "passes of the two-way coupling at most"
    return (1, "one FE pass") if case.fem.coupling == "one-way" else (0, "")


def check_wear_grid(case: Case, job: str) -> None:
    """Refuse ``case`` for ``job`` if its wear grid would need more memory than the budget (a ``run`` or a
    ``repeat``; other jobs have none): a one-line ``ValueError`` naming ``wear.points_across``, its value, the
    estimate and the value that fits. The plate's own work is its declaration's check
    (:attr:`wear.case.plate_cases.PlateCase.check_work`)."""
    if job in ("run", "repeat"):
        points = case.wear.points_across
        check_budget(
            "wear.points_across",
            points,
            lambda n: wear_grid_memory(case, int(n)),
            what="the wear grid and its outputs",
            valid=(40, points),
        )


def _check_time(keys: list, job: str, what: str) -> None:
    """Refuse the FE time past the budget, naming the first of ``keys`` ((name, value, FE time as a function of it,
    cheap end of its range)) the case changed from ``job``'s default, then the others in their order."""
    default = default_case(job).to_dict()
    for name, value, need, cheap in sorted(keys, key=lambda k: k[1] == default[k[0].split(".")[0]][k[0].split(".")[1]]):
        increasing = name != "fem.mesh_scale"
        valid = (cheap, value) if increasing else (value, cheap)
        check_budget(name, value, need, what=what, valid=valid, memory=False, increasing=increasing, integer=increasing)


def check_solid_work(case: Case, job: str) -> None:
    """Refuse a 3-D plate run or repeat past the time budget (module docstring), naming the first key the case
    changed of those behind the estimate."""
    if job == "indent":
        return
    f = case.fem
    scale, load, unload, cycles = f.mesh_scale, f.solid_load_steps, f.solid_unload_steps, f.solid_iterations
    impacts = case.repeat.impacts if job == "repeat" else 1
    keys: list[tuple[str, float, Callable[[float], float], float]] = [
        ("fem.solid_load_steps", load, lambda n: solid_seconds(scale, int(n) + unload, cycles, impacts), 2),
        ("fem.solid_unload_steps", unload, lambda n: solid_seconds(scale, load + int(n), cycles, impacts), 1),
        ("fem.mesh_scale", scale, lambda s: solid_seconds(s, load + unload, cycles, impacts), 8.0),
    ]
    if job == "repeat":
        keys.insert(0, ("repeat.impacts", impacts, lambda n: solid_seconds(scale, load + unload, cycles, int(n)), 1))
    what = (
        f"~{solid_elements(scale):.3g} 3-D elements x {load + unload} increments x {min(cycles, SOLID_CYCLES)} "
        f"plate cycles x {impacts} impact{'s' if impacts > 1 else ''}"
    )
    _check_time(keys, job, what)


def check_axisymmetric_work(case: Case, job: str) -> None:
    """Refuse an axisymmetric FE plate past the memory or time budget (module docstring)."""
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
    # a repeat's impacts computed between cycle-jump blocks, each a cheaper pass (REPEAT_BLOCK_PASS)
    work = passes + (REPEAT_BLOCK_PASS * repeat_block_impacts(case, case.repeat.impacts) if job == "repeat" else 0.0)
    # (key, value, FE time as a function of it, cheap end of its range)
    keys: list[tuple[str, float, Callable[[float], float], float]] = [
        ("fem.load_steps", load, lambda n: fe_seconds(scale, int(n) + unload, work), 2),
        ("fem.unload_steps", unload, lambda n: fe_seconds(scale, load + int(n), work), 1),
        ("fem.mesh_scale", scale, lambda s: fe_seconds(s, load + unload, work), 8.0),
    ]
    if job == "repeat":
        impacts, most = case.repeat.impacts, case.repeat.max_plastic_impacts

        def repeat_seconds(n: int, first: int) -> float:
            """The FE time of ``n`` impacts: ``first`` computed one by one, then those between the blocks."""
            between = REPEAT_BLOCK_PASS * repeat_block_impacts(case.with_(repeat={"max_plastic_impacts": first}), n)
            return fe_seconds(scale, load + unload, 1) * (min(n, first) + between)

        keys[:0] = [
            ("repeat.max_plastic_impacts", most, lambda n: repeat_seconds(impacts, int(n)), 1),
            ("repeat.impacts", impacts, lambda n: repeat_seconds(int(n), most), 1),
        ]
        between = repeat_block_impacts(case, impacts)
        if between:
            how += f" and ~{between:.3g} between cycle-jump blocks"
    elif job == "run" and f.coupling == "two-way":
        keys.insert(0, ("fem.max_iterations", passes, lambda n: fe_seconds(scale, load + unload, int(n)), 1))
    what = f"~{elements:.3g} FE elements x {load + unload} increments x {passes} {how}"
    _check_time(keys, job, what)
