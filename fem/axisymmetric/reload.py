r"""Elastic reloading of a :class:`fem.Plate` from its current state, condensed onto the surface (SI units).

A plate that has shaken down answers a new indentation elastically: from its unloaded state (displacement u₀,
plastic strain ε_p, residual stress σ₀ in equilibrium with no load) the stress is σ₀ + D ε(Δu) with
K_e Δu = −Σ_j f_j e_{z,j}, K_e the elastic stiffness and f_j ≥ 0 the contact reactions at the surface nodes.
Condensed onto the candidate contact nodes with the compliance C = S K_e⁻¹ Sᵀ (S picks their u_z; one LU of
K_e and one back-substitution per candidate), the contact at overlap δ is the linear complementarity problem

.. math:: g = q(\delta) + C f \ge 0, \quad f \ge 0, \quad f^T g = 0, \qquad q_i(\delta) = z_s(r_i; \delta) -
          z_i - u_{0,z,i},

(g the gap to the sphere, z_s the sphere's surface, z_i the node's reference height), i.e. the bound-constrained
quadratic programme min ½ fᵀCf + qᵀf, f ≥ 0, solved as a non-negative least-squares problem on the Cholesky
factor of C. This is the FE solution on the same mesh, not an approximation of it, **as long as no point
yields**: each step's full field is recovered (one back-substitution) and return-mapped from (ε_p, ᾱ); the
largest increment of ᾱ this trial gives is reported per step (:attr:`ElasticReload.trial_plastic_strain_increment`;
measured against the FE's own elastic–plastic reload of a once-indented plate: 8.3e-5 vs 1.0e-4, both first
non-zero at the same step), and where it is not negligible the plastic problem must be solved
(:meth:`fem.Plate.load`).

The same step from any converged, loaded state (reactions f_s) has q = z_s − z − u_{s,z} − C f_s
(:meth:`SurfaceCompliance.step`): :class:`fem.Plate` uses it as an elastic predictor, keeping a step whose field
yields nowhere and solving the others by Newton (a second plastic cycle: 4 of 15 increments by Newton, forces equal
to 1e-9).

Cost: one LU and ~one back-substitution per candidate node and per step, instead of Newton iterations with a
refactorised tangent per step (default repeated-impact case: 4.5× faster over 300 impacts,
``benchmarks/bench_repeat.py --solvers 300``). Memory: the unit responses, free DOFs × candidate nodes (a few MB on
the repeated-impact mesh: 15k DOFs × ~50 nodes).
"""

from __future__ import annotations

from dataclasses import dataclass
from weakref import WeakKeyDictionary

import numpy as np
import scipy.sparse.linalg as spla
from scipy.optimize import nnls

from contact.checks import check_array
from fem.axisymmetric.result import IndentationResult
from fem.axisymmetric.solver import PlateSolver, PlateState
from fem.core.assembly import strain
from fem.core.plasticity import radial_return
from fem.core.sphere import contact_radius, pressure_from_reactions

__all__ = ["ElasticReload", "SurfaceCompliance", "candidate_nodes", "elastic_reload"]

#: Per solver: (free DOFs, LU of K_e on them, (the last node set, its unit responses) or None). A solver is
#: rebuilt whenever the mesh moves (:meth:`fem.Plate.move_surface`), so its entry goes with it.
_FACTORS: WeakKeyDictionary[PlateSolver, tuple] = WeakKeyDictionary()


@dataclass(frozen=True, eq=False)
class ElasticReload:
    """Elastic reloading of a plate: ``result`` (an :class:`fem.IndentationResult` over the path, overlaps from
    the original plane, m; N; Pa) and ``trial_plastic_strain_increment``, the largest increment of equivalent
    plastic strain a return mapping of each step's elastic field gives (array, one per step; 0 where the reloading
    is truly elastic, and for every step when the yield check was skipped)."""

    result: IndentationResult
    trial_plastic_strain_increment: np.ndarray


def candidate_nodes(solver, state: PlateState, top: float, widen: float = 1.3) -> np.ndarray:
    """Surface nodes (indices, sorted by r) that may touch along a path up to overlap ``top`` (m) from ``state``:
    out to ``widen`` × the larger of the radius the undeformed sphere reaches and the state's contact radius
    (the surface outside the contact sinks under load, so the set can only be smaller than the rigid overlap's, but
    a finite plate may lift a little: a step that penetrates outside them is refused)."""
    r = solver.disc.surface_r
    reached = np.flatnonzero(solver.obstacle(top) - state.u[solver.surface_uz] <= 0.0)
    reach = max(
        float(r[reached[-1]]) if reached.size else 0.0,
        float(r[np.flatnonzero(state.active)[-1]]) if state.active.any() else 0.0,
    )
    if reach == 0.0:
        return np.zeros(0, int)
    return np.flatnonzero(r <= widen * reach)


class SurfaceCompliance:
    r"""The elastic compliance of ``solver``'s mesh condensed onto the surface ``nodes``: C = S K_e⁻¹ Sᵀ (m/N) and
    the free-DOF response to a unit reaction at each node. The LU of K_e (and the last node set's responses) is
    kept for the solver, which is rebuilt whenever the mesh moves (:meth:`fem.Plate.move_surface`)."""

    def __init__(self, solver, nodes: np.ndarray) -> None:
        self.solver, self.nodes = solver, nodes
        cache = _FACTORS.get(solver)
        if cache is None:
            free = np.setdiff1d(np.arange(solver.disc.ndofs), solver.fixed_dofs)
            stiffness = solver.elastic_stiffness()[free][:, free].tocsc()
            lu = spla.splu(
                stiffness, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True}
            )
            cache = (free, lu, None)
        free, lu, cached = cache
        self.free = free
        position = np.full(solver.disc.ndofs, -1)
        position[free] = np.arange(free.size)
        rows = position[solver.surface_uz[nodes]]
        if cached is not None and np.isin(nodes, cached[0]).all():
            self.response = cached[1][:, np.searchsorted(cached[0], nodes)]
        else:
            unit = np.zeros((free.size, nodes.size))
            unit[rows, np.arange(nodes.size)] = -1.0  # a compressive reaction pushes the node down (−z)
            self.response = lu.solve(unit)  # free-DOF displacement per unit reaction
            cached = (nodes, self.response)
        _FACTORS[solver] = (free, lu, cached)
        compliance = -self.response[rows]  # C_ij = −u_z,i per unit f_j (positive definite)
        self.matrix = 0.5 * (compliance + compliance.T)
        self.cholesky = np.linalg.cholesky(self.matrix)

    def step(self, start: PlateState, start_reactions: np.ndarray, overlap: float, check_yield: bool = True):
        r"""Elastic step from the converged ``start`` (its contact reactions ``start_reactions``, N, one per surface
        node) to ``overlap`` (m): the LCP of the module docstring with q = z_s − z − u_{s,z} − C f_s. Returns
        (state, reactions N, gap m, trial Δᾱ, penetration outside the nodes: bool)."""
        solver = self.solver
        nodes = self.nodes
        rigid_gap = solver.obstacle(overlap) - start.u[solver.surface_uz]
        q = rigid_gap[nodes] - self.matrix @ start_reactions[nodes]
        reactions = np.zeros(solver.disc.surface_r.size)
        if np.any(q < 0.0):
            # min ½fᵀCf + qᵀf = ½‖Lᵀf + L⁻¹q‖² − const with C = LLᵀ
            f, _ = nnls(self.cholesky.T, -np.linalg.solve(self.cholesky, q), maxiter=50 * nodes.size)
            reactions[nodes] = f
        u = start.u.copy()
        u[self.free] += self.response @ (reactions - start_reactions)[nodes]
        gap = solver.obstacle(overlap) - u[solver.surface_uz]
        outside = np.ones(gap.size, bool)
        outside[nodes] = False
        increment = 0.0
        # the field changes unless the ball stays off the surface: a step that releases the last contact force
        # (separation after unloading) can yield in reverse, so it is checked too
        if check_yield and (reactions.any() or start_reactions[nodes].any()):
            upd = radial_return(solver.material, strain(solver.disc, u), start.plastic_strain, start.alpha)
            increment = float(np.max(upd.alpha - start.alpha))
        state = PlateState(float(overlap), u, start.plastic_strain, start.alpha, reactions > 0.0)
        return state, reactions, gap, increment, bool(np.any(gap[outside] < -solver.gap_tol))


def elastic_reload(plate, overlaps, check_yield: bool = True) -> ElasticReload:
    r"""Elastic response of ``plate`` (:class:`fem.Plate`, its state unchanged) along ``overlaps`` (m, sphere
    tip below the original plane, any order) — see the module docstring. ``check_yield``: return-map each step's
    field to report :attr:`ElasticReload.trial_plastic_strain_increment` (an unloading along a path already
    checked on the way up may skip it). Raises ValueError when the surface is not reached at all by the path."""
    path = check_array("overlaps", overlaps, low=0.0, units="m", what="overlap")
    solver = plate.solver
    disc = solver.disc
    state: PlateState = plate.state
    start_reactions = solver.reactions(state) * state.active
    top = float(path.max())
    for widen in (1.3, 2.0, 3.0):
        nodes = candidate_nodes(solver, state, top, widen)
        if nodes.size == 0:
            raise ValueError(
                f"overlaps reach at most {top:.6g} m: the sphere does not touch the surface "
                f"(first contact at {plate.first_contact_overlap():.6g} m)"
            )
        compliance = SurfaceCompliance(solver, nodes)
        steps = [compliance.step(state, start_reactions, overlap, check_yield) for overlap in path]
        if not any(s[4] for s in steps):
            break
    else:
        raise ValueError("elastic_reload: surface nodes outside 3 × the reached radius penetrate the sphere")
    force, radius, pressure = [], [], []
    for new, reactions, gap, _, _ in steps:
        force.append(float(reactions.sum()))
        radius.append(contact_radius(disc.surface_r, new.active, gap) if new.active.any() else 0.0)
        pressure.append(
            pressure_from_reactions(disc.surface_hats, disc.surface_hat_mass, reactions, disc.surface_r, radius[-1])
        )
    increments = np.array([s[3] for s in steps])
    force, radius = np.array(force), np.array(radius)
    area = np.pi * radius**2
    result = IndentationResult(
        overlap=path.copy(),
        force=force,
        contact_radius=radius,
        max_pressure=np.array([float(p.max(initial=0.0)) for p in pressure]),
        mean_pressure=np.divide(force, area, out=np.zeros_like(force), where=area > 0.0),
        surface_r=disc.surface_r.copy(),
        pressure=np.array(pressure),
        radial_displacement=np.array([new.u[solver.surface_ur] for new, *_ in steps]),
        first_yield=None,
        residual_depth=-state.u[solver.surface_uz].copy(),
        max_equivalent_plastic_strain=float(state.alpha.max(initial=0.0)) + increments,
        regime=["elastic"] * path.size,
        newton_iterations=np.zeros(path.size, int),
        radius=plate.radius,
        effective_modulus=plate.effective_modulus,
    )
    return ElasticReload(result, increments)
