r"""From the eroded volume of each wall face to rates, remaining life and the worn wall (SI units).

**Rates.** Face f of area :math:`A_f` lost the volume :math:`V_f` (m³) of plate material of density ρ (kg/m³)
during the exposure time T (s) that the impact records span. Its eroded mass, erosion rate and thickness-loss rate
are

.. math:: m_f = \rho V_f, \qquad E_f = \frac{\rho V_f}{A_f T}\ \ (\mathrm{kg\,m^{-2}\,s^{-1}}), \qquad
          \dot h_f = \frac{V_f}{A_f T}\ \ (\mathrm{m/s}),

:math:`\dot h_f` also in mm/year with the year of :data:`SECONDS_PER_YEAR` (365.25 days). A wall of thickness
:math:`t_f` (a value, or one per face) lasts :math:`L_f = t_f / \dot h_f`; :math:`L_f = \infty` on a face
without wear.

**The worn wall.** After a service time :math:`t_s` the face has lost the depth :math:`h_f = \dot h_f t_s =
V_f t_s / (T A_f)`. The wall's vertices move, not its faces: vertex v moves by

.. math:: h_v = \frac{\sum_{f \ni v} A_f h_f}{\sum_{f \ni v} A_f}
          \quad\text{along}\quad \hat n_v = \frac{\sum_{f \ni v} \mathbf S_f}{|\sum_{f \ni v} \mathbf S_f|},

into the wall (:math:`\mathbf S_f` the face's vector area, :mod:`wear.wall.mesh`). The area weighting makes
:math:`h_v` the volume lost around the vertex over the area it was lost from, :math:`\sum V_f / \sum A_f` (scaled
to :math:`t_s`): a uniform depth is kept exactly; cutting a face into smaller faces of the same depth does not
change it; a sliver face does not weigh as much as a large one (an unweighted mean of the faces would let it). The
same weighting of the normals makes :math:`\hat n_v` the normal of the vertex's neighbourhood as a whole.

*Volume.* Lump each face's area equally onto its k vertices, :math:`A_v = \sum_{f \ni v} A_f / k_f`. On a wall
whose faces all have the same k (all triangles, or all quads), :math:`A_v = \sum_{f \ni v} A_f / k`, so

.. math:: \sum_v A_v h_v = \frac1k \sum_v \sum_{f \ni v} A_f h_f = \sum_f A_f h_f:

the lumped volume equals the eroded volume exactly, whatever the depths. On a flat wall of triangles the volume
between the wall and the worn wall is exactly this sum (each face sweeps a prism of volume :math:`A_f` times the
mean of its vertices' depths), so the eroded volume is conserved exactly. On a curved wall the swept volume
(:func:`swept_volume`) differs from it by the change of area with depth and by the faceting: on the inner wall of a
pipe of radius R cut into N faces round, by the factor :math:`\cos(\pi/N)\,(1 + h/(2R))` (+0.28 % for R = 25 mm,
h = 0.2 mm, N = 64). On a wall of mixed face sizes the lumped volume is not conserved exactly either.
"""

from __future__ import annotations

from dataclasses import dataclass

import meshio
import numpy as np

from contact.checks import check_instance
from wear.wall.mesh import Wall

__all__ = [
    "SECONDS_PER_YEAR",
    "HotSpots",
    "WallWear",
    "hot_spots",
    "remaining_life",
    "swept_volume",
    "vertex_depth",
    "vertex_normals",
    "wall_wear",
    "worn_mesh",
    "worn_wall",
]

#: The year of the rates in mm/year and of the lives in years: 365.25 days (s).
SECONDS_PER_YEAR = 365.25 * 86400.0


@dataclass(frozen=True, eq=False)
class WallWear:
    """The wear of each face of a wall (module docstring): ``volume_m3`` (f,) eroded over ``exposure_s`` by the
    impacts on a plate of ``density_kg_m3``, the faces' ``area_m2`` (f,), and the derived per-face mass (kg),
    erosion rate (kg m⁻² s⁻¹) and thickness-loss rate (m/s)."""

    volume_m3: np.ndarray
    area_m2: np.ndarray
    exposure_s: float
    density_kg_m3: float
    mass_kg: np.ndarray
    erosion_rate_kg_m2_s: np.ndarray
    thickness_loss_rate_m_s: np.ndarray

    @property
    def thickness_loss_mm_year(self) -> np.ndarray:
        """The thickness-loss rate in mm/year (:data:`SECONDS_PER_YEAR`)."""
        return self.thickness_loss_rate_m_s * 1e3 * SECONDS_PER_YEAR

    def depth_m(self, service_s: float) -> np.ndarray:
        r"""The depth each face has lost after ``service_s`` (s): :math:`V_f t_s / (T A_f)` (m)."""
        if not (np.isfinite(service_s) and service_s >= 0.0):
            raise ValueError(f"service_s={service_s!r} is out of range: the service time is >= 0 s and finite")
        return self.thickness_loss_rate_m_s * service_s


def wall_wear(wall: Wall, volume_m3: np.ndarray, exposure_s: float, density_kg_m3: float) -> WallWear:
    """The per-face rates of ``wall`` from its eroded volume ``volume_m3`` (m³, one per face) over ``exposure_s``
    (s) in a plate of ``density_kg_m3`` (kg/m³); see the module docstring."""
    volume = np.asarray(volume_m3, dtype=float)
    if volume.shape != (len(wall),):
        raise ValueError(f"volume_m3 has shape {volume.shape}: give one volume (m^3) per wall face ({len(wall)})")
    bad = np.flatnonzero(~np.isfinite(volume) | (volume < 0.0))
    if len(bad):
        raise ValueError(f"volume_m3[{bad[0]}]={float(volume[bad[0]])!r} is out of range: an eroded volume is >= 0 m^3")
    if not (np.isfinite(exposure_s) and exposure_s > 0.0):
        raise ValueError(f"exposure_s={exposure_s!r} is out of range: the exposure time is > 0 s and finite")
    if not (np.isfinite(density_kg_m3) and density_kg_m3 > 0.0):
        raise ValueError(f"density_kg_m3={density_kg_m3!r} is out of range: the plate density is > 0 kg/m^3")
    rate = volume / (wall.area * exposure_s)
    return WallWear(
        volume_m3=volume,
        area_m2=wall.area,
        exposure_s=float(exposure_s),
        density_kg_m3=float(density_kg_m3),
        mass_kg=density_kg_m3 * volume,
        erosion_rate_kg_m2_s=density_kg_m3 * rate,
        thickness_loss_rate_m_s=rate,
    )


def remaining_life(wear: WallWear, thickness_m: float | np.ndarray) -> np.ndarray:
    r"""The time (s) each face takes to lose ``thickness_m`` (m; a value or one per face) at its thickness-loss
    rate: :math:`t_f / \dot h_f`, ``inf`` on a face without wear, NaN on a face of unknown thickness (NaN)."""
    check_instance("wear", wear, WallWear, "a wear.wall.WallWear: wear.wall.wall_wear(...)")
    rate = wear.thickness_loss_rate_m_s
    thickness = np.asarray(thickness_m, dtype=float)
    if thickness.ndim == 0:
        thickness = np.full(rate.shape, float(thickness))
    if thickness.shape != rate.shape:
        raise ValueError(f"thickness_m has shape {thickness.shape}: give one value (m) or one per face ({len(rate)})")
    bad = np.flatnonzero(np.isinf(thickness) | (thickness <= 0.0))
    if len(bad):
        raise ValueError(
            f"thickness_m={float(thickness[bad[0]])!r} (face {bad[0]}) is out of range: a thickness is > 0 m"
        )
    life = np.full(rate.shape, np.inf)
    np.divide(thickness, rate, out=life, where=rate > 0.0)
    life[np.isnan(thickness)] = np.nan
    return life


def vertex_normals(wall: Wall) -> np.ndarray:
    """The unit normal at each point of ``wall`` ((p, 3), into the wall): the sum of the vector areas of the faces
    around it, normalised (module docstring); a point on no face gets (0, 0, 0)."""
    owner = np.repeat(np.arange(len(wall)), wall.sizes)
    n_points = len(wall.points)
    vector = wall.vector_area[owner]
    summed = np.stack([np.bincount(wall.face_points, weights=vector[:, i], minlength=n_points) for i in range(3)], 1)
    norm = np.linalg.norm(summed, axis=1)
    return np.divide(summed, norm[:, None], out=np.zeros_like(summed), where=norm[:, None] > 0.0)


def vertex_depth(wall: Wall, depth_m: np.ndarray) -> np.ndarray:
    """The depth (m) at each point of ``wall``: the area-weighted mean of the depths ``depth_m`` (m, one per face)
    of the faces around it (module docstring); 0 at a point on no face."""
    owner = np.repeat(np.arange(len(wall)), wall.sizes)
    area = wall.area[owner]
    weight = np.bincount(wall.face_points, weights=area, minlength=len(wall.points))
    total = np.bincount(wall.face_points, weights=area * np.asarray(depth_m, float)[owner], minlength=len(wall.points))
    return np.divide(total, weight, out=np.zeros_like(total), where=weight > 0.0)


def worn_wall(wall: Wall, wear: WallWear, service_s: float) -> Wall:
    """``wall`` after ``service_s`` (s) of the wear ``wear``: each point moved into the wall along its normal by its
    depth (:func:`vertex_normals`, :func:`vertex_depth`); faces, patches and labels unchanged."""
    if len(wear.volume_m3) != len(wall):
        raise ValueError(
            f"the wear has {len(wear.volume_m3)} faces: the wall has {len(wall)}; give the wear of this wall"
        )
    depth = vertex_depth(wall, wear.depth_m(service_s))
    return Wall(
        points=wall.points + depth[:, None] * vertex_normals(wall),
        face_points=wall.face_points,
        face_offsets=wall.face_offsets,
        patch=wall.patch,
        patch_names=wall.patch_names,
        labels=wall.labels,
    )


def swept_volume(wall: Wall, worn: Wall) -> float:
    r"""The volume (m³) between ``wall`` and ``worn`` (the same faces on moved points), positive where the worn wall
    lies inside the material: the divergence theorem, :math:`\frac16 \sum x_0 \cdot (x_1 \times x_2)` over the
    triangles of the closed surface made of the worn wall's fan triangles, the wall's reversed, and the quads that the
    wall's boundary edges sweep."""
    if worn.points.shape != wall.points.shape or not np.array_equal(worn.face_points, wall.face_points):
        raise ValueError("worn is not the wall's faces on moved points: give worn_wall(wall, ...)")
    tri, _ = wall.triangles
    origin = wall.points.mean(axis=0)
    p, q = wall.points - origin, worn.points - origin

    def volume(a: np.ndarray, b: np.ndarray, c: np.ndarray) -> float:
        return float(np.einsum("ij,ij->", a, np.cross(b, c))) / 6.0

    total = volume(q[tri[:, 0]], q[tri[:, 1]], q[tri[:, 2]]) - volume(p[tri[:, 0]], p[tri[:, 1]], p[tri[:, 2]])
    edges = np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]])
    _, inverse, counts = np.unique(np.sort(edges, axis=1), axis=0, return_inverse=True, return_counts=True)
    a, b = edges[counts[inverse.ravel()] == 1].T
    # the quad (a, b, b', a') of a boundary edge a -> b (in its face's order) faces out of the swept region
    return total + volume(p[a], p[b], q[b]) + volume(p[a], q[b], q[a])


def worn_mesh(
    wall: Wall,
    wear: WallWear,
    service_s: float,
    thickness_m: float | np.ndarray,
    cell_fields: dict[str, np.ndarray] | None = None,
) -> meshio.Mesh:
    """The worn wall after ``service_s`` (s) as a meshio mesh (write it as STL or VTU), with the per-face fields
    ``eroded_volume_m3``, ``eroded_mass_kg``, ``erosion_rate_kg_m2_s``, ``thickness_loss_rate_m_s``,
    ``thickness_loss_mm_year``, ``remaining_life_s`` (of ``thickness_m``, m) and ``wear_depth_m`` (the face's depth
    after ``service_s``), any more ``cell_fields`` (name → one value per face), and the point field ``wear_depth_m``
    (the depth each point moved)."""
    depth = wear.depth_m(service_s)
    fields = {
        "eroded_volume_m3": wear.volume_m3,
        "eroded_mass_kg": wear.mass_kg,
        "erosion_rate_kg_m2_s": wear.erosion_rate_kg_m2_s,
        "thickness_loss_rate_m_s": wear.thickness_loss_rate_m_s,
        "thickness_loss_mm_year": wear.thickness_loss_mm_year,
        "remaining_life_s": remaining_life(wear, thickness_m),
        "wear_depth_m": depth,
        **(cell_fields or {}),
    }
    return worn_wall(wall, wear, service_s).to_meshio(fields, {"wear_depth_m": vertex_depth(wall, depth)})


@dataclass(frozen=True, eq=False)
class HotSpots:
    """The faces of fastest thickness loss, fastest first: ``face`` (n,) wall face index, ``label`` (n,) its source
    label, ``patch`` (n,) its patch name, ``position_m`` (n, 3) its centre, ``thickness_loss_rate_m_s`` and
    ``thickness_loss_mm_year`` (n,), ``remaining_life_s`` and ``remaining_life_year`` (n,)."""

    face: np.ndarray
    label: np.ndarray
    patch: tuple[str, ...]
    position_m: np.ndarray
    thickness_loss_rate_m_s: np.ndarray
    thickness_loss_mm_year: np.ndarray
    remaining_life_s: np.ndarray
    remaining_life_year: np.ndarray


def hot_spots(wall: Wall, wear: WallWear, thickness_m: float | np.ndarray, n: int = 10) -> HotSpots:
    """The ``n`` faces of ``wall`` with the largest thickness-loss rate (ties: lower face index first) and their
    remaining life of ``thickness_m`` (m; a value or one per face, NaN where unknown); faces without wear are left
    out."""
    if not (isinstance(n, (int, np.integer)) and n >= 1):
        raise ValueError(f"n={n!r} is out of range: the number of hot spots is an integer >= 1")
    rate = wear.thickness_loss_rate_m_s
    life = remaining_life(wear, thickness_m)
    order = np.lexsort((np.arange(len(rate)), -rate))
    face = order[rate[order] > 0.0][:n]
    return HotSpots(
        face=face,
        label=wall.labels[face],
        patch=tuple(wall.patch_names[p] for p in wall.patch[face]),
        position_m=wall.centre[face],
        thickness_loss_rate_m_s=rate[face],
        thickness_loss_mm_year=wear.thickness_loss_mm_year[face],
        remaining_life_s=life[face],
        remaining_life_year=life[face] / SECONDS_PER_YEAR,
    )
