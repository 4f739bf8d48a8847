r"""The impact table on the wall: each record's face, the unit normal its angle is measured against, its angle
and speed.

The impact angle from the wall normal (deg, the project's convention; the erosion literature's angle from the
surface is α = 90° − θ) of a record of velocity v at a hit with unit normal :math:`\hat n` (pointing into the
wall, :mod:`wear.wall.mesh`) is

.. math:: \theta = \arccos\left(\hat n \cdot \frac{v}{|v|}\right) \in [0°, 90°],

the normal being the one the source code used where the records carry it (``normal="recorded"``: OpenFOAM's tet
triangle) or the face's (``normal="face"``). A record whose velocity points out of the wall
(:math:`\hat n \cdot v < 0`, θ > 90° + :data:`GRAZING_DEG`) or that lies farther than ``tolerance`` from its face
is bad input: a ``ValueError`` naming its file, row and column, or with ``skip_bad`` counted in
:attr:`Hits.skipped` and left out of every sum (its face is −1).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from contact.checks import check_instance
from wear.wall.grid import FaceGrid
from wear.wall.locate import default_tolerance, distance_to_faces, nearest_faces
from wear.wall.mesh import Wall
from wear.wall.options import WallOptions
from wear.wall.records import ImpactRecords

__all__ = ["Hits", "hits_on_wall", "GRAZING_DEG"]

#: How far past 90° (deg from the normal) a record is still a grazing hit, not one leaving the wall: a parcel
#: sliding along a wall has θ = 90° to round-off of its velocity against the normal (about 1e-4° seen).
GRAZING_DEG = 1e-3
_GRAZING_COSINE = -float(np.sin(np.radians(GRAZING_DEG)))


@dataclass(frozen=True, eq=False)
class Hits:
    """The records on the wall: ``face`` (n,) the wall face of each (−1: skipped), ``normal`` (n, 3) the unit
    normal the angle is measured against, ``angle`` (n,) θ (deg from the normal), ``speed`` (n,) :math:`|v|` (m/s),
    ``distance`` (n,) from the face (m); ``skipped``: the number of records left out, by reason (``"far_from_wall"``,
    ``"leaving_wall"``)."""

    face: np.ndarray
    normal: np.ndarray
    angle: np.ndarray
    speed: np.ndarray
    distance: np.ndarray
    skipped: dict[str, int]

    @property
    def kept(self) -> np.ndarray:
        """The records on a face (n,) bool."""
        return self.face >= 0


def hits_on_wall(
    records: ImpactRecords,
    wall: Wall,
    options: WallOptions | None = None,
    locator: FaceGrid | None = None,
) -> Hits:
    """Place ``records`` on ``wall``: the face of each (its own, or the nearest to its position when −1), the
    normal, the angle and the speed, with ``options``' ``normal``, ``tolerance`` and ``skip_bad``
    (:class:`wear.wall.options.WallOptions`; default: its defaults). ``locator``: the wall's
    :class:`wear.wall.grid.FaceGrid` to find the nearest faces and the distances to the faces given with (fast, for
    many records; default :func:`wear.wall.locate.nearest_faces`, :func:`wear.wall.locate.distance_to_faces`). See
    the module docstring for the bad records."""
    check_instance(
        "records", records, ImpactRecords, "a wear.wall.ImpactRecords: wear.wall.read_table(path) or the like"
    )
    check_instance("wall", wall, Wall, "a wear.wall.Wall: wear.wall.read_wall(path)")
    options = WallOptions() if options is None else options
    check_instance("options", options, WallOptions, "a wear.wall.options.WallOptions")
    normal = options.normal or ("recorded" if records.normal is not None else "face")
    if normal == "recorded" and records.normal is None:
        raise ValueError(f"normal='recorded': the records of {records.files[0]} carry no normal; use normal='face'")
    tolerance = options.tolerance
    if tolerance is None:  # the wall's own (WallOptions checked a given one)
        tolerance = default_tolerance(wall)
        if not tolerance > 0.0:
            raise ValueError(f"tolerance={tolerance!r} is out of range: the distance of a hit from its face is > 0 m")
    if len(records.face) and records.face.max() >= len(wall):
        i = int(np.argmax(records.face))
        raise ValueError(
            f"{records.where(i, 'face')}: {records.face[i]} is out of range: the wall has {len(wall)} faces "
            f"(0 ... {len(wall) - 1}, or -1: found from the position)"
        )
    face = records.face.copy()
    distance = np.zeros(len(face))
    given = face >= 0
    if given.any():
        measure = distance_to_faces if locator is None else lambda _, points, faces: locator.distance(points, faces)
        distance[given] = measure(wall, records.position[given], face[given])
    if (~given).any():
        find = nearest_faces if locator is None else lambda _, points: locator.nearest(points)
        face[~given], distance[~given] = find(wall, records.position[~given])
    n = records.normal if normal == "recorded" else wall.normal[face]
    speed = records.speed
    cosine = np.clip(np.einsum("ij,ij->i", n, records.velocity) / speed, -1.0, 1.0)
    far = distance > tolerance
    away = ~far & (cosine < _GRAZING_COSINE)
    angle = np.degrees(np.arccos(np.where(away, cosine, np.maximum(cosine, 0.0))))  # grazing: 90°, not past it
    skipped = {}
    for bad, reason in ((far, "far_from_wall"), (away, "leaving_wall")):
        hit = np.flatnonzero(bad)
        if len(hit) and not options.skip_bad:
            raise ValueError(_message(records, wall, hit[0], reason, given, face, distance, angle, tolerance, len(hit)))
        if len(hit):
            skipped[reason] = len(hit)
    face[far | away] = -1
    return Hits(face=face, normal=n, angle=angle, speed=speed, distance=distance, skipped=skipped)


#: How to keep going past such records.
_SKIP = "; to count and leave out such records instead, give skip_bad (impactwear wall --skip-bad)"


def _message(
    records: ImpactRecords,
    wall: Wall,
    i: int,
    reason: str,
    given: np.ndarray,
    face: np.ndarray,
    distance: np.ndarray,
    angle: np.ndarray,
    tolerance: float,
    count: int,
) -> str:
    """One line on record ``i``, too far from the wall or leaving it (``reason``)."""
    f = face[i]
    name = f"face {f} (label {wall.labels[f]}) of patch {wall.patch_names[wall.patch[f]]}"
    more = f" ({count - 1} more such records)" if count > 1 else ""
    if reason == "far_from_wall":
        text = " ".join(f"{v:.6g}" for v in records.position[i])
        which = "its face" if given[i] else "the nearest wall face"
        return (
            f"{records.where(i, 'position')}: ({text}) lies {distance[i]:.3g} m from {which}, {name}, farther than "
            f"tolerance={tolerance:.6g} m{more}{_SKIP}"
        )
    text = " ".join(f"{v:.6g}" for v in records.velocity[i])
    return (
        f"{records.where(i, 'velocity')}: ({text}) points out of the wall ({angle[i]:.6g} deg from the normal of "
        f"{name}; the wall normals point out of the fluid: if every hit does, the wall is oriented the other way, "
        f"flip it){more}{_SKIP}"
    )
