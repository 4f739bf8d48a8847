"""Figures of one ``impactwear run`` (matplotlib, Agg; SI quantities shown in µm, µs, MPa, N).

Each function takes a :class:`wear.RunResult` (or arrays) and a PNG path, and returns the path.
:func:`restitution_comparison` is the e_n vs V/V_y figure (coupled FE vs Thornton 1997) that the
validation report reuses.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np
from matplotlib.ticker import MaxNLocator
from matplotlib.tri import CubicTriInterpolator, Triangulation, UniformTriRefiner

from contact.theory import hertz_pressure, mesarovic_johnson_pressure, thornton_restitution
from wear.app.figures.common import place_legends, plain_log_ticks, save_figure, subplots
from wear.app.figures.field import cell_field_on_nodes, refine_grid

__all__ = [
    "force_overlap",
    "pressure_profiles",
    "wear_map",
    "cross_sections",
    "plastic_zone",
    "restitution_comparison",
    "write_run_figures",
]


def force_overlap(result, path) -> Path:
    """Normal force and overlap against time, and force against overlap."""
    h = result.impact.history
    fig, (ax1, ax3) = subplots(1, 2, figsize=(10, 4))
    ax1.plot(h.t * 1e6, h.normal_force, "C0", label="normal force")
    ax1.plot(h.t * 1e6, np.abs(h.tangential_force), "C0--", label="|tangential force|")
    ax1.set_xlabel("time (µs)")
    ax1.set_ylabel("force (N)")
    ax2 = ax1.twinx()
    ax2.plot(h.t * 1e6, h.overlap * 1e6, "C1", label="overlap")
    ax2.set_ylabel("overlap (µm)", color="C1")
    ax1.legend(loc="upper right", fontsize=8)
    ax1.set_title(f"impact ({result.impact.normal_model} normal law)")
    ax3.plot(h.overlap * 1e6, h.normal_force, "C0", label="impact")
    for (overlap, force, label), (style, size) in zip(
        result.plate.force_steps(), (("k.", 3), ("C3x", 4)), strict=False
    ):
        ax3.plot(overlap * 1e6, force, style, ms=size, label=label)
    ax3.set_xlabel("overlap (µm)")
    ax3.set_ylabel("normal force (N)")
    ax3.legend(fontsize=8)
    fig.tight_layout()
    return save_figure(fig, path)


def pressure_profiles(result, path, stages: int = 6) -> Path:
    """p(r) at several times along the impact against Hertz (equation 16) and, after the maximum, against the
    Mesarovic–Johnson unloading profile (equation 19) built from the pressure at the maximum (p*, a*)."""
    ph = result.pressure
    force = ph.force()
    i_max = int(np.argmax(force))
    loaded = np.flatnonzero(ph.extent > 0)
    picks = np.unique(
        np.concatenate(
            [
                np.linspace(loaded[0], i_max, stages // 2 + 1).astype(int)[1:],
                np.linspace(i_max, loaded[-1], stages // 2 + 1).astype(int)[1:-1],
            ]
        )
    )
    fig, ax = subplots(figsize=(9, 4.5))
    h = result.impact.history
    # the contact radius of the impact at each pressure sample (the table's extent is the first node beyond it)
    radius = np.interp(ph.time, h.t, h.contact_radius)
    a_star = radius[i_max]
    p_star = force[i_max] / (math.pi * a_star**2) if a_star > 0 else 0.0
    plastic = result.case.plate.yield_strength is not None and result.regime != "elastic"
    for n, i in enumerate(picks):
        a = radius[i]
        r = np.linspace(0.0, 1.1 * max(ph.extent[i], a, 1e-12), 200)
        colour = f"C{n % 10}"
        t_us = ph.time[i] * 1e6
        ax.plot(r * 1e6, ph.at(i, r) / 1e6, colour, label=f"{ph.source}, t = {t_us:.2f} µs")
        p0 = 3.0 * force[i] / (2.0 * math.pi * a * a) if a > 0 else 0.0
        ax.plot(r * 1e6, hertz_pressure(r, a, p0) / 1e6, colour, ls=":", lw=1)
        if plastic and i > i_max and a < a_star:
            ax.plot(r * 1e6, mesarovic_johnson_pressure(r, a, a_star, p_star) / 1e6, colour, ls="--", lw=1)
    ax.plot([], [], "k:", lw=1, label="Hertz, Eq. 16 (same F, impact's a)")
    if plastic:
        ax.plot([], [], "k--", lw=1, label="Mesarovic–Johnson, Eq. 19 (unloading from p* = F*/πa*²)")
    ax.set_xlabel("r (µm)")
    ax.set_ylabel("contact pressure (MPa)")
    place_legends(fig, [ax], fontsize=7)
    return save_figure(fig, path)


def wear_map(result, path, levels: int = 24) -> Path:
    """Wear depth map over the plate (x along the impact, y across) as filled contours on ``levels`` bands of a
    bicubic resampling of the wear grid (four times finer), not as the grid's cells."""
    wm = result.wear
    x, y, depth = refine_grid(wm.x, wm.y, wm.depth)
    top = max(float(depth.max()), 1e-300)
    fig, ax = subplots(figsize=(7, 5))
    art = ax.contourf(x * 1e6, y * 1e6, depth * 1e9, levels=np.linspace(0.0, top * 1e9, levels + 1), cmap="viridis")
    fig.colorbar(art, ax=ax, label="wear depth (nm)", ticks=MaxNLocator(nbins=6))
    ax.set_aspect("equal")
    ax.set_xlabel("x along the impact (µm)")
    ax.set_ylabel("y (µm)")
    ax.set_title(f"worn volume {wm.volume_m3:.3g} m³, max depth {wm.max_depth_m * 1e9:.3g} nm")
    fig.tight_layout()
    return save_figure(fig, path)


def cross_sections(result, path) -> Path:
    """Dent + wear depth along y = 0 and across x = dent centre (surface z = −(dent + wear)); on the 3-D plate also
    the axisymmetric plate's dent it started from, centred at the same point."""
    s = result.surface
    axisymmetric = None
    start = result.plate.fields.get("start_dent")
    if start is not None:
        r_fe, h_fe = start

        def axisymmetric(offset):
            return np.interp(np.abs(offset), r_fe, h_fe, right=0.0)

    dent = s.dent_on_grid()
    wear = s.wear_depth
    j0 = int(np.argmin(np.abs(s.y)))
    i0 = int(np.argmin(np.abs(s.x - s.dent_centre[0])))
    fig, axes = subplots(1, 2, figsize=(10, 4))
    panels = []
    for ax, coord, d, w, label in (
        (axes[0], s.x, dent[:, j0], wear[:, j0], "x along the impact (µm), y = 0"),
        (axes[1], s.y, dent[i0, :], wear[i0, :], "y across (µm), x = dent centre"),
    ):
        ax.plot(coord * 1e6, -d * 1e6, "C0", label="dent only" if axisymmetric is None else "dent only (3-D plate)")
        ax.plot(coord * 1e6, -(d + w) * 1e6, "C3--", label="dent + wear")
        if axisymmetric is not None:
            centre = s.dent_centre[0] if coord is s.x else s.dent_centre[1]
            ax.plot(coord * 1e6, -axisymmetric(coord - centre) * 1e6, "k:", lw=1, label="dent, axisymmetric plate")
        ax.set_xlabel(label)
        ax.set_ylabel("surface z (µm)")
        ax2 = ax.twinx()
        ax2.plot(coord * 1e6, w * 1e9, "C2", lw=1, label="wear depth (right axis)")
        ax2.set_ylabel("wear depth (nm)", color="C2")
        panels.append((ax, ax2))
    place_legends(fig, panels, fontsize=8)
    return save_figure(fig, path)


def restitution_comparison(speed_ratio, coupled_restitution, path, thornton=None) -> Path:
    """Normal restitution vs V/V_y: the coupled FE impact beside Thornton (1997) (for the validation report).

    ``speed_ratio``: V_n/V_y; ``coupled_restitution``: e_n of the coupled runs; ``thornton``: Thornton's e at
    the same ratios (default :func:`contact.theory.thornton_restitution`). The lower panel shows the difference.
    """
    x = np.asarray(speed_ratio, float)
    e = np.asarray(coupled_restitution, float)
    fine = np.geomspace(max(x.min(), 1.0), max(x.max(), 1.01), 200)
    ref = thornton_restitution(x) if thornton is None else np.asarray(thornton, float)
    fig, (ax, axd) = subplots(2, 1, figsize=(6.5, 6), sharex=True, gridspec_kw={"height_ratios": [3, 1]})
    ax.semilogx(fine, thornton_restitution(fine), "k-", label="Thornton 1997 (closed form)")
    ax.semilogx(x, e, "o", color="C3", label="coupled FE impact (two-way)")
    ax.set_ylabel("normal restitution e_n")
    ax.legend()
    axd.semilogx(x, (e - ref) / ref * 100.0, "o-", color="C3")
    axd.axhline(0.0, color="k", lw=0.5)
    axd.set_xlabel("V_n / V_y")
    axd.set_ylabel("FE − Thornton (%)")
    # the axes share x; under a decade matplotlib would label every minor tick (1.6×10⁰, 1.7×10⁰, ... on top of
    # each other): the ratios themselves then, else 1, 2, 5 × 10ⁿ (ratios close on a wide axis would collide)
    plain_log_ticks(axd.xaxis, x, few=8 if np.log10(x.max() / x.min()) < 1.0 else 0)
    fig.tight_layout()
    return save_figure(fig, path)


def plastic_zone(result, path, reach: float = 3.0) -> Path:
    """The 3-D plate's equivalent plastic strain on the plane of incidence y = 0, x along the impact against depth,
    after the impact (reference configuration): filled contours over the triangles the elements' faces tile the
    plane with (so the field fills the section up to the surface z = 0, where the strain is largest), within
    ``reach`` × the largest contact radius of the dent centre; the elastic–plastic boundary as a line."""
    points, triangles, strain, a = result.plate.fields["plastic_section"]
    nodal = cell_field_on_nodes(points, triangles, strain)
    plastic = cell_field_on_nodes(points, triangles, (strain > 0.0).astype(float))
    x0 = result.surface.dent_centre[0]
    lo, hi = points.min(axis=0), points.max(axis=0)
    x_lim = (max(x0 - reach * a, lo[0]), min(x0 + reach * a, hi[0]))
    z_lim = (max(-reach * a, lo[1]), hi[1])
    # only the triangles that reach into the view: the plate extends far beyond the contact
    corners = points[triangles]
    near = (
        (corners[..., 0].max(axis=1) >= x_lim[0])
        & (corners[..., 0].min(axis=1) <= x_lim[1])
        & (corners[..., 1].max(axis=1) >= z_lim[0])
    )
    used, local = np.unique(triangles[near], return_inverse=True)
    tri = Triangulation(points[used, 0] * 1e6, points[used, 1] * 1e6, local.reshape(-1, 3))
    # a cubic on each triangle ("geom" slopes: local and fast) smooths the kinks of the linear field on elements
    # tens of µm across; clipped to the nodal range, as the cubic overshoots next to a kink
    refiner = UniformTriRefiner(tri)
    fine, fine_strain = refiner.refine_field(nodal[used], CubicTriInterpolator(tri, nodal[used], kind="geom"), 2)
    top = float(strain.max()) * 100.0
    levels = MaxNLocator(nbins=10).tick_values(0.0, top) if top > 0 else np.array([0.0, 1.0])
    fig, ax = subplots(figsize=(8, 4))
    shown = np.clip(fine_strain, 0.0, nodal[used].max()) * 100.0
    art = ax.tricontourf(fine, shown, levels=levels, cmap="viridis")
    fig.colorbar(art, ax=ax, label="equivalent plastic strain (%)")
    if plastic[used].min() < 0.5 < plastic[used].max():
        # half-way between elements that yielded and elements that did not
        cubic = CubicTriInterpolator(tri, plastic[used], kind="geom")
        fine, fine_plastic = refiner.refine_field(plastic[used], cubic, 2)
        ax.tricontour(fine, fine_plastic, levels=[0.5], colors="r", linewidths=1.2)
        ax.plot([], [], "r", lw=1.2, label="elastic–plastic boundary")
        ax.legend(loc="lower right", fontsize=8, framealpha=0.9)
    ax.set_xlim(x_lim[0] * 1e6, x_lim[1] * 1e6)
    ax.set_ylim(z_lim[0] * 1e6, z_lim[1] * 1e6)
    ax.set_aspect("equal")
    ax.set_xlabel("x along the impact (µm), plane of incidence y = 0")
    ax.set_ylabel("z (µm), surface at 0")
    ax.set_title(f"plastic zone of the 3-D plate (μ = {result.case.impact.friction:g}, reference configuration)")
    fig.tight_layout()
    return save_figure(fig, path)


def write_run_figures(result, folder: str | os.PathLike) -> list[Path]:
    """All run figures into ``folder``; returns their paths."""
    folder = Path(folder)
    paths = [
        force_overlap(result, folder / "force_overlap.png"),
        pressure_profiles(result, folder / "pressure_profiles.png"),
        wear_map(result, folder / "wear_map.png"),
        cross_sections(result, folder / "cross_sections.png"),
    ]
    if "plastic_section" in result.plate.fields:
        paths.append(plastic_zone(result, folder / "plastic_zone.png"))
    return paths
