r"""Meshes of the 3-D plate: the half block x ∈ [−L, L], y ∈ [0, L], z ∈ [−L, 0], refined along the impact track.

The plate is symmetric about the plane of incidence y = 0, so only its half y ≥ 0 is meshed. The generator works in
units of the largest contact radius a_max (like :mod:`fem.axisymmetric.mesh`) and bisects a coarse tetrahedral block
adaptively (scikit-fem's conforming refinement of :class:`~skfem.MeshTet`, no hanging nodes, the shape quality bounded)
until every element's size h = (6V)^{1/3} — the edge of the cube a Kuhn tetrahedron of volume V is cut from — meets

* h ≤ 1 / ``contact_elements`` in the contact box: x from the track's start − 1.3 to its end + 1.3, y ≤ 1.3,
  depth ≤ 1 (the plastic zone of w = δ/δ_c = 20 reaches ≈ 0.8 a_max below the surface);
* outside, h growing by ``grading`` per unit (∞-norm) distance from the box;
* optionally, h ≤ 1 / ``edge_elements`` in a band around the contact edge — the points within ``edge_width`` of
  the distance ρ = 1 from the track and at most ``edge_width`` deep — growing by ``grading`` per unit distance
  from the band. The surface stresses peak there: the radial tension (1 − 2ν) p0 / 3 at the edge of a Hertz
  contact, where ring cracks start, and the tensile cusp at the trailing edge of a sliding contact
  (:mod:`fem.solid.surface_stress`).

The quadratic tetrahedra put a node every h/2. L = 64 a_max: the finite clamped block stiffens the Hertz force by
≈ 0.6 a/L, 0.9% here (the axisymmetric mesh, 128 a_max, 0.5%; the difference is within both models' accuracy).
Named boundaries: ``surface`` (z = 0), ``bottom`` (z = −L), ``symmetry`` (y = 0). Lengths in m after
:func:`scale_block`.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Iterator
from contextlib import contextmanager

import numpy as np
from skfem import MeshHex, MeshTet

from contact.checks import check_number

__all__ = ["BLOCK_SIZE", "generate_block", "scale_block", "element_size"]

#: Block half-width L / a_max (dimensionless).
BLOCK_SIZE = 64.0
#: The contact box's half-width across the track and beyond its ends, and its depth (units of a_max).
BOX_WIDTH = 1.3
BOX_DEPTH = 1.0


@contextmanager
def _quiet_refinement() -> Iterator[None]:
    """scikit-fem warns on every refined mesh of over 1000 elements that it copies an array to C order (a
    performance note, not a user's concern): silenced while the block is bisected."""
    logger = logging.getLogger("skfem")
    level = logger.level
    logger.setLevel(logging.ERROR)
    try:
        yield
    finally:
        logger.setLevel(level)


def _with_named_boundaries(mesh: MeshTet, size: float) -> MeshTet:
    tol = 1e-9 * size
    return mesh.with_boundaries(
        {
            "surface": lambda x: np.abs(x[2]) < tol,
            "bottom": lambda x: np.abs(x[2] + size) < tol,
            "symmetry": lambda x: np.abs(x[1]) < tol,
        }
    )


def element_size(mesh: MeshTet) -> np.ndarray:
    """Element sizes h = (6 V)^{1/3} (in the mesh's length unit)."""
    p = mesh.p[:, mesh.t]
    edges = p[:, 1:] - p[:, :1]
    volume = np.abs(np.einsum("ie,ie->e", np.cross(edges[:, 0], edges[:, 1], axis=0), edges[:, 2])) / 6.0
    return np.cbrt(6.0 * volume)


def _refined(mesh: MeshTet, target: Callable[[np.ndarray], np.ndarray]) -> MeshTet:
    """Bisect ``mesh`` until every element's size is at most ``target`` of its corners (3, 4, elements)."""
    with _quiet_refinement():
        for _ in range(200):
            marked = np.flatnonzero(element_size(mesh) > target(mesh.p[:, mesh.t]) * (1.0 + 1e-9))
            if marked.size == 0:
                break
            mesh = mesh.refined(marked)
    return MeshTet(np.ascontiguousarray(mesh.p), np.ascontiguousarray(mesh.t))


def generate_block(
    contact_elements: int = 8,
    grading: float = 0.5,
    track: tuple[float, float] = (0.0, 0.0),
    depth: float = BOX_DEPTH,
    edge_elements: int | None = None,
    edge_width: float = 0.1,
) -> MeshTet:
    """Dimensionless half block (unit length = a_max), refined to 1/``contact_elements`` around the track.

    Parameters
    ----------
    contact_elements : int
        Elements (Kuhn cube edges) across a_max in the contact box; the quadratic nodes are twice as dense.
    grading : float
        Growth of h per unit distance outside the box (dimensionless).
    track : (float, float)
        Start and end x of the contact centre's path (units of a_max); (0, 0) for a normal impact.
    depth : float
        Depth of the contact box (units of a_max): 1 holds the plastic zone of w = 20; an elastic contact's surface
        tractions need less.
    edge_elements : int or None
        Elements across a_max in the band around the contact edge (None: no band).
    edge_width : float
        Half-width and depth of that band (units of a_max).
    """
    contact_elements = int(check_number("contact_elements", contact_elements, low=1, high=64))
    grading = check_number("grading", grading, low=0.05, high=2.0)
    start, end = sorted(float(v) for v in track)
    if max(abs(start), abs(end)) > BLOCK_SIZE / 4:
        raise ValueError(
            f"track=({start:g}, {end:g}): the contact centre's path must stay within ±{BLOCK_SIZE / 4:g} a_max of "
            "the impact point (units of the largest contact radius)"
        )
    size = BLOCK_SIZE
    depth = check_number("depth", depth, low=0.05, high=BLOCK_SIZE / 4)
    box_low = np.array([start - BOX_WIDTH, 0.0, -depth])
    box_high = np.array([end + BOX_WIDTH, BOX_WIDTH, 0.0])
    h_contact = 1.0 / contact_elements
    cells = 4
    mesh = MeshHex.init_tensor(
        np.linspace(-size, size, 2 * cells + 1), np.linspace(0.0, size, cells + 1), np.linspace(-size, 0.0, cells + 1)
    ).to_meshtet()

    def box_target(corners: np.ndarray) -> np.ndarray:
        # ∞-norm distance between the element's bounding box and the contact box
        distance = np.maximum(box_low[:, None] - corners.max(axis=1), corners.min(axis=1) - box_high[:, None])
        return h_contact + grading * np.maximum(distance, 0.0).max(axis=0)

    mesh = _refined(mesh, box_target)
    if edge_elements is not None:
        h_edge = 1.0 / int(check_number("edge_elements", edge_elements, low=contact_elements, high=256))
        width = check_number("edge_width", edge_width, low=0.01, high=1.0, units="a_max")

        def edge_target(corners: np.ndarray) -> np.ndarray:
            # distance of the corners from the track (the contact centre's path) in the surface plane
            rho = np.hypot(np.maximum(np.maximum(start - corners[0], corners[0] - end), 0.0), corners[1])
            off_band = np.maximum(rho.min(axis=0) - (1.0 + width), (1.0 - width) - rho.max(axis=0))
            too_deep = -width - corners[2].max(axis=0)
            return h_edge + grading * np.maximum(np.maximum(off_band, too_deep), 0.0)

        mesh = _refined(mesh, edge_target)
    return _with_named_boundaries(mesh, size)


def scale_block(mesh: MeshTet, length: float) -> MeshTet:
    """Return ``mesh`` with every coordinate multiplied by ``length`` (m), boundaries kept."""
    scaled = MeshTet(np.ascontiguousarray(mesh.p * length), np.ascontiguousarray(mesh.t))
    return _with_named_boundaries(scaled, float(np.max(scaled.p[0])))
