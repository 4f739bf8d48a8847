"""The result of the erosion of a patch (:func:`wear.erosion.erode`): the worn and dented surface, its time series
and frames, and the counts of the impacts. SI units."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from wear.erosion.stream import Stream
from wear.erosion.table import ResponseTable

__all__ = ["ErosionResult"]


@dataclass(frozen=True, eq=False)
class ErosionResult:
    """Result of :func:`wear.erosion.erode` (SI units).

    ``x``, ``y`` (n,) node coordinates (m); ``wear`` (n, n) worn depth (m); ``dent`` (n, n) or None;
    ``initial`` (n, n) the initial surface depth (m) or None;
    ``time`` (k,) s, ``impacts`` (k,), ``particle_mass_kg`` (k,) particles delivered, ``mass_loss_kg`` (k,)
    = ρ h² Σ w, ``erosion_rate`` (k,) kg/kg (cumulative), ``max_depth_m`` (k,), ``rms_slope`` (k,) of the
    surface, sampled along the run; ``frame_time`` (f,) s and ``frames`` (f, n, n) the surface at saved
    times; counts ``n_impacts``, ``shadowed`` (did not hit: local angle ≥ 89°) and ``clamped`` (local normal
    speed or angle outside the table, clamped to it); ``removed_m3`` Σ of the stamped volumes (m³).
    """

    x: np.ndarray
    y: np.ndarray
    wear: np.ndarray
    dent: np.ndarray | None
    initial: np.ndarray | None
    time: np.ndarray
    impacts: np.ndarray
    particle_mass_kg: np.ndarray
    mass_loss_kg: np.ndarray
    erosion_rate: np.ndarray
    max_depth_m: np.ndarray
    rms_slope: np.ndarray
    frame_time: np.ndarray
    frames: np.ndarray
    n_impacts: int
    shadowed: int
    clamped: int
    removed_m3: float
    stream: Stream
    table: ResponseTable = field(repr=False)
    seed: int = 0

    @property
    def spacing(self) -> float:
        """Grid spacing h (m)."""
        return float(self.x[1] - self.x[0])

    @property
    def patch_size(self) -> float:
        """Side of the square periodic patch (m)."""
        return self.spacing * self.x.size

    @property
    def surface(self) -> np.ndarray:
        """Surface depth (m, into the plate) = initial + wear + dent, shape (n, n)."""
        out = self.wear.copy()
        for part in (self.initial, self.dent):
            if part is not None:
                out += part
        return out

    @property
    def interval_erosion_rate(self) -> np.ndarray:
        """Erosion rate between successive samples (kg/kg; first entry 0): shows how the surface feedback
        changes the rate as the surface roughens."""
        dm = np.diff(self.mass_loss_kg)
        dp = np.diff(self.particle_mass_kg)
        with np.errstate(invalid="ignore", divide="ignore"):
            rate = np.where(dp > 0, dm / np.where(dp > 0, dp, 1.0), 0.0)
        return np.concatenate([[0.0], rate])

    @property
    def final_erosion_rate(self) -> float:
        """Erosion rate over the whole exposure (kg of plate per kg of particles)."""
        return float(self.erosion_rate[-1])
