r"""Frictionless elastic contact of a rigid indenter with a half-space whose surface has any shape.

The boundary-element solution used to check what the FE plate does on a dented or worn surface, and to compute
the pressure on a 2-D worn scar the axisymmetric FE cannot represent. For a shaken-down plate the reload is
elastic, so its contact pressure is the elastic contact pressure of the *current* surface: residual stresses are
self-equilibrated and drop out by superposition (small strain).

Problem: on a square grid of cells of side ``spacing`` (m), the initial gap :math:`h_{ij} \ge 0` (m) between the
indenter and the unloaded surface, the total force :math:`W` (N). Find the pressure :math:`p \ge 0` (Pa), uniform
on each cell, and the approach :math:`\delta` (m) with

.. math::

    g_{ij} = h_{ij} + u_{ij} - \delta \ge 0, \qquad p_{ij}\, g_{ij} = 0, \qquad \textstyle\sum p_{ij}\,\Delta^2 = W,

    u_{ij} = \sum_{kl} K_{i-k,\,j-l}\, p_{kl}

where :math:`u` is the combined normal displacement of both surfaces (m, positive apart) and :math:`K` Love's
(1929) influence coefficient of a uniformly loaded rectangle on a half-space of effective modulus :math:`E^*`.
The convolution is taken with zero-padded FFTs (non-periodic, "DC-FFT", Liu, Wang & Liu 2000), the complementarity
problem by the conjugate-gradient method of Polonsky & Keer (1999, Wear 231:206), which keeps the force fixed and
finds the approach as the mean gap on the contact.

Accuracy (tests/test_halfspace.py, against Hertz): with ~25 cells across the contact radius the peak pressure is
within 1% and the approach within 1%; the discretisation error falls as the grid is refined.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from contact.checks import check_number

__all__ = ["HalfspaceContact", "influence_coefficients", "halfspace_contact", "sphere_on_axisymmetric_surface"]


@dataclass(frozen=True)
class HalfspaceContact:
    """Solution of :func:`halfspace_contact`: ``pressure`` (Pa, cells), ``approach`` δ (m), ``gap`` (m, ≥ 0 up to
    the tolerance; 0 on the contact), ``in_contact`` (bool, cells), ``iterations``, ``spacing`` (m)."""

    pressure: np.ndarray
    approach: float
    gap: np.ndarray
    in_contact: np.ndarray
    iterations: int
    spacing: float

    @property
    def max_pressure(self) -> float:
        """Largest cell pressure (Pa)."""
        return float(self.pressure.max())

    @property
    def contact_area(self) -> float:
        """Area of the cells in contact (m²)."""
        return float(np.count_nonzero(self.in_contact)) * self.spacing**2


def influence_coefficients(shape: tuple[int, int], spacing: float, effective_modulus: float) -> np.ndarray:
    r"""Normal surface displacement (m per Pa) at cell centres ``(i, j)`` offsets ``−(n−1) … n−1`` from a unit
    pressure on a square cell of side ``spacing`` (m) at the origin (Love 1929; Johnson 1985, §3.2):

    .. math::

        K(x, y) = \frac{1}{\pi E^*} \big[ f(x + c, y + c) - f(x + c, y - c) - f(x - c, y + c) + f(x - c, y - c) \big],
        \quad f(s, t) = s \ln\!\big(t + \sqrt{s^2 + t^2}\big) + t \ln\!\big(s + \sqrt{s^2 + t^2}\big)

    with c = spacing / 2. Returned on the ``(2 n_y, 2 n_x)`` wrap-around grid that the zero-padded FFT needs."""
    ny, nx = shape
    half = 0.5 * spacing
    iy = np.r_[np.arange(ny), 0, np.arange(-ny + 1, 0)]
    ix = np.r_[np.arange(nx), 0, np.arange(-nx + 1, 0)]
    y = (iy * spacing)[:, None]
    x = (ix * spacing)[None, :]

    def f(s, t):
        rho = np.sqrt(s * s + t * t)
        # s ln(t + ρ) → 0 as s → 0 even where t + ρ → 0: evaluate with a guard instead of log(0)
        with np.errstate(divide="ignore", invalid="ignore"):
            a = np.where(s == 0.0, 0.0, s * np.log(np.where(t + rho > 0.0, t + rho, 1.0)))
            b = np.where(t == 0.0, 0.0, t * np.log(np.where(s + rho > 0.0, s + rho, 1.0)))
        return a + b

    k = f(x + half, y + half) - f(x + half, y - half) - f(x - half, y + half) + f(x - half, y - half)
    k = k / (math.pi * effective_modulus)
    k[ny, :] = 0.0  # the padding row and column carry no cell
    k[:, nx] = 0.0
    return k


def halfspace_contact(
    gap: np.ndarray,
    spacing: float,
    force: float,
    effective_modulus: float,
    tolerance: float = 1e-8,
    max_iterations: int = 2000,
) -> HalfspaceContact:
    r"""Pressure of a rigid indenter pressed with ``force`` (N) on an elastic half-space (effective modulus
    ``effective_modulus``, Pa) across the initial ``gap`` (m, 2-D, cells of side ``spacing`` m; its minimum is
    where contact starts). Polonsky & Keer (1999) conjugate gradients at fixed force; converged when the relative
    change of the pressure (ℓ¹, over the force) is below ``tolerance``. The grid must hold the whole contact:
    a contact touching the grid's edge raises ValueError.

    Examples
    --------
    A sphere of radius 2.5 mm pressed with 200 N, 12 cells across Hertz's contact radius a (Johnson 1985, §4.2):
    the approach within 1 % of Hertz's δ = a²/R and the force carried exactly.

    >>> import numpy as np
    >>> from contact.theory import hertz_contact_radius_from_force, hertz_overlap
    >>> radius, force, e_star = 2.5e-3, 200.0, 1.5e11
    >>> a = hertz_contact_radius_from_force(force, radius, e_star)
    >>> x = (np.arange(48) - 23.5) * (4.0 * a / 48)
    >>> xx, yy = np.meshgrid(x, x)
    >>> sol = halfspace_contact((xx**2 + yy**2) / (2.0 * radius), 4.0 * a / 48, force, e_star)
    >>> bool(abs(sol.approach / hertz_overlap(force, radius, e_star) - 1) < 0.01)
    True
    >>> round(float(sol.pressure.sum() * sol.spacing**2), 6)  # N
    200.0
    """
    gap = np.asarray(gap, dtype=float)
    if gap.ndim != 2 or min(gap.shape) < 4 or not np.all(np.isfinite(gap)):
        raise ValueError(f"gap: a 2-D finite array of at least 4 x 4 cells (m) is needed, got shape {gap.shape}")
    check_number("spacing", spacing, low=0.0, low_open=True, high=1.0, units="m")
    check_number("force", force, low=0.0, low_open=True, high=1e9, units="N")
    check_number("effective_modulus", effective_modulus, low=1e5, high=1e13, units="Pa")
    ny, nx = gap.shape
    area = spacing * spacing
    kernel = np.fft.rfft2(influence_coefficients(gap.shape, spacing, effective_modulus))

    def displacement(p: np.ndarray) -> np.ndarray:
        padded = np.zeros((2 * ny, 2 * nx))
        padded[:ny, :nx] = p
        return np.fft.irfft2(np.fft.rfft2(padded) * kernel, s=padded.shape)[:ny, :nx]

    h = gap - gap.min()
    # start on the cells within a tenth of the gap's range of first contact, uniform pressure
    p = np.where(h <= 0.1 * (h.max() + 1e-300), 1.0, 0.0)
    p *= force / (area * p.sum())
    direction = np.zeros_like(p)
    previous_norm = 1.0
    restart = True
    change = math.inf
    iterations = 0
    while iterations < max_iterations:
        iterations += 1
        contact = p > 0.0
        g = h + displacement(p)
        g -= g[contact].mean()
        norm = float(np.sum(g[contact] ** 2))
        direction = np.where(contact, g + (0.0 if restart else norm / previous_norm) * direction, 0.0)
        previous_norm = norm
        r = displacement(direction)
        r -= r[contact].mean()
        denominator = float(np.sum(r[contact] * direction[contact]))
        step = float(np.sum(g[contact] * direction[contact])) / denominator if denominator > 0.0 else 0.0
        old = p.copy()
        p = np.where(contact, p - step * direction, 0.0)
        p[p < 0.0] = 0.0
        entering = (~contact) & (g < 0.0)
        restart = bool(entering.any())
        p[entering] -= step * g[entering]
        p *= force / (area * p.sum())
        change = float(np.abs(p - old).sum()) * area / force
        if change < tolerance:
            break
    if change >= tolerance:
        raise ValueError(
            f"halfspace_contact did not converge in max_iterations={max_iterations} (change {change:.2e} > "
            f"tolerance {tolerance:.1e})"
        )
    in_contact = p > 0.0
    if in_contact[0, :].any() or in_contact[-1, :].any() or in_contact[:, 0].any() or in_contact[:, -1].any():
        raise ValueError("gap: the contact reaches the edge of the grid: widen the grid (or press less)")
    u = displacement(p)
    approach = float(np.mean((h + u)[in_contact]))
    return HalfspaceContact(
        p, approach + float(gap.min()), np.maximum(h + u - approach, 0.0), in_contact, iterations, spacing
    )


def sphere_on_axisymmetric_surface(
    radius: float, depth, force: float, effective_modulus: float, half_width: float, cells: int = 128
) -> tuple[HalfspaceContact, np.ndarray]:
    r"""A sphere of radius ``radius`` R (m) pressed with ``force`` W (N) onto a half-space (effective modulus E*, Pa)
    whose unloaded surface lies ``depth``\ (ρ) (m, a callable, positive below the original plane: a dent or a worn
    pit) below the plane, about the sphere's axis: :func:`halfspace_contact` on ``cells``² cells over
    ±``half_width`` (m) with the gap h(ρ) = R − √(R² − ρ²) + depth(ρ) (exact sphere). Returns the solution and ρ (m)
    of each cell (for radial profiles)."""
    radius = check_number("radius", radius, low=0.0, low_open=True, units="m", what="sphere radius")
    half_width = check_number(
        "half_width", half_width, low=0.0, low_open=True, high=radius, units="m", what="half-width of the grid"
    )
    cells = int(check_number("cells", cells, low=8, high=4096, what="cells along each side"))
    spacing = 2.0 * half_width / cells
    x = (np.arange(cells) - (cells - 1) / 2) * spacing
    rho = np.hypot(*np.meshgrid(x, x))
    gap = radius - np.sqrt(radius * radius - rho * rho) + np.asarray(depth(rho), float)
    return halfspace_contact(gap, spacing, force, effective_modulus), rho
