"""Figures of an FE indentation (``impactwear indent``): pressure profiles against Hertz (errata Eq. 16) and
Mesarovic–Johnson (Eq. 19), the force–overlap loop, and the plastic zone. SI units on every axis (shown in
µm, N, MPa)."""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from contact.theory import hertz_pressure, mesarovic_johnson_pressure
from wear.app.figures.common import plt, save_figure

__all__ = ["pressure_figure", "force_overlap_figure", "plastic_zone_figure", "write_figures"]


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
    """Pressure p(r) at chosen loading steps (FE vs Hertz Eq. 16 at the FE's F) and unloading steps (FE vs
    Mesarovic–Johnson Eq. 19 from the FE's p*, a* at the maximum)."""
    loading, unloading = _pick_steps(res)
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    r = res.surface_r
    e_star, radius = res.effective_modulus, res.radius
    for k in loading:
        a = res.contact_radius[k]
        (line,) = axes[0].plot(r * 1e6, res.pressure[k] / 1e6, label=f"FE δ={res.overlap[k] * 1e6:.3g} µm")
        a_h = (3.0 * res.force[k] * radius / (4.0 * e_star)) ** (1.0 / 3.0)
        p0 = 3.0 * res.force[k] / (2.0 * math.pi * a_h**2)
        axes[0].plot(r * 1e6, hertz_pressure(r, a_h, p0) / 1e6, "--", color=line.get_color(), lw=1)
        axes[0].axvline(a * 1e6, color=line.get_color(), lw=0.5, ls=":")
    axes[0].set_title("loading: FE (solid) vs Hertz Eq. 16 at the same F (dashed)", fontsize=9)
    peak = int(np.argmax(res.overlap))
    a_star, p_star = res.contact_radius[peak], res.mean_pressure[peak]
    axes[1].plot(r * 1e6, res.pressure[peak] / 1e6, color="k", label="FE at δ_max")
    for k in unloading:
        (line,) = axes[1].plot(r * 1e6, res.pressure[k] / 1e6, label=f"FE a/a*={res.contact_radius[k] / a_star:.2f}")
        ref = mesarovic_johnson_pressure(r, res.contact_radius[k], a_star, p_star)
        axes[1].plot(r * 1e6, ref / 1e6, "--", color=line.get_color(), lw=1)
    axes[1].set_title("unloading: FE (solid) vs Mesarovic–Johnson Eq. 19 (dashed)", fontsize=9)
    xmax = 1.4 * max(res.contact_radius.max(), 1e-300) * 1e6
    for ax in axes:
        ax.set_xlim(0, xmax)
        ax.set_xlabel("r (µm)")
        ax.legend(fontsize=7)
    axes[0].set_ylabel("contact pressure (MPa)")
    return fig


def force_overlap_figure(res):
    """F–δ loading and unloading (FE) with the Hertz curve (errata Eq. 4) and the FE first yield."""
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
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


def plastic_zone_figure(res):
    """Equivalent plastic strain under the contact at the last step (quadrature points, r–z in µm)."""
    run = res._run
    disc = run.solver.disc
    alpha = run.final.alpha
    a = max(res.contact_radius.max(), 1e-300)
    box = (disc.qp_r < 2.5 * a) & (disc.qp_z > -2.5 * a)
    fig, ax = plt.subplots(figsize=(5.5, 4.5))
    sc = ax.scatter(
        disc.qp_r[box] * 1e6, disc.qp_z[box] * 1e6, c=alpha[box], s=3, cmap="viridis", vmin=0.0, vmax=alpha.max() or 1
    )
    plastic = box & (alpha > 0.0)
    if plastic.any():
        ax.tricontour(disc.qp_r[box] * 1e6, disc.qp_z[box] * 1e6, (alpha[box] > 0).astype(float), levels=[0.5],
                      colors="r", linewidths=1)  # fmt: skip
    ax.axvline(a * 1e6, color="k", ls=":", lw=0.8)
    fig.colorbar(sc, ax=ax, label="equivalent plastic strain (after the last step)")
    ax.set_xlabel("r (µm)")
    ax.set_ylabel("z (µm)")
    ax.set_aspect("equal")
    ax.set_title("plastic zone (red: elastic–plastic boundary; dotted: max contact radius)", fontsize=8)
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
