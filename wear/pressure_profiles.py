"""Closed-form axisymmetric contact-pressure profiles on the table in s = √(1 − r²/a²) of
:class:`wear.pressure.PressureHistory`: Hertz truncated at a limiting pressure, and the contact radius of
Mesarovic & Johnson's elastic unloading.

Hertz carrying the force F over the contact radius a is p = p₀s with p₀ = 3F/(2πa²). Truncated at p_y
(Thornton 1997), p = min(p₀s, p_y) with p₀ chosen so that the profile still carries F: with q = p_y/p₀,
F/(πa²p_y) = 1 − q²/3; if the mean pressure F/(πa²) reaches p_y the pressure is uniform at F/(πa²). Mesarovic &
Johnson (2000) unloading from (a*, F*): F/F* = (2/π)[arcsin x − x√(1−x²)], x = a/a*. SI units: m, N, Pa.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["truncated_hertz_rows", "mesarovic_johnson_radius_fraction"]


def truncated_hertz_rows(s, contact_radius, force, limiting_pressure) -> np.ndarray:
    """Rows p(s) of Hertz profiles carrying ``force`` over ``contact_radius``, truncated at ``limiting_pressure``."""
    a2 = contact_radius**2
    with np.errstate(divide="ignore", invalid="ignore"):
        mean = np.where(a2 > 0.0, force / (math.pi * a2), 0.0)
    shape = s  # Hertz: p = p₀ √(1 − r²/a²) = p₀ s
    p0 = 1.5 * mean
    truncated = p0 > limiting_pressure
    rows = p0[:, None] * shape[None, :]
    if np.any(truncated):
        # F/(πa²p_y) = 1 − q²/3, q = p_y/p₀ ∈ [0, 1)
        ratio = mean[truncated] / limiting_pressure
        q = np.sqrt(np.maximum(3.0 * (1.0 - ratio), 0.0))
        p0_t = limiting_pressure / np.maximum(q, 1e-12)  # q = 0 rows are uniform, set below
        trunc_rows = np.minimum(p0_t[:, None] * shape[None, :], limiting_pressure)
        uniform = ratio >= 1.0  # cannot be carried below p_y: keep the force, uniform pressure
        trunc_rows[uniform] = mean[truncated][uniform, None]
        rows[truncated] = trunc_rows
    return rows


def mesarovic_johnson_radius_fraction(force_fraction: np.ndarray) -> np.ndarray:
    """Solve F/F* = (2/π)[arcsin x − x√(1−x²)] for x = a/a* ∈ [0, 1] (monotonic; bisection to 1e-15)."""
    target = np.clip(force_fraction, 0.0, 1.0)
    lo, hi = np.zeros_like(target), np.ones_like(target)
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        g = 2.0 / math.pi * (np.arcsin(mid) - mid * np.sqrt(1.0 - mid * mid))
        below = g < target
        lo = np.where(below, mid, lo)
        hi = np.where(below, hi, mid)
    return 0.5 * (lo + hi)
