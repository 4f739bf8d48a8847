"""Erosion of a plate patch by a particle stream: the stream and the eroded patch (:mod:`wear.erosion.stream`), the
footprint of one impact and the response table it is interpolated in (:mod:`wear.erosion.response`), the
stamping kernels (:mod:`wear.erosion.stamp`) and the erosion of a case (:mod:`wear.erosion.run`). SI units, angles
in degrees from the plate normal."""

from wear.erosion.response import Footprint, ImpactResponse, ResponseTable, build_response_table, table_axes
from wear.erosion.run import ErosionRun, erode_angles, erode_case, nominal_contact_radius
from wear.erosion.stream import ErosionResult, Stream, erode, footprint_on_grid

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
    "nominal_contact_radius",
    "table_axes",
]
