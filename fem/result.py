"""Results of an indentation run: per-step curves, pressures, first yield, force law, mesh output (SI)."""

from __future__ import annotations

import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from contact.tabulated import TabulatedLaw

__all__ = ["FirstYieldPoint", "IndentationResult"]

REGIMES = ("elastic", "contained", "surface-plastic", "fully-plastic")


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
    ``mean_pressure`` F/(πa²) (Pa), ``surface_r`` (m), ``pressure`` (steps, surface nodes) (Pa),
    ``first_yield`` (:class:`FirstYieldPoint` or None), ``residual_depth`` (m, surface u_z after
    the last step, positive = into the plate), ``max_equivalent_plastic_strain`` (per step),
    ``regime`` (per step), ``newton_iterations`` (per step), ``time`` (s, per step, only from
    :func:`fem.indent_impact`), ``radius`` R (m), ``effective_modulus`` E* (Pa).
    """

    overlap: np.ndarray
    force: np.ndarray
    contact_radius: np.ndarray
    max_pressure: np.ndarray
    mean_pressure: np.ndarray
    surface_r: np.ndarray
    pressure: np.ndarray
    first_yield: FirstYieldPoint | None
    residual_depth: np.ndarray
    max_equivalent_plastic_strain: np.ndarray
    regime: list
    newton_iterations: np.ndarray
    radius: float
    effective_modulus: float
    time: np.ndarray | None = None
    unloadings: list = field(default_factory=list)
    _run: object = field(default=None, repr=False)

    # ------------------------------------------------------------------ unloading
    def unload_from(self, max_overlap: float, steps: int = 20) -> IndentationResult:
        """Unload from ``max_overlap`` δ_max (m) in ``steps`` equal increments to zero overlap.

        Restarts from the kept loading state just below δ_max (the run must use
        ``keep_states=True``), loads to δ_max in one increment and unloads; the loading branch is
        path independent, so this costs one FE increment plus the unloading; unloading steps whose elastic field
        yields nowhere are taken without Newton iterations (:mod:`fem.reload`: the same solution). The unloading
        curve is recorded here, so :meth:`force_law` returns one unloading curve per call.
        """
        if self._run is None:
            raise ValueError("unload_from needs the states of the loading run: call fem.indent(..., keep_states=True)")
        result = self._run.unload_from(max_overlap, steps)
        self.unloadings.append(result)
        return result

    # ------------------------------------------------------------------ force law
    def _loading_branch(self):
        d = np.asarray(self.overlap)
        peak = int(np.argmax(d))
        keep = np.concatenate([[True], np.diff(d[: peak + 1]) > 0.0])
        lo, lf, la = d[: peak + 1][keep], self.force[: peak + 1][keep], self.contact_radius[: peak + 1][keep]
        if lo[0] > 0.0:
            lo, lf, la = np.r_[0.0, lo], np.r_[0.0, lf], np.r_[0.0, la]
        return lo, lf, la, peak

    def _unloading_curve(self, samples: int):
        """Unloading curve of this run (δ decreasing from its peak), resampled, ending at F = 0."""
        d, f, a = np.asarray(self.overlap), np.asarray(self.force), np.asarray(self.contact_radius)
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
        s = np.linspace(1.0, 0.0, samples)
        grid = dp + s * (od[0] - dp)
        order = np.argsort(od)
        force = np.interp(grid, od[order], of[order] ** (2 / 3)) ** 1.5
        radius = np.interp(grid, od[order], oa[order])
        return float(od[0]), grid, force, radius

    def force_law(self, samples: int = 41) -> TabulatedLaw:
        """Tabulated loading F(δ), a(δ) and one unloading curve per computed unloading (this run's
        own, if its path unloads, and each :meth:`unload_from`), resampled to ``samples`` points
        from δ_max down to the residual overlap δ_p where F = 0. Units m, N."""
        lo, lf, la, _ = self._loading_branch()
        curves = [c for c in [self._unloading_curve(samples)] + [u._unloading_curve(samples) for u in self.unloadings]]
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
    def write(self, path: str | os.PathLike) -> Path:
        """Write the deformed mesh of the last step (meshio; format from the suffix, e.g. .vtu) with
        point data ``u`` (m), ``pressure`` (Pa, surface) and cell data ``von_mises`` (Pa) and
        ``equivalent_plastic_strain`` (element averages). Atomic: temp file then os.replace."""
        if self._run is None:
            raise ValueError("write needs the final state of the run, which this result does not hold")
        return self._run.write(Path(path), self)
