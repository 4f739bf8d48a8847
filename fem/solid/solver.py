r"""Newton solver of the 3-D plate pressed and dragged by a rigid sphere, with Coulomb friction.

Each increment prescribes the sphere's overlap δ, the x of its axis c (the contact centre's path) and the slide ξ:
the x displacement of the ball's surface in contact, relative to the plate far away (ξ̇ is the contact point's slip
velocity of the impact model). The plate's surface nodes obey

* **contact** (node by node): u_z,i ≤ z_s(ρ_i) − z_i with ρ_i = √((x_i − c)² + y_i²) and z_s the sphere's surface
  (:func:`fem.core.sphere.sphere_surface`); a node in contact has u_z prescribed there;
* **friction**: the discrete Coulomb law on the surface vertices (:mod:`fem.solid.friction`): weak stick constraints on
  the sticking vertices' dual functions, whose multipliers are the stick tractions, and at every other vertex the
  ball's tangential hat moment μ times its normal one, a load that follows the normal force.

Nodes that penetrate join the contact, nodes where the pressure is negative leave it; the stick set is Coulomb's law
returned vertex by vertex (:meth:`fem.solid.friction.SurfaceFriction.update_stick`). Each contact and stick set is
solved by Newton with the consistent tangent (the slip traction's linearisation makes it nonsymmetric), backtracking
along a step that would raise the residual; an increment whose sets do not settle in a few rounds is cut in halves. The
sets are sought on equilibria converged to a loose tolerance (``set_rtol``, 10⁻³ of the contact force) and only the
settled sets' equilibrium is converged to the solver's ``rtol`` (and the sets checked once more): Newton's
quadratic tail is spent once an increment, not once a set round (a plastic frictional increment of the default
impact 17 → 13 iterations, an unloading one 50 → 30; the same sets, displacements within 10⁻⁴).

Plasticity is the same J2 radial return as the axisymmetric plate (:mod:`fem.core.plasticity`, 6 Mandel components).
Linear solves: the constrained rows become s·I, the stick rows enter as an augmented Lagrangian (one multiplier
update a Newton step; both matrices on the tangent's fixed pattern, :mod:`fem.solid.systems`), and the system is
solved by CG (GMRES where slip tractions make it nonsymmetric) preconditioned with the PARDISO factor of an earlier
symmetric such matrix (:mod:`fem.core.kept_factor`), to an inexact-Newton tolerance, refactorised when the Krylov
method is slow: a modified-Newton iteration that keeps one factorisation over much of an increment.

One module for one algorithm (~410 lines): the Newton loop at fixed sets and the contact and stick set rounds around
it share the solver's state (its sets, tolerances, kept factor) and its counters; split, each half would take that
state as a dozen arguments. What needs none of it is apart: the Coulomb law (:mod:`fem.solid.friction`), the linear
systems and the stick rows' augmented-Lagrangian step (:mod:`fem.solid.systems`), the backtracking of a Newton step
(:mod:`fem.solid.line_search`), the increment driver (:mod:`fem.core.increments`).
"""

from __future__ import annotations

from functools import partial

import numpy as np
import scipy.sparse as sp
from skfem import MeshTet

from fem.core.anderson import anderson_step
from fem.core.assembly import assemble, element_matrices, internal_force, strain, tangent_stiffness
from fem.core.increments import NotConverged, WorkCounters, advance
from fem.core.kept_factor import KeptFactor
from fem.core.linear import SingularMatrixError, pardiso_threads
from fem.core.plasticity import J2Material, radial_return
from fem.core.sphere import sphere_surface
from fem.solid.forms import discretise_solid
from fem.solid.friction import SurfaceFriction
from fem.solid.line_search import backtrack
from fem.solid.state import SolidState
from fem.solid.systems import TangentSystems

__all__ = ["SETS_UNSETTLED", "SolidSolver"]

#: Why an attempt failed whose equilibria converged but whose contact and stick sets did not settle.
SETS_UNSETTLED = "contact/stick sets did not settle"


def _linear_tolerance(target_force: float, size: float) -> float:
    """Inexact Newton (Eisenstat & Walker 1996): the linear residual (N) a step may leave, tight only where the
    equilibrium residual is near its target ``target_force`` (N); ``size`` (N) is the step's own scale, the
    out-of-balance force plus the constraints' defect times a DOF's stiffness. The convergence test stays exact."""
    return max(1e-3 * target_force, min(1e-2 * size, 0.1 * np.sqrt(target_force * size)))


class SolidSolver:
    """3-D half plate on ``mesh`` (m) of ``material`` pressed by a rigid sphere of ``radius`` (m) with friction
    coefficient ``friction``, its slip traction limited by the surface's ``shear_strength`` k (Pa; default: Y/√3 of
    a perfectly plastic ``material``, else none; :mod:`fem.solid.friction`). ``force_scale`` (N) and ``gap_scale`` (m)
    set the tolerances (1e-12 and 1e-7 of them); ``rtol`` is the converged out-of-balance force relative to the
    contact force, ``set_rtol`` (max(rtol, 10⁻³)) the looser one the contact and stick sets are sought at."""

    def __init__(
        self,
        mesh: MeshTet,
        material: J2Material,
        radius: float,
        friction: float,
        force_scale: float,
        gap_scale: float,
        rtol: float = 1e-6,
        max_iterations: int = 30,
        max_cuts: int = 5,
        shear_strength: float | None = None,
    ) -> None:
        self.disc = d = discretise_solid(mesh)
        self.material = material
        self.radius = radius
        self.friction = friction
        self.rtol = rtol
        self.atol = 1e-12 * force_scale
        self.gap_tol = 1e-7 * gap_scale
        self.max_iterations = max_iterations
        self.max_cuts = max_cuts
        # an increment whose contact and stick sets still change after 6 rounds is cut: at a reversal of the
        # slide on a plastic dent (μ = 0.5, 30°) the rounds of a whole increment released ring after ring towards
        # gross slip and failed after 9 rounds, where its halves settled in 3 rounds each
        self.max_set_updates = 6
        # 10⁻² found other contact sets at an edge node (displacements 2% apart); 10⁻³ the same sets as rtol
        self.set_rtol = max(rtol, 1e-3)
        self.stats = WorkCounters()
        self.tangent_elastic = material.elastic_tangent_of(6)
        self.elastic_element_matrices = element_matrices(d, self.tangent_elastic)
        self.elastic_stiffness = assemble(d, self.elastic_element_matrices)
        self.systems = TangentSystems(d)
        if shear_strength is None:
            shear_strength = material.surface_shear_strength
        self.surface = SurfaceFriction(d, mesh.p.shape[1], material.shear, material.nu, shear_strength)
        self.uz, self.ut = self.surface.uz, self.surface.ut
        self.linear = KeptFactor(self.stats, max_krylov=15)
        nel, nq = d.weight.shape
        self._zero_plastic = np.zeros((nel, nq, 6))
        self._zero_alpha = np.zeros((nel, nq))
        #: depth (m, ≥ 0) worn off each surface node: the contact gap is measured to the worn surface (the mesh keeps
        #: its reference surface: nm of wear against µm elements)
        self.worn_depth = np.zeros(d.surface_nodes.size)

    # -- the contact geometry and the surface fields
    def initial_state(self) -> SolidState:
        """The undeformed, unloaded plate."""
        n = self.disc.surface_nodes.size
        return SolidState(
            0.0,
            0.0,
            0.0,
            np.zeros(self.disc.ndofs),
            self._zero_plastic,
            self._zero_alpha,
            np.zeros(n, bool),
            np.zeros(n, bool),
            np.tile([1.0, 0.0], (self.disc.surface_vertex_nodes.size, 1)),
        )

    def obstacle(self, overlap: float, centre: float) -> np.ndarray:
        """Largest u_z (m) of each surface node with the sphere at ``overlap`` and axis x = ``centre`` (m): the
        sphere's surface less the node's height, which wear lowered by :attr:`worn_depth`."""
        xy = self.disc.surface_xy
        rho = np.hypot(xy[:, 0] - centre, xy[:, 1])
        height = self.disc.nodes[2, self.disc.surface_nodes] - self.worn_depth
        return sphere_surface(rho, overlap, self.radius) - height

    def surface_forces(self, state: SolidState) -> tuple[np.ndarray, np.ndarray]:
        """The ball's forces on the surface nodes (N): normal (positive pressing) and tangential (x, y)."""
        f = internal_force(self.disc, self.stress_update(state).stress)
        return -f[self.uz], self.surface.ball_shear(f)

    def stress_update(self, state: SolidState, reference: SolidState | None = None):
        """Stress update of ``state.u`` from ``reference`` (default: the state itself, i.e. its stresses)."""
        ref = state if reference is None else reference
        return radial_return(self.material, strain(self.disc, state.u), ref.plastic_strain, ref.alpha)

    # -- one increment
    def _equilibrate(
        self,
        start: SolidState,
        target: tuple[float, float, float],
        u,
        contact,
        stick,
        direction,
        mu,
        elastic: bool,
        rtol: float,
    ):
        """Newton at fixed contact and stick sets and slip directions ``direction`` (surface vertices, 2). Returns
        (u, stress update, f_int, iterations). ``elastic``: iterate with the elastic stiffness (initial-stiffness
        method: linear convergence, but robust where the consistent tangent of a perfectly plastic point that
        flips between reverse yield and elastic unloading misleads Newton or is not positive definite), up to
        4 × the iterations. ``rtol``: the out-of-balance force it stops at, relative to the contact force."""
        d = self.disc
        overlap, centre, slide = target
        obstacle = self.obstacle(overlap, centre)
        constrained, values, free = self._prescribed(contact, obstacle)
        constraint = self.systems.constraint(free)
        surface = self.surface
        slip_vertices = surface.slip_vertices(stick) if mu > 0.0 else None
        rows, targets, row_ids = surface.stick_rows(start, slide, contact, stick, free) if mu > 0.0 else (None,) * 3
        if rows is not None and rows.shape[0] == 0:
            rows = None
        multipliers = np.zeros(0 if rows is None else rows.shape[0])
        history: list = []
        slipping = slip_vertices is not None and slip_vertices.any()
        balance = partial(self._balance, start, contact, rows, slip_vertices if slipping else None, direction, mu)
        upd, f, normal_moments, residual_vector, balanced = balance(u, multipliers)
        for it in range(self.max_iterations * (4 if elastic else 1)):
            residual = np.linalg.norm(balanced[free])
            scale = max(np.linalg.norm(f[self.uz[contact]]), self.atol / rtol)
            du_c = values - u[constrained]
            # the rows are scaled to unit row sums (a weighted mean slip), so their error is a length
            stick_error = 0.0 if rows is None else float(np.max(np.abs(targets - rows @ u), initial=0.0))
            if (
                np.max(np.abs(du_c), initial=0.0) <= self.gap_tol
                and stick_error <= self.gap_tol
                and residual <= rtol * scale
            ):
                return u, upd, f, it
            if it == 0:
                start_size = max(residual, scale)
            elif not residual <= 1e6 * max(min(scale, start_size), 1e3 * self.atol / self.rtol):
                # diverging: the contact forces grow with the residual, so the bound is the increment's first size
                break
            K = self._tangent(upd, elastic)
            rhs = residual_vector
            step = np.zeros(d.ndofs)
            step[constrained] = du_c
            rhs = rhs - K @ step
            keep = free.astype(float)
            diag = float(np.mean(self.systems.diagonal(K)[free]))
            rhs[constrained] = diag * du_c
            K_mod = self.systems.constrained(K, constraint, diag)
            moved = np.linalg.norm(du_c) + (0.0 if rows is None else np.linalg.norm(targets - rows @ (u + step)))
            tolerance = _linear_tolerance(rtol * scale, residual + diag * float(moved))
            key = constrained.tobytes() + (b"elastic" if elastic else b"")
            coupling = None
            if slipping:
                coupling = surface.slip_linearisation(K, normal_moments, direction, slip_vertices, mu, keep, contact)
            try:
                if rows is None:
                    du, new_multipliers = self.linear.solve(K_mod, rhs, tolerance, key, coupling), multipliers
                else:
                    defect = targets - rows @ (u + step)
                    du, new_multipliers = self.systems.augmented_step(
                        self.linear, K_mod, rhs, rows, row_ids, defect, multipliers, key, tolerance, coupling
                    )
            except SingularMatrixError:
                break
            self.stats.iterations += 1
            if elastic:
                # the initial-stiffness iteration is no Newton method: its steps are taken whole
                if du_c.any():
                    history.clear()
                    u = u + du
                else:
                    u = anderson_step(history, u, du)
                multipliers = new_multipliers
                upd, f, normal_moments, residual_vector, balanced = balance(u, multipliers)
            else:
                searched = backtrack(balance, free, u, step, du, multipliers, new_multipliers, residual)
                if searched is None:
                    break
                u, multipliers, (upd, f, normal_moments, residual_vector, balanced), shortened = searched
                self.stats.backtracks += int(shortened)
        raise NotConverged(residual)

    def _prescribed(self, contact: np.ndarray, obstacle: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The constrained DOFs of the ``contact`` set (the clamped ones and the contact nodes' u_z), the displacements
        (m) prescribed on them (0 and the ``obstacle``) and the mask of the free DOFs."""
        d = self.disc
        constrained = np.unique(np.concatenate([d.fixed_dofs, self.uz[contact]]))
        values = np.zeros(d.ndofs)
        values[self.uz[contact]] = obstacle[contact]
        free = np.ones(d.ndofs, bool)
        free[constrained] = False
        return constrained, values[constrained], free

    def _balance(self, start: SolidState, contact, rows, slip_vertices, direction, mu: float, u, multipliers):
        """The state at displacement ``u`` (m): (stress update, internal force f (N), the normal hat moments (N) or
        None without slip, the out-of-balance force r = f_ext − f, and r less the stick rows' loads of
        ``multipliers``). The slip traction is an external load that follows the normal force: at the slipping
        vertices (H f_t)_j = μ (H f_n)_j⁺ ŝ_j."""
        d = self.disc
        upd = radial_return(self.material, strain(d, u), start.plastic_strain, start.alpha)
        f = internal_force(d, upd.stress)
        residual_vector, normal_moments = -f, None
        if slip_vertices is not None:
            slip_loads, normal_moments = self.surface.slip_loads(f, contact, slip_vertices, direction, mu)
            residual_vector = residual_vector + slip_loads
        # the stick tractions (the multipliers of the last solve) balance the residual on the stick zone
        balanced = residual_vector if rows is None else residual_vector - rows.T @ multipliers
        return upd, f, normal_moments, residual_vector, balanced

    def _tangent(self, upd, elastic: bool = False) -> sp.csr_matrix:
        """The consistent tangent (N/m) of the stress update ``upd``; the elastic stiffness if ``elastic``."""
        if elastic:
            return self.disc.matrix(self.elastic_stiffness.data.copy())
        return tangent_stiffness(
            self.disc, self.elastic_stiffness, self.elastic_element_matrices, self.tangent_elastic, upd
        )

    def _newton(self, start: SolidState, target, u0, contact, stick, direction, mu) -> SolidState:
        """Equilibrium at ``target`` = (δ, c, ξ), correcting the contact and stick sets until neither is violated."""
        overlap, centre, slide = target
        obstacle = self.obstacle(overlap, centre)
        u = u0.copy()
        seen: set[bytes] = set()
        spent = 0
        released = np.zeros_like(stick)  # nodes that left the stick set in this increment do not return to it
        first_stick = stick
        # an unloading increment is mostly elastic: the elastic stiffness (one factor for the whole increment)
        # converges in a few iterations where the consistent tangent of the points that flip between reverse yield
        # and elastic unloading takes tens, each with a new factor
        unloading = overlap < start.overlap and bool(np.any(start.alpha))
        # the sets are sought at set_rtol, the settled ones confirmed at rtol (module docstring)
        tolerance, rounds, turns = self.set_rtol, 0, 0
        while True:
            try:
                u, upd, f, it = self._equilibrate(start, target, u, contact, stick, direction, mu, unloading, tolerance)
            except NotConverged:
                u, upd, f, it = self._equilibrate(
                    start, target, start.u, contact, stick, direction, mu, not unloading, tolerance
                )
                self.stats.elastic_retries += 1
            spent += it
            normal = -f[self.uz]
            p_vertex = self.surface.vertex_field(normal)
            p_node = self.disc.surface_hats.T @ p_vertex
            p_scale = max(float(np.max(np.abs(p_vertex), initial=0.0)), 1e-300)
            gap = obstacle - u[self.uz]
            pulling = contact & (p_node < -10.0 * tolerance * p_scale)
            penetrating = ~contact & (gap < -self.gap_tol)
            new_contact = (contact & ~pulling) | penetrating
            new_stick, new_direction = stick & new_contact, direction
            # a round is its sets and the vertices released so far: a set revisited with more released (which may
            # not stick again) is no cycle. At normal incidence the slip zone's vertices barely move: those whose
            # slip turns back restick, then leave the cone, and the next round (without them) settles; taken for a
            # cycle, every cut of the increment failed
            this_round = contact.tobytes() + stick.tobytes() + released.tobytes()
            if mu > 0.0:
                new_stick, new_direction = self.surface.update_stick(
                    start, target, u, f, stick, direction, new_contact, mu, released
                )
                released |= stick & ~new_stick
            key = new_contact.tobytes() + new_stick.tobytes() + released.tobytes()
            if np.array_equal(new_contact, contact) and np.array_equal(new_stick, stick):
                if turns < self.max_set_updates and self.surface.turned(direction, new_direction, stick, contact):
                    # the sets settled, but a vertex's slip turned away from the traction it was solved with: the
                    # state holds Coulomb's law (and hands its directions on) only once every traction follows its
                    # slip; kept, the slip zone went on pulling the old way after the slide reversed
                    direction, turns = new_direction, turns + 1
                    self.stats.set_updates += 1
                    continue
                if tolerance > self.rtol:
                    tolerance = self.rtol
                    continue
                self.stats.history.append(spent)
                return SolidState(
                    overlap, centre, slide, u, upd.plastic_strain, upd.alpha, contact, stick, direction, spent, mu
                )
            # a round that only takes back resticks of this increment (their stick traction left the cone) refunds
            # the round that made them: the released vertices may not stick again, so such pairs end. Where the slip
            # zone's slip turns (normal unloading at normal incidence) they cost two rounds a vertex in every cut,
            # and the increments failed however often cut
            taken_back = released & ~first_stick
            if np.array_equal(new_contact, contact) and np.array_equal(new_stick, stick & ~taken_back):
                rounds = max(rounds - 1, 0)
            else:
                rounds += 1
            if rounds >= self.max_set_updates:
                raise NotConverged(SETS_UNSETTLED)
            tolerance = self.set_rtol
            self.stats.set_updates += 1
            seen.add(this_round)
            if key in seen:
                # a cycle: correct the contact only (penetration first), keep the stick set
                new_stick = stick & new_contact
                if (new_contact.tobytes() + new_stick.tobytes() + released.tobytes()) in seen:
                    raise NotConverged(SETS_UNSETTLED)
            contact, stick, direction = new_contact, new_stick, new_direction

    def _guess(self, state: SolidState, previous: SolidState | None, target, mu: float):
        overlap, centre, slide = target
        obstacle = self.obstacle(overlap, centre)
        u0 = state.u
        if previous is not None and overlap > state.overlap > previous.overlap:
            factor = min((overlap - state.overlap) / (state.overlap - previous.overlap), 4.0)
            u0 = state.u + factor * (state.u - previous.u)
        contact = state.contact | (obstacle - u0[self.uz] <= self.gap_tol)
        if state.overlap == 0.0 and not state.contact.any():
            # Hertz's contact radius of the approach from the surface the sphere first touches (a worn one lies
            # below the plane the overlap counts from)
            worn = float(np.min(self.obstacle(0.0, centre))) if self.worn_depth.any() else 0.0
            rho = np.hypot(self.disc.surface_xy[:, 0] - centre, self.disc.surface_xy[:, 1])
            contact = rho < np.sqrt(self.radius * max(overlap - worn, 0.0))
        last_step = 0.0 if previous is None else state.slide - previous.slide
        return u0, contact, self.surface.stick_guess(state, target, contact, mu, last_step), state.direction

    def attempt(self, state: SolidState, previous: SolidState | None, step: tuple[float, float, float, float]):
        """The Newton attempt at ``step`` = (overlap δ, centre c, slide ξ in m, friction coefficient μ) from
        ``state`` (``previous``: the state before it, for the guess); :class:`fem.core.increments.NotConverged` if it
        fails."""
        target, mu = step[:3], step[3]
        u0, contact, stick, direction = self._guess(state, previous, target, mu)
        return self._newton(state, target, u0, contact, stick, direction, mu)

    @staticmethod
    def midpoint(state: SolidState, step: tuple[float, float, float, float]) -> tuple[float, float, float, float]:
        """The step halfway from ``state``'s (δ, c, ξ) to ``step``'s (m), at its friction coefficient."""
        start = (state.overlap, state.centre, state.slide)
        return (*(0.5 * (a + b) for a, b in zip(start, step[:3], strict=True)), step[3])

    @staticmethod
    def describe(state: SolidState, step: tuple[float, float, float, float]) -> str:
        """The failed increment, for the user."""
        return (
            f"3-D plate: Newton did not converge at overlap={step[0]:.6g} m, centre={step[1]:.6g} m, "
            f"slide={step[2]:.6g} m"
        )

    def advance(
        self,
        state: SolidState,
        previous: SolidState | None,
        target: tuple[float, float, float],
        friction: float | None = None,
    ) -> SolidState:
        """Converged state at ``target`` = (overlap δ, centre c, slide ξ) in m from ``state``, with friction
        coefficient ``friction`` (default the solver's); cuts the increment in halves if needed
        (:func:`fem.core.increments.advance`)."""
        mu = self.friction if friction is None else friction
        with pardiso_threads():
            return advance(self, state, previous, (*target, mu))
