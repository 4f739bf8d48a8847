"""The output folder of ``impactwear calibrate`` (:func:`wear.chain.calibrate.calibrate`), written atomically by the
one writer: ``calibration.json`` (the fitted constants with their 95% intervals, statements on what the data cannot
determine, residuals, RMS log error, correlations), ``calibration.csv`` (every row: its inputs, measured, predicted,
log residual, fitted or not), ``calibration.png`` and ``calibrated.toml`` (the case with the fitted law, which
``impactwear run``, ``erode`` and ``repeat`` read as is, and a sweep's ``[base]`` takes table by table)."""

from __future__ import annotations

import os

import numpy as np

from wear.app.figures.calibration import plot_calibration
from wear.app.outputs.folder import output_folder
from wear.app.outputs.writer import versions, write_rows, write_summary, write_text
from wear.case import TABLES, dump_case
from wear.chain.calibrate import CalibrationResult

__all__ = ["write_calibration", "CASE_TABLES", "ENTRIES"]

#: What ``impactwear calibrate`` writes in its folder (checked against the folder before any work).
ENTRIES = ("calibration.json", "calibration.csv", "calibration.png", "calibrated.toml")

#: The tables of calibrated.toml: every case table but [calibration] (its data file is not part of the result).
CASE_TABLES = tuple(t for t in TABLES if t != "calibration")


def write_calibration(result: CalibrationResult, out: str | os.PathLike) -> dict:
    """Write the output folder of ``result`` atomically; returns the summary."""
    d = result.data
    summary = {**result.summary(), "case": result.case.to_dict(CASE_TABLES), "versions": versions()}
    with output_folder(out, "calibrate", ENTRIES) as tmp:
        summary = write_summary(tmp / "calibration.json", summary)
        fitted = d.fitted & ~np.isin(np.arange(d.angle.size), result.left_out)
        header = [
            "row",
            "angle_deg",
            "speed_m_s",
            *d.keys,
            f"measured_{d.quantity}",
            f"predicted_{d.quantity}",
            "log_residual",
            "fitted",
        ]
        rows = (
            [
                i + 1,
                f"{d.angle[i]:.10g}",
                f"{d.speed[i]:.10g}",
                *(f"{v[i]:.10g}" for v in d.keys.values()),
                "" if np.isnan(d.measured[i]) else f"{d.measured[i]:.10g}",
                f"{result.predicted[i]:.10g}",
                "" if np.isnan(result.log_residual[i]) else f"{result.log_residual[i]:.6g}",
                int(fitted[i]),
            ]
            for i in range(d.angle.size)
        )
        write_rows(tmp / "calibration.csv", header, rows)
        plot_calibration(result, tmp / "calibration.png")
        note = (
            f"# The case calibrated by impactwear calibrate (law {result.case.wear.law!r} fitted to {d.source}).\n"
            "# impactwear run, erode and repeat read it as is.\n\n"
        )
        write_text(tmp / "calibrated.toml", note + dump_case(result.case, CASE_TABLES))
    return summary
