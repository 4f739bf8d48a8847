"""Repeated impacts of the same ball at the same spot, each on the plate the previous ones left: the entry point over
the plate models (``fem.model``, :data:`wear.chain.plates.PLATES`), each repeating on its own plate
(:attr:`wear.chain.plate_model.PlateModel.repeat`; the FE plates through the one loop of
:func:`wear.chain.repeat_loop.repeat_at_site`). SI units; the repetition's settings are ``case.repeat``
(:class:`wear.case.RepeatSpec`).
"""

from __future__ import annotations

from collections.abc import Callable

from wear.case import Case, check_job_case
from wear.chain.plates import plate_model
from wear.chain.records import PlateState, RepeatResult

__all__ = ["repeat"]


def repeat(
    case: Case,
    progress: Callable[[int, int], None] | None = None,
    on_computed: Callable[[int, PlateState], None] | None = None,
) -> RepeatResult:
    """Run ``case.repeat.impacts`` impacts of ``case`` at one spot on the plate of ``case.fem.model``.
    ``progress(done, total)`` after each computed impact or block; ``on_computed(impact_number, fe_plate)`` after
    each computed impact (e.g. to write the FE mesh).

    Examples
    --------
    Two impacts of the default case at one spot on a coarse FE plate (element sizes × 6, 6 + 4 load steps): worn
    with α = 1, β = 0 under Thornton's pressure, each impact wears K times its own normal impulse m v_n (1 + e)
    (momentum balance), and the second, on the dent the first left, does less plastic work and rebounds with more
    of its normal speed:

    >>> import math
    >>> from wear.case import Case
    >>> from contact.theory import sphere_mass
    >>> case = Case().with_(
    ...     fem={"mesh_scale": 6.0, "load_steps": 6, "unload_steps": 4},
    ...     wear={"alpha": 1.0, "beta": 0.0, "pressure": "thornton", "speed": "sliding"},
    ...     repeat={"impacts": 2},
    ... )
    >>> result = repeat(case)
    >>> m_vn = sphere_mass(case.ball.radius, case.ball.density) * 3.0 * math.cos(math.radians(30.0))  # kg m/s
    >>> [bool(abs(r.wear_volume / (case.wear.K * m_vn * (1 + r.normal_restitution)) - 1) < 1e-3)
    ...  for r in result.records]
    [True, True]
    >>> first, second = result.records
    >>> second.plastic_work < first.plastic_work, second.normal_restitution > first.normal_restitution
    (True, True)
    """
    if not isinstance(case, Case):
        raise ValueError(f"case={type(case).__name__} is not a wear.Case")
    check_job_case(case, "repeat")
    return plate_model(case).repeat(case, progress, on_computed)
