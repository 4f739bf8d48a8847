r"""A stateful 3-D plate for repeated oblique impacts at one site (SI units).

:class:`SolidPlate` holds a :class:`~fem.solid.solver.SolidSolver` and the plate's current
:class:`~fem.solid.state.SolidState` (displacement u, plastic strain ε_p, equivalent plastic strain ᾱ): each impact
starts from the state the previous one left (its residual stress, plastic strain, dent and pile-up), as the
axisymmetric :class:`fem.Plate` does for the repeat chain::

    plate = SolidPlate(radius, material, max_overlap, track=(x0, x1), friction=0.3)
    d0 = plate.first_contact_overlap(c0)          # δ at which the sphere at x = c0 first touches the dented surface
    start = plate.start_state(d0, c0)             # the kept state, at first contact, with no stick history
    solid, probe = press_path(plate.solver, start, overlaps, centres, slides)   # does not change plate.state
    plate.commit(solid.final)                     # the lifted-off state after the impact becomes the plate's

Overlaps are measured from the ORIGINAL plane z = 0 (δ = depth of the sphere's tip below it), so on a dented plate
the sphere first touches the surface at δ₀ = :meth:`SolidPlate.first_contact_overlap` (≈ the dent's depth).

**A new impact's stick history.** The stick constraint of a vertex ties its tangential displacement since the
increment's start to the ball's slide ξ since then (:meth:`fem.solid.friction.SurfaceFriction.stick_rows`): the
kept state's u is the reference, and the slide ξ of a new impact counts from 0 at its first contact
(:meth:`start_state` sets ξ = 0, the contact and stick sets empty): the residual tangential displacement of the
last impact is kept, but no vertex is stuck to the new ball before it touches.

**Wear moves the surface the ball meets** (:meth:`SolidPlate.move_surface`): each surface node's worn depth lowers its
height in the contact gap (:attr:`fem.solid.solver.SolidSolver.worn_depth`), as the axisymmetric plate's moved nodes
do; the mesh keeps its reference surface (nm of wear per impact against µm elements), and the plate written to a
file has its surface lowered by the wear.

Forces and plastic work are those of the whole plate (twice the half model's).
"""

from __future__ import annotations

from dataclasses import fields, replace

import meshio
import numpy as np

from contact.checks import check_array, check_friction, check_number
from contact.materials import Material
from fem.core.increments import WorkCounters
from fem.core.plasticity import plastic_work
from fem.solid.indentation import SolidIndentation, SolidRecorder, solid_solver
from fem.solid.solver import SolidSolver
from fem.solid.state import SolidState

__all__ = ["SolidPlate", "press_path", "solid_plastic_work"]


def solid_plastic_work(solver: SolidSolver, before: SolidState, after: SolidState) -> float:
    """Plastic work (J) the whole plate (twice the half model) dissipated from ``before`` to ``after``
    (:func:`fem.core.plasticity.plastic_work`)."""
    return 2.0 * plastic_work(solver.material, solver.disc.weight, before.alpha, after.alpha)


def _since(before: WorkCounters, now: WorkCounters) -> WorkCounters:
    """The work ``now`` − ``before`` of one solver's cumulative counters."""
    out = WorkCounters()
    for counter in fields(out):
        if counter.name != "history":
            setattr(out, counter.name, getattr(now, counter.name) - getattr(before, counter.name))
    out.history.extend(now.history[len(before.history) :])
    return out


def press_path(
    solver: SolidSolver,
    start: SolidState,
    overlaps: np.ndarray,
    centres: np.ndarray,
    slides: np.ndarray,
    probe_after: int | None = None,
    probe: tuple[float, float, float] | None = None,
) -> tuple[SolidIndentation, dict | None]:
    """Press and drag the sphere over ``solver``'s plate from ``start`` along ``overlaps``, ``centres`` and
    ``slides`` (m, one entry per step), recording each step (the slip of the first from ``start``). With
    ``probe_after`` = k and ``probe`` = (δ, c, ξ): one extra step from the state after step k to ``probe``, measured
    (:meth:`fem.solid.indentation.SolidRecorder.measure`) and not recorded; the path goes on from step k. Returns
    (the recorded path with the solver's work over it, the probe's numbers or None)."""
    before = replace(solver.stats, history=list(solver.stats.history))
    recorder = SolidRecorder(solver, start)
    state, previous, measured = start, None, None
    for k in range(len(overlaps)):
        target = (float(overlaps[k]), float(centres[k]), float(slides[k]))
        previous, state = state, solver.advance(state, previous, target)
        recorder.add(state)
        if probe is not None and k == probe_after:
            measured = recorder.measure(solver.advance(state, previous, probe))
    solid = recorder.result()
    return replace(solid, stats=_since(before, solver.stats)), measured


class SolidPlate:
    """A 3-D elastic–plastic half plate that keeps its state between impacts of a sphere (module docstring).

    ``radius`` R (m) of the (rigid, or elastic via E*) ball; ``plate`` a :class:`contact.Material`; ``max_overlap``
    (m): the largest overlap expected from first contact (sizes the mesh, :func:`fem.solid.indentation.solid_solver`,
    and the solver's tolerances); ``track`` (m): the first and last x of the contact centre over the site's impacts;
    ``friction`` μ ≤ :data:`contact.checks.FRICTION_MAX`; ``ball`` None (rigid) or a Material; ``hardening``
    H (Pa); ``contact_elements`` across the contact radius of ``max_overlap`` in a box ``box_depth`` of it deep."""

    def __init__(
        self,
        radius: float,
        plate: Material,
        max_overlap: float,
        track: tuple[float, float] = (0.0, 0.0),
        friction: float = 0.0,
        ball: Material | None = None,
        hardening: float = 0.0,
        contact_elements: int = 4,
        box_depth: float = 1.0,
        rtol: float = 1e-6,
    ) -> None:
        self.radius = check_number("radius", radius, low=1e-6, high=10.0, units="m", what="ball radius")
        max_overlap = check_number("max_overlap", max_overlap, low=0.0, low_open=True, high=radius, units="m")
        self.friction = check_friction("friction", friction)
        self.solver = solid_solver(
            self.radius,
            plate,
            max_overlap,
            np.asarray(track, float),
            self.friction,
            ball,
            hardening,
            contact_elements,
            box_depth,
            rtol,
        )
        self.state: SolidState = self.solver.initial_state()
        self._virgin = True
        #: the last impact's recorded path (its final state is :attr:`state`), None before the first commit
        self.last: SolidIndentation | None = None

    @property
    def is_virgin(self) -> bool:
        """True until a state is committed."""
        return self._virgin

    @property
    def surface_displacement(self) -> np.ndarray:
        """u_z (m, positive up, out of the plate) of the surface nodes (quadratic: vertices and mid-edge nodes)."""
        return self.state.u[self.solver.uz]

    @property
    def dent_depth(self) -> float:
        """Largest displacement of the surface into the plate (m, max −u_z; 0 on a virgin plate)."""
        return max(float(np.max(-self.surface_displacement)), 0.0)

    @property
    def pile_up_height(self) -> float:
        """Largest rise of the surface above the original plane (m, max u_z; the lip of a plastic dent)."""
        return max(float(np.max(self.surface_displacement)), 0.0)

    def first_contact_overlap(self, centre: float = 0.0) -> float:
        """Overlap δ (m, sphere tip below the original plane) at which the sphere with its axis at x = ``centre``
        (m) first touches the current surface: min over the surface nodes of z_s(ρ; 0) − z (0 on a virgin plate)."""
        gap0 = self.solver.obstacle(0.0, centre) - self.surface_displacement
        return max(float(np.min(gap0)), 0.0)

    @property
    def surface_xy(self) -> np.ndarray:
        """(x, y) (m, (n, 2), y ≥ 0) of the surface nodes (vertices and mid-edge nodes), as :meth:`move_surface`
        takes them."""
        return self.solver.disc.surface_xy

    @property
    def wear_depth(self) -> np.ndarray:
        """The depth (m, ≥ 0) worn off each surface node by the impacts so far (:meth:`move_surface`)."""
        return self.solver.worn_depth.copy()

    def move_surface(self, depth) -> None:
        """Remove material: lower the surface at each surface node (:attr:`surface_xy`) by ``depth`` (m, ≥ 0, one
        value per node); the next impact's contact gap is measured to the worn surface."""
        depth = check_array("depth", depth, low=0.0, units="m", what="wear depth")
        if depth.shape != self.solver.worn_depth.shape:
            raise ValueError(
                f"depth has shape {depth.shape}: one value per surface node {self.solver.worn_depth.shape}"
            )
        self.solver.worn_depth = self.solver.worn_depth + depth

    def plastic_work(self, since: SolidState) -> float:
        """Plastic work (J, whole plate) dissipated from the state ``since`` to the current state."""
        return solid_plastic_work(self.solver, since, self.state)

    def start_state(self, first_contact: float, centre: float) -> SolidState:
        """The state an impact starts from: on a virgin plate the unloaded plate
        (:meth:`fem.solid.solver.SolidSolver.initial_state`, as a fresh solver starts), else the kept state with the
        sphere at first contact (overlap ``first_contact``, axis at ``centre``, m), slide ξ = 0 and no contact or
        stick set (a new contact has no stick history, module docstring)."""
        if self._virgin:
            return self.solver.initial_state()
        none = np.zeros_like(self.state.contact)
        return replace(
            self.state, overlap=first_contact, centre=centre, slide=0.0, contact=none, stick=none, iterations=0
        )

    def commit(self, solid: SolidIndentation) -> None:
        """Make the final state of ``solid`` (a path pressed on this plate's solver, the ball lifted off) the plate's
        current state."""
        if solid.solver is not self.solver:
            raise ValueError("solid: a path pressed on another plate's solver cannot be committed to this plate")
        self.state = solid.final
        self.last = solid
        self._virgin = False

    def to_meshio(self) -> meshio.Mesh:
        """The plate after the last committed impact (:meth:`fem.solid.indentation.SolidIndentation.to_meshio`), its
        surface lowered by the wear: point data ``wear_depth`` (m, the surface vertices' worn depth, 0 inside) and
        ``surface`` (1 on the surface vertices, 0 inside)."""
        if self.last is None:
            raise ValueError("the plate has no committed impact yet: nothing to write")
        mesh = self.last.to_meshio()
        d = self.solver.disc
        half = d.mesh.p.shape[1]  # the half block's vertices, then their mirror images
        vertices = d.surface_nodes < half  # the surface nodes that are vertices (the first nodes of the mesh)
        worn = np.zeros(half)
        worn[d.surface_nodes[vertices]] = self.solver.worn_depth[vertices]
        surface = np.zeros(half)
        surface[d.surface_nodes[vertices]] = 1.0
        worn, surface = np.r_[worn, worn], np.r_[surface, surface]
        points = np.array(mesh.points, float)
        points[:, 2] -= worn
        point_data = {**mesh.point_data, "wear_depth": worn, "surface": surface}
        return meshio.Mesh(points, mesh.cells, point_data=point_data, cell_data=mesh.cell_data)
