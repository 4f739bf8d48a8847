"""How a wall run places its records on the wall and where it sums them: one frozen :class:`WallOptions`, checked
where it is made (from ``impactwear wall``'s flags, or by a Python caller) and carried whole from
:func:`wear.wall.erode_component` through :func:`wear.wall.engine.erode_wall` to every worker's chunk
(:func:`wear.wall.engine.chunk_sums`, :func:`wear.wall.hits.hits_on_wall`), so that no layer between repeats or
re-checks its fields."""

from __future__ import annotations

from dataclasses import dataclass

from contact.checks import check_bool, check_choice, check_count, check_instance, check_number

__all__ = ["NORMALS", "WallOptions"]

#: Which normal an impact angle is measured against.
NORMALS = ("recorded", "face")


@dataclass(frozen=True)
class WallOptions:
    """``normal``: the normal an impact angle is measured against (one of :data:`NORMALS`; None: the recorded one
    where the records carry it, else the face's); ``tolerance`` (m): the largest distance of a hit from its face
    (None: :func:`wear.wall.locate.default_tolerance` of the wall); ``skip_bad``: count and leave out the records
    far from the wall or leaving it instead of refusing them; ``workers``: the processes that sum the chunks (1:
    this one); ``scheduler``: None (``workers`` local processes), ``"local"`` (a new Dask ``LocalCluster`` of
    ``workers`` processes) or the address of a Dask scheduler (``tcp://host:port``). A bad field is a one-line
    ``ValueError`` naming it."""

    normal: str | None = None
    tolerance: float | None = None
    skip_bad: bool = False
    workers: int = 1
    scheduler: str | None = None

    def __post_init__(self) -> None:
        if self.normal is not None:
            check_choice("normal", self.normal, NORMALS)
        if self.tolerance is not None:
            check_number(
                "tolerance",
                self.tolerance,
                low=0.0,
                low_open=True,
                allow_inf=True,
                units="m",
                what="the distance of a hit from its face",
            )
        check_bool("skip_bad", self.skip_bad)
        check_count("workers", self.workers, low=1, what="processes")
        if self.scheduler is not None:
            check_instance(
                "scheduler", self.scheduler, str, "a Dask scheduler: 'local' or an address, e.g. tcp://host:8786"
            )
