r"""The discrete Coulomb law of the ball on the 3-D plate's surface (SI units).

The plate's surface nodes are quadratic; the law lives on its vertices, through their hat functions ψ_j (the linear
fields, :mod:`fem.solid.forms`): a vertex's *hat moment* of a nodal force field is the force its share of the surface
carries, (H f)_j, and the tractions reported are the linear fields with those moments (M⁻¹ H f, M the hats' mass).

* **stick** (weakly, on each sticking vertex j): Σ_i G̃_ij (u_t,i − u_t,i(start) − Δξ e_x) = 0, with G̃ the
  loads of the vertices' dual functions φ̃_j = 4ψ_j − 1 on the quadratic nodes (a dual mortar: Wohlmuth 2000),
  whose multipliers are the stick tractions; the hat moment of a multiplier's loads is its own vertex's only;
* **slip**: at every other vertex the ball's tangential force is μ times its normal force, on the hat moments,
  up to the surface's shear strength k times the hat's area A_j = ∫ψ_j dA (Orowan's friction τ = min(μp, k)),

  .. math:: (H f_t)_j = \min\bigl(\mu\,\max((H f_n)_j, 0),\ k A_j\bigr)\,\hat s_j,

  laid down as the linear traction field with those moments, τ = M⁻¹ H f_t (its loads' moments are zero at
  the stick vertices), ŝ_j the vertex's slip direction. Where the whole contact slides, the tangential force is then
  μ times the normal force exactly (Σ_j (H f_n)_j = P); the same traction on the projected pressure field, μ p⁺ ŝ,
  exceeded μP by the negative lobes of the projection just outside the contact (∫p⁺/∫p = 1.03 on the default mesh).
  Where the moments reach kA_j the traction is k itself. A perfectly plastic plate's surface cannot carry more:
  the von Mises stress of a surface point with shear τ is at least √3 τ whatever the pressure, so a Coulomb
  traction μp > k = Y/√3 has no equilibrium (the plate's surface layer flows without bound, and Newton fails where
  a contact slides throughout at μ = 0.5 with mean pressures ≈ 2Y). k = Y/√3 is the limit metal-forming codes put on
  Coulomb friction (Abaqus's shear stress limit τ_max; Orowan 1943).

The stick set follows Coulomb's law returned vertex by vertex on the trial traction τ + c s (the active set of a
semi-smooth Newton method; Hüeber, Stadler & Wohlmuth 2008): a stick vertex slips where its traction leaves the
cone ‖τ‖ ≤ μp, along that traction; a slipping one sticks where its trial traction falls inside the cone (its slip
turns back against the traction). Releasing a vertex on the cone alone and sending it along the ball's slide set off
a cascade to full reverse slip where the slide turned (an elastic impact's plate slid at −1.04 μP where
Mindlin–Deresiewicz gives −0.07 μP). Where the ball's slide reverses, the whole contact sticks first (Mindlin's
unloading). The slip traction follows the normal force, so Newton's tangent carries its linearisation (a
nonsymmetric tangent; lagged, it made Newton a fixed-point iteration of 14–19 iterations an increment). A stick
constraint on the quadratic nodes themselves (node by node) would leave the mid-edge nodes between a stick and a slip
vertex to one side or the other: ±6–7% on the tangential compliance of a Cattaneo–Mindlin contact on the default
mesh.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from fem.solid.forms import SolidDiscretisation
from fem.solid.state import SolidState

__all__ = ["SurfaceFriction"]


class SurfaceFriction:
    """The Coulomb law on the surface of the discretised half plate ``disc`` (its first ``vertex_count`` nodes are
    the mesh's vertices) of shear modulus ``shear_modulus`` (Pa) and Poisson's ratio ``poisson``, whose slip
    traction is limited by the surface's ``shear_strength`` k (Pa; ∞: Coulomb's μp). A stick vertex leaves the
    cone once its traction exceeds it by ``cone_tolerance`` (relative)."""

    def __init__(
        self,
        disc: SolidDiscretisation,
        vertex_count: int,
        shear_modulus: float,
        poisson: float,
        shear_strength: float = np.inf,
        cone_tolerance: float = 0.05,
    ) -> None:
        self.disc = d = disc
        self.shear_modulus = shear_modulus
        self.poisson = poisson
        self.shear_strength = shear_strength
        self.cone_tolerance = cone_tolerance
        self.uz = d.surface_dofs(2)
        self.ut = np.stack([d.surface_dofs(0), d.surface_dofs(1)], axis=1)
        # the two end vertices (rows of the hats) of every surface node: a vertex twice
        rows = d.surface_hats.tocsc()
        self.node_vertices = np.array(
            [rows.indices[rows.indptr[i] : rows.indptr[i + 1]][[0, -1]] for i in range(d.surface_nodes.size)]
        )
        self.is_vertex = d.surface_nodes < vertex_count
        self.on_symmetry = np.abs(d.surface_xy[:, 1]) <= 1e-9 * float(np.ptp(d.nodes[0]))
        self.vertex_on_symmetry = self.vertex_mask(self.on_symmetry)
        self.mass_lu = spla.splu(d.surface_hat_mass.tocsc())
        self.area = np.maximum(d.surface_area, 1e-300)
        # the consistent nodal loads of a unit traction: their hat moments over the contact nodes are the hats'
        # areas in contact
        self.unit_loads = np.asarray(d.surface_loads @ np.ones(d.surface_vertex_nodes.size)).ravel()

    def vertex_mask(self, node_mask: np.ndarray) -> np.ndarray:
        """A mask of the surface nodes taken at the surface vertices (a mask of the vertices)."""
        return self.vertex_values(node_mask)

    def vertex_values(self, node_values: np.ndarray) -> np.ndarray:
        """Values of the surface nodes (surface nodes, ...) taken at the surface vertices (surface vertices, ...)."""
        values = np.asarray(node_values)
        out = np.zeros((self.disc.surface_vertex_nodes.size, *values.shape[1:]), values.dtype)
        out[self.node_vertices[self.is_vertex, 0]] = values[self.is_vertex]
        return out

    def vertex_field(self, nodal: np.ndarray) -> np.ndarray:
        """The linear field (per surface vertex) whose hat moments are those of the nodal forces ``nodal``
        (surface nodes, ...) in N: a traction in Pa."""
        return self.mass_lu.solve(np.asarray(self.disc.surface_hats @ nodal, dtype=float))

    def ball_shear(self, f: np.ndarray) -> np.ndarray:
        """Tangential nodal forces (surface nodes, 2) of the ball from the internal force ``f`` (N): on the
        symmetry plane the y force is the mirror half's reaction, not the ball's."""
        shear = f[self.ut]
        shear[self.on_symmetry, 1] = 0.0
        return shear

    def moment_loads(self, moments: np.ndarray) -> np.ndarray:
        """Nodal loads (N, all DOFs) of the linear shear traction field whose hat moments are ``moments``
        (surface vertices, 2) in N."""
        return self.shear_loads(self.mass_lu.solve(np.ascontiguousarray(moments)))

    def shear_loads(self, tau: np.ndarray) -> np.ndarray:
        """Consistent nodal loads (N, all DOFs) of a shear traction field ``tau`` (surface vertices, 2) in Pa."""
        loads = self.disc.surface_loads @ tau
        out = np.zeros(self.disc.ndofs)
        out[self.ut[:, 0]] = loads[:, 0]
        out[self.ut[:, 1]] = loads[:, 1]
        return out

    def moment_limits(self, contact: np.ndarray) -> np.ndarray:
        """The largest tangential hat moment (N) of each surface vertex, k A_j with A_j the area of its hat in
        contact (on the ``contact`` nodes; m²). With the whole hat's area the hats across the contact's edge
        carried μ times their normal moment where the part of them in contact is at k: gross sliding at k = 0.3μp₀
        +7.3% over Orowan's ∫min(μp, k) dA on the default mesh, +5.8% with the area in contact (at 0.6μp₀ +2.7%
        either way: the hats across r = c average the kink of min(μp, k), +1.2% with 6 elements across a)."""
        if not np.isfinite(self.shear_strength):
            return np.full(self.disc.surface_vertex_nodes.size, np.inf)
        return self.shear_strength * np.asarray(self.disc.surface_hats @ (self.unit_loads * contact))

    def slip_loads(self, f: np.ndarray, contact, slip_vertices, direction, mu: float) -> tuple[np.ndarray, np.ndarray]:
        """The slip tractions' nodal loads (N, all DOFs) for the internal force ``f`` (N): at the ``slip_vertices``
        (H f_t)_j = min(μ (H f_n)_j⁺, k A_j) ŝ_j along ``direction`` (surface vertices, 2). Returns (loads, the
        normal hat moments in N)."""
        # the ball presses the contact nodes only (elsewhere f_n is the equilibrium residual)
        normal_moments = np.asarray(self.disc.surface_hats @ (-f[self.uz] * contact))
        moments = np.minimum(mu * np.maximum(normal_moments, 0.0), self.moment_limits(contact)) * slip_vertices
        return self.moment_loads(moments[:, None] * direction), normal_moments

    def slip_linearisation(
        self,
        K: sp.csr_matrix,
        normal_moments,
        direction,
        slip_vertices,
        mu: float,
        keep: np.ndarray,
        contact: np.ndarray,
    ) -> Callable[[np.ndarray], np.ndarray]:
        r"""The change of the slip tractions' nodal loads with the displacement, as a function of a displacement
        change v (m) to loads (N) on the free DOFs ``keep``: the slip traction follows the normal hat moments, whose
        nodal forces are the normal rows of K v,

        .. math:: \delta f_t = L\,M^{-1}\,\mu\,\hat s\;H\,(-K v)_z\big|_{contact}

        (L the linear traction's consistent loads, M⁻¹ the hat moments to the linear field; ŝ held at the set's
        direction; ``normal_moments`` the iterate's (N) of the forces on the ``contact`` nodes, whose positive part
        the traction follows below the shear strength's k A_j; at it the traction is fixed). It makes Newton's
        tangent the consistent, nonsymmetric one, K − ∂f_t/∂u: the lagged slip traction made Newton a fixed-point
        iteration of 14–19 iterations per frictional increment."""
        pressed = mu * slip_vertices * (normal_moments > 0.0) * (mu * normal_moments < self.moment_limits(contact))
        # only the contact nodes' normal rows of K v are needed: K's other rows are not multiplied
        pressing = np.flatnonzero(contact)
        normal_rows = K[self.uz[pressing]]

        def coupling(v: np.ndarray) -> np.ndarray:
            normal_forces = np.zeros(contact.size)
            normal_forces[pressing] = -(normal_rows @ v)
            moments = np.asarray(self.disc.surface_hats @ normal_forces)
            return self.moment_loads((pressed * moments)[:, None] * direction) * keep

        return coupling

    def stick_rows(self, start: SolidState, slide: float, contact, stick, free) -> tuple[sp.csr_matrix, np.ndarray]:
        r"""The stick constraints, weak on each sticking vertex's dual function φ̃_j (the dual mortar pairing with
        the quadratic displacements, :mod:`fem.solid.forms`):

        .. math:: \sum_i \tilde G_{ij}\,\bigl(u_{t,i} - u_{t,i}^{start} - \Delta\xi\, e_x\bigr) = 0,

        x and y rows (no y row on the symmetry plane: there τ_y = 0 by symmetry). Their multipliers, times the rows'
        scales, are the stick vertices' tangential hat moments (N): a multiplier's loads have no moment at the
        neighbouring vertices, so the cone of a stick vertex and the slip traction of its slipping neighbours do
        not share forces. Returns (rows over all DOFs, each scaled to a unit sum of absolute values so that its error
        is a length in m, targets in m, row ids 2·vertex + component).
        """
        d = self.disc
        sticking = self.vertex_mask(stick & contact)
        loads = d.surface_dual_loads[:, sticking].T.tocsr()  # (k, surface nodes)
        on_plane = self.vertex_on_symmetry[sticking]
        blocks, targets, ids = [], [], []
        vertex_ids = np.flatnonzero(sticking)
        for component, keep_rows in ((0, slice(None)), (1, ~on_plane)):
            ids.append(2 * vertex_ids[keep_rows] + component)
            block = loads[keep_rows]
            dofs = self.ut[:, component]
            coo = block.tocoo()
            columns = dofs[coo.col]
            mask = free[columns]
            blocks.append(
                sp.csr_matrix((coo.data[mask], (coo.row[mask], columns[mask])), shape=(block.shape[0], d.ndofs))
            )
            moved = start.u[dofs] + ((slide - start.slide) if component == 0 else 0.0)
            targets.append(block @ moved)
        rows, targets = sp.vstack(blocks).tocsr(), np.concatenate(targets)
        sums = np.asarray(abs(rows).sum(axis=1)).ravel()
        sums[sums == 0.0] = 1.0
        return (sp.diags(1.0 / sums) @ rows).tocsr(), targets / sums, np.concatenate(ids)

    def slip_vertices(self, stick: np.ndarray) -> np.ndarray:
        """Surface vertices that do not stick: those with a positive normal moment slip (a vertex just outside the
        contact nodes carries the moments of its edges' mid-edge nodes in contact)."""
        return ~self.vertex_mask(stick)

    def vertex_tractions(self, normal: np.ndarray, shear: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        r"""The vertex pressure p_j and shear q_j (Pa) of the ball's nodal forces ``normal`` (surface nodes; on the
        contact nodes only) and ``shear`` (surface nodes, 2; :meth:`ball_shear`) in N: each vertex's hat moment over
        its hat's area,

        .. math:: p_j = \frac{(H f_n)_j}{A_j},\qquad q_j = \frac{(H f_t)_j}{A_j},\qquad A_j = \int \psi_j\,dA,

        the very moments the Coulomb law holds vertex by vertex (:meth:`slip_loads`), so that a slipping vertex has
        ‖q_j‖ = min(μ p_j, k A_j^contact / A_j) ≤ min(μ p_j, k) (to the equilibrium's residual), and the linear fields
        through them carry the nodal forces exactly, ∫ Σ_j p_j ψ_j dA = Σ_j A_j p_j = Σ_i f_n,i (the hats are a
        partition of unity on the surface nodes). On the symmetry plane y = 0 the whole plate's q_y is 0: its mirror
        half's cancels it (the half's own lacks the y forces the plane's reactions took). The linear fields with
        those moments, M⁻¹ H f (the L² projection, :meth:`vertex_field`), carry the same forces but oscillate at the
        contact's edge and at a stick edge: on the default impact they reported sliding vertices at 16 μp and 4 k."""
        traction = np.asarray(self.disc.surface_hats @ shear) / self.area[:, None]
        traction[self.vertex_on_symmetry, 1] = 0.0
        return np.asarray(self.disc.surface_hats @ normal) / self.area, traction

    def update_stick(self, start, target, u, f, stick, direction, new_contact, mu, released):
        """The stick set and slip directions after one equilibrium: Coulomb's law returned vertex by vertex (the
        active set of a semi-smooth Newton method; Hüeber, Stadler & Wohlmuth 2008). With the vertex's traction τ
        and its slip s in the increment, the trial traction τ + c s (c = G/h, the plate's shear modulus over the
        size h of the vertex's hat) sticks inside the cone min(μp, k) and slips along itself outside it. The
        traction and the cone are the vertex's hat moments over its area (:meth:`vertex_tractions`), those the slip
        law sets and the plate reports: tested on the L² projection of the moments, which overshoots the cone by
        20–45% at a discrete stick edge, a stick edge vertex left the cone, slipped against its own traction and
        could not stick again in that increment, so the stick zone lost a ring of vertices every few increments
        (default impact, 3 elements across the contact: 12.6%, 3.4%, 1.3% of the contact's area-time stuck at 10,
        20, 40 loading increments; with the moments 20.1%, 20.2%, 20.4%, Mindlin's c/a = (1 − Q/μP)^{1/3} ≈ 0.46 at
        the impact's Q/μP ≈ 0.9 puts 21% of the area in stick). A stick vertex
        (s = 0) thus slips where its traction leaves the cone, along that traction; a slipping one (τ = μpŝ) goes on
        where it keeps to its way and sticks where its slip turns back against its traction (unless it was
        ``released`` from the stick set in this increment: within one increment the set only shrinks after that,
        which ends the cycles a coarse stick boundary can set off)."""
        pressure, tau = self.vertex_tractions(-f[self.uz] * new_contact, self.ball_shear(f))
        sticks = self.vertex_mask(stick)
        in_contact = self.vertex_mask(new_contact)
        magnitude = np.linalg.norm(tau, axis=1)
        cone = np.minimum(mu * np.maximum(pressure, 0.0), self.moment_limits(new_contact) / self.area)
        # a stick vertex's traction overshoots the cone by a few per cent at a discrete stick edge (where the
        # continuum's ‖τ‖/μp → 1 like 1 − √(c − r)); releasing on that overshoot sets off a cascade to gross slip
        floor = 1e-3 * max(float(cone.max(initial=0.0)), 1e-300)
        leave = sticks & (magnitude > (1.0 + self.cone_tolerance) * cone + floor)
        nodal_slip = np.stack(
            [
                target[2] - start.slide - (u[self.ut[:, 0]] - start.u[self.ut[:, 0]]),
                -(u[self.ut[:, 1]] - start.u[self.ut[:, 1]]),
            ],
            axis=1,
        )
        # the slip at each vertex as the stick constraint weighs it (zero at a stick vertex): the quadratic field's
        # own vertex values carry the corner/mid-edge alternation of its reactions
        area = self.area
        slip = np.asarray(self.disc.surface_dual_loads.T @ nodal_slip) / area[:, None]
        # the trial traction: a slipping vertex's traction carries the direction while its slip is small (the
        # direction of a small slip is noise that turned the slip zone's traction sideways), its slip once large
        trial = cone[:, None] * direction + (self.shear_modulus / np.sqrt(area))[:, None] * slip
        trial_size = np.linalg.norm(trial, axis=1)
        was_released = self.vertex_mask(released)
        restick = in_contact & ~sticks & ~was_released & (trial_size < cone)
        new_direction = direction.copy()
        moving = ~sticks & ~restick & (trial_size > 0.0)
        new_direction[moving] = trial[moving] / trial_size[moving, None]
        released_now = leave & (magnitude > 0.0)
        new_direction[released_now] = tau[released_now] / magnitude[released_now, None]
        vertex_sticks = in_contact & ((sticks & ~leave) | restick)
        ends = self.node_vertices
        return new_contact & vertex_sticks[ends[:, 0]] & vertex_sticks[ends[:, 1]], new_direction

    def turned(self, direction: np.ndarray, new_direction: np.ndarray, stick, contact, angle: float = 5.0) -> bool:
        """Whether a vertex slipping in ``contact`` (outside ``stick``; node masks) has its slip direction
        ``new_direction`` more than ``angle`` (degrees) away from the ``direction`` its slip traction was solved with
        (surface vertices, 2)."""
        slipping = self.vertex_mask(contact) & ~self.vertex_mask(stick)
        cosine = np.sum(direction[slipping] * new_direction[slipping], axis=1)
        return bool(np.any(cosine < np.cos(np.radians(angle))))

    def stick_guess(self, state: SolidState, target, contact: np.ndarray, mu: float, last_step: float = 0.0):
        """The stick set an increment starts from. Where the slide reverses against ``last_step`` (m, the slide of
        the increment before), the whole contact sticks and releases from the edge where the cone is exceeded
        (Mindlin's unloading, Johnson §7.3). In partial slip a node that comes into contact sticks first;
        after a frictionless history the whole contact does (and releases where the cone is exceeded). After gross
        sliding the contact slips on while the slide goes on the same way, and sticks when it reverses. At first
        contact (normal and tangential loads applied together) it all slips if the slide reaches Mindlin's
        gross-slip slide of the target overlap, μδ(2 − ν)/(2(1 − ν)) for a rigid sphere on a Hertzian plate
        (Johnson Eq. 7.42 with Hertz's P and a), else it sticks. A start on the wrong side costs a release (or
        stick) round per ring of vertices, each with its own stick factor."""
        if mu <= 0.0:
            return np.zeros_like(contact)
        step = target[2] - state.slide
        if step * last_step < 0.0:
            return contact.copy()
        if state.stick.any():
            return (state.stick | ~state.contact) & contact
        if state.friction > 0.0 and state.contact.any():
            previous = float(np.mean(state.direction[:, 0]))
            return contact if step * previous <= 0.0 else np.zeros_like(contact)
        if state.contact.any():
            return contact
        nu = self.poisson
        gross = mu * target[0] * (2.0 - nu) / (2.0 * (1.0 - nu))
        return np.zeros_like(contact) if abs(step) >= gross else contact
