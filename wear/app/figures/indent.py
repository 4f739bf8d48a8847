"""Figures of an FE indentation (``impactwear indent``): pressure profiles against Hertz (errata equation 16) and
Mesarovic–Johnson (equation 19), the force–overlap loop, and the plastic zone. SI units on every axis (shown in
µm, N, MPa)."""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np
from matplotlib.lines import Line2D

from contact.theory import hertz_pressure, mesarovic_johnson_pressure
from wear.app.figures.common import save_figure, subplots
from wear.app.figures.field import quadrature_field_on_mesh

__all__ = ["pressure_figure", "force_overlap_figure", "plastic_zone_axes", "plastic_zone_figure", "write_figures"]


def _pick_steps(res, count: int = 4) -> tuple[list[int], list[int]]:
    peak = int(np.argmax(res.overlap))
    loading = np.unique(np.linspace(0, peak, count + 1).round().astype(int)[1:])
    unloading = [
        peak + int(np.argmin(np.abs(res.contact_radius[peak:] / max(res.contact_radius[peak], 1e-300) - x)))
        for x in (0.75, 0.5)
        if peak < res.overlap.size - 1
    ]
    return list(loading), sorted(set(unloading) - {peak})


def pressure_figure(res):
    """Pressure p(r) at chosen loading steps (FE vs Hertz equation 16 at the FE's F, the FE contact radius dotted)
    and unloading steps (FE vs Mesarovic–Johnson equation 19 from the FE's p*, a* at the maximum).

    A colour is one step; the line style says what is drawn, and each style has its own legend entry (grey), so
    every line is named by the legend."""
    loading, unloading = _pick_steps(res)
    fig, axes = subplots(1, 2, figsize=(11, 4.2), sharey=True)
    r = res.surface_r
    e_star, radius = res.effective_modulus, res.radius
    for k in loading:
        a = res.contact_radius[k]
        (line,) = axes[0].plot(r * 1e6, res.pressure[k] / 1e6, label=f"FE, δ = {res.overlap[k] * 1e6:.3g} µm")
        a_h = (3.0 * res.force[k] * radius / (4.0 * e_star)) ** (1.0 / 3.0)
        p0 = 3.0 * res.force[k] / (2.0 * math.pi * a_h**2)
        axes[0].plot(r * 1e6, hertz_pressure(r, a_h, p0) / 1e6, "--", color=line.get_color(), lw=1)
        axes[0].axvline(a * 1e6, color=line.get_color(), lw=0.8, ls=":")
    key = {"color": "0.4", "lw": 1}
    loading_keys = [
        Line2D([], [], ls="--", label="Hertz Eq. 16 at the same F", **key),
        Line2D([], [], ls=":", label="FE contact radius a", **key),
    ]
    axes[0].set_title(
        "loading: FE (solid) vs Hertz Eq. 16 at the same F (dashed);\ndotted: the FE contact radius a of each step",
        fontsize=9,
    )
    peak = int(np.argmax(res.overlap))
    a_star, p_star = res.contact_radius[peak], res.mean_pressure[peak]
    axes[1].plot(r * 1e6, res.pressure[peak] / 1e6, color="k", label="FE at δ_max")
    for k in unloading:
        (line,) = axes[1].plot(r * 1e6, res.pressure[k] / 1e6, label=f"FE, a/a* = {res.contact_radius[k] / a_star:.2f}")
        ref = mesarovic_johnson_pressure(r, res.contact_radius[k], a_star, p_star)
        axes[1].plot(r * 1e6, ref / 1e6, "--", color=line.get_color(), lw=1)
    unloading_keys = [Line2D([], [], ls="--", label="Mesarovic–Johnson Eq. 19 (p*, a* at δ_max)", **key)]
    axes[1].set_title(
        "unloading: FE (solid) vs Mesarovic–Johnson Eq. 19 (dashed)\nfrom the FE's p*, a* at δ_max", fontsize=9
    )
    xmax = 1.4 * max(res.contact_radius.max(), 1e-300) * 1e6
    for ax, keys in ((axes[0], loading_keys), (axes[1], unloading_keys)):
        ax.set_xlim(0, xmax)
        ax.set_xlabel("r (µm)")
        handles = [line for line in ax.get_lines() if not line.get_label().startswith("_")]
        ax.legend(handles=handles + keys, fontsize=7)
    axes[0].set_ylabel("contact pressure (MPa)")
    return fig


def force_overlap_figure(res):
    """F–δ loading and unloading (FE) with the Hertz curve (errata equation 4) and the FE first yield."""
    fig, ax = subplots(figsize=(5.5, 4.2))
    d = np.r_[0.0, res.overlap]
    ax.plot(d * 1e6, np.r_[0.0, res.force], "o-", ms=2.5, label="FE")
    dd = np.linspace(0, res.overlap.max(), 200)
    ax.plot(dd * 1e6, 4.0 / 3.0 * res.effective_modulus * math.sqrt(res.radius) * dd**1.5, "--", label="Hertz Eq. 4")
    if res.first_yield is not None:
        ax.plot(res.first_yield.overlap * 1e6, res.first_yield.force, "k*", ms=9, label="FE first yield")
    ax.set_ylim(0, 1.1 * res.force.max())
    ax.set_xlabel("overlap δ (µm)")
    ax.set_ylabel("normal force F (N)")
    ax.legend()
    return fig


def plastic_zone_axes(
    ax,
    points: np.ndarray,
    triangles: np.ndarray,
    qp_r: np.ndarray,
    qp_z: np.ndarray,
    alpha: np.ndarray,
    contact_radius: float,
    reach: float = 2.5,
):
    """Draw the equivalent plastic strain ᾱ (quadrature values (elements, qp) on the FE mesh ``points`` (n, 2)
    (r, z) m, ``triangles`` (elements, 3)) into ``ax`` as filled contours in %, with the elastic–plastic
    boundary as a line and the contact radius ``contact_radius`` (m) dotted; r and z in µm over ``reach`` × a.

    Returns the filled contour set (for the colour bar)."""
    from matplotlib.ticker import MaxNLocator
    from matplotlib.tri import CubicTriInterpolator, Triangulation, UniformTriRefiner

    alpha = np.asarray(alpha, dtype=float)
    # the yield indicator: the return mapping leaves exactly 0 where a point never yielded
    plastic = (alpha > 0.0).astype(float)
    fine_points, fine_triangles, (alpha_n, plastic_n) = quadrature_field_on_mesh(
        points, triangles, qp_r, qp_z, alpha, plastic
    )
    a = max(float(contact_radius), 1e-300)
    # only the triangles in view: the mesh reaches far beyond the contact, and refining it all costs seconds
    corners = fine_points[fine_triangles]
    near = ((corners[..., 0] <= 1.05 * reach * a) & (corners[..., 1] >= -1.05 * reach * a)).any(axis=1)
    used, local = np.unique(fine_triangles[near], return_inverse=True)
    tri = Triangulation(fine_points[used, 0] * 1e6, fine_points[used, 1] * 1e6, local.reshape(-1, 3))
    alpha_n, plastic_n = alpha_n[used], plastic_n[used]
    top = float(alpha.max())
    levels = MaxNLocator(nbins=10).tick_values(0.0, top * 100.0) if top > 0 else np.array([0.0, 1.0])
    filled = ax.tricontourf(tri, alpha_n * 100.0, levels=levels, cmap="viridis")
    handles = []
    if plastic_n.min() < 0.5 < plastic_n.max():
        # the line is half-way between plastic and elastic quadrature points, not at a tiny ᾱ (the projection
        # smears ᾱ over one triangle and would push such a line outward by that much); the cubic refinement
        # smooths the kinks a piecewise-linear contour has on the coarser elements at depth ("geom" slopes: local,
        # ten times faster than the default global "min_E" fit, and as smooth to the eye)
        cubic = CubicTriInterpolator(tri, plastic_n, kind="geom")
        smooth, smooth_plastic = UniformTriRefiner(tri).refine_field(plastic_n, triinterpolator=cubic, subdiv=2)
        ax.tricontour(smooth, smooth_plastic, levels=[0.5], colors="r", linewidths=1.2)
        handles.append(Line2D([], [], color="r", lw=1.2, label="elastic–plastic boundary"))
    # orange shows on both ends of viridis (and in the white legend)
    ax.axvline(a * 1e6, color="tab:orange", ls=":", lw=1.2)
    handles.append(Line2D([], [], color="tab:orange", ls=":", lw=1.2, label=f"max contact radius a = {a * 1e6:.3g} µm"))
    ax.set_xlim(0.0, reach * a * 1e6)
    ax.set_ylim(-reach * a * 1e6, 0.0)
    ax.set_aspect("equal")
    ax.set_xlabel("radius r (µm)")
    ax.set_ylabel("depth z (µm)")
    ax.legend(handles=handles, loc="lower right", fontsize=8, framealpha=0.9)
    return filled


def plastic_zone_figure(res):
    """Equivalent plastic strain under the contact after the last step, on the FE mesh (r–z in µm)."""
    run = res.run
    disc = run.solver.disc
    fig, ax = subplots(figsize=(6.0, 4.8))
    filled = plastic_zone_axes(
        ax, disc.mesh.p.T, disc.mesh.t.T, disc.qp_r, disc.qp_z, run.final.alpha, res.contact_radius.max()
    )
    fig.colorbar(filled, ax=ax, label="equivalent plastic strain ᾱ (%)")
    ax.set_title("plastic zone after the last step (reference configuration)", fontsize=9)
    return fig


def write_figures(res, out: str | os.PathLike) -> list[Path]:
    """Write pressure.png, force_overlap.png and plastic_zone.png into ``out`` (atomically)."""
    out = Path(out)
    paths = []
    for name, make in (
        ("pressure.png", pressure_figure),
        ("force_overlap.png", force_overlap_figure),
        ("plastic_zone.png", plastic_zone_figure),
    ):
        fig = make(res)
        paths.append(save_figure(fig, out / name, bbox_inches="tight"))
    return paths
