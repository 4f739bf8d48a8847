"""Erosion of a plate patch by a particle stream: the stream (:mod:`wear.erosion.stream`), the footprint of one
impact (:mod:`wear.erosion.response`) and the response table it is interpolated in (:mod:`wear.erosion.table`), the
eroded patch (:mod:`wear.erosion.patch`, with the stamping kernels of :mod:`wear.erosion.stamp`, the bound on its
memory of :mod:`wear.erosion.memory` and its result :mod:`wear.erosion.result`) and the erosion of a case
(:mod:`wear.erosion.run`). SI units, angles in degrees from the plate normal."""

from wear.erosion.patch import erode, footprint_on_grid
from wear.erosion.response import Footprint, ImpactResponse
from wear.erosion.result import ErosionResult
from wear.erosion.run import ErosionRun, erode_angles, erode_case, nominal_contact_radius
from wear.erosion.stream import Stream, impacts_on_patch
from wear.erosion.table import ResponseTable, build_response_table, table_axes

__all__ = [
    "ErosionResult",
    "ErosionRun",
    "Footprint",
    "ImpactResponse",
    "ResponseTable",
    "Stream",
    "build_response_table",
    "erode",
    "erode_angles",
    "erode_case",
    "footprint_on_grid",
    "impacts_on_patch",
    "nominal_contact_radius",
    "table_axes",
]
