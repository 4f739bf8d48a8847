"""The output folder of ``impactwear wall`` (:mod:`wear.wall.component`), built aside and moved in whole
(:func:`wear.app.outputs.folder.output_folder`; SI units; angles in degrees from the wall normal):

- ``faces.csv``: one row per wall face: ``face`` (0-based, in the wall's order), ``label`` (its number in the wall
  file, or OpenFOAM's mesh face label), ``patch``, the centre ``x_m``, ``y_m``, ``z_m``, ``area_m2``, and the fields
  of :meth:`wear.wall.component.ComponentErosion.face_fields` (impacts, particles, particle mass, mean speed, eroded
  volume and mass, erosion rate, thickness-loss rate in m/s and mm/year, thickness, remaining life in s and years,
  the depth after the service time, the particles in each 10° angle bin);
- ``hot_spots.csv``: the ten faces of fastest thickness loss, fastest first;
- ``speed_histogram.csv`` and ``angle_histogram.csv``: the particles on the wall by speed and by angle;
- ``wall.vtu``: the wall with the per-face fields (open in ParaView);
- ``worn_wall.vtu`` and ``worn_wall.stl``: the wall after the service time, its points moved into the wall by the
  eroded depth (the STL as triangles, oriented as the wall, for the next CFD run);
- ``wall.png`` and ``impacts.png`` (:mod:`wear.app.figures.wall`);
- ``summary.json``: the case, the records read, kept and skipped, the law, the exposure and the results.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

import meshio
import numpy as np

from wear.app.figures import wall as fig
from wear.app.outputs.folder import output_folder
from wear.app.outputs.writer import write_csv, write_mesh, write_summary
from wear.case import JOBS
from wear.wall.component import ComponentErosion

__all__ = ["ENTRIES", "HOT_SPOTS", "write_wall"]

#: What ``impactwear wall`` may write in its folder (checked against the folder before any work).
ENTRIES = (
    "faces.csv",
    "hot_spots.csv",
    "speed_histogram.csv",
    "angle_histogram.csv",
    "wall.vtu",
    "worn_wall.vtu",
    "worn_wall.stl",
    "wall.png",
    "impacts.png",
    "summary.json",
)
#: The number of faces in ``hot_spots.csv``.
HOT_SPOTS = 10


def write_wall(run: ComponentErosion, out: str | os.PathLike, notes: Sequence[str] = (), figures: bool = True) -> dict:
    """Write the erosion of a wall as the output folder ``out`` (module docstring; without ``figures`` no PNG);
    returns the summary (with ``notes``: what the run said, e.g. its warnings)."""
    with output_folder(out, "wall", ENTRIES) as tmp:
        return _write_files(run, tmp, notes, figures)


def _write_files(run: ComponentErosion, out: Path, notes: Sequence[str], figures: bool) -> dict:
    wall, sums = run.wall, run.sums
    centre = wall.centre
    write_csv(
        out / "faces.csv",
        {
            "face": np.arange(len(wall)),
            "label": wall.labels,
            "patch": [wall.patch_names[p] for p in wall.patch],
            "x_m": centre[:, 0],
            "y_m": centre[:, 1],
            "z_m": centre[:, 2],
            "area_m2": wall.area,
            **run.face_fields(),
        },
    )
    spots = run.hot_spots(HOT_SPOTS)
    write_csv(
        out / "hot_spots.csv",
        {
            "rank": np.arange(1, len(spots.face) + 1),
            "face": spots.face,
            "label": spots.label,
            "patch": list(spots.patch),
            "x_m": spots.position_m[:, 0],
            "y_m": spots.position_m[:, 1],
            "z_m": spots.position_m[:, 2],
            "thickness_loss_rate_m_s": spots.thickness_loss_rate_m_s,
            "thickness_loss_mm_year": spots.thickness_loss_mm_year,
            "remaining_life_s": spots.remaining_life_s,
            "remaining_life_year": spots.remaining_life_year,
        },
    )
    speed_edges, angle_edges = sums.speed_edges_m_s, sums.angle_edges_deg
    write_csv(
        out / "speed_histogram.csv",
        {"speed_low_m_s": speed_edges[:-1], "speed_high_m_s": speed_edges[1:], "particles": sums.speed_histogram},
    )
    write_csv(
        out / "angle_histogram.csv",
        {
            "angle_low_deg": angle_edges[:-1],
            "angle_high_deg": angle_edges[1:],
            "particles": sums.angle_histogram.sum(axis=0),
        },
    )
    write_mesh(out / "wall.vtu", wall.to_meshio(run.face_fields()))
    worn = run.worn_mesh()
    write_mesh(out / "worn_wall.vtu", worn)
    tri, _ = wall.triangles
    write_mesh(out / "worn_wall.stl", meshio.Mesh(worn.points, [("triangle", tri)]))
    summary = {"case": run.case.to_dict(JOBS["wall"].tables), **run.summary()}
    if figures:
        hot = int(spots.face[0]) if len(spots.face) else None
        law = f"{run.law_name} law, exposure {run.exposure_s:.4g} s"
        fig.plot_wall_rate(wall, run.wear.thickness_loss_mm_year, hot, out / "wall.png", law)
        particles = float(np.sum(sums.speed_histogram))
        title = f"particles on the wall: {particles:,.0f} in {summary['records']['on_wall']:,} impact records"
        fig.plot_impact_histograms(
            speed_edges, sums.speed_histogram, angle_edges, sums.angle_histogram.sum(axis=0), out / "impacts.png", title
        )
    return write_summary(out / "summary.json", {**summary, "notes": list(dict.fromkeys(notes))})
