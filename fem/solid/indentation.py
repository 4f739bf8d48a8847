r"""The 3-D plate's public entry point: :func:`indent_solid` (SI units).

A rigid sphere is pressed into the 3-D half plate (:mod:`fem.solid.mesh`, :mod:`fem.solid.solver`) along a path of
overlaps δ, contact-centre positions c (x, m, in the plane of incidence) and slides ξ (the x displacement of the
ball's surface in contact relative to the plate far away, m), with Coulomb friction μ. An elastic ball is
represented, as on the axisymmetric plate (:mod:`fem.axisymmetric.indent`), by a rigid sphere and a plate of the same
effective modulus E*: exact for the normal Hertz contact; for the tangential compliance the ball's own (2 − ν_b)/G_b is
then missing (Johnson Eq. 7.42), as is the ball's share of the normal–tangential coupling.

Forces are those on the whole plate (twice the half model's).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import meshio
import numpy as np

from contact.checks import check_array, check_friction, check_number
from contact.fields import SurfaceField
from contact.materials import Material
from fem.core.increments import WorkCounters
from fem.core.material import check_small_strain, estimate_contact_radius, plate_model
from fem.core.plasticity import J2Material, von_mises
from fem.core.sphere import contact_radius_around
from fem.solid.mesh import generate_block, scale_block
from fem.solid.solver import SolidSolver
from fem.solid.state import SolidState
from fem.solid.surface_stress import surface_stress

__all__ = ["SolidIndentation", "SolidRecorder", "indent_solid", "solid_solver"]


@dataclass(frozen=True, eq=False)
class SolidIndentation:
    """The 3-D plate along a path (arrays: one entry per step).

    ``overlap`` δ, ``centre`` c, ``slide`` ξ (m); ``normal_force`` P and ``tangential_force`` Q (x) on the whole
    plate (N); ``contact_radius`` (m: the edge found from the gaps of the free surface nodes beside it,
    :meth:`SolidRecorder.contact_radius`) and ``stick_radius`` √(A_stick/π) of the stick area (m; summed over
    the sticking surface vertices' hats, so its edge falls midway between a vertex in and one out);
    ``max_pressure`` (Pa); ``max_equivalent_plastic_strain``; ``newton_iterations``; ``surface_vertices`` (n, 3)
    reference coordinates of the surface vertices (m); ``pressure`` (steps, n) and ``shear`` (steps, n, 2) the
    contact tractions on the plate at those vertices (Pa, linear between them: the ball's force on each vertex's
    share of the surface over its area, :meth:`fem.solid.friction.SurfaceFriction.vertex_tractions`;
    ``max_pressure`` their largest);
    ``sticking`` (steps, n) the vertices in stick; ``slip`` (steps, n, 2) the ball's slip (x, y) over each vertex
    in contact in the step that ends there, Δξ e_x − Δu_t (m; zero in stick and out of contact); ``node_slip``
    (steps, q, 2) and ``node_sticking`` (steps, q) the same at every quadratic surface node (vertices and mid-edge
    nodes, :attr:`fem.solid.forms.SolidDiscretisation.surface_xy`: a mid-edge node sticks where both its vertices do);
    ``residual_depth`` (n) the surface vertices' u_z after the last step, positive into the plate (m); ``stats`` the
    solver's work.
    """

    overlap: np.ndarray
    centre: np.ndarray
    slide: np.ndarray
    normal_force: np.ndarray
    tangential_force: np.ndarray
    contact_radius: np.ndarray
    stick_radius: np.ndarray
    max_pressure: np.ndarray
    max_equivalent_plastic_strain: np.ndarray
    newton_iterations: np.ndarray
    surface_vertices: np.ndarray
    pressure: np.ndarray
    shear: np.ndarray
    sticking: np.ndarray
    slip: np.ndarray
    node_slip: np.ndarray
    node_sticking: np.ndarray
    residual_depth: np.ndarray
    stats: WorkCounters
    final: SolidState = field(repr=False)
    solver: SolidSolver = field(repr=False)

    def surface_stress(self) -> np.ndarray:
        """The stress (surface vertices, 6) on the surface after the last step (Pa, Mandel:
        σ_xx, σ_yy, σ_zz, √2 σ_yz, √2 σ_xz, √2 σ_xy), recovered from the element stresses and the contact tractions
        of the last step (:func:`fem.solid.surface_stress.surface_stress`)."""
        solver, state = self.solver, self.final
        stress = solver.stress_update(state).stress
        normal, shear = solver.surface_forces(state)
        surface = solver.surface
        in_contact = surface.vertex_mask(state.contact)
        # the recovery takes the tractions' L² projection M⁻¹Hf, pointwise the closer inside a smooth contact:
        # Johnson's Hertz σ_z within 0.02 p0 (tests/test_fem_surface_stress.py), where the reported hat averages
        # (SurfaceFriction.vertex_tractions, the friction law's own) miss it by 0.026 p0 at a vertex inside the edge
        pressure = np.where(in_contact, surface.vertex_field(normal), 0.0)
        traction = np.where(in_contact[:, None], surface.vertex_field(shear), 0.0)
        return surface_stress(solver.disc, stress, pressure, traction)

    def surface_field(self, times: np.ndarray) -> SurfaceField:
        """The plate's surface fields with its steps placed at impact ``times`` (s), as the wear law reads them, at the
        half plate's quadratic surface nodes (vertices and mid-edge nodes; mirrored about y = 0) on the surface
        triangles split at their mid-edge nodes: the reported tractions, linear between the vertices (read at the
        mid-edge nodes), the stick set and the slip of each node (the quadratic displacement's own: at 4 elements
        across the contact a read-out at the vertices alone lost 10% of the worn volume at normal incidence against
        the axisymmetric plate, at the nodes 1%), and the residual surface after the last step."""
        d = self.solver.disc
        on_nodes = d.surface_hats.T  # the linear field of the vertex values at every surface node
        return SurfaceField(
            time=np.asarray(times, float),
            points=d.surface_xy,
            pressure=np.asarray(on_nodes @ self.pressure.T).T,
            shear=np.stack([np.asarray(on_nodes @ self.shear[:, :, k].T).T for k in range(2)], axis=2),
            slip=self.node_slip,
            sticking=self.node_sticking,
            centre=self.centre,
            contact_radius=self.contact_radius,
            dent_points=d.surface_xy,
            dent=-self.final.u[d.surface_dofs(2)],
            mirrored=True,
            triangles=d.surface_node_triangles,
            dent_triangles=d.surface_node_triangles,
        )

    def to_meshio(self) -> meshio.Mesh:
        """The whole plate after the last step (the half block and its mirror image about y = 0) as linear
        tetrahedra on the element vertices: points (m, reference), point data ``u`` (m), cell data ``von_mises``
        (Pa, the residual stress after an unloaded path) and ``equivalent_plastic_strain`` (element averages)."""
        solver, state = self.solver, self.final
        mesh = solver.disc.mesh
        points = mesh.p.T
        u = state.u.reshape(-1, 3)[: points.shape[0]]
        vm = von_mises(solver.stress_update(state).stress).mean(axis=1)
        eps = state.alpha.mean(axis=1)
        tets = mesh.t.T
        mirror = points * [1.0, -1.0, 1.0]
        # the mirror image reverses the orientation: swap two vertices of each tetrahedron
        mirrored = tets[:, [1, 0, 2, 3]] + points.shape[0]
        return meshio.Mesh(
            np.vstack([points, mirror]),
            [("tetra", np.vstack([tets, mirrored]))],
            point_data={"u": np.vstack([u, u * [1.0, -1.0, 1.0]])},
            cell_data={"von_mises": [np.r_[vm, vm]], "equivalent_plastic_strain": [np.r_[eps, eps]]},
        )


def _per_step(name: str, values, steps: int, low: float | None, high: float | None, units: str) -> np.ndarray:
    if values is None:
        return np.zeros(steps)
    if np.ndim(values) == 0:
        return np.full(steps, check_number(name, values, low=low, high=high, units=units))
    array = check_array(name, values, low=low, high=high, units=units)
    if array.size != steps:
        raise ValueError(f"{name}: {array.size} entries, but the overlap path has {steps} (one per step)")
    return array


def solid_solver(
    radius: float,
    plate: Material,
    max_overlap: float,
    centres: np.ndarray,
    friction: float,
    ball: Material | None = None,
    hardening: float = 0.0,
    contact_elements: int = 4,
    box_depth: float = 1.0,
    rtol: float = 1e-6,
    edge_elements: int | None = None,
) -> SolidSolver:
    """The 3-D half plate of ``plate`` for a sphere of ``radius`` (m) reaching ``max_overlap`` (m) over the contact
    centres ``centres`` (m) with friction up to ``friction``: a block (:func:`fem.solid.mesh.generate_block`) with
    ``contact_elements`` elements across the largest expected contact radius (Hertz, or Kogut & Etsion once
    yielded) over a box ``box_depth`` of it deep, around the centres' track, and ``edge_elements`` (None: none)
    across it in a band around the contact edge (where the surface stresses peak)."""
    material, e_star = plate_model(plate, ball, hardening)
    check_small_strain(radius, e_star, plate, max_overlap)
    a_max = estimate_contact_radius(radius, e_star, plate, max_overlap)
    track = (float(np.min(centres)) / a_max, float(np.max(centres)) / a_max)
    block = generate_block(contact_elements, track=track, depth=box_depth, edge_elements=edge_elements)
    mesh = scale_block(block, a_max)
    force_scale = 4.0 / 3.0 * e_star * math.sqrt(radius) * max_overlap**1.5
    return SolidSolver(
        mesh,
        J2Material(material.E, material.nu, material.yield_strength, material.hardening),
        radius,
        friction,
        force_scale,
        max_overlap,
        rtol=rtol,
    )


class SolidRecorder:
    """Collects what :class:`SolidIndentation` reports of each converged step of ``solver`` along a path from
    ``start`` (default: the unloaded plate)."""

    def __init__(self, solver: SolidSolver, start: SolidState | None = None) -> None:
        self.solver = solver
        self.start = solver.initial_state() if start is None else start
        self.records: dict[str, list] = {
            k: [] for k in ("P", "Q", "a", "c", "pmax", "eps", "it", "p", "tau", "st", "slip", "node_st", "node_slip")
        }
        self.states: list[SolidState] = []

    def measure(self, state: SolidState) -> dict[str, float | int | np.ndarray]:
        """One step's numbers: forces on the whole plate (N), contact and stick radii (m), peak pressure (Pa),
        largest equivalent plastic strain, Newton iterations, vertex pressure and shear (Pa,
        :meth:`fem.solid.friction.SurfaceFriction.vertex_tractions`), stick mask, and the slip (m) over each vertex
        in contact since the last recorded step (the first: since the path's start)."""
        solver, d = self.solver, self.solver.disc
        normal, shear = solver.surface_forces(state)
        surface = solver.surface
        pressure, traction = surface.vertex_tractions(normal * state.contact, shear)
        in_contact = surface.vertex_mask(state.contact)
        sticking = surface.vertex_mask(state.stick)
        before = self.states[-1] if self.states else self.start
        moved = (state.u - before.u).reshape(-1, 3)[d.surface_nodes, :2]
        node_slip = np.column_stack([np.full(moved.shape[0], state.slide - before.slide), np.zeros(moved.shape[0])])
        node_slip -= moved
        node_sticks = state.stick & state.contact
        slip = surface.vertex_values(node_slip)
        return {
            "P": 2.0 * float(normal[state.contact].sum()),
            "Q": 2.0 * float(shear[:, 0].sum()),
            "a": self.contact_radius(state, in_contact),
            "c": math.sqrt(2.0 * float(d.surface_area[sticking].sum()) / math.pi),
            "pmax": float(np.max(pressure, initial=0.0)),
            "eps": float(np.max(state.alpha, initial=0.0)),
            "it": state.iterations,
            "p": pressure,
            "tau": traction,
            "st": sticking & in_contact,
            "slip": np.where((in_contact & ~sticking)[:, None], slip, 0.0),
            "node_st": node_sticks,
            # the ball slides over every node its pressure field (linear between the vertices) presses, but where
            # the node sticks: over a mid-edge node between a pressed vertex and a free one too
            "node_slip": np.where(((d.surface_hats.T @ pressure > 0.0) & ~node_sticks)[:, None], node_slip, 0.0),
        }

    def contact_radius(self, state: SolidState, in_contact: np.ndarray) -> float:
        """The contact radius (m) of ``state`` (``in_contact``: its surface vertices in contact): the edge found
        from the gaps of the free surface nodes within one element of it (:func:`fem.core.sphere.contact_radius_around`;
        the element's size from the area of the vertices in contact)."""
        if not in_contact.any():
            return 0.0
        solver, d = self.solver, self.solver.disc
        gap = solver.obstacle(state.overlap, state.centre) - state.u[solver.uz]
        xy = d.surface_xy
        distance = np.hypot(xy[:, 0] - state.centre, xy[:, 1])
        element = math.sqrt(float(np.median(d.surface_area[in_contact])))
        return contact_radius_around(distance, state.contact, gap, band=element)

    def add(self, state: SolidState) -> None:
        """Record a converged step."""
        for key, value in self.measure(state).items():
            self.records[key].append(value)
        self.states.append(state)

    def result(self) -> SolidIndentation:
        """The recorded path as a :class:`SolidIndentation`."""
        r, d, state = self.records, self.solver.disc, self.states[-1]
        return SolidIndentation(
            overlap=np.array([s.overlap for s in self.states]),
            centre=np.array([s.centre for s in self.states]),
            slide=np.array([s.slide for s in self.states]),
            normal_force=np.array(r["P"]),
            tangential_force=np.array(r["Q"]),
            contact_radius=np.array(r["a"]),
            stick_radius=np.array(r["c"]),
            max_pressure=np.array(r["pmax"]),
            max_equivalent_plastic_strain=np.array(r["eps"]),
            newton_iterations=np.array(r["it"]),
            surface_vertices=d.nodes[:, d.surface_vertex_nodes].T,
            pressure=np.array(r["p"]),
            shear=np.array(r["tau"]),
            sticking=np.array(r["st"]),
            slip=np.array(r["slip"]),
            node_slip=np.array(r["node_slip"]),
            node_sticking=np.array(r["node_st"]),
            residual_depth=-state.u[3 * d.surface_vertex_nodes + 2],
            stats=self.solver.stats,
            final=state,
            solver=self.solver,
        )


def indent_solid(
    radius: float,
    plate: Material,
    overlaps,
    centres=None,
    slides=None,
    friction=0.0,
    ball: Material | None = None,
    hardening: float = 0.0,
    contact_elements: int = 4,
    box_depth: float = 1.0,
    rtol: float = 1e-6,
    edge_elements: int | None = None,
) -> SolidIndentation:
    r"""Press and drag a sphere of ``radius`` (m) over the 3-D ``plate`` along a path.

    ``overlaps`` δ (m, one entry per increment), ``centres`` c (m, the sphere axis' x; default 0), ``slides`` ξ
    (m; default 0), ``friction`` μ (one value, or one per step: 0 while the normal load is applied and μ after
    is the Cattaneo–Mindlin protocol). ``ball`` None = rigid. ``hardening`` H (Pa). The mesh
    (:func:`solid_solver`) has ``contact_elements`` elements across the path's largest expected contact radius over
    a box ``box_depth`` of it deep, around the centres' track, and ``edge_elements`` across it in a band around
    the contact edge (None: no band; :func:`fem.solid.mesh.generate_block`).
    """
    radius = check_number("radius", radius, low=1e-6, high=10.0, units="m", what="ball radius")
    path = check_array("overlaps", overlaps, low=0.0, units="m", what="overlap")
    if path.max() <= 0.0:
        raise ValueError("overlaps are all 0: the path must press the ball into the plate (m)")
    steps = path.size
    centre = _per_step("centres", centres, steps, -radius, radius, "m")
    slide = _per_step("slides", slides, steps, -radius, radius, "m")
    mu = _per_step("friction", check_friction("friction", friction), steps, None, None, "")
    hardening = check_number("hardening", hardening, low=0.0, high=1e12, units="Pa", what="hardening modulus")
    solver = solid_solver(
        radius,
        plate,
        float(path.max()),
        centre,
        float(mu.max()),
        ball,
        hardening,
        contact_elements,
        box_depth,
        rtol,
        edge_elements,
    )
    recorder = SolidRecorder(solver)
    state, previous = solver.initial_state(), None
    for k in range(steps):
        new = solver.advance(state, previous, (float(path[k]), float(centre[k]), float(slide[k])), float(mu[k]))
        previous, state = state, new
        recorder.add(state)
    return recorder.result()
