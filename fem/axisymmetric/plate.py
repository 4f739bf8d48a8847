r"""A stateful FE plate for sequences of indentations (repeated impacts at one site; SI units).

:class:`Plate` holds a :class:`~fem.axisymmetric.solver.PlateSolver` and the plate's current
:class:`~fem.axisymmetric.solver.PlateState` (displacement u, plastic strain ε_p, equivalent plastic strain ᾱ, contact
set). Each indentation starts from the state the previous one left: the residual stress and plastic strain are kept, and
the contact gap is measured to the current surface (the sphere meets the dent, and the worn surface)::

    plate = fem.Plate(radius, material, max_overlap)
    d0 = plate.first_contact_overlap()          # δ at which the sphere first touches the current surface
    res = plate.load(d0 + path)                 # loading from the current state, kept states
    back = plate.unload(res, d_max, steps=8)    # unload from d_max until the ball has left; commits the state
    plate.move_surface(wear_depth)              # remove material: surface nodes down by the wear depth (m)

Overlaps are measured from the ORIGINAL plane z = 0 (δ = depth of the sphere's tip below it), so a later
indentation has F = 0 up to :meth:`Plate.first_contact_overlap` (≈ the depth of the dent plus the wear at the
centre).

Wear (:meth:`Plate.move_surface`) moves the mesh's vertices: the surface vertices down by the cumulative wear
depth W(r) and the vertices below by W(r)(1 − d/H), d their depth, so the element rows near the surface keep
their shape (H: ``taper_depth``, at least 4 × the smallest surface facet). The topology is unchanged and u, ε_p
and ᾱ stay attached to the same nodes and quadrature points: a Lagrangian approximation that does not remove the
stresses of the worn layer, exact in the limit W ≪ H (repeated-impact wear is nm per impact against µm elements).
"""

from __future__ import annotations

import math
import os
from dataclasses import replace

import meshio
import numpy as np
from skfem import MeshTri

from contact.checks import check_array, check_number
from contact.materials import Material
from contact.theory import first_yield as hertz_first_yield
from fem.axisymmetric.indent import IndentationRun, plate_mesh, state_mesh
from fem.axisymmetric.result import IndentationResult, join
from fem.axisymmetric.solver import PlateSolver, PlateState
from fem.core.material import check_small_strain, plate_model
from fem.core.plasticity import plastic_work

__all__ = ["Plate", "surface_profile"]


class Plate:
    """An axisymmetric elastic–plastic plate that keeps its state between indentations by a sphere.

    ``radius`` R (m) of the (rigid, or elastic via E*) ball; ``plate`` a :class:`contact.Material`;
    ``max_overlap`` (m): the largest overlap expected (sizes the default mesh and the solver's tolerances);
    ``ball`` None (rigid) or a Material; ``mesh`` None (:func:`fem.plate_mesh`) or a :class:`skfem.MeshTri` with
    boundaries ``axis``, ``surface``, ``bottom``; ``hardening`` H (Pa); ``rtol`` Newton tolerance (as
    :func:`fem.indent`); ``taper_depth`` (m) over which the wear displacement of the vertices fades (default and
    smallest: 4 × the smallest surface facet); ``elastic_predictor``: after the first indentation, each step is
    first tried as an elastic step condensed onto the surface (:mod:`fem.axisymmetric.reload`) and kept when it yields
    nowhere (it is then the FE solution without Newton iterations); else the Newton increment.
    """

    def __init__(
        self,
        radius: float,
        plate: Material,
        max_overlap: float,
        ball: Material | None = None,
        mesh: MeshTri | None = None,
        hardening: float = 0.0,
        rtol: float = 1e-6,
        taper_depth: float | None = None,
        elastic_predictor: bool = True,
    ) -> None:
        self.radius = check_number("radius", radius, low=1e-6, high=10.0, units="m", what="ball radius")
        max_overlap = check_number("max_overlap", max_overlap, low=0.0, low_open=True, high=radius, units="m")
        hardening = check_number("hardening", hardening, low=0.0, high=1e12, units="Pa", what="hardening modulus")
        self.material, self.effective_modulus = plate_model(plate, ball, hardening)
        check_small_strain(radius, self.effective_modulus, plate, max_overlap)
        if mesh is None:
            mesh = plate_mesh(radius, plate, max_overlap, ball)
        elif not isinstance(mesh, MeshTri):
            raise ValueError(f"mesh={mesh!r} is not None or a skfem.MeshTri")
        self._force_scale = 4.0 / 3.0 * self.effective_modulus * math.sqrt(radius) * max_overlap**1.5
        self._gap_scale = max_overlap
        self._rtol = rtol
        self.elastic_predictor = bool(elastic_predictor)
        self._reference_points = np.array(mesh.p, float)
        self.solver = PlateSolver(mesh, self.material, self.radius, self._force_scale, self._gap_scale, rtol=rtol)
        self.state: PlateState = self.solver.initial_state()
        self._virgin = True
        self._before = (self.state, 0.0)
        d = self.solver.disc
        self._reference_surface_z = d.surface_z.copy()
        #: cumulative wear depth (m, ≥ 0) at each surface node (sorted by r, :attr:`surface_r`)
        self.wear_depth = np.zeros(d.surface_r.size)
        facets = mesh.facets[:, mesh.boundaries["surface"]]
        self._surface_vertices = np.unique(facets)
        facet_length = np.abs(mesh.p[0, facets[1]] - mesh.p[0, facets[0]])
        #: depth (m) over which the wear displacement of the vertices fades out (see the module docstring)
        self.taper_depth = 4.0 * float(facet_length.min())
        if taper_depth is not None:
            given = check_number(
                "taper_depth",
                taper_depth,
                low=0.0,
                low_open=True,
                high=-mesh.p[1].min(),
                units="m",
                what="depth over which the wear displacement fades",
            )
            self.taper_depth = max(self.taper_depth, given)

    # ---------------------------------------------------------------- geometry of the current surface
    @property
    def surface_r(self) -> np.ndarray:
        """Radii (m) of the surface nodes, sorted."""
        return self.solver.disc.surface_r.copy()

    @property
    def surface_height(self) -> np.ndarray:
        """Current z (m) of each surface node: reference height (0, or below it where worn) plus u_z; negative
        below the original plane."""
        return self.solver.disc.surface_z + self.state.u[self.solver.surface_uz]

    @property
    def dent_depth(self) -> np.ndarray:
        """Surface displacement into the plate (m, −u_z; positive = into the plate) at each surface node, without
        the wear."""
        return -self.state.u[self.solver.surface_uz]

    def surface_radial_displacement(self) -> np.ndarray:
        """The surface nodes' radial displacement u_r now (m, positive away from the axis; at :attr:`surface_r`)."""
        return self.state.u[self.solver.surface_ur].copy()

    @property
    def is_virgin(self) -> bool:
        """True until a state is committed (no indentation has left its state yet)."""
        return self._virgin

    def first_yield_overlap(self) -> float | None:
        """Overlap δ_y (m) at which a virgin plate first yields under Hertz contact (errata equation 18 with the exact
        C(ν)); None for a plate that never yields or is no longer virgin (its first yield is behind it)."""
        m = self.material
        if not self._virgin or m.yield_strength is None:
            return None
        return hertz_first_yield(self.radius, self.effective_modulus, m.yield_strength, m.nu).overlap

    def plastic_work(self, since: PlateState) -> float:
        """Plastic work (J) the plate dissipated from the state ``since`` to its current state
        (:func:`fem.core.plasticity.plastic_work`)."""
        return plastic_work(self.material, self.solver.disc.weight, since.alpha, self.state.alpha)

    def first_contact_overlap(self) -> float:
        """Overlap δ (m, sphere tip below the original plane) at which the sphere first touches the current
        surface: min over the surface nodes of z_s(r; 0) − z(r) (0 for a flat, virgin plate)."""
        gap0 = self.solver.obstacle(0.0) - self.state.u[self.solver.surface_uz]
        return max(float(np.min(gap0)), 0.0)

    # ---------------------------------------------------------------- indentation
    def load(self, overlaps) -> IndentationResult:
        """Load from the current state along ``overlaps`` (m, from the original plane), keeping every state so
        :meth:`unload` can restart from any of them. Does not change :attr:`state`."""
        path = check_array("overlaps", overlaps, low=0.0, units="m", what="overlap")
        run = IndentationRun(self.solver, self.effective_modulus, self.radius)
        # the state and first contact before this loading (an unload may be repeated: it must not see its own commit)
        self._before = (self.state, self.first_contact_overlap())
        return run.run(path, start=None if self._virgin else self.state, keep=True, predictor=self.elastic_predictor)

    def unload(
        self,
        loading: IndentationResult,
        max_overlap: float,
        steps: int = 8,
        end: float | None = None,
        commit: bool = True,
    ) -> IndentationResult:
        """Unload ``loading`` (a :meth:`load` result) from ``max_overlap`` (m) in ``steps`` equal increments to
        ``end`` (m; default: the first-contact overlap before the loading, minus 5% of the unloading range), then
        further if the ball still touches. Restarts from the kept loading state just below ``max_overlap`` (the
        loading branch is path independent). With ``commit`` the final, unloaded state becomes :attr:`state`.
        The result is recorded in ``loading.unloadings`` (so ``loading.force_law()`` includes it)."""
        run = loading.run
        steps = int(check_number("steps", steps, low=1, high=10000))
        top = max(st.overlap for st in run.kept)
        max_overlap = check_number("max_overlap", max_overlap, low=0.0, low_open=True, high=top * (1 + 1e-9), units="m")
        start = max((st for st in run.kept if st.overlap <= max_overlap * (1 + 1e-12)), key=lambda st: st.overlap)
        if end is None:
            first = self._before[1]
            end = max(0.0, first - 0.05 * (max_overlap - first))
        path = np.linspace(max_overlap, end, steps + 1)[1:]
        if start.overlap < max_overlap:
            path = np.r_[max_overlap, path]
        kept = run.kept
        result = run.run(path, start=start, keep=False, predictor=self.elastic_predictor)
        if run.final.n_active and end > 0.0:
            # still touching (pile-up, or a surface that rose): continue to the original plane
            more = run.run(np.linspace(end, 0.0, 4)[1:], start=run.final, keep=False, predictor=self.elastic_predictor)
            result = join(result, more)
        run.kept = kept
        loading.unloadings.append(result)
        if commit:
            self.commit(run.final)
        return result

    def commit(self, state: PlateState) -> None:
        """Make ``state`` (a converged :class:`PlateState` of this plate's mesh) the plate's current state."""
        if state.u.shape != self.state.u.shape:
            raise ValueError(f"state.u has {state.u.size} DOFs: this plate's mesh has {self.state.u.size}")
        self.state = state
        self._virgin = False

    # ---------------------------------------------------------------- wear
    def move_surface(self, depth) -> None:
        """Remove material: move the surface nodes down by ``depth`` (m, ≥ 0, one value per surface node sorted
        by r, as :attr:`surface_r`) and rebuild the discretisation; u, ε_p and ᾱ are kept (same topology)."""
        d = self.solver.disc
        depth = check_array("depth", depth, low=0.0, units="m", what="wear depth")
        if depth.shape != d.surface_r.shape:
            raise ValueError(f"depth has shape {depth.shape}: one value per surface node {d.surface_r.shape} (m)")
        if not depth.any():
            return
        self.wear_depth = self.wear_depth + depth
        p0 = self._reference_points
        # the surface nodes' radii are fixed (nodes move in z only), so W(r) interpolates on them exactly
        total = np.interp(p0[0], d.surface_r, self.wear_depth, right=0.0)
        below = np.maximum(0.0, -p0[1])  # depth of each vertex below the original plane
        points = p0.copy()
        points[1] -= total * np.clip(1.0 - below / self.taper_depth, 0.0, 1.0)
        mesh = replace(self.solver.disc.mesh, doflocs=points)
        self.solver = PlateSolver(mesh, self.material, self.radius, self._force_scale, self._gap_scale, rtol=self._rtol)
        # the mesh's edges are straight, so a P2 mid-side node sits on the chord between its vertices: its contact
        # gap is measured to the worn surface at its own radius instead. The chord is off by h²W''/8 (0.3% of
        # a²/R for a pit 0.5 a²/R deep, 16 elements across a), enough to put a node-scale 19% spike on the
        # peak pressure (tests/test_halfspace_fe.py: within 0.3% of the half-space solution once measured so)
        disc = self.solver.disc
        self.solver.disc = replace(disc, surface_z=self._reference_surface_z - self.wear_depth)

    @property
    def mesh(self) -> MeshTri:
        """The current (worn) mesh (m)."""
        return self.solver.disc.mesh

    # ---------------------------------------------------------------- output
    def to_meshio(self) -> meshio.Mesh:
        """The current state as a meshio mesh: the worn mesh deformed by u,
        point data ``u`` (m), ``wear_depth`` (m, the surface vertices' cumulative wear, 0 elsewhere),
        ``surface`` (1 on the surface vertices), cell data ``von_mises`` (Pa) and ``equivalent_plastic_strain``
        (element averages)."""
        s = self.solver
        mesh = s.disc.mesh
        nv = mesh.p.shape[1]
        wear = np.zeros(nv)
        surface = np.zeros(nv)
        sv = self._surface_vertices
        wear[sv] = np.interp(mesh.p[0, sv], s.disc.surface_r, self.wear_depth)
        surface[sv] = 1.0
        return state_mesh(s, self.state, {"wear_depth": wear, "surface": surface})

    def write(self, path: str | os.PathLike) -> None:
        """Write :meth:`to_meshio` to ``path`` (meshio; format from the suffix, e.g. ``.vtu``)."""
        self.to_meshio().write(path)


def surface_profile(r: np.ndarray, depth: np.ndarray, where: np.ndarray) -> np.ndarray:
    """Depth (m) of the FE surface at radii ``where`` (m) from its nodal values ``depth`` at the sorted surface nodes
    ``r`` (m), interpolated as the P2 elements carry it: quadratic through (vertex, mid-side, vertex) when the nodes
    alternate so (every odd node halfway between its neighbours), else linear; 0 beyond the last node.

    Why not linear: the pressure of a conforming seat follows the gap's curvature, and a piecewise-linear surface has a
    slope kink at every node — the half-space solution on it then depends on the grid (its peak rose 2.6 → 3.0 GPa as
    the cells shrank from 16 to 2.4 µm on a 2000-impact seat; on the P2 or a cubic-spline surface it converges)."""
    r, depth = np.asarray(r, float), np.asarray(depth, float)
    where = np.asarray(where, float)
    odd = r[1:-1:2]
    if r.size < 3 or r.size % 2 == 0 or not np.allclose(odd, 0.5 * (r[0:-2:2] + r[2::2]), rtol=1e-9, atol=0.0):
        return np.interp(where, r, depth, right=0.0)
    k = np.clip(np.searchsorted(r[0::2], where, side="right") - 1, 0, (r.size - 1) // 2 - 1)
    x0, x2 = r[2 * k], r[2 * k + 2]
    y0, y1, y2 = depth[2 * k], depth[2 * k + 1], depth[2 * k + 2]
    t = (where - x0) / (x2 - x0)  # the mid-side node sits at t = 1/2
    value = y0 * (2.0 * t - 1.0) * (t - 1.0) + y1 * 4.0 * t * (1.0 - t) + y2 * t * (2.0 * t - 1.0)
    return np.where(where <= r[-1], value, 0.0)
