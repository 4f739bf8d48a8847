"""Erosion of a component's wall from CFD or DEM impact records: the impact table (:mod:`wear.wall.records`) read
from OpenFOAM (:mod:`wear.wall.openfoam`), Ansys Fluent (:mod:`wear.wall.fluent`) or a plain table
(:mod:`wear.wall.table`), the wall (:mod:`wear.wall.mesh`; an OpenFOAM case's wall patches: :mod:`wear.wall.foam`),
the records placed on it with their impact angles (:mod:`wear.wall.hits`, :mod:`wear.wall.locate`), the wear law per
record (:mod:`wear.wall.per_record`), per-face sums (:mod:`wear.wall.sums`), and from them the rates, remaining life and
worn wall (:mod:`wear.wall.worn`); all of it from records to the worn wall, in chunks on a pool or a Dask cluster,
by :func:`erode_component` (:mod:`wear.wall.component`, :mod:`wear.wall.engine`). SI units; angles in degrees from the
wall normal, which points out of the fluid into the wall."""

from wear.wall.component import ComponentErosion, erode_component, read_wall
from wear.wall.engine import WallSums, erode_wall
from wear.wall.fluent import read_fluent_dpm
from wear.wall.foam import read_patch_field, read_polymesh
from wear.wall.hits import Hits, hits_on_wall
from wear.wall.mesh import Wall, concat_walls, read_surface
from wear.wall.openfoam import read_patch_post_processing
from wear.wall.options import WallOptions
from wear.wall.per_record import WallLaw, wall_law
from wear.wall.records import ImpactRecords, concat_records
from wear.wall.sources import plan_chunks
from wear.wall.sums import face_sum, record_volumes
from wear.wall.table import read_table
from wear.wall.worn import HotSpots, WallWear, hot_spots, remaining_life, wall_wear, worn_mesh, worn_wall

__all__ = [
    "ComponentErosion",
    "Hits",
    "HotSpots",
    "ImpactRecords",
    "Wall",
    "WallLaw",
    "WallOptions",
    "WallSums",
    "WallWear",
    "concat_records",
    "concat_walls",
    "erode_component",
    "erode_wall",
    "face_sum",
    "hits_on_wall",
    "hot_spots",
    "plan_chunks",
    "read_fluent_dpm",
    "read_patch_field",
    "read_patch_post_processing",
    "read_polymesh",
    "read_surface",
    "read_table",
    "read_wall",
    "record_volumes",
    "remaining_life",
    "wall_law",
    "wall_wear",
    "worn_mesh",
    "worn_wall",
]
