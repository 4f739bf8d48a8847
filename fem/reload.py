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

Cost: one LU and ~one back-substitution per candidate node and per step, instead of Newton iterations with a
refactorised tangent per step (measured on the repeated-impact mesh: see ``benchmarks/bench_repeat.py``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import scipy.sparse.linalg as spla

from contact.validation import check_array

from .plasticity import radial_return
from .result import IndentationResult
from .solver import PlateState
from .sphere_contact import contact_radius

__all__ = ["ElasticReload", "elastic_reload"]


@dataclass(frozen=True, eq=False)
class ElasticReload:
    """Elastic reloading of a plate: ``result`` (an :class:`fem.IndentationResult` over the path, overlaps from
    the original plane, m; N; Pa) and ``trial_plastic_strain_increment``, the largest increment of equivalent
    plastic strain a return mapping of each step's elastic field gives (array, one per step; 0 where the reloading
    is truly elastic, and for every step when the yield check was skipped)."""

    result: IndentationResult
    trial_plastic_strain_increment: np.ndarray


def _candidates(plate, obstacle_top: np.ndarray, u_z: np.ndarray, widen: float) -> np.ndarray:
    """Surface nodes that may touch at the path's largest overlap: those the undeformed sphere reaches, and
    out to ``widen`` × that radius (the surface outside the contact sinks under load, so the set can only be
    smaller than the rigid overlap's, but a finite plate may lift a little: checked after the solve)."""
    r = plate.solver.disc.surface_r
    reached = np.flatnonzero(obstacle_top - u_z <= 0.0)
    if reached.size == 0:
        return np.zeros(0, int)
    reach = widen * float(r[reached[-1]])
    return np.flatnonzero(r <= reach)


def _factorisation(solver):
    """(free DOFs, LU of the elastic stiffness on them, cached unit responses) of this solver's mesh: kept on the
    solver, which is rebuilt whenever the mesh moves (:meth:`fem.Plate.move_surface`)."""
    cache = getattr(solver, "_reload_cache", None)
    if cache is None:
        free = np.setdiff1d(np.arange(solver.disc.ndofs), solver.fixed_dofs)
        stiffness = solver._elastic_stiffness()[free][:, free].tocsc()
        lu = spla.splu(stiffness, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True})
        cache = solver._reload_cache = (free, lu, None)
    return cache


def elastic_reload(plate, overlaps, check_yield: bool = True) -> ElasticReload:
    r"""Elastic response of ``plate`` (:class:`fem.Plate`, its state unchanged) along ``overlaps`` (m, sphere
    tip below the original plane, any order) — see the module docstring. ``check_yield``: return-map each step's
    field to report :attr:`ElasticReload.trial_plastic_strain_increment` (an unloading along a path already
    checked on the way up may skip it). Raises ValueError when the surface is not reached at all by the path."""
    path = check_array("overlaps", overlaps, low=0.0, units="m", what="overlap")
    solver = plate.solver
    disc = solver.disc
    state: PlateState = plate.state
    u0 = state.u
    u0_z = u0[solver.surface_uz]
    free, lu, cached = _factorisation(solver)
    position = np.full(disc.ndofs, -1)
    position[free] = np.arange(free.size)
    top = float(path.max())
    for widen in (1.3, 2.0, 3.0):
        nodes = _candidates(plate, solver.obstacle(top), u0_z, widen)
        if nodes.size == 0:
            raise ValueError(f"overlaps reach at most {top:.6g} m: the sphere does not touch the surface "
                             f"(first contact at {plate.first_contact_overlap():.6g} m)")  # fmt: skip
        rows = position[solver.surface_uz[nodes]]
        if cached is not None and np.isin(nodes, cached[0]).all():
            response = cached[1][:, np.searchsorted(cached[0], nodes)]
        else:
            unit = np.zeros((free.size, nodes.size))
            unit[rows, np.arange(nodes.size)] = -1.0  # a compressive reaction pushes the node down (−z)
            response = lu.solve(unit)  # free-DOF displacement per unit reaction
            cached = (nodes, response)
            solver._reload_cache = (free, lu, cached)
        compliance = -response[rows]  # C_ij = −u_z,i per unit f_j (positive definite)
        compliance = 0.5 * (compliance + compliance.T)
        cholesky = np.linalg.cholesky(compliance)
        steps = [_step(solver, plate, overlap, nodes, compliance, cholesky, response, free, check_yield)
                 for overlap in path]  # fmt: skip
        outside = np.ones(disc.surface_r.size, bool)
        outside[nodes] = False
        if not any(np.any(s["gap"][outside] < -solver.gap_tol) for s in steps):
            break
    else:
        raise ValueError("elastic_reload: surface nodes outside 3 × the reached radius penetrate the sphere")
    result = IndentationResult(
        overlap=path.copy(),
        force=np.array([s["force"] for s in steps]),
        contact_radius=np.array([s["contact_radius"] for s in steps]),
        max_pressure=np.array([float(s["pressure"].max(initial=0.0)) for s in steps]),
        mean_pressure=np.array(
            [s["force"] / (math.pi * s["contact_radius"] ** 2) if s["contact_radius"] > 0 else 0.0 for s in steps]
        ),  # fmt: skip
        surface_r=disc.surface_r.copy(),
        pressure=np.array([s["pressure"] for s in steps]),
        first_yield=None,
        residual_depth=-u0_z.copy(),
        max_equivalent_plastic_strain=np.array([s["alpha"] for s in steps]),
        regime=["elastic"] * path.size,
        newton_iterations=np.zeros(path.size, int),
        radius=plate.radius,
        effective_modulus=plate.effective_modulus,
    )
    return ElasticReload(result, np.array([s["increment"] for s in steps]))


def _step(solver, plate, overlap, nodes, compliance, cholesky, response, free, check_yield) -> dict:
    from scipy.optimize import nnls

    disc = solver.disc
    state = plate.state
    u0_z = state.u[solver.surface_uz]
    rigid_gap = solver.obstacle(overlap) - u0_z
    q = rigid_gap[nodes]
    reactions = np.zeros(disc.surface_r.size)
    if np.any(q < 0.0):
        # min ½fᵀCf + qᵀf = ½‖Lᵀf + L⁻¹q‖² − const with C = LLᵀ
        f, _ = nnls(cholesky.T, -np.linalg.solve(cholesky, q), maxiter=50 * nodes.size)
        reactions[nodes] = f
    du_free = response @ reactions[nodes]
    u = state.u.copy()
    u[free] += du_free
    gap = solver.obstacle(overlap) - u[solver.surface_uz]
    active = reactions > 0.0
    increment, alpha = 0.0, float(state.alpha.max(initial=0.0))
    if check_yield and active.any():
        from .forms import strain

        upd = radial_return(solver.material, strain(disc, u), state.plastic_strain, state.alpha)
        increment = float(np.max(upd.alpha - state.alpha))
        alpha = float(upd.alpha.max())
    return {
        "force": float(reactions.sum()),
        "contact_radius": contact_radius(disc.surface_r, active, gap) if active.any() else 0.0,
        "pressure": solver.mass_lu.solve(reactions),
        "gap": gap,
        "increment": increment,
        "alpha": alpha,
    }
