r"""Public entry points: :func:`indent`, :func:`indent_impact`, :func:`plate_mesh` (SI units).

An elastic ball is represented by a rigid sphere and a plate of modulus E_p' = E*(1 − ν_p²), so
that the effective modulus E* (errata Eq. 5) is unchanged: exact for the Hertz (elastic) solution,
an approximation once the plate yields (the ball's own deformation is then not resolved).
"""

from __future__ import annotations

import math
import os

import meshio
import numpy as np
from skfem import MeshTri

from contact.checks import check_array, check_number
from contact.materials import Material
from contact.theory import first_yield as hertz_first_yield
from fem.axisymmetric.mesh import DEFAULT_PARAMETERS, default_mesh, generate_mesh, load_mesh, scale_mesh
from fem.axisymmetric.reload import SurfaceCompliance, candidate_nodes
from fem.axisymmetric.result import FirstYieldPoint, IndentationResult
from fem.axisymmetric.solver import PlateSolver, PlateState
from fem.core.material import check_small_strain, estimate_contact_radius, plate_model
from fem.core.plasticity import J2Material, von_mises
from fem.core.sphere import contact_radius, pressure_from_reactions

__all__ = ["IndentationRun", "indent", "indent_impact", "plate_mesh"]

#: First yield is refined until the elastic state it is scaled from carries a force within this fraction of the
#: first-yield force (relative): the mesh's own first yield to 1%, well inside its 3% accuracy against the exact
#: closed form (tests/test_fem_yield.py).
FIRST_YIELD_RTOL = 0.01
#: Most elastic re-solves spent refining first yield (two suffice on the default meshes: the self-similar scaling
#: is exact in the continuum, so each re-solve only corrects the mesh's error at a different contact radius).
FIRST_YIELD_SOLVES = 6


def plate_mesh(
    radius: float,
    plate: Material,
    max_overlap: float,
    ball: Material | None = None,
    contact_elements: int | None = None,
    yield_elements: int | None = None,
    growth: float = 1.0,
) -> MeshTri:
    """Mesh (m) for a path reaching ``max_overlap`` (m): the default mesh scaled to the expected
    largest contact radius, or (if element counts are given, or ``growth`` > 1: a contact that will widen to
    ``growth`` × that radius, see :func:`fem.axisymmetric.mesh.generate_mesh`) a mesh generated for this case (its yield
    box sized at the case's first-yield contact radius)."""
    radius = check_number("radius", radius, low=1e-6, high=10.0, units="m", what="ball radius")
    max_overlap = check_number("max_overlap", max_overlap, low=0.0, low_open=True, high=radius, units="m")
    _, e_star = plate_model(plate, ball, 0.0)
    a_max = estimate_contact_radius(radius, e_star, plate, max_overlap)
    if contact_elements is None and yield_elements is None and growth == 1.0:
        return default_mesh(a_max)
    params = dict(DEFAULT_PARAMETERS, growth=growth)
    if contact_elements is not None:
        params["contact_elements"] = contact_elements
    if yield_elements is not None:
        params["yield_elements"] = yield_elements
    if plate.yield_strength is not None:
        a_y = hertz_first_yield(radius, e_star, plate.yield_strength, plate.nu).contact_radius
        params["yield_radius_ratio"] = min(1.0, a_y / a_max)
    return scale_mesh(generate_mesh(**params), a_max)


class IndentationRun:
    """A solver plus the states of a loading run: ``solver`` (:class:`fem.axisymmetric.solver.PlateSolver`), ``final``
    (the state after the last step), ``kept`` (every converged loading state, with ``keep_states``; see
    :meth:`IndentationResult.unload_from`), ``first_yield`` and ``reach`` (m, the largest contact radius of the
    virgin loading). Each :class:`IndentationResult` it computes holds it as ``run``."""

    def __init__(self, solver: PlateSolver, e_star: float, radius: float):
        self.solver = solver
        self.e_star = e_star
        self.radius = radius
        self.kept: list[PlateState] = []
        self.final: PlateState | None = None
        # a run restarted from a given state (fem.Plate) has no virgin loading of its own to take these from
        self.reach = 0.0
        self.first_yield = None

    # -- one step's numbers
    def measure(self, state: PlateState, reach: float = 0.0, solver: PlateSolver | None = None) -> dict:
        """Numbers of one step; ``reach`` (m) = largest contact radius so far (the regime refers to it); ``solver``
        (default the run's) evaluates the stresses."""
        s = self.solver if solver is None else solver
        d = s.disc
        reactions = s.reactions(state)
        reactions[~state.active] = 0.0  # off the contact set only the (converged) residual remains
        gap = s.obstacle(state.overlap) - state.u[s.surface_uz]
        a = contact_radius(d.surface_r, state.active, gap)
        pressure = pressure_from_reactions(d.surface_hats, d.surface_hat_mass, reactions, d.surface_r, a)
        force = float(reactions.sum())
        plastic = state.alpha > 0.0
        if not plastic.any():
            regime = "elastic"
        else:
            under = d.surface_layer & (d.qp_r < max(a, reach))
            if not (plastic & under).any():
                regime = "contained"
            elif (plastic | ~under).all():
                regime = "fully-plastic"
            else:
                regime = "surface-plastic"
        return {
            "reactions": reactions,
            "force": force,
            "contact_radius": a,
            "pressure": pressure,
            "radial_displacement": state.u[s.surface_ur].copy(),
            "max_pressure": float(pressure.max(initial=0.0)),
            "mean_pressure": force / (math.pi * a * a) if a > 0 else 0.0,
            "alpha": float(state.alpha.max()),
            "regime": regime,
        }

    def run(
        self,
        overlaps: np.ndarray,
        start: PlateState | None = None,
        keep: bool = False,
        times=None,
        predictor: bool = False,
    ):
        """States along ``overlaps`` (m) from ``start`` (None: the virgin plate). ``predictor`` (only with a
        ``start``): try each step as an elastic step (:class:`fem.axisymmetric.reload.SurfaceCompliance`) and keep it
        when its return mapping yields nowhere (then it is the FE solution, no Newton needed); else a Newton
        increment."""
        s = self.solver
        state = s.initial_state() if start is None else start
        previous = None
        rows, states = [], []
        yield_point = None
        last_elastic = None
        reach = 0.0 if start is None else self.reach
        compliance = reactions = None
        if predictor and start is not None and len(overlaps):
            nodes = candidate_nodes(s, state, float(np.max(overlaps)))
            if nodes.size:
                compliance = SurfaceCompliance(s, nodes)
                reactions = s.reactions(state) * state.active
        for overlap in overlaps:
            new = None
            if compliance is not None:
                trial, _, _, increment, outside = compliance.step(state, reactions, float(overlap))
                if increment == 0.0 and not outside:
                    new = trial
            if new is None:
                new = s.advance(state, previous, float(overlap))
            previous, state = state, new
            row = self.measure(state, reach)
            reactions = row.pop("reactions")
            reach = max(reach, row["contact_radius"])
            row["iterations"] = state.iterations
            row["overlap"] = state.overlap
            rows.append(row)
            if keep:
                states.append(state)
            if s.material.yield_strength is not None and yield_point is None and start is None:
                if row["alpha"] == 0.0:
                    if row["force"] > 0.0:
                        last_elastic = state
                else:
                    yield_point = self._first_yield(last_elastic, state.overlap)
        self.final = state
        if start is None:
            self.reach = reach
            self.first_yield = yield_point
        else:
            yield_point = self.first_yield
        if keep:
            self.kept = [st for st in states]
        return self._result(rows, state, yield_point, times)

    def _elastic_solver(self) -> PlateSolver:
        """The run's solver with the plate made purely elastic (same mesh and tolerances): up to first yield the
        elastic–plastic solution is the elastic one, and past it the elastic stress says by how much it yields."""
        s = self.solver
        elastic = PlateSolver.__new__(PlateSolver)
        elastic.__dict__.update(s.__dict__)
        elastic.material = J2Material(s.material.E, s.material.nu, None)
        return elastic

    def _first_yield(self, elastic_state: PlateState | None, yielded_overlap: float) -> FirstYieldPoint:
        r"""First yield in the step from ``elastic_state`` (the last elastic state of the run, None if the first
        step yielded) to ``yielded_overlap`` (m, the first step that yielded), found on the run's mesh.

        The elastic Hertz field is self-similar: stresses scale as p₀ ∝ √δ and lengths as a ∝ √δ, so an elastic
        state at δ with largest von Mises stress σ yields at δ_y = δ (Y/σ)², F_y = F (Y/σ)³. That scaling is exact
        in the continuum but not on a fixed mesh, which resolves a small contact worse than a large one: scaled
        from a state far from δ_y (a coarse first step, or a first step that already yielded) F_y was off by up
        to 2.6×. So the scaled δ_y is re-solved elastically on the same mesh and scaled again (a fixed point,
        kept inside the bracket [last elastic, first yielded] and bisected if it leaves it) until the state it
        is scaled from is within :data:`FIRST_YIELD_RTOL` of first yield in force: two or three elastic solves.
        """
        s = self.solver
        elastic = self._elastic_solver()
        strength = s.material.yield_strength
        low = 0.0 if elastic_state is None else elastic_state.overlap
        high = yielded_overlap
        state = elastic_state
        if state is None:
            state = elastic.advance(elastic.initial_state(), None, yielded_overlap)
        for solve in range(FIRST_YIELD_SOLVES + 1):
            vm = von_mises(elastic.stress_update(state).stress)
            k = np.unravel_index(int(np.argmax(vm)), vm.shape)
            ratio = strength / float(vm[k])
            if ratio >= 1.0:
                low = max(low, state.overlap)
            else:
                high = min(high, state.overlap)
            if abs(ratio**3 - 1.0) <= FIRST_YIELD_RTOL or solve == FIRST_YIELD_SOLVES:
                break
            target = state.overlap * ratio**2
            if not low < target < high:  # the scaling left the bracket: bisect it (geometrically, δ spans decades)
                target = math.sqrt(low * high) if low > 0.0 else 0.5 * high
            state = elastic.advance(elastic.initial_state(), None, target)
        row = self.measure(state, solver=elastic)
        scale = ratio  # lengths scale like √δ = ratio
        return FirstYieldPoint(
            force=row["force"] * ratio**3,
            overlap=state.overlap * ratio**2,
            depth=float(-s.disc.qp_z[k]) * scale,
            radius=float(s.disc.qp_r[k]) * scale,
            contact_radius=row["contact_radius"] * scale,
        )

    def _result(self, rows, state, yield_point, times) -> IndentationResult:
        s = self.solver
        return IndentationResult(
            overlap=np.array([r["overlap"] for r in rows]),
            force=np.array([r["force"] for r in rows]),
            contact_radius=np.array([r["contact_radius"] for r in rows]),
            max_pressure=np.array([r["max_pressure"] for r in rows]),
            mean_pressure=np.array([r["mean_pressure"] for r in rows]),
            surface_r=s.disc.surface_r.copy(),
            pressure=np.array([r["pressure"] for r in rows]),
            radial_displacement=np.array([r["radial_displacement"] for r in rows]),
            first_yield=yield_point,
            residual_depth=-state.u[s.surface_uz].copy(),
            max_equivalent_plastic_strain=np.array([r["alpha"] for r in rows]),
            regime=[r["regime"] for r in rows],
            newton_iterations=np.array([r["iterations"] for r in rows]),
            radius=self.radius,
            effective_modulus=self.e_star,
            time=None if times is None else np.asarray(times, dtype=float),
            run=self,
        )

    def unload_from(self, max_overlap: float, steps: int) -> IndentationResult:
        max_overlap = check_number("max_overlap", max_overlap, low=0.0, low_open=True, units="m")
        steps = int(check_number("steps", steps, low=1, high=10000))
        if not self.kept:
            raise ValueError("unload_from needs kept loading states: call fem.indent(..., keep_states=True)")
        loading = [st for st in self.kept if st.overlap <= max_overlap * (1 + 1e-12)]
        top = max(st.overlap for st in self.kept)
        if not loading or max_overlap > top * (1 + 1e-9):
            raise ValueError(
                f"max_overlap={max_overlap:.6g} is out of range: must be in (0, {top:.6g}] m (the kept loading run)"
            )
        start = max(loading, key=lambda st: st.overlap)
        path = np.r_[max_overlap, np.linspace(max_overlap, 0.0, steps + 1)[1:]]
        if start.overlap == max_overlap:
            path = path[1:]
        kept = self.kept
        result = self.run(path, start=start, keep=False, predictor=True)
        self.kept = kept
        return result

    def to_meshio(self, result: IndentationResult) -> meshio.Mesh:
        """The final state of the run as a meshio mesh, with the last step's pressure (:func:`state_mesh`)."""
        d = self.solver.disc
        nv = d.mesh.p.shape[1]
        pressure = np.zeros(nv)
        surf = d.surface_nodes
        on_vertices = surf < nv
        if result.pressure.size:
            pressure[surf[on_vertices]] = result.pressure[-1][on_vertices]
        return state_mesh(self.solver, self.final, {"pressure": pressure})


def state_mesh(solver: PlateSolver, state: PlateState, point_data: dict[str, np.ndarray]) -> meshio.Mesh:
    """``state`` on ``solver``'s mesh as a meshio mesh: points (r, z, 0) m deformed by u, point data ``u`` (m) plus
    ``point_data`` (one value per vertex), cell data ``von_mises`` (Pa) and ``equivalent_plastic_strain`` (element
    averages)."""
    mesh = solver.disc.mesh
    nv = mesh.p.shape[1]
    u = state.u.reshape(-1, 2)[:nv]
    vm = von_mises(solver.stress_update(state).stress).mean(axis=1)
    return meshio.Mesh(
        np.column_stack([mesh.p.T + u, np.zeros(nv)]),
        [("triangle", mesh.t.T)],
        point_data={"u": np.column_stack([u, np.zeros(nv)]), **point_data},
        cell_data={"von_mises": [vm], "equivalent_plastic_strain": [state.alpha.mean(axis=1)]},
    )


def _check_path(overlaps) -> np.ndarray:
    path = check_array("overlaps", overlaps, low=0.0, units="m", what="overlap")
    if path.max() <= 0.0:
        raise ValueError("overlaps are all 0: the path must press the ball into the plate (m)")
    return path


def indent(
    radius: float,
    plate: Material,
    overlaps,
    ball: Material | None = None,
    mesh: MeshTri | str | os.PathLike | None = None,
    hardening: float = 0.0,
    keep_states: bool = False,
    rtol: float = 1e-6,
    _times=None,
) -> IndentationResult:
    r"""Press a sphere of ``radius`` (m) into ``plate`` along the overlap path ``overlaps`` (m).

    Displacement control: each entry is one increment (loading while δ grows, unloading when it
    decreases). ``ball`` None = rigid; an elastic ball via its effective modulus E* (errata Eq. 5).
    ``mesh``: None (the default mesh scaled to the path), a :class:`skfem.MeshTri` or a mesh file
    (m, named boundaries ``axis``, ``surface``, ``bottom``). ``hardening`` H (Pa): linear isotropic
    hardening of the plate (0 = perfectly plastic). ``keep_states`` keeps every converged state so
    :meth:`IndentationResult.unload_from` can restart from them. ``rtol``: Newton stops when the
    free residual is below ``rtol`` × the contact reactions (2-norms, N).

    Examples
    --------
    A rigid 10 mm ball pressed to 3 times the closed-form first-yield overlap into a steel plate (Y = 1 GPa), on a
    coarse mesh (16 elements across the largest contact radius): elastic at first, with Hertz's force
    F = 4/3 E* √R δ^(3/2) (Johnson 1985, Eq. 4.23), then yield starts within 2 % of the force of
    :func:`contact.theory.first_yield` (errata Eq. 18) and the plastic zone stays below the surface:

    >>> import numpy as np
    >>> from contact import Material, effective_modulus
    >>> from contact.theory import first_yield, hertz_force
    >>> plate = Material(E=210e9, nu=0.3, density=7850.0, yield_strength=1e9)
    >>> e_star = effective_modulus(Material.rigid(), plate)
    >>> fy = first_yield(10e-3, e_star, 1e9, 0.3)
    >>> path = fy.overlap * np.linspace(0.25, 3.0, 12)  # m
    >>> mesh = plate_mesh(10e-3, plate, float(path.max()), contact_elements=16, yield_elements=0)
    >>> result = indent(10e-3, plate, path, mesh=mesh)
    >>> bool(abs(result.force[0] / hertz_force(path[0], 10e-3, e_star) - 1) < 0.01)
    True
    >>> bool(abs(result.first_yield.force / fy.force - 1) < 0.02)
    True
    >>> result.regime[0], result.regime[-1]
    ('elastic', 'contained')
    """
    radius = check_number("radius", radius, low=1e-6, high=10.0, units="m", what="ball radius")
    path = _check_path(overlaps)
    hardening = check_number("hardening", hardening, low=0.0, high=1e12, units="Pa", what="hardening modulus")
    if ball is not None and not isinstance(ball, Material):
        raise ValueError(f"ball={ball!r} is not a contact.Material or None (rigid)")
    material, e_star = plate_model(plate, ball, hardening)
    check_small_strain(radius, e_star, plate, float(path.max()))
    if mesh is None:
        mesh_obj = plate_mesh(radius, plate, float(path.max()), ball)
    elif isinstance(mesh, MeshTri):
        for name in ("axis", "surface", "bottom"):
            if mesh.boundaries is None or name not in mesh.boundaries:
                raise ValueError(f"mesh has no boundary named {name!r}: name 'axis', 'surface' and 'bottom' (m)")
        mesh_obj = mesh
    elif isinstance(mesh, (str, os.PathLike)):
        mesh_obj = load_mesh(mesh)
    else:
        raise ValueError(f"mesh={mesh!r} is not None, a skfem.MeshTri or a mesh file path")
    force_scale = 4.0 / 3.0 * e_star * math.sqrt(radius) * float(path.max()) ** 1.5
    solver = PlateSolver(mesh_obj, material, radius, force_scale, float(path.max()), rtol=rtol)
    run = IndentationRun(solver, e_star, radius)
    return run.run(path, keep=keep_states, times=_times)


def indent_impact(impact_result, plate: Material, steps: int = 60, **kwargs) -> IndentationResult:
    """Indent along the overlap history of an impact (``contact`` ImpactResult: ``.radius`` (m),
    ``.ball``, ``.history.t`` (s), ``.history.overlap`` (m)).

    ``steps`` increments: two thirds on loading, one third on unloading, spaced as
    δ_max·sin(πk/2n) so they are denser near the maximum overlap. ``time`` (s) on the result
    gives the impact time of each step (interpolated on the history).
    """
    steps = int(check_number("steps", steps, low=4, high=100000))
    history = impact_result.history
    t = np.asarray(history.t, dtype=float)
    d = np.asarray(history.overlap, dtype=float)
    if t.shape != d.shape or t.size < 3:
        raise ValueError("impact_result.history: t and overlap must be arrays of the same length >= 3 (s, m)")
    peak = int(np.argmax(d))
    d_max = float(d[peak])
    if d_max <= 0.0:
        raise ValueError("impact_result.history.overlap never exceeds 0 m: no contact to indent")
    n_load = max(2, (2 * steps) // 3)
    n_unload = max(1, steps - n_load)
    load_d = d_max * np.sin(0.5 * np.pi * np.arange(1, n_load + 1) / n_load)
    unload_d = d_max * np.sin(0.5 * np.pi * (1.0 - np.arange(1, n_unload + 1) / n_unload))
    rise = np.maximum.accumulate(np.maximum(d[: peak + 1], 0.0))
    fall = np.maximum.accumulate(np.maximum(d[peak:][::-1], 0.0))
    load_t = np.interp(load_d, rise, t[: peak + 1])
    unload_t = np.interp(unload_d, fall, t[peak:][::-1])
    overlaps = np.r_[load_d, unload_d]
    times = np.r_[load_t, unload_t]
    ball = getattr(impact_result, "ball", None)
    if ball is not None and getattr(ball, "is_rigid", False):
        ball = None
    return indent(impact_result.radius, plate, overlaps, ball=ball, _times=times, **kwargs)
