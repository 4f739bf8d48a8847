"""The chains: one impact through the whole model (:mod:`wear.chain.single`), repeated impacts at one site on the
plate the previous ones left (:mod:`wear.chain.repeated_impacts`), the FE plate along a load–unload path
(:mod:`wear.chain.indent`) and the coupled restitution against Thornton (:mod:`wear.chain.restitution`)."""

from wear.chain.indent import IndentRun, indent_case
from wear.chain.records import RepeatResult
from wear.chain.repeated_impacts import repeat
from wear.chain.restitution import RestitutionSweep, restitution_sweep
from wear.chain.single import RunResult, run

__all__ = [
    "IndentRun",
    "RepeatResult",
    "RestitutionSweep",
    "RunResult",
    "indent_case",
    "repeat",
    "restitution_sweep",
    "run",
]
