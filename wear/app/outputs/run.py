"""The output folder of ``impactwear run`` (:func:`wear.run`), written atomically by the one writer.

Files: ``summary.json`` (case, versions, results, stage times, notes), ``history.csv`` (impact histories, units in
the column names), ``pressure.npz`` (the wear stage's p(s, t) table, and the FE table p(r, t) if any),
``surface.vtu``, ``plate.vtu``, ``plate_fe.vtu`` (with an FE plate: the (r, z) section, or the whole 3-D plate with
``fem.model = "3d"``; field names with units, :mod:`wear.app.outputs.fields`), the PNG figures and ``surface_3d.png``.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable, Sequence
from pathlib import Path

import meshio
import numpy as np

from contact import History
from wear.app.figures.run import write_run_figures
from wear.app.outputs.folder import output_folder
from wear.app.outputs.render import render_surface, rendering_available
from wear.app.outputs.writer import versions, write_csv, write_mesh, write_npz, write_summary
from wear.chain.single import RunResult
from wear.surface import deform_plate_mesh, plate_block_mesh, surface_mesh

__all__ = ["write_run", "history_columns", "ENTRIES", "HISTORY_COLUMNS", "PRESSURE_ABOUT"]

#: What ``impactwear run`` may write in its folder (checked against the folder before any work).
ENTRIES = (
    "summary.json",
    "history.csv",
    "pressure.npz",
    "surface.vtu",
    "plate.vtu",
    "plate_fe.vtu",
    "force_overlap.png",
    "pressure_profiles.png",
    "wear_map.png",
    "cross_sections.png",
    "plastic_zone.png",
    "surface_3d.png",
)

#: What pressure.npz holds (stored in it as ``about``).
PRESSURE_ABOUT = (
    "p(r, t): pressure_Pa[i, k] (Pa) at time_s[i] (s) and radius r_m[i, k] (m) from the contact centre, which is at "
    "contact_x_m[i] (m) along the impact direction; the pressure is 0 beyond extent_m[i] (m); s[k] is the sample "
    "coordinate (r = extent * sqrt(1 - s^2)); source names the pressure model. With the FE plate also fe_time_s, "
    "fe_surface_r_m and fe_pressure_Pa[i, j]: the FE plate's contact pressure at its surface nodes. With the 3-D "
    "plate (fem.model = '3d') the pressure above is its profile across the track, and fe3d_time_s[i], "
    "fe3d_surface_xy_m[j] (surface vertices of the half plate y >= 0), fe3d_pressure_Pa[i, j], fe3d_shear_Pa[i, j, 2] "
    "(traction on the plate, x and y: the ball's force on the vertex's share of the surface over that share's area, "
    "linear between the vertices, so that |shear| <= min(friction * pressure, shear strength) at a sliding vertex and "
    "the fields integrate to the plate's forces), fe3d_sticking[i, j] and fe3d_slip_m[i, j, 2] (the ball's slip over "
    "the vertex in the step ending at i, x and y) are its fields."
)

#: history.csv columns: :class:`contact.History` field → column name with units.
HISTORY_COLUMNS = {
    "t": "time_s",
    "overlap": "overlap_m",
    "normal_force": "normal_force_N",
    "tangential_force": "tangential_force_N",
    "tangential_displacement": "tangential_displacement_m",
    "contact_radius": "contact_radius_m",
    "peak_pressure": "peak_pressure_Pa",
    "slip_velocity": "slip_velocity_m_s",
    "sliding": "sliding",
    "center_x": "center_x_m",
    "contact_x": "contact_x_m",
    "omega": "spin_rad_s",
    "normal_velocity": "normal_velocity_m_s",
    "tangential_velocity": "tangential_velocity_m_s",
}


def history_columns(history: History) -> dict[str, np.ndarray]:
    """The impact's histories as history.csv columns (SI units in the names)."""
    return {label: np.asarray(getattr(history, attr), dtype=float) for attr, label in HISTORY_COLUMNS.items()}


def write_run(
    result: RunResult,
    out: str | os.PathLike,
    progress: Callable[[str], None] | None = None,
    notes: Sequence[str] = (),
) -> dict:
    """Write the whole output folder of ``result`` atomically; returns the summary. ``progress(step)`` is called
    at "meshes", "figures", "render"; ``notes`` (what the run said, e.g. its warnings) go into the summary with the
    writer's own."""
    notify = progress or (lambda step: None)
    case = result.case
    times = dict(result.stage_times)
    notes = list(notes)
    with output_folder(out, "run", ENTRIES) as tmp:
        notify("meshes")
        t0 = time.perf_counter()
        write_csv(tmp / "history.csv", history_columns(result.impact.history))
        ph = result.pressure
        radius = ph.extent[:, None] * np.sqrt(np.clip(1.0 - ph.s[None, :] ** 2, 0.0, None))
        arrays = {
            "time_s": ph.time,
            "contact_x_m": ph.contact_x,
            "extent_m": ph.extent,
            "pressure_Pa": ph.pressure,
            "r_m": radius,
            "s": ph.s,
            "source": np.array(ph.source),
            "about": np.array(PRESSURE_ABOUT),
        }
        arrays.update(result.plate.pressure_arrays())
        write_npz(tmp / "pressure.npz", arrays)
        surf_mesh = surface_mesh(result.surface)
        write_mesh(tmp / "surface.vtu", surf_mesh)
        if case.output.plate_mesh:
            try:
                user = meshio.read(case.output.plate_mesh)
            except Exception as exc:  # meshio raises many types for unreadable files
                raise ValueError(
                    f"output.plate_mesh={case.output.plate_mesh!r} cannot be read by meshio: {exc}"
                ) from None
            write_mesh(tmp / "plate.vtu", deform_plate_mesh(user, result.surface))
        else:
            write_mesh(tmp / "plate.vtu", plate_block_mesh(result.surface, case.output.block_thickness))
        for name, mesh in result.plate.meshes(case, result.pressure).items():
            write_mesh(tmp / f"{name}.vtu", mesh)
        times["meshes"] = time.perf_counter() - t0
        if case.output.figures:
            notify("figures")
            t0 = time.perf_counter()
            write_run_figures(result, tmp)
            times["figures"] = time.perf_counter() - t0
        if case.output.render:
            notify("render")
            t0 = time.perf_counter()
            ok, why = rendering_available()
            if ok:
                render_surface(surf_mesh, tmp / "surface_3d.png", title="dent + wear")
            else:
                notes.append(why)
            times["render"] = time.perf_counter() - t0
        summary = result.summary()
        summary["stage_times_s"] = times
        summary["versions"] = versions()
        summary["notes"] = list(dict.fromkeys(notes))
        summary["files"] = [*sorted(p.name for p in Path(tmp).iterdir()), "summary.json"]
        summary = write_summary(tmp / "summary.json", summary)
    return summary
