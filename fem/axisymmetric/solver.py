r"""Newton solver of the plate pressed by the sphere: plasticity inside, the contact set outside.

Each increment prescribes the overlap δ. Inner loop (:meth:`PlateSolver._equilibrate`): Newton at a fixed
contact set — return-map every quadrature point from the converged state of the previous increment, assemble
f_int and (where points yield) the consistent tangent into the fixed CSR pattern, solve the reduced system
(u_r = 0 on the axis, u_z = 0 at the bottom, u_z = z_s(r) − z_node at the contact nodes) by conjugate gradients
preconditioned with the LU of an earlier tangent (SuperLU, refactorised when CG is slow and at each plastic
increment) to an inexact-Newton tolerance (Eisenstat–Walker); backtracking once the constraints hold, and a
direction along which no step lowers the residual ends the attempt. Outer loop (:meth:`PlateSolver._newton`): the set is
corrected — pulling nodes leave, penetrating nodes join — until the converged state violates neither
(complementarity: reactions ≥ 0 on the set, gaps ≥ 0 off it, to ``rtol`` and 1e-7 of the path's overlap).
The set may take any shape; a cycling set is broken by one-node corrections. Where Newton fails as the plate is
set free of a conforming dent, an elastic-stiffness (initial-stiffness) retry converges. An increment that still
does not converge is cut in halves (up to ``max_cuts`` times) before :class:`ConvergenceError` names it.

States (u, ε_p, ᾱ, contact set) are plain frozen records so a loading run can keep them and an unloading run can
restart from any of them (path independence of the loading branch).

One module for one algorithm (~410 lines): the Newton loop, the active-set correction and the step cutting share
the solver's state (tangent factorisation, CSR pattern, contact set) increment by increment; split apart they would
pass that state back and forth.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla
from skfem import MeshTri

from fem.axisymmetric.forms import discretise
from fem.core.assembly import assemble, element_matrices, internal_force, strain, tangent_stiffness
from fem.core.increments import NotConverged, WorkCounters, advance
from fem.core.plasticity import J2Material, radial_return
from fem.core.sphere import sphere_surface

__all__ = ["PlateState", "PlateSolver"]


@dataclass(frozen=True, eq=False)
class PlateState:
    """Converged state: ``overlap`` δ (m), ``u`` nodal displacements (m, interleaved r, z),
    ``plastic_strain`` (elements, qp, 4) Mandel, ``alpha`` (elements, qp) equivalent plastic
    strain, ``active`` bool mask of the surface nodes in contact, ``iterations`` Newton iterations spent."""

    overlap: float
    u: np.ndarray
    plastic_strain: np.ndarray
    alpha: np.ndarray
    active: np.ndarray
    iterations: int = 0

    @property
    def n_active(self) -> int:
        return int(np.count_nonzero(self.active))


class PlateSolver:
    """Axisymmetric plate on ``mesh`` (m) of ``material`` pressed by a rigid sphere of ``radius`` (m).

    ``force_scale`` (N) sets the absolute residual floor (1e-12 of it); ``gap_scale`` (m) the
    penetration tolerance (1e-7 of it).
    """

    def __init__(
        self,
        mesh: MeshTri,
        material: J2Material,
        radius: float,
        force_scale: float,
        gap_scale: float,
        rtol: float = 1e-6,
        max_iterations: int = 25,
        max_cuts: int = 6,
    ) -> None:
        self.disc = discretise(mesh)
        self.material = material
        self.radius = radius
        self.rtol = rtol
        self.atol = 1e-12 * force_scale
        self.force_scale = force_scale
        self.gap_scale = gap_scale
        self.relaxed_penetration = 1e-4
        self.relaxed_pull = 1e-5
        self.gap_tol = 1e-7 * gap_scale
        self.max_iterations = max_iterations
        self.max_set_updates = 40
        # a node pulls when its reaction is below −release_tol × the contact force (2-norm): the iterate's own
        # equilibrium error is rtol of it, so smaller negative reactions are not resolved
        self.release_tol = 10.0 * rtol
        self.early_joins = 3
        self.max_cuts = max_cuts
        d = self.disc
        self.elastic_element_matrices = element_matrices(d, material.elastic_tangent)
        self.fixed_dofs = np.unique(np.concatenate([d.axis_dofs, d.bottom_dofs]))
        self.surface_ur = 2 * d.surface_nodes
        self.surface_uz = 2 * d.surface_nodes + 1
        self.stats = WorkCounters()
        self._elastic_K = None
        self._lu = None
        self._refresh = False
        self.cg_rtol = 1e-9
        self.cg_max_iterations = 12
        nel, nq = d.weight.shape
        self._zero_plastic = np.zeros((nel, nq, 4))
        self._zero_alpha = np.zeros((nel, nq))

    def initial_state(self) -> PlateState:
        """The undeformed, unloaded plate."""
        nodes = self.disc.surface_r.size
        return PlateState(0.0, np.zeros(self.disc.ndofs), self._zero_plastic, self._zero_alpha, np.zeros(nodes, bool))

    def obstacle(self, overlap: float) -> np.ndarray:
        """Largest u_z (m) each surface node may take at ``overlap`` (m): the sphere's surface z_s(r) minus the
        node's reference height (0 on a flat plate; below 0 where wear moved the node), so the gap is measured to
        the current surface, not to the plane z = 0."""
        return sphere_surface(self.disc.surface_r, overlap, self.radius) - self.disc.surface_z

    def stress_update(self, state: PlateState, reference: PlateState | None = None):
        """Stress update of ``state.u`` from ``reference`` (default: the state itself, i.e. its stresses)."""
        ref = state if reference is None else reference
        return radial_return(self.material, strain(self.disc, state.u), ref.plastic_strain, ref.alpha)

    def reactions(self, state: PlateState) -> np.ndarray:
        """Contact forces (N, positive = compressive) at the surface nodes sorted by r."""
        upd = self.stress_update(state)
        return -internal_force(self.disc, upd.stress)[self.surface_uz]

    def elastic_stiffness(self) -> sp.csr_matrix:
        """The elastic stiffness matrix K_e (N/m, all DOFs, no boundary conditions), assembled once."""
        if self._elastic_K is None:
            self._elastic_K = assemble(self.disc, self.elastic_element_matrices)
        return self._elastic_K

    def _tangent(self, upd) -> sp.csr_matrix:
        return tangent_stiffness(
            self.disc, self.elastic_stiffness(), self.elastic_element_matrices, self.material.elastic_tangent, upd
        )

    def _newton(self, start: PlateState, overlap: float, u0: np.ndarray, active0: np.ndarray) -> PlateState:
        """Equilibrium at ``overlap`` (m) from the converged ``start``: Newton at a fixed contact set, then the
        set is corrected (nodes that pull leave, free nodes that penetrate join) and Newton resumes, until the
        converged iterate violates neither condition. The set may take any shape (a P2 vertex can leave while
        its neighbours press): the discrete problem's unique solution, not a disc imposed on it.

        A set met before (the full correction cycles: an edge node pulls when held and penetrates when
        free) is avoided by correcting one node only, the worst violation not yet tried. If every correction
        leads back to a set met before — seen only where the last nodes leave a plastically conforming dent,
        with contact forces ~1e-6 of the peak — the best equilibrium met is accepted when its violations are
        below ``relaxed_penetration`` × the path's overlap and ``relaxed_pull`` × its force scale (counted in
        ``stats.relaxed``); otherwise the increment is cut."""
        uz = self.surface_uz
        obstacle = self.obstacle(overlap)
        u = u0.copy()
        active = active0.copy()
        seen: set[bytes] = set()
        # a plastic increment changes the tangent in the whole plastic zone: the last increment's LU is a poor
        # preconditioner for its first solve, so factorise afresh (CG on that LU serves the later iterations)
        self._refresh = bool(np.any(start.alpha))
        iterations = 0
        best = None
        for _ in range(self.max_set_updates):
            try:
                u, upd, f, spent, active = self._equilibrate(start, u, active, obstacle, seen)
            except NotConverged:
                # the consistent tangent misleads where quadrature points flip between reverse yield and elastic
                # unloading (the plate set free of a conforming dent): the elastic stiffness converges there,
                # restarted from the increment's start so its first iterate is the elastic trial state (exact when
                # the release is elastic, as at the last contact loss: one iteration instead of ~90 from the
                # failed iterate, whose spuriously yielding points creep back one by one)
                u, upd, f, spent, active = self._equilibrate(start, start.u, active, obstacle, seen, elastic=True)
                self.stats.elastic_retries += 1
            iterations += spent
            reactions = -f[uz]
            gap = obstacle - u[uz]
            force = max(np.linalg.norm(reactions[active]), self.atol / self.rtol)
            pulling = active & (reactions < -self.release_tol * force)
            penetrating = ~active & (gap < -self.gap_tol)
            if not (pulling.any() or penetrating.any()):
                self.stats.iterations += iterations
                self.stats.history.append(iterations)
                return PlateState(overlap, u, upd.plastic_strain, upd.alpha, active, iterations)
            violation = max(
                -np.min(gap[penetrating], initial=0.0) / (self.relaxed_penetration * self.gap_scale),
                -np.min(reactions[pulling], initial=0.0) / (self.relaxed_pull * self.force_scale),
            )
            if best is None or violation < best[0]:
                best = (violation, PlateState(overlap, u, upd.plastic_strain, upd.alpha, active, 0))
            seen.add(active.tobytes())
            new = (active & ~pulling) | penetrating
            if new.tobytes() in seen:
                # one node at a time, worst first: joins by penetration, then leaves by pull
                order = np.r_[
                    np.flatnonzero(penetrating)[np.argsort(gap[penetrating])],
                    np.flatnonzero(pulling)[np.argsort(reactions[pulling])],
                ]
                for node in order:
                    new = active.copy()
                    new[node] = not new[node]
                    if new.tobytes() not in seen:
                        break
                else:
                    break
            active = new
        if best is not None and best[0] <= 1.0:
            self.stats.iterations += iterations
            self.stats.history.append(iterations)
            self.stats.relaxed += 1
            return replace(best[1], iterations=iterations)
        raise NotConverged(float("nan"))

    def _equilibrate(
        self, start: PlateState, u: np.ndarray, active: np.ndarray, obstacle: np.ndarray, seen: set, elastic=False
    ):
        """Newton at the contact set ``active``: u_z = ``obstacle`` there (prescribed on the first iteration, so
        the constraint holds exactly afterwards), equilibrium of the free DOFs. Free nodes that penetrate join
        the set during the first ``early_joins`` iterations (a set not in ``seen``): that saves a restart when
        the increment's guess of the set was too small, as on every loading step. Returns (u, stress update,
        internal force, iterations, set); raises :class:`NotConverged`. ``elastic``: iterate with the elastic
        stiffness (initial-stiffness method: slower, linear convergence, but robust), up to 4 × the iterations."""
        d = self.disc
        uz = self.surface_uz

        def masks(active):
            constrained = np.concatenate([self.fixed_dofs, uz[active]])
            free_mask = np.ones(d.ndofs, dtype=bool)
            free_mask[constrained] = False
            return constrained, free_mask

        constrained, free_mask = masks(active)
        cached = None
        first_residual = None
        residual = np.inf
        previous_residual = None
        for it in range(self.max_iterations * (4 if elastic else 1)):
            if cached is None:
                upd = radial_return(self.material, strain(d, u), start.plastic_strain, start.alpha)
                f = internal_force(d, upd.stress)
            else:
                upd, f = cached
            if 0 < it <= self.early_joins:
                penetrating = ~active & (obstacle - u[uz] < -self.gap_tol)
                if penetrating.any() and (active | penetrating).tobytes() not in seen:
                    active = active | penetrating
                    constrained, free_mask = masks(active)
                    first_residual = None
            du_c = np.concatenate([-u[self.fixed_dofs], obstacle[active] - u[uz[active]]])
            residual = np.linalg.norm(f[free_mask])
            scale = max(np.linalg.norm(f[uz[active]]), self.atol / self.rtol)
            prescribed = np.max(np.abs(du_c), initial=0.0) <= self.gap_tol
            if prescribed and residual <= self.rtol * scale:
                return u, upd, f, it, active
            if first_residual is None and prescribed:
                first_residual = max(residual, self.rtol * scale)
            elif first_residual is not None and residual > 1e4 * first_residual:
                break  # diverging: cut the increment now
            t0 = time.perf_counter()
            K = self.elastic_stiffness() if elastic else self._tangent(upd)
            du = np.zeros(d.ndofs)
            du[constrained] = du_c
            rhs = -f - K @ du
            # constrained rows become s·I with s the mean free diagonal, so forces and the prescribed
            # displacements weigh alike in the CG residual
            keep = free_mask.astype(float)
            diag_scale = float(np.mean(K.diagonal()[free_mask]))
            rhs[constrained] = diag_scale * du_c
            K_mod = (sp.diags(keep) @ K @ sp.diags(keep) + sp.diags(diag_scale * (1.0 - keep))).tocsr()
            t1 = time.perf_counter()
            step = self._linear_solve(K_mod, rhs, self._forcing(residual, previous_residual, self.rtol * scale, rhs))
            previous_residual = residual
            t2 = time.perf_counter()
            self.stats.assembly_time += t1 - t0
            self.stats.factor_time += t2 - t1
            if not np.all(np.isfinite(step)):
                break
            u, cached = self._line_search(start, u, step, free_mask, residual, prescribed)
            if prescribed and np.linalg.norm(cached[1][free_mask]) > residual:
                break  # no step length along the Newton direction lowers the residual: not a descent direction
        raise NotConverged(residual)

    def _forcing(self, residual: float, previous: float | None, target: float, rhs: np.ndarray) -> float:
        r"""Relative tolerance of the inner linear solve (inexact Newton, Eisenstat & Walker 1996, choice 2):
        :math:`\eta_k = 0.9\,(r_k / r_{k-1})^2`, at most 1e-2 (1e-2 on the first iteration), and no tighter
        than needed to bring the residual to a tenth of the ``target`` (N) — solving the linearisation to 1e-9
        when the nonlinearity limits the next residual anyway was half the cost of an increment."""
        eta = 1e-2 if not previous else 0.9 * (residual / previous) ** 2
        floor = 0.1 * target / max(float(np.linalg.norm(rhs)), 1e-300)
        return max(min(max(eta, floor), 1e-2), self.cg_rtol)

    def _line_search(
        self, start: PlateState, u: np.ndarray, step: np.ndarray, free_mask, residual: float, backtrack: bool
    ):
        """Full Newton step, unless (``backtrack``: the constraints already hold) it increases the free residual:
        then the best of the step halved up to four times. Guards the divergence when quadrature points of a
        perfectly plastic dent flip between reverse yield and elastic unloading, as when the last nodes leave;
        the evaluation at the accepted point is reused by the next iteration."""
        d = self.disc
        best = None
        for alpha in (1.0, 0.5, 0.25, 0.125, 0.0625):
            trial = u + alpha * step
            upd = radial_return(self.material, strain(d, trial), start.plastic_strain, start.alpha)
            f = internal_force(d, upd.stress)
            value = np.linalg.norm(f[free_mask])
            if best is None or value < best[0]:
                best = (value, trial, upd, f)
            if not backtrack or value <= residual:
                break
        return best[1], (best[2], best[3])

    def _factorise(self, K_mod: sp.csr_matrix) -> None:
        self._lu = spla.splu(
            K_mod.tocsc(), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True}
        )
        self.stats.factorisations += 1

    def _linear_solve(self, K_mod: sp.csr_matrix, rhs: np.ndarray, tolerance: float) -> np.ndarray:
        """Solve K_mod x = rhs: preconditioned CG with the LU of an earlier tangent (the tangent changes only
        in the plastic zone and at the contact edge), refactorising when CG needs more than
        ``cg_max_iterations`` (or on the first call)."""
        if self._refresh:
            self._refresh = False
            self._lu = None
        if self._lu is not None:
            count = [0]

            def callback(_):
                count[0] += 1

            M = spla.LinearOperator(K_mod.shape, matvec=self._lu.solve, dtype=float)
            x, info = spla.cg(
                K_mod,
                rhs,
                x0=self._lu.solve(rhs),
                rtol=tolerance,
                maxiter=self.cg_max_iterations,
                M=M,
                callback=callback,
            )
            self.stats.cg_iterations += count[0]
            if info == 0:
                return x
        self._factorise(K_mod)
        return self._lu.solve(rhs)

    def _guess(self, state: PlateState, previous: PlateState | None, overlap: float) -> tuple[np.ndarray, np.ndarray]:
        d = self.disc
        step = overlap - state.overlap
        if state.n_active == 0 and not np.any(state.u):
            # first contact of a virgin plate: Hertz contact set
            return state.u, d.surface_r < math.sqrt(self.radius * max(overlap, 0.0))
        if previous is not None and step > 0.0:
            # extrapolate on loading only: on unloading a large extrapolated trial state can set off spurious
            # reverse yielding that Newton does not recover from; the previous state is a good start there
            last = state.overlap - previous.overlap
            if last != 0.0 and step * last > 0.0:
                factor = min(step / last, 4.0)
                u0 = state.u + factor * (state.u - previous.u)
                gap = self.obstacle(overlap) - u0[self.surface_uz]
                # nodes the extrapolation keeps on the sphere (gap ≈ 0) or pushes into it
                guess = gap <= 1e-6 * abs(step) + self.gap_tol
                if guess.any():
                    # one node short: a missing node joins within the first iterations, while a node too many
                    # (it would pull) can only leave after the set has converged, costing a second solve
                    guess[np.flatnonzero(guess)[-1]] = False
                return u0, guess
        if previous is not None and step < 0.0 and state.n_active and previous.n_active:
            # unloading: the edge recedes about as many nodes as in the last increment (scaled by the step);
            # nodes released too early penetrate and join again in the first iterations
            last = state.overlap - previous.overlap
            if last < 0.0:
                edge = int(np.flatnonzero(state.active)[-1])
                receded = int(np.flatnonzero(previous.active)[-1]) - edge
                keep = np.arange(state.active.size) <= edge - int(max(receded, 0) * min(step / last, 4.0))
                return state.u, state.active & keep
        return state.u, state.active

    def attempt(self, state: PlateState, previous: PlateState | None, overlap: float) -> PlateState:
        """The Newton attempt at ``overlap`` (m) from ``state`` (``previous``: the state before it, for the guess);
        :class:`fem.core.increments.NotConverged` if it fails."""
        u0, n0 = self._guess(state, previous, overlap)
        return self._newton(state, overlap, u0, n0)

    @staticmethod
    def midpoint(state: PlateState, overlap: float) -> float:
        """The overlap (m) halfway from ``state``'s to ``overlap``."""
        return 0.5 * (state.overlap + overlap)

    @staticmethod
    def describe(state: PlateState, overlap: float) -> str:
        """The failed increment, for the user."""
        return f"Newton did not converge at overlap={overlap:.6g} m (increment from {state.overlap:.6g} m)"

    def advance(self, state: PlateState, previous: PlateState | None, overlap: float) -> PlateState:
        """Converged state at ``overlap`` (m) from ``state``; cuts the increment in halves if needed
        (:func:`fem.core.increments.advance`)."""
        return advance(self, state, previous, overlap)
