r"""The worn and dented plate surface as meshes (meshio, ParaView-readable). SI units: metres.

The plate surface after one impact is described by two depths, both positive *into* the plate:

* the wear depth w(x, y) (m) on the regular wear grid (x along the impact direction, y across),
* the dent depth h(r) (m): the FE residual surface profile of the axisymmetric plate, placed at
  the contact centre (x_c, y_c) of maximum overlap, r = √((x − x_c)² + (y − y_c)²).

A surface node sits at :math:`z = -(h + w)`, the undeformed surface being z = 0.

Approximation (oblique impacts on the axisymmetric plate): the dent is the residual profile of a *normal*
indentation to the same maximum overlap, centred where the overlap peaked. The tangential traction and the drift of
the contact centre during the impact (a few percent of the contact diameter for the default case) are not in the
dent shape; the wear map does carry them. The 3-D plate (``fem.model = "3d"``) gives the dent itself as a field on
the grid (``dent_grid``): asymmetric, with its pile-up lip.
"""

from __future__ import annotations

from dataclasses import dataclass

import meshio
import numpy as np
from scipy.interpolate import RegularGridInterpolator

from contact.checks import check_array, check_number

__all__ = [
    "DeformedSurface",
    "DentDimensions",
    "surface_mesh",
    "plate_block_mesh",
    "deform_plate_mesh",
    "integrate_point_data",
]


@dataclass(frozen=True, eq=False)
class DeformedSurface:
    """Wear on a grid plus an axisymmetric dent: the top surface of the plate (m).

    Attributes
    ----------
    x : (nx,) array, m
        Grid coordinates along the impact direction, strictly increasing.
    y : (ny,) array, m
        Grid coordinates across the impact direction, strictly increasing.
    wear_depth : (nx, ny) array, m
        Worn depth at the grid nodes (``indexing="ij"``), ≥ 0.
    dent_radius : (k,) array, m
        Radii of the residual dent profile, increasing from 0.
    dent_depth : (k,) array, m
        Residual dent depth at ``dent_radius`` (positive into the plate; pile-up is negative).
        Zero beyond the last radius.
    dent_centre : (float, float), m
        (x_c, y_c) where the dent is centred: the contact centre at maximum overlap.
    dent_grid : (nx, ny) array, m, or None
        The dent on the grid nodes (the 3-D plate's residual surface); when given, it is the dent, and
        ``dent_radius``/``dent_depth`` are its profile across the track through ``dent_centre`` (for reference).
    """

    x: np.ndarray
    y: np.ndarray
    wear_depth: np.ndarray
    dent_radius: np.ndarray
    dent_depth: np.ndarray
    dent_centre: tuple[float, float] = (0.0, 0.0)
    dent_grid: np.ndarray | None = None

    def __post_init__(self) -> None:
        x = check_array("x", self.x, units="m", min_size=2)
        y = check_array("y", self.y, units="m", min_size=2)
        if np.any(np.diff(x) <= 0) or np.any(np.diff(y) <= 0):
            raise ValueError("x and y must increase strictly (m)")
        w = check_array("wear_depth", self.wear_depth, low=0.0, units="m", ndim=2)
        if w.shape != (x.size, y.size):
            raise ValueError(f"wear_depth has shape {w.shape}: must be (len(x), len(y)) = ({x.size}, {y.size})")
        r = check_array("dent_radius", self.dent_radius, low=0.0, units="m", min_size=2)
        h = check_array("dent_depth", self.dent_depth, units="m", min_size=2)
        if r.shape != h.shape or np.any(np.diff(r) <= 0):
            raise ValueError("dent_radius must increase strictly and have the shape of dent_depth (m)")
        cx = check_number("dent_centre[0]", self.dent_centre[0], units="m")
        cy = check_number("dent_centre[1]", self.dent_centre[1], units="m")
        arrays = [("x", x), ("y", y), ("wear_depth", w), ("dent_radius", r), ("dent_depth", h)]
        if self.dent_grid is not None:
            g = check_array("dent_grid", self.dent_grid, units="m", ndim=2)
            if g.shape != w.shape:
                raise ValueError(f"dent_grid has shape {g.shape}: must be (len(x), len(y)) = ({x.size}, {y.size})")
            arrays.append(("dent_grid", g))
        for name, arr in arrays:
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)
        object.__setattr__(self, "dent_centre", (cx, cy))

    @classmethod
    def flat_dent(cls, x, y, wear_depth) -> DeformedSurface:
        """A surface with wear only (no dent), e.g. a rigid-plastic-free or elastic plate."""
        return cls(x, y, wear_depth, np.array([0.0, 1.0]), np.zeros(2))

    def dent_at(self, px, py) -> np.ndarray:
        """Dent depth h (m) at points (px, py) (m): bilinear on ``dent_grid`` (0 outside it), else linear in r of
        the profile (0 beyond it)."""
        if self.dent_grid is not None:
            return self._on_grid(self.dent_grid, px, py)
        r = np.hypot(np.asarray(px, float) - self.dent_centre[0], np.asarray(py, float) - self.dent_centre[1])
        return np.interp(r, self.dent_radius, self.dent_depth, right=0.0)

    def wear_at(self, px, py) -> np.ndarray:
        """Wear depth w (m) at points (px, py) (m): bilinear on the grid, 0 outside it."""
        return self._on_grid(self.wear_depth, px, py)

    def _on_grid(self, values: np.ndarray, px, py) -> np.ndarray:
        interp = RegularGridInterpolator((self.x, self.y), values, bounds_error=False, fill_value=0.0)
        px, py = np.broadcast_arrays(np.asarray(px, float), np.asarray(py, float))
        return interp(np.column_stack([px.ravel(), py.ravel()])).reshape(px.shape)

    def dent_on_grid(self) -> np.ndarray:
        """Dent depth (m) at the grid nodes, shape (nx, ny)."""
        if self.dent_grid is not None:
            return self.dent_grid
        gx, gy = np.meshgrid(self.x, self.y, indexing="ij")
        return self.dent_at(gx, gy)

    @property
    def max_dent_depth(self) -> float:
        """Largest dent depth (m)."""
        return float(np.max(self.dent_grid if self.dent_grid is not None else self.dent_depth))

    def dent_dimensions(self, samples: int = 4001) -> DentDimensions:
        """Length (along x) and width (across, y) of the dent where it lies below the original plane, through its
        deepest point, and the pile-up height above the plane (m)."""
        if self.dent_grid is not None:
            i, j = np.unravel_index(int(np.argmax(self.dent_grid)), self.dent_grid.shape)
            centre = (float(self.x[i]), float(self.y[j]))
            reach = max(float(np.ptp(self.x)), float(np.ptp(self.y)))
            pile_up = max(0.0, -float(np.min(self.dent_grid)))
        else:
            centre, reach = self.dent_centre, float(self.dent_radius[-1])
            pile_up = max(0.0, -float(np.min(self.dent_depth)))
        s = np.linspace(-reach, reach, samples)
        along = self.dent_at(centre[0] + s, np.full_like(s, centre[1]))
        across = self.dent_at(np.full_like(s, centre[0]), centre[1] + s)
        return DentDimensions(_below(s, along), _below(s, across), pile_up)


@dataclass(frozen=True)
class DentDimensions:
    """A dent's ``length`` along the impact and ``width`` across it, where the surface is below the original
    plane through the deepest point, and the ``pile_up`` height above the plane (all m)."""

    length: float
    width: float
    pile_up: float


def _below(s: np.ndarray, depth: np.ndarray) -> float:
    """Length (m) of the run of ``depth`` > 0 around its deepest sample, the ends interpolated."""
    k = int(np.argmax(depth))
    if depth[k] <= 0.0:
        return 0.0
    out = np.flatnonzero(depth <= 0.0)
    ends = []
    for side in (out[out < k], out[out > k]):
        if side.size == 0:
            ends.append(s[0] if not ends else s[-1])
            continue
        o = int(side[-1] if not ends else side[0])
        i = o + 1 if not ends else o - 1
        ends.append(s[o] + (s[i] - s[o]) * (0.0 - depth[o]) / (depth[i] - depth[o]))
    return float(ends[1] - ends[0])


def _grid_quads(nx: int, ny: int) -> np.ndarray:
    """Quad connectivity of an (nx, ny) node grid numbered i*ny + j, counter-clockwise seen from +z."""
    i, j = np.meshgrid(np.arange(nx - 1), np.arange(ny - 1), indexing="ij")
    n0 = (i * ny + j).ravel()
    return np.column_stack([n0, n0 + ny, n0 + ny + 1, n0 + 1])


def surface_mesh(surface: DeformedSurface) -> meshio.Mesh:
    """The plate's top surface as quads over the wear grid.

    Node z = −(dent_depth + wear_depth) (m). Point data ``wear_depth``, ``dent_depth``,
    ``total_depth`` (m, positive into the plate).
    """
    gx, gy = np.meshgrid(surface.x, surface.y, indexing="ij")
    wear = surface.wear_depth
    dent = surface.dent_on_grid()
    points = np.column_stack([gx.ravel(), gy.ravel(), -(dent + wear).ravel()])
    return meshio.Mesh(
        points,
        [("quad", _grid_quads(surface.x.size, surface.y.size))],
        point_data={
            "wear_depth": wear.ravel().copy(),
            "dent_depth": dent.ravel(),
            "total_depth": (dent + wear).ravel(),
        },
    )


def _coarsen(coords: np.ndarray, max_points: int) -> np.ndarray:
    """Every k-th coordinate (keeping both ends) so that at most ``max_points`` remain."""
    if coords.size <= max_points:
        return coords
    idx = np.unique(np.append(np.linspace(0, coords.size - 1, max_points).round().astype(int), coords.size - 1))
    return coords[idx]


def plate_block_mesh(
    surface: DeformedSurface,
    thickness: float,
    *,
    n_layers: int = 8,
    grading: float = 1.5,
    max_points_per_side: int = 80,
) -> meshio.Mesh:
    r"""A 3-D hexahedral block of the plate under the wear grid, its top nodes moved to −(h + w).

    The block spans the grid in x and y (coarsened to at most ``max_points_per_side`` nodes per
    side) and z ∈ [−``thickness``, 0] (m) in ``n_layers`` layers, thinner at the top by the
    geometric ``grading`` factor. The vertical displacement of the top node fades linearly to
    zero at the bottom, :math:`u_z(z) = -(h + w)(1 + z/t)`, which keeps every element valid;
    it is a visual continuation, not an elastic field. Point data as in :func:`surface_mesh`
    plus ``displacement`` (m).
    """
    thickness = check_number("thickness", thickness, low=0.0, low_open=True, high=10.0, units="m")
    n_layers = int(check_number("n_layers", n_layers, low=1, high=200))
    grading = check_number("grading", grading, low=1.0, high=10.0)
    x = _coarsen(surface.x, max_points_per_side)
    y = _coarsen(surface.y, max_points_per_side)
    layer = grading ** np.arange(n_layers)
    z_levels = -np.concatenate([[0.0], np.cumsum(layer)]) / layer.sum() * thickness  # 0 … −t, top first
    gx, gy = np.meshgrid(x, y, indexing="ij")
    wear = surface.wear_at(gx, gy).ravel()
    dent = surface.dent_at(gx, gy).ravel()
    top_depth = wear + dent
    nxy = x.size * y.size
    points = np.empty(((n_layers + 1) * nxy, 3))
    uz = np.empty((n_layers + 1) * nxy)
    for k, z in enumerate(z_levels):
        fade = 1.0 + z / thickness
        sl = slice(k * nxy, (k + 1) * nxy)
        uz[sl] = -top_depth * fade
        points[sl, 0], points[sl, 1], points[sl, 2] = gx.ravel(), gy.ravel(), z + uz[sl]
    quads = _grid_quads(x.size, y.size)
    # level k is above level k+1: bottom face (k+1) then top face (k), both counter-clockwise from +z
    hexes = np.concatenate([np.column_stack([quads + (k + 1) * nxy, quads + k * nxy]) for k in range(n_layers)])
    on_top = np.zeros((n_layers + 1) * nxy)
    on_top[:nxy] = 1.0
    return meshio.Mesh(
        points,
        [("hexahedron", hexes)],
        point_data={
            "wear_depth": np.where(on_top > 0, np.tile(wear, n_layers + 1), 0.0),
            "dent_depth": np.where(on_top > 0, np.tile(dent, n_layers + 1), 0.0),
            "displacement": np.column_stack([np.zeros_like(uz), np.zeros_like(uz), uz]),
        },
    )


def deform_plate_mesh(mesh: meshio.Mesh, surface: DeformedSurface, *, tolerance: float | None = None) -> meshio.Mesh:
    r"""Move a user's plate mesh (any meshio mesh, metres) by the dent and the wear.

    The mesh's top face is the plane z = z_top = max z, and the impact grid's origin is at
    (x, y) = (0, 0) of the mesh. Nodes within ``tolerance`` (default 1e-9 × the mesh size) of the
    top get :math:`u_z = -(h + w)`; the displacement fades linearly with depth below the top over
    the mesh's height, as in :func:`plate_block_mesh`. Returns a new mesh with point data
    ``wear_depth``, ``dent_depth`` (top nodes) and ``displacement``.
    """
    pts = np.asarray(mesh.points, dtype=float)
    if pts.ndim != 2 or pts.shape[1] != 3:
        raise ValueError(f"mesh.points has shape {pts.shape}: a 3-D plate mesh needs (n, 3) points (m)")
    z_top, z_bottom = float(pts[:, 2].max()), float(pts[:, 2].min())
    height = z_top - z_bottom
    if height <= 0.0:
        raise ValueError("mesh has zero height: a plate block needs nodes below its top face (m)")
    tol = 1e-9 * float(np.ptp(pts, axis=0).max()) if tolerance is None else float(tolerance)
    top = pts[:, 2] >= z_top - tol
    wear_above = surface.wear_at(pts[:, 0], pts[:, 1])
    dent_above = surface.dent_at(pts[:, 0], pts[:, 1])
    wear = np.where(top, wear_above, 0.0)
    dent = np.where(top, dent_above, 0.0)
    fade = 1.0 - (z_top - pts[:, 2]) / height
    uz = -(wear_above + dent_above) * fade
    moved = pts.copy()
    moved[:, 2] += uz
    point_data = dict(mesh.point_data)
    point_data.update(
        wear_depth=wear,
        dent_depth=dent,
        displacement=np.column_stack([np.zeros_like(uz), np.zeros_like(uz), uz]),
    )
    return meshio.Mesh(moved, mesh.cells, point_data=point_data, cell_data=dict(mesh.cell_data))


_GAUSS_2x2 = np.array([-1.0, 1.0]) / np.sqrt(3.0)


def integrate_point_data(mesh: meshio.Mesh, name: str) -> float:
    r"""∫ f dA of point data ``name`` over the xy projection of a surface mesh's quads and triangles.

    Fields are interpolated linearly (triangles) or bilinearly (quads, 2×2 Gauss, exact for a
    bilinear field on any convex quad). For the wear depth this is the worn volume (m³).
    """
    f = np.asarray(mesh.point_data[name], dtype=float)
    xy = np.asarray(mesh.points, dtype=float)[:, :2]
    total = 0.0
    for block in mesh.cells:
        conn = np.asarray(block.data)
        if block.type == "triangle":
            p0, p1, p2 = (xy[conn[:, k]] for k in range(3))
            e1, e2 = p1 - p0, p2 - p0
            area = 0.5 * np.abs(e1[:, 0] * e2[:, 1] - e2[:, 0] * e1[:, 1])
            total += float(np.sum(area * f[conn].mean(axis=1)))
        elif block.type == "quad":
            corners = xy[conn]  # (n, 4, 2)
            vals = f[conn]
            for s in _GAUSS_2x2:
                for t in _GAUSS_2x2:
                    dn_ds = np.array([-(1 - t), (1 - t), (1 + t), -(1 + t)]) / 4.0
                    dn_dt = np.array([-(1 - s), -(1 + s), (1 + s), (1 - s)]) / 4.0
                    shape = np.array([(1 - s) * (1 - t), (1 + s) * (1 - t), (1 + s) * (1 + t), (1 - s) * (1 + t)]) / 4.0
                    jx = corners.transpose(0, 2, 1) @ np.column_stack([dn_ds, dn_dt])  # (n, 2, 2)
                    det = np.abs(np.linalg.det(jx))
                    total += float(np.sum(det * (vals @ shape)))
        else:
            raise ValueError(f"mesh cell type {block.type!r} is not a surface cell: need 'quad' or 'triangle'")
    return total
