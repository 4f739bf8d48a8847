r"""The wall: a surface of polygon faces, with each face's area and unit normal (SI units).

**Normal convention.** A face's unit normal :math:`\hat n` points *out of the fluid, into the wall material*: a
particle hitting the face has :math:`\hat n \cdot v > 0`, and its impact angle from the normal is
:math:`\theta = \arccos(\hat n \cdot v / |v|)` in [0°, 90°]. The normal follows the right-hand rule of the face's
point order, which is this convention for the boundary faces of a fluid volume oriented outward: OpenFOAM's
boundary faces (their normal points out of their owner cell) and the outward-oriented surface of the fluid
volume (an STL of the flow domain). A surface oriented the other way is read with ``flip=True``.

**Area and normal** of a polygon :math:`p_0 \ldots p_{k-1}`, planar or not, from its vector area

.. math:: \mathbf S = \tfrac12 \sum_{i=0}^{k-1} p_i \times p_{i+1 \bmod k}, \qquad A = |\mathbf S|,
          \qquad \hat n = \mathbf S / A,

which equals the sum of the areas of the triangles from any point to the polygon's edges (OpenFOAM's face area
vector). The faces are also cut into the fan triangles :math:`(p_0, p_i, p_{i+1})` for finding the face nearest
to a point (:mod:`wear.wall.locate`).

The faces are stored flat: the point indices of face f are ``face_points[face_offsets[f]:face_offsets[f + 1]]``.
"""

from __future__ import annotations

import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path

import meshio
import numpy as np

from contact.checks import check_path

__all__ = ["Wall", "concat_walls", "duplicate_faces", "read_surface", "SURFACE_CELLS", "THICKNESS_FIELD"]

#: The cell field of a wall file that gives the wall thickness of each face (m).
THICKNESS_FIELD = "thickness_m"
#: meshio cell types read as wall faces; lines and points in a file are not part of the wall.
SURFACE_CELLS = ("triangle", "quad", "polygon")
_VOLUME_CELLS = ("tetra", "hexahedron", "wedge", "pyramid", "tetra10", "hexahedron20")


@dataclass(frozen=True, eq=False)
class Wall:
    """A wall surface: ``points`` (m, (p, 3)), polygon faces (``face_points`` flat, ``face_offsets`` (f + 1,)), the
    ``patch`` (f,) each face belongs to (an index into ``patch_names``) and each face's ``label`` (f,) in its source
    (OpenFOAM: the global mesh face label; a surface file: the face's number in the file), and the wall thickness of
    each face ``thickness_m`` (m, (f,); NaN where not given; None: none given). ``other_patches``: the patches of
    the source mesh left out of the wall, as (name, first label, number of faces) (an OpenFOAM case read with some
    of its patches; records on them are counted, not placed on the wall). See the module docstring for the normal
    convention."""

    points: np.ndarray
    face_points: np.ndarray
    face_offsets: np.ndarray
    patch: np.ndarray
    patch_names: tuple[str, ...]
    labels: np.ndarray
    thickness_m: np.ndarray | None = None
    other_patches: tuple[tuple[str, int, int], ...] = ()

    def __post_init__(self) -> None:
        set_ = object.__setattr__
        set_(self, "points", np.asarray(self.points, dtype=float).reshape(-1, 3))
        set_(self, "face_points", np.asarray(self.face_points, dtype=np.int64))
        set_(self, "face_offsets", np.asarray(self.face_offsets, dtype=np.int64))
        set_(self, "patch", np.asarray(self.patch, dtype=np.int64))
        set_(self, "labels", np.asarray(self.labels, dtype=np.int64))
        set_(self, "patch_names", tuple(self.patch_names))
        set_(self, "other_patches", tuple((str(n), int(a), int(k)) for n, a, k in self.other_patches))
        bad = np.flatnonzero(~np.isfinite(self.points).all(axis=1))
        if len(bad):  # a NaN point gives NaN areas and sizes, and the face grid's cells from it crash
            raise ValueError(f"point {bad[0]} of the wall is not a finite position: {_text(self.points[bad[0]])} m")
        sizes = np.diff(self.face_offsets)
        if len(sizes) == 0:
            raise ValueError("the wall has no faces: give a surface with triangles, quads or polygons")
        if sizes.min() < 3:
            raise ValueError(f"face {int(np.argmin(sizes))} of the wall has {sizes.min()} points: a face needs >= 3")
        if len(self.patch) != len(sizes) or len(self.labels) != len(sizes):
            raise ValueError("patch and labels must give one value per face")
        if self.thickness_m is not None:
            set_(self, "thickness_m", np.asarray(self.thickness_m, dtype=float).reshape(len(sizes)))
            bad = np.flatnonzero(~(self.thickness_m > 0.0) & ~np.isnan(self.thickness_m))
            if len(bad):
                raise ValueError(
                    f"thickness_m={float(self.thickness_m[bad[0]])!r} at face {bad[0]} of patch "
                    f"{self.patch_names[self.patch[bad[0]]]} is out of range: a wall thickness is > 0 m"
                )
        bad = np.flatnonzero(self.area <= 0.0)
        if len(bad):
            raise ValueError(
                f"face {bad[0]} of patch {self.patch_names[self.patch[bad[0]]]} (label {self.labels[bad[0]]}) has "
                "zero area: remove degenerate faces from the wall"
            )

    def __len__(self) -> int:
        return len(self.face_offsets) - 1

    @cached_property
    def sizes(self) -> np.ndarray:
        """Number of points of each face."""
        return np.diff(self.face_offsets)

    @cached_property
    def vector_area(self) -> np.ndarray:
        """Vector area S of each face (m², (f, 3)); see the module docstring."""
        nxt = np.roll(self.face_points, -1)
        nxt[self.face_offsets[1:] - 1] = self.face_points[self.face_offsets[:-1]]
        edges = np.cross(self.points[self.face_points], self.points[nxt])
        return 0.5 * np.add.reduceat(edges, self.face_offsets[:-1], axis=0)

    @cached_property
    def area(self) -> np.ndarray:
        """Area :math:`|S|` of each face (m²)."""
        return np.linalg.norm(self.vector_area, axis=1)

    @cached_property
    def normal(self) -> np.ndarray:
        """Unit normal :math:`S / |S|` of each face, pointing into the wall material ((f, 3))."""
        return self.vector_area / self.area[:, None]

    @cached_property
    def centre(self) -> np.ndarray:
        """Mean of each face's points (m, (f, 3))."""
        return np.add.reduceat(self.points[self.face_points], self.face_offsets[:-1], axis=0) / self.sizes[:, None]

    @cached_property
    def triangles(self) -> tuple[np.ndarray, np.ndarray]:
        """The fan triangles (p₀, pᵢ, pᵢ₊₁) of the faces: point indices (t, 3) and the face of each (t,)."""
        face = np.repeat(np.arange(len(self)), self.sizes - 2)
        first = np.repeat(self.face_offsets[:-1], self.sizes - 2)
        i = np.arange(len(face)) - np.repeat(np.cumsum(self.sizes - 2) - (self.sizes - 2), self.sizes - 2) + 1
        fp = self.face_points
        return np.stack([fp[first], fp[first + i], fp[first + i + 1]], axis=1), face

    def face(self, f: int) -> np.ndarray:
        """The point indices of face ``f``."""
        return self.face_points[self.face_offsets[f] : self.face_offsets[f + 1]]

    def index_of_labels(self, labels: np.ndarray) -> np.ndarray:
        """The wall face index of each source face label, −1 where a label is not a face of the wall."""
        order = np.argsort(self.labels, kind="stable")
        sorted_labels = self.labels[order]
        pos = np.clip(np.searchsorted(sorted_labels, labels), 0, len(order) - 1)
        return np.where(sorted_labels[pos] == labels, order[pos], -1)

    def to_meshio(
        self, cell_fields: dict[str, np.ndarray] | None = None, point_fields: dict[str, np.ndarray] | None = None
    ) -> meshio.Mesh:
        """The wall as a meshio mesh (one cell block per face size), with the face normal, area (m²) and patch, plus
        ``cell_fields`` (name → one value or row per face, in face order) and ``point_fields`` (one per point)."""
        fields = {"area_m2": self.area, "normal": self.normal, "patch": self.patch, **(cell_fields or {})}
        for name, values in fields.items():
            if len(values) != len(self):
                raise ValueError(f"cell field {name!r} has {len(values)} values: the wall has {len(self)} faces")
        blocks, data = [], {name: [] for name in fields}
        for k in np.unique(self.sizes):
            faces = np.flatnonzero(self.sizes == k)
            idx = self.face_offsets[faces][:, None] + np.arange(k)
            kind = {3: "triangle", 4: "quad"}.get(int(k), "polygon")
            blocks.append((kind, self.face_points[idx]))
            for name, values in fields.items():
                data[name].append(np.asarray(values)[faces])
        return meshio.Mesh(self.points, blocks, cell_data=data, point_data=dict(point_fields or {}))


def _text(values: np.ndarray) -> str:
    return "(" + " ".join(f"{v:.6g}" for v in values) + ")"


def duplicate_faces(wall: Wall) -> tuple[int, int, int] | None:
    """(face, the earlier face it repeats, the number of faces that repeat another) of a wall whose faces repeat
    one another, or None. Two faces repeat when their centres coincide within 1e-6 of the face size: the centre
    of a convex face lies inside it, so such faces overlap (a face given twice, in any point order, or a part given
    twice), and the area and the impacts would be counted twice."""
    from scipy.spatial import cKDTree  # only here: the wall module needs no scipy otherwise

    reach = 1e-6 * float(np.sqrt(np.median(wall.area)))
    pairs = cKDTree(wall.centre).query_pairs(reach, output_type="ndarray")
    if len(pairs) == 0:
        return None
    pairs = np.sort(pairs, axis=1)
    first = pairs[np.lexsort((pairs[:, 0], pairs[:, 1]))][0]
    return int(first[1]), int(first[0]), len(np.unique(pairs[:, 1]))


def concat_walls(walls: Sequence[Wall]) -> Wall:
    """One wall of several (e.g. a wall split into files), faces in order; patches of the same name merge."""
    names: list[str] = []
    points, face_points, offsets, patch, labels = [], [], [np.zeros(1, np.int64)], [], []
    given = any(wall.thickness_m is not None for wall in walls)
    thickness = [np.full(len(w), np.nan) if w.thickness_m is None else w.thickness_m for w in walls]
    n_points = n_flat = 0
    for wall in walls:
        for name in wall.patch_names:
            if name not in names:
                names.append(name)
        remap = np.array([names.index(name) for name in wall.patch_names], dtype=np.int64)
        points.append(wall.points)
        face_points.append(wall.face_points + n_points)
        offsets.append(wall.face_offsets[1:] + n_flat)
        patch.append(remap[wall.patch])
        labels.append(wall.labels)
        n_points += len(wall.points)
        n_flat += len(wall.face_points)
    return Wall(
        points=np.concatenate(points),
        face_points=np.concatenate(face_points),
        face_offsets=np.concatenate(offsets),
        patch=np.concatenate(patch),
        patch_names=tuple(names),
        labels=np.concatenate(labels),
        thickness_m=np.concatenate(thickness) if given else None,
        other_patches=tuple(p for wall in walls for p in wall.other_patches),
    )


def read_surface(path: str | Path, flip: bool = False, patch: str | None = None) -> Wall:
    """A wall from a surface file meshio reads (STL, OBJ, VTU, VTP, PLY, ...): its triangles, quads and polygons,
    one patch named ``patch`` (default: the file's stem); ``flip`` reverses the faces' orientation (see the module
    docstring). A cell field ``thickness_m`` in the file is the wall thickness of each face (m). A volume mesh is
    refused (give its boundary surface)."""
    p = check_path("path", path, "a surface file (STL, OBJ, VTU, ...)")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # meshio's notes on a format are not the user's business
            mesh = meshio.read(p)
    except Exception as err:  # meshio raises many types for a file it cannot read
        raise ValueError(f"wall={str(p)!r} is not a surface meshio reads ({type(err).__name__}: {err})") from None
    volume = [c.type for c in mesh.cells if c.type in _VOLUME_CELLS]
    if volume:
        raise ValueError(f"wall={str(p)!r} is a volume mesh ({volume[0]} cells): give the wall's surface")
    kept = [i for i, c in enumerate(mesh.cells) if c.type in SURFACE_CELLS or c.type.startswith("polygon")]
    blocks = [mesh.cells[i].data for i in kept]
    thickness = mesh.cell_data.get(THICKNESS_FIELD)
    if not blocks:
        raise ValueError(f"wall={str(p)!r} has no triangles, quads or polygons: give the wall's surface")
    points = np.asarray(mesh.points, dtype=float)
    bad = np.flatnonzero(~np.isfinite(points).all(axis=1))
    if len(bad):  # named here, with the file: the wall's own check knows no file
        raise ValueError(
            f"wall={str(p)!r}, point {bad[0]}: {_text(points[bad[0]])} is not a finite position (m): give every "
            "point of the wall as numbers"
        )
    if thickness is not None:
        given = np.concatenate([np.ravel(thickness[i]) for i in kept]).astype(float)
        bad = np.flatnonzero(~np.isfinite(given))
        if len(bad):  # NaN would leave the face out of the shortest life without a word
            raise ValueError(
                f"wall={str(p)!r}, face {bad[0]}, column {THICKNESS_FIELD}: {float(given[bad[0]])!r} is not a finite "
                "number: give every face's wall thickness in m (> 0)"
            )
    blocks = [np.asarray(block, dtype=np.int64) for block in blocks]
    blocks = [block[:, ::-1] for block in blocks] if flip else blocks
    sizes = np.concatenate([np.full(len(block), block.shape[1]) for block in blocks])
    return Wall(
        points=points if points.shape[1] == 3 else np.column_stack([points, np.zeros(len(points))]),
        face_points=np.concatenate([block.ravel() for block in blocks]),
        face_offsets=np.concatenate([[0], np.cumsum(sizes)]),
        patch=np.zeros(len(sizes), np.int64),
        patch_names=(patch or p.stem,),
        labels=np.arange(len(sizes)),
        thickness_m=None if thickness is None else given,
    )
