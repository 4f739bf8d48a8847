"""A sweep stage (``impactwear sweep``'s ``[sweep] stage``): the job whose default case a sweep's ``[base]`` is laid
over, the case tables its results depend on, the function it runs and the SI units of its results."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

from wear.case import default_case

__all__ = ["Stage"]


@dataclass(frozen=True)
class Stage:
    """A sweep stage of a job: ``name`` (``[sweep] stage``), ``job`` (a name of :data:`wear.case.JOBS`: a sweep's
    ``[base]`` is laid over its default case), the ``tables`` its results depend on (only those enter the case id),
    a one-line ``description``, its ``function`` (a case as tables of values, SI units → a flat dict of JSON
    scalars) and ``units``, result name → SI unit for the results that have one (for the sweep's figures and the
    column names of ``results.csv``)."""

    name: str
    job: str
    tables: tuple[str, ...]
    description: str
    function: Callable[[dict], dict]
    units: Mapping[str, str] = field(default_factory=dict)

    def run(self, case: dict) -> dict:
        """The stage's results for ``case`` (a full case as tables of values, SI units)."""
        return self.function(case)

    def result_units(self) -> dict[str, str]:
        """Result name → SI unit, for the results that have one."""
        return dict(self.units)

    def defaults(self) -> dict:
        """The default case of the stage's job, as tables of values (the tables the stage reads)."""
        return default_case(self.job).to_dict(self.tables)
