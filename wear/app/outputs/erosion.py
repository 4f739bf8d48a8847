"""The output folder of ``impactwear erode`` (:mod:`wear.erosion.run`), built aside and moved in whole
(:func:`wear.app.outputs.folder.output_folder`; SI units; angles in degrees from the plate normal):

- ``erosion.csv``: time_s, impacts, particle_mass_kg, mass_loss_kg, mass_loss_per_area_kg_m2,
  erosion_rate_kg_per_kg (cumulative), interval_erosion_rate_kg_per_kg (since the previous row), max_depth_m,
  rms_slope;
  ``erosion.png`` (mass loss and rates against time);
- ``surface.vtu`` (final surface: a structured quad grid, z = −depth, point data ``total_depth_m`` (wear and
  dents) and ``wear_depth_m``),
  ``frames/surface_NNNN.vtu`` and ``erosion.pvd`` (the series, time in s; open in ParaView); ``surface.png``;
- ``response_table.csv`` (the footprint table: normal speed, local angle, volumes, contact radius) and
  ``summary.json`` (case, number of impacts, patch, table resolution, results, timings).

Over several stream angles: one such folder per angle (``angle_<deg>/``, without the series) and
``erosion_vs_angle.csv`` (angle_deg, erosion_rate_kg_per_kg, mass_loss_kg) with ``erosion_vs_angle.png``.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

import meshio
import numpy as np

from wear.app.figures import erosion as fig
from wear.app.outputs.folder import output_folder
from wear.app.outputs.writer import write_mesh, write_pvd, write_rows, write_summary
from wear.erosion import ErosionRun

__all__ = [
    "write_erosion",
    "write_erosion_angles",
    "surface_grid_mesh",
    "ENTRIES",
    "EROSION_COLUMNS",
    "TABLE_COLUMNS",
]

#: What ``impactwear erode`` may write in its folder, with and without ``--angles`` (checked against the folder
#: before any work).
ENTRIES = (
    "erosion.csv",
    "response_table.csv",
    "surface.vtu",
    "frames",
    "erosion.pvd",
    "erosion.png",
    "surface.png",
    "summary.json",
    "angle_*",
    "erosion_vs_angle.csv",
    "erosion_vs_angle.png",
)

EROSION_COLUMNS = [
    "time_s",
    "impacts",
    "particle_mass_kg",
    "mass_loss_kg",
    "mass_loss_per_area_kg_m2",
    "erosion_rate_kg_per_kg",
    "interval_erosion_rate_kg_per_kg",
    "max_depth_m",
    "rms_slope",
]
TABLE_COLUMNS = [
    "normal_speed_m_s",
    "angle_deg",
    "volume_m3",
    "cutting_volume_m3",
    "deformation_volume_m3",
    "contact_radius_m",
]


def surface_grid_mesh(x: np.ndarray, y: np.ndarray, surface: np.ndarray, wear: np.ndarray | None = None) -> meshio.Mesh:
    """A height field (m, positive into the plate) as a structured quad grid: z = −depth, point data
    ``total_depth`` and (if given) ``wear_depth`` (m; written as ``total_depth_m``, ``wear_depth_m``)."""
    nx, ny = len(x), len(y)
    xx, yy = np.meshgrid(x, y)
    points = np.column_stack([xx.ravel(), yy.ravel(), -np.asarray(surface).ravel()])
    node = np.arange(nx * ny).reshape(ny, nx)
    quads = np.column_stack(
        [node[:-1, :-1].ravel(), node[:-1, 1:].ravel(), node[1:, 1:].ravel(), node[1:, :-1].ravel()]
    )
    data = {"total_depth": np.asarray(surface).ravel()}
    if wear is not None:
        data["wear_depth"] = np.asarray(wear).ravel()
    return meshio.Mesh(points, [("quad", quads)], point_data=data)


def write_erosion(run: ErosionRun, out: str | os.PathLike, notes: Sequence[str] = ()) -> dict:
    """Write one erosion, with its series and figures, as the output folder ``out``; returns the summary (with
    ``notes``: what the run said, e.g. its warnings)."""
    with output_folder(out, "erode", ENTRIES) as tmp:
        return _write_files(run, tmp, series=True, notes=notes)


def _write_files(run: ErosionRun, out: Path, series: bool, notes: Sequence[str] = ()) -> dict:
    """The files of one erosion in the folder ``out``; with ``series`` also the frames, the .pvd and the figures."""
    r = run.result
    area = r.patch_size**2
    write_rows(
        out / "erosion.csv",
        EROSION_COLUMNS,
        zip(
            r.time,
            r.impacts,
            r.particle_mass_kg,
            r.mass_loss_kg,
            r.mass_loss_kg / area,
            r.erosion_rate,
            r.interval_erosion_rate,
            r.max_depth_m,
            r.rms_slope,
            strict=True,
        ),
    )
    write_rows(out / "response_table.csv", TABLE_COLUMNS, r.table.rows())
    write_mesh(out / "surface.vtu", surface_grid_mesh(r.x, r.y, r.surface, r.wear))
    if series:
        (out / "frames").mkdir(exist_ok=True)
        entries = [(0.0, "frames/surface_0000.vtu")]
        write_mesh(out / entries[0][1], surface_grid_mesh(r.x, r.y, np.zeros_like(r.wear)))
        for k, (t, frame) in enumerate(zip(r.frame_time, r.frames, strict=True), start=1):
            name = f"frames/surface_{k:04d}.vtu"
            write_mesh(out / name, surface_grid_mesh(r.x, r.y, frame))
            entries.append((float(t), name))
        write_pvd(out / "erosion.pvd", entries)
        title = f"{r.stream.speed:g} m/s at {r.stream.angle:g} deg"
        fig.plot_time_series(
            r.time, r.mass_loss_kg, r.erosion_rate, out / "erosion.png", title, interval_rate=r.interval_erosion_rate
        )
        fig.plot_surface(r.x, r.y, r.surface, out / "surface.png", r.stream.azimuth, title)
    return write_summary(out / "summary.json", {**run.summary(), "notes": list(dict.fromkeys(notes))})


def write_erosion_angles(runs: list[ErosionRun], out: str | os.PathLike) -> list[tuple[float, float, float]]:
    """Write one erosion per stream angle into ``out/angle_<deg>/`` and ``erosion_vs_angle.csv`` and ``.png``;
    returns the rows (angle deg, erosion rate kg/kg, mass loss kg)."""
    rows = []
    with output_folder(out, "erode", ENTRIES) as tmp:
        for run in runs:
            a = run.result.stream.angle
            (tmp / f"angle_{a:g}").mkdir()
            _write_files(run, tmp / f"angle_{a:g}", series=False)
            rows.append((a, run.result.final_erosion_rate, float(run.result.mass_loss_kg[-1])))
        write_rows(tmp / "erosion_vs_angle.csv", ["angle_deg", "erosion_rate_kg_per_kg", "mass_loss_kg"], rows)
        case = runs[0].case
        fig.plot_angles(
            [r[0] for r in rows],
            [r[1] for r in rows],
            [r[2] for r in rows],
            tmp / "erosion_vs_angle.png",
            f"{case.impact.speed:g} m/s, {case.erosion.exposure_time:g} s",
        )
    return rows
