"""Results of an indentation run: per-step curves, pressures, first yield, force law, mesh output (SI)."""

from __future__ import annotations

import os
from dataclasses import dataclass, field, replace

import meshio
import numpy as np

from contact.tabulated import TabulatedLaw

__all__ = [
    "REGIMES",
    "FirstYieldPoint",
    "IndentationResult",
    "join",
    "loading_branch",
    "unloading_curve",
    "worst_regime",
]

#: The plate's regimes, from the least to the most plastic: no plastic strain; a plastic zone contained below the
#: surface; a plastic zone reaching the surface inside the contact; the whole surface layer under the contact
#: plastic.
REGIMES = ("elastic", "contained", "surface-plastic", "fully-plastic")


def worst_regime(regimes) -> str:
    """The most plastic of ``regimes`` (see :data:`REGIMES`; "elastic" if there are none)."""
    return max((r for r in regimes if r in REGIMES), key=REGIMES.index, default="elastic")


@dataclass(frozen=True)
class FirstYieldPoint:
    """First yield found by the FE: ``force`` (N), ``overlap`` (m), ``depth`` (m below the surface)
    and ``radius`` (m from the axis) of the first yielding point, ``contact_radius`` (m)."""

    force: float
    overlap: float
    depth: float
    radius: float
    contact_radius: float


@dataclass(eq=False)
class IndentationResult:
    """Indentation of the plate by a sphere along an overlap path (arrays: one entry per step).

    ``overlap`` δ (m), ``force`` F (N), ``contact_radius`` a (m), ``max_pressure`` (Pa),
    ``mean_pressure`` F/(πa²) (Pa), ``surface_r`` (m), ``pressure`` (steps, surface nodes) (Pa, linear between
    the surface vertices: :func:`fem.core.sphere.pressure_from_reactions`), ``radial_displacement`` (steps, surface
    nodes) the surface nodes' u_r (m, positive away from the axis: the plate surface's slip under the ball is its
    change), ``first_yield``
    (:class:`FirstYieldPoint` or None), ``residual_depth`` (m, surface u_z after the last step, positive = into
    the plate), ``max_equivalent_plastic_strain`` (per step), ``regime`` (per step), ``newton_iterations`` (per
    step), ``time`` (s, per step, only from :func:`fem.indent_impact`), ``radius`` R (m), ``effective_modulus``
    E* (Pa), ``run`` (the :class:`fem.axisymmetric.indent.IndentationRun` that computed it: its mesh, final state and
    kept states; None for a result not computed by a run, e.g. :func:`fem.elastic_reload`).
    """

    overlap: np.ndarray
    force: np.ndarray
    contact_radius: np.ndarray
    max_pressure: np.ndarray
    mean_pressure: np.ndarray
    surface_r: np.ndarray
    pressure: np.ndarray
    radial_displacement: np.ndarray
    first_yield: FirstYieldPoint | None
    residual_depth: np.ndarray
    max_equivalent_plastic_strain: np.ndarray
    regime: list
    newton_iterations: np.ndarray
    radius: float
    effective_modulus: float
    time: np.ndarray | None = None
    unloadings: list = field(default_factory=list)
    run: object = field(default=None, repr=False)

    # ------------------------------------------------------------------ unloading
    def unload_from(self, max_overlap: float, steps: int = 20) -> IndentationResult:
        """Unload from ``max_overlap`` δ_max (m) in ``steps`` equal increments to zero overlap.

        Restarts from the kept loading state just below δ_max (the run must use
        ``keep_states=True``), loads to δ_max in one increment and unloads; the loading branch is
        path independent, so this costs one FE increment plus the unloading; unloading steps whose elastic field
        yields nowhere are taken without Newton iterations (:mod:`fem.axisymmetric.reload`: the same solution). The
        unloading curve is recorded here, so :meth:`force_law` returns one unloading curve per call.
        """
        if self.run is None:
            raise ValueError("unload_from needs the states of the loading run: call fem.indent(..., keep_states=True)")
        result = self.run.unload_from(max_overlap, steps)
        self.unloadings.append(result)
        return result

    # ------------------------------------------------------------------ force law
    def force_law(self, samples: int = 41) -> TabulatedLaw:
        """Tabulated loading F(δ), a(δ) and one unloading curve per computed unloading (this run's
        own, if its path unloads, and each :meth:`unload_from`), resampled to ``samples`` points
        from δ_max down to the residual overlap δ_p where F = 0. Units m, N."""
        lo, lf, la = loading_branch(self.overlap, self.force, self.contact_radius)
        curves = [unloading_curve(r.overlap, r.force, r.contact_radius, samples) for r in [self, *self.unloadings]]
        curves = sorted((c for c in curves if c is not None), key=lambda c: c[0])
        unique = []
        for c in curves:
            if not unique or c[0] > unique[-1][0] * (1.0 + 1e-12):
                unique.append(c)
        if not unique:
            raise ValueError(
                "force_law needs an unloading: give overlaps that decrease after the maximum, or call "
                "unload_from(max_overlap) on a keep_states=True run"
            )
        return TabulatedLaw(
            loading_overlap=lo,
            loading_force=lf,
            loading_contact_radius=la,
            unloading_max_overlap=np.array([c[0] for c in unique]),
            unloading_overlap=np.array([c[1] for c in unique]),
            unloading_force=np.array([c[2] for c in unique]),
            unloading_contact_radius=np.array([c[3] for c in unique]),
        )

    # ------------------------------------------------------------------ output
    def to_meshio(self) -> meshio.Mesh:
        """The deformed mesh of the last step: points (r, z, 0) m, point data ``u`` (m) and ``pressure`` (Pa,
        surface), cell data ``von_mises`` (Pa) and ``equivalent_plastic_strain`` (element averages)."""
        if self.run is None:
            raise ValueError("to_meshio needs the final state of the run, which this result does not hold")
        return self.run.to_meshio(self)

    def write(self, path: str | os.PathLike) -> None:
        """Write :meth:`to_meshio` to ``path`` (meshio; format from the suffix, e.g. ``.vtu``)."""
        self.to_meshio().write(path)


def loading_branch(overlap, force, contact_radius, first_contact: float = 0.0):
    """The monotonic loading branch of a path, from first contact: (δ − ``first_contact``, F, a) over the steps up to
    the largest overlap where δ increases and the sphere touches, from (0, 0, 0). Units m, N, m."""
    d = np.asarray(overlap, float) - first_contact
    k = int(np.argmax(d))
    d = d[: k + 1]
    f = np.maximum(np.asarray(force, float)[: k + 1], 0.0)
    a = np.maximum(np.asarray(contact_radius, float)[: k + 1], 0.0)
    keep = (d > 0.0) & np.concatenate([[True], np.diff(d) > 0.0])
    return np.r_[0.0, d[keep]], np.r_[0.0, f[keep]], np.r_[0.0, a[keep]]


def unloading_curve(overlap, force, contact_radius, samples: int):
    """The unloading curve of a path (δ decreasing from its largest value), resampled on ``samples`` overlaps from
    the top down to the residual overlap δ_p where F = 0: (top δ*, overlaps, forces, contact radii), or None if the
    path does not unload. F^{2/3} is interpolated linearly in δ (Hertz-like), and δ_p extrapolated so. Units m, N."""
    d, f, a = np.asarray(overlap, float), np.asarray(force, float), np.asarray(contact_radius, float)
    peak = int(np.argmax(d))
    if peak == d.size - 1:
        return None
    ud, uf, ua = d[peak:], f[peak:], a[peak:]
    positive = np.flatnonzero(uf > 0.0)
    last = int(positive[-1]) if positive.size else 0
    if last == 0:
        return None
    # the residual overlap: F^{2/3} is linear in δ near the end (Hertz-like re-contact)
    if last + 1 < ud.size:
        g1, g0 = uf[last] ** (2 / 3), uf[last - 1] ** (2 / 3)
        slope = (g0 - g1) / (ud[last - 1] - ud[last])
        dp = ud[last] - g1 / slope if slope > 0 else ud[last + 1]
        dp = float(np.clip(dp, ud[last + 1], ud[last]))
    else:
        dp = float(ud[last])  # the path stopped before the force vanished
    od = np.r_[ud[: last + 1], dp]
    of = np.r_[uf[: last + 1], 0.0]
    oa = np.r_[ua[: last + 1], 0.0]
    grid = np.linspace(od[0], dp, samples)  # its ends exactly δ* and δ_p: a reloading joins the branch at δ*
    order = np.argsort(od)
    curve_force = np.interp(grid, od[order], of[order] ** (2 / 3)) ** 1.5
    radius = np.interp(grid, od[order], oa[order])
    return float(od[0]), grid, curve_force, radius


def join(first: IndentationResult, second: IndentationResult, below: float | None = None) -> IndentationResult:
    """The steps of ``first`` (those strictly below the overlap ``below``, m, up to its peak, if given) followed by
    the steps of ``second`` (e.g. a loading and the unloading from δ* = ``below``). The state, surface and residual
    depth are ``second``'s; the first yield is ``first``'s if it lies within the joined path."""
    d = np.asarray(first.overlap, float)
    k = d.size
    if below is not None:
        kept = (d < below * (1.0 - 1e-12)) & np.concatenate([[True], np.diff(d) > 0])
        k = d.size if kept.all() else int(np.argmin(kept))
    reach = max(float(np.max(d[:k], initial=0.0)), float(np.max(second.overlap, initial=0.0)))
    fy = first.first_yield if first.first_yield is not None else second.first_yield
    if fy is not None and fy.overlap > reach:
        fy = None

    def cat(name: str) -> np.ndarray:
        return np.concatenate([np.asarray(getattr(first, name))[:k], np.asarray(getattr(second, name))])

    return replace(
        second,
        overlap=cat("overlap"),
        force=cat("force"),
        contact_radius=cat("contact_radius"),
        max_pressure=cat("max_pressure"),
        mean_pressure=cat("mean_pressure"),
        pressure=np.vstack([np.asarray(first.pressure)[:k], np.asarray(second.pressure)]),
        radial_displacement=np.vstack([first.radial_displacement[:k], second.radial_displacement]),
        first_yield=fy,
        max_equivalent_plastic_strain=cat("max_equivalent_plastic_strain"),
        regime=list(first.regime[:k]) + list(second.regime),
        newton_iterations=cat("newton_iterations"),
        time=None,
        unloadings=[],
    )
