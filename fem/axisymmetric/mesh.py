r"""Meshes of the axisymmetric plate: the (r, z) block [0, L] × [−L, 0], refined towards the contact.

The generator works in units of the largest contact radius a_max of the path (so one mesh file
serves every case after scaling) and refines a coarse triangulation of the block adaptively
(red-green-blue refinement, conforming, no hanging nodes) until the element size h — the leg
of the right isosceles triangles — meets a target that depends on the distance from the origin:

* h ≤ a_max / ``contact_elements`` in the contact box r ≤ 1.2 a_max, depth ≤ 0.8 a_max;
* h ≤ a_y / ``yield_elements`` in the first-yield box r ≤ 1.2 a_y, depth ≤ 1.0 a_y, where
  a_y = ``yield_radius_ratio`` · a_max is the contact radius at first yield (z ≈ 0.48 a_y);
* outside, h grows by ``grading`` per unit distance (∞-norm) from the boxes.

Refining by halving makes every size a power-of-two fraction of the block size L; L = 128 a_max
(≥ 100 a_max, because the finite block stiffens the Hertz force by ≈ 0.6 a/L) so that a_max / 32
is reached exactly. Named boundaries: ``axis`` (r = 0), ``surface`` (z = 0), ``bottom`` (z = −L),
``side`` (r = L). Lengths are in m after :func:`scale_mesh`.
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

import numpy as np
from skfem import MeshTri

from contact.checks import check_number

__all__ = [
    "BOUNDARY_NAMES",
    "DEFAULT_MESH_FILE",
    "generate_mesh",
    "load_mesh",
    "scale_mesh",
    "default_mesh",
    "mesh_block_size",
]

BOUNDARY_NAMES = ("axis", "surface", "bottom", "side")

#: The default mesh shipped as data of the ``meshes`` package (dimensionless: unit length = a_max); ``python -m
#: fem.axisymmetric.regenerate_mesh`` regenerates it from :data:`DEFAULT_PARAMETERS`.
DEFAULT_MESH_FILE = Path(str(resources.files("meshes").joinpath("indent_default.msh")))

#: Parameters of the default mesh (see :func:`generate_mesh`).
DEFAULT_PARAMETERS = {"contact_elements": 32, "yield_elements": 20, "yield_radius_ratio": 1.0 / 5.5, "grading": 0.5}


def _with_named_boundaries(mesh: MeshTri, size: float) -> MeshTri:
    tol = 1e-9 * size
    return mesh.with_boundaries(
        {
            "axis": lambda x: np.abs(x[0]) < tol,
            "surface": lambda x: np.abs(x[1]) < tol,
            "bottom": lambda x: np.abs(x[1] + size) < tol,
            "side": lambda x: np.abs(x[0] - size) < tol,
        }
    )


def mesh_block_size(contact_elements: int = 32) -> float:
    """Block size L / a_max of a generated mesh: the power-of-two multiple of 1/contact_elements ≥ 100."""
    size = 1.0 / contact_elements
    while size < 100.0:
        size *= 2.0
    return size


def generate_mesh(
    contact_elements: int = 32,
    yield_elements: int = 20,
    yield_radius_ratio: float = 1.0 / 5.5,
    grading: float = 0.5,
    growth: float = 1.0,
) -> MeshTri:
    """Dimensionless mesh (unit length = largest contact radius a_max) of the block [0, L] × [−L, 0].

    Parameters
    ----------
    contact_elements : int
        Elements across a_max in the contact box (≥ 30 resolve the pressure profile; 32 by default).
    yield_elements : int
        Elements across the first-yield contact radius a_y (≈ 20); 0 switches the box off.
    yield_radius_ratio : float
        a_y / a_max (dimensionless); 1/5.5 is the standard cycle (w = δ/δ_c = 20, Kogut & Etsion's
        A/A_c = 0.94 w^1.146 gives a/a_y ≈ 5.4).
    grading : float
        Growth of h per unit distance outside the refined boxes (dimensionless).
    growth : float
        Largest contact radius the mesh must resolve later, over a_max (≥ 1): a box r ≤ 1.2·growth,
        depth ≤ 0.8·growth with h = growth / contact_elements keeps as many elements across a contact grown to
        growth·a_max as across a_max (repeated impacts: the seat conforms and the contact widens, 2.35× over 10⁴
        impacts of the default case). 1 adds nothing.
    """
    contact_elements = int(check_number("contact_elements", contact_elements, low=2, high=1000))
    yield_elements = int(check_number("yield_elements", yield_elements, low=0, high=1000))
    ratio = check_number("yield_radius_ratio", yield_radius_ratio, low=0.0, low_open=True, high=1.0)
    grading = check_number("grading", grading, low=0.05, high=2.0)
    growth = check_number("growth", growth, low=1.0, high=10.0)
    size = mesh_block_size(contact_elements)
    h_contact = 1.0 / contact_elements
    h_yield = ratio / yield_elements if yield_elements else h_contact

    def target(r: np.ndarray, depth: np.ndarray) -> np.ndarray:
        # ∞-norm distance outside each box, scaled so the boxes have the stated extents
        d_contact = np.maximum(np.maximum(r - 1.2, depth - 0.8), 0.0)
        d_yield = np.maximum(np.maximum(r - 1.2 * ratio, depth - 1.0 * ratio), 0.0)
        d_growth = np.maximum(np.maximum(r - 1.2 * growth, depth - 0.8 * growth), 0.0)
        h = np.minimum(h_contact + grading * d_contact, h_yield + grading * d_yield)
        return np.minimum(h, growth * h_contact + grading * d_growth) if growth > 1.0 else h

    mesh = MeshTri.init_tensor(np.array([0.0, size]), np.array([-size, 0.0]))
    for _ in range(40):
        p, t = mesh.p, mesh.t
        # element size = leg of the right isosceles triangle = √(2·area)
        e1 = p[:, t[1]] - p[:, t[0]]
        e2 = p[:, t[2]] - p[:, t[0]]
        h = np.sqrt(np.abs(e1[0] * e2[1] - e1[1] * e2[0]))
        # target at the element point nearest the origin (so each box is fully covered)
        r_near = p[0, t].min(axis=0)
        depth_near = (-p[1, t]).min(axis=0)
        marked = np.flatnonzero(h > target(r_near, depth_near) * (1.0 + 1e-9))
        if marked.size == 0:
            break
        mesh = mesh.refined(marked)
    return _with_named_boundaries(mesh, size)


def scale_mesh(mesh: MeshTri, length: float) -> MeshTri:
    """Return ``mesh`` with every coordinate multiplied by ``length`` (m), boundaries kept."""
    scaled = MeshTri(mesh.p * length, mesh.t)
    size = float(np.max(scaled.p[0]))
    return _with_named_boundaries(scaled, size)


def _check_boundaries(mesh: MeshTri, name: str) -> None:
    missing = [b for b in ("axis", "surface", "bottom") if mesh.boundaries is None or b not in mesh.boundaries]
    if missing:
        raise ValueError(
            f"{name} has no boundary named {', '.join(repr(m) for m in missing)}: a plate mesh must name its "
            "boundaries 'axis' (r = 0), 'surface' (z = 0) and 'bottom' (z = -L) (r, z in m)"
        )


def load_mesh(path: str | Path) -> MeshTri:
    """Read a triangular plate mesh (any meshio format, r, z in m) with named boundaries.

    The boundaries ``axis`` (r = 0), ``surface`` (z = 0) and ``bottom`` (z = −L) must be present
    (e.g. gmsh physical groups); the plate lies in r ≥ 0, z ≤ 0.
    """
    path = Path(path)
    if not path.is_file():
        raise ValueError(f"mesh={str(path)!r} is not a file: give a meshio-readable mesh file")
    try:
        mesh = MeshTri.load(str(path))
    except Exception as exc:  # meshio raises many types for unreadable files
        raise ValueError(f"mesh={str(path)!r} could not be read as a triangular mesh: {exc}") from None
    _check_boundaries(mesh, f"mesh={str(path)!r}")
    if np.min(mesh.p[0]) < -1e-12 * np.ptp(mesh.p) or np.max(mesh.p[1]) > 1e-12 * np.ptp(mesh.p):
        raise ValueError(f"mesh={str(path)!r} leaves the quadrant r >= 0, z <= 0 (m)")
    return mesh


def default_mesh(max_contact_radius: float) -> MeshTri:
    """The shipped default mesh scaled to a largest contact radius ``max_contact_radius`` (m)."""
    a = check_number("max_contact_radius", max_contact_radius, low=0.0, low_open=True, units="m")
    mesh = MeshTri.load(str(DEFAULT_MESH_FILE))
    _check_boundaries(mesh, f"default mesh {DEFAULT_MESH_FILE.name}")
    return scale_mesh(mesh, a)
