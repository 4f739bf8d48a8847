"""The output folder of ``impactwear indent`` (:func:`wear.chain.indent.indent_case`): ``force_overlap.csv``,
``pressure.csv`` (p(r) per step), ``residual_depth.csv``, ``plate.vtu``, the figures and ``summary.json``, built
aside and moved in whole (:func:`wear.app.outputs.folder.output_folder`). SI units in every column name."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from wear.app.figures.indent import write_figures
from wear.app.outputs.folder import output_folder
from wear.app.outputs.writer import write_mesh, write_rows, write_summary
from wear.chain.indent import IndentRun

__all__ = ["ENTRIES", "write_indent"]

#: What ``impactwear indent`` may write in its folder (checked against the folder before any work).
ENTRIES = (
    "force_overlap.csv",
    "pressure.csv",
    "residual_depth.csv",
    "plate.vtu",
    "pressure.png",
    "force_overlap.png",
    "plastic_zone.png",
    "summary.json",
)


def write_indent(run: IndentRun, out: str | os.PathLike, figures: bool = True, notes: Sequence[str] = ()) -> dict:
    """Write the outputs of ``run`` as the output folder ``out``; returns the summary (with ``notes``: what the run
    said, e.g. its warnings)."""
    with output_folder(out, "indent", ENTRIES) as tmp:
        return _write_files(run, tmp, figures, notes)


def _write_files(run: IndentRun, out: Path, figures: bool, notes: Sequence[str]) -> dict:
    res = run.result
    steps = range(res.overlap.size)
    write_rows(
        out / "force_overlap.csv",
        [
            "step",
            "overlap_m",
            "normal_force_N",
            "contact_radius_m",
            "peak_pressure_Pa",
            "mean_pressure_Pa",
            "max_equivalent_plastic_strain",
            "regime",
        ],
        (
            [
                k,
                res.overlap[k],
                res.force[k],
                res.contact_radius[k],
                res.max_pressure[k],
                res.mean_pressure[k],
                res.max_equivalent_plastic_strain[k],
                res.regime[k],
            ]
            for k in steps
        ),
    )
    write_rows(
        out / "pressure.csv",
        ["r_m"] + [f"step{k}_Pa" for k in steps],
        ([r, *res.pressure[:, i]] for i, r in enumerate(res.surface_r)),
    )
    write_rows(
        out / "residual_depth.csv", ["r_m", "residual_depth_m"], zip(res.surface_r, res.residual_depth, strict=True)
    )
    write_mesh(out / "plate.vtu", res.to_meshio())
    if figures:
        write_figures(res, out)
    return write_summary(out / "summary.json", {**run.summary(), "notes": list(dict.fromkeys(notes))})
