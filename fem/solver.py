r"""Newton solver of the plate pressed by the sphere: plasticity and contact in one semi-smooth loop.

Each increment prescribes the overlap δ. Per Newton iteration: return-map every quadrature point
from the converged state of the previous increment, assemble f_int and (where points yield) the
consistent tangent into the fixed CSR pattern, update the contiguous active set of surface
nodes, and solve the reduced system (constraints u_r = 0 on the axis, u_z = 0 at the bottom,
u_z = z_s(r) at active nodes) with one sparse LU (SuperLU, minimum-degree ordering on AᵀA + A,
symmetric mode). Convergence: unchanged active set and ‖f_free‖₂ ≤ rtol · ‖reactions‖₂. An
increment that does not converge is cut in halves (up to ``max_cuts`` times) before
:class:`ConvergenceError` is raised naming the increment and the residual.

States (u, ε_p, ᾱ, active count) are plain frozen records so a loading run can keep them and an
unloading run can restart from any of them (path independence of the loading branch).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import scipy.sparse.linalg as spla
from skfem import MeshTri

from .forms import assemble, discretise, element_matrices, internal_force, strain
from .plasticity import J2Material, radial_return
from .sphere_contact import sphere_surface, update_active_count

__all__ = ["ConvergenceError", "PlateState", "PlateSolver"]


class ConvergenceError(RuntimeError):
    """Newton did not converge even after cutting the increment."""


@dataclass(frozen=True, eq=False)
class PlateState:
    """Converged state: ``overlap`` δ (m), ``u`` nodal displacements (m, interleaved r, z),
    ``plastic_strain`` (elements, qp, 4) Mandel, ``alpha`` (elements, qp) equivalent plastic
    strain, ``n_active`` active surface nodes, ``iterations`` Newton iterations spent."""

    overlap: float
    u: np.ndarray
    plastic_strain: np.ndarray
    alpha: np.ndarray
    n_active: int
    iterations: int = 0


@dataclass
class SolverStats:
    """Counters of the work done (for the benchmark): factorisations, Newton iterations, cuts."""

    factorisations: int = 0
    iterations: int = 0
    cuts: int = 0
    increments: int = 0
    assembly_time: float = 0.0
    factor_time: float = 0.0
    history: list = field(default_factory=list)


class _NotConverged(Exception):
    pass


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
        rtol: float = 1e-8,
        max_iterations: int = 25,
        max_cuts: int = 6,
    ) -> None:
        self.disc = discretise(mesh)
        self.material = material
        self.radius = radius
        self.rtol = rtol
        self.atol = 1e-12 * force_scale
        self.gap_tol = 1e-7 * gap_scale
        self.max_iterations = max_iterations
        self.max_cuts = max_cuts
        d = self.disc
        self.elastic_element_matrices = element_matrices(d, material.elastic_tangent)
        self.fixed_dofs = np.unique(np.concatenate([d.axis_dofs, d.bottom_dofs]))
        self.surface_uz = 2 * d.surface_nodes + 1
        self.mass_lu = spla.splu(d.surface_mass.tocsc())
        self.stats = SolverStats()
        nel, nq = d.weight.shape
        self._zero_plastic = np.zeros((nel, nq, 4))
        self._zero_alpha = np.zeros((nel, nq))

    def initial_state(self) -> PlateState:
        """The undeformed, unloaded plate."""
        return PlateState(0.0, np.zeros(self.disc.ndofs), self._zero_plastic, self._zero_alpha, 0)

    def stress_update(self, state: PlateState, reference: PlateState | None = None):
        """Stress update of ``state.u`` from ``reference`` (default: the state itself, i.e. its stresses)."""
        ref = state if reference is None else reference
        return radial_return(self.material, strain(self.disc, state.u), ref.plastic_strain, ref.alpha)

    def reactions(self, state: PlateState) -> np.ndarray:
        """Contact forces (N, positive = compressive) at the surface nodes sorted by r."""
        upd = self.stress_update(state)
        return -internal_force(self.disc, upd.stress)[self.surface_uz]

    def _tangent(self, upd) -> np.ndarray:
        d = self.disc
        ke = self.elastic_element_matrices
        if upd.yielding.any():
            ke = ke.copy()
            elements = np.flatnonzero(upd.yielding.any(axis=1))
            D = np.broadcast_to(self.material.elastic_tangent, (elements.size, d.weight.shape[1], 4, 4)).copy()
            D[upd.yielding[elements]] = upd.tangent
            ke[elements] = element_matrices(d, D, elements)
        return assemble(d, ke)

    def _newton(self, start: PlateState, overlap: float, u0: np.ndarray, n0: int) -> PlateState:
        import time

        d = self.disc
        zs = sphere_surface(d.surface_r, overlap, self.radius)
        u = u0.copy()
        n = n0
        seen: set[int] = set()
        frozen = False
        uz = self.surface_uz
        for it in range(self.max_iterations):
            upd = radial_return(self.material, strain(d, u), start.plastic_strain, start.alpha)
            f = internal_force(d, upd.stress)
            changed = False
            if it > 0 and not frozen:
                n_new = update_active_count(n, -f[uz], zs - u[uz], self.gap_tol)
                if n_new != n:
                    if n_new in seen:  # active set cycles between neighbours: keep the larger, stop switching
                        frozen = True
                        n_new = max(n, n_new)
                    seen.add(n)
                    changed = n_new != n
                    n = n_new
            constrained = np.concatenate([self.fixed_dofs, uz[:n]])
            du_c = np.concatenate([-u[self.fixed_dofs], zs[:n] - u[uz[:n]]])
            free_mask = np.ones(d.ndofs, dtype=bool)
            free_mask[constrained] = False
            residual = np.linalg.norm(f[free_mask])
            scale = max(np.linalg.norm(f[uz[:n]]), self.atol / self.rtol)
            if (
                it > 0
                and not changed
                and residual <= self.rtol * scale
                and np.max(np.abs(du_c), initial=0.0) <= (self.gap_tol)
            ):
                self.stats.iterations += it
                self.stats.history.append(it)
                return PlateState(overlap, u, upd.plastic_strain, upd.alpha, n, it)
            t0 = time.perf_counter()
            K = self._tangent(upd)
            free = np.flatnonzero(free_mask)
            K_ff = K[free][:, free]
            rhs = -f[free] - K[free][:, constrained] @ du_c
            t1 = time.perf_counter()
            lu = spla.splu(
                K_ff.tocsc(), permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True}
            )
            du_f = lu.solve(rhs)
            t2 = time.perf_counter()
            self.stats.assembly_time += t1 - t0
            self.stats.factor_time += t2 - t1
            self.stats.factorisations += 1
            if not np.all(np.isfinite(du_f)):
                break
            u[free] += du_f
            u[constrained] += du_c
        self._last_residual = residual
        raise _NotConverged(residual)

    def _guess(self, state: PlateState, previous: PlateState | None, overlap: float) -> tuple[np.ndarray, int]:
        d = self.disc
        step = overlap - state.overlap
        if state.n_active == 0 and not np.any(state.u):
            # first contact of a virgin plate: Hertz contact set
            return state.u, int(np.count_nonzero(d.surface_r < math.sqrt(self.radius * max(overlap, 0.0))))
        if previous is not None:
            last = state.overlap - previous.overlap
            if last != 0.0 and step * last > 0.0:
                factor = min(step / last, 4.0)
                u0 = state.u + factor * (state.u - previous.u)
                gap = sphere_surface(d.surface_r, overlap, self.radius) - u0[self.surface_uz]
                # nodes the extrapolation keeps on the sphere (gap ≈ 0) or pushes into it
                open_nodes = np.flatnonzero(gap > 1e-6 * abs(step) + self.gap_tol)
                return u0, int(open_nodes[0]) if open_nodes.size else gap.size
        return state.u, state.n_active

    def advance(self, state: PlateState, previous: PlateState | None, overlap: float, depth: int = 0) -> PlateState:
        """Converged state at ``overlap`` (m) from ``state``; cuts the increment in halves if needed."""
        u0, n0 = self._guess(state, previous, overlap)
        try:
            new = self._newton(state, overlap, u0, n0)
            self.stats.increments += 1
            return new
        except _NotConverged as exc:
            if depth >= self.max_cuts:
                raise ConvergenceError(
                    f"Newton did not converge at overlap={overlap:.6g} m (increment from {state.overlap:.6g} m, "
                    f"cut {depth} times): free residual {float(exc.args[0]):.3e} N"
                ) from None
        self.stats.cuts += 1
        middle = 0.5 * (state.overlap + overlap)
        half = self.advance(state, previous, middle, depth + 1)
        return self.advance(half, state, overlap, depth + 1)
