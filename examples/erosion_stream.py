"""Erosion of a steel plate by a stream of sand particles
======================================================

Erosion of a steel plate by a stream of sand particles, with surface feedback (public API of wear.erosion).

Builds the response table of one particle impact over normal speed x local angle (H-DD impact + the wear law,
errata Eq. 15), erodes a periodic patch for a few seconds of the paper's Fig. 10 stream (20 m/s, 464 g/m^3) at
three angles, prints the erosion rate, and writes ``erosion_stream.csv`` (time series at 45 deg) and
``erosion_angles.csv`` into ``--out``. SI units; angles in degrees from the plate normal.

Run: ``python examples/erosion_stream.py [--out DIR]`` (IMPACTWEAR_QUICK=1: coarser table, smaller patch).
For the full case and the CLI see ``impactwear erode examples/fig10_stream.toml``.
"""

from __future__ import annotations

import argparse
import csv
import os
import tempfile
from pathlib import Path

from contact import Material
from wear import WearLaw
from wear.erosion import ImpactResponse, Stream, build_response_table, erode, table_axes


def write_csv(path: Path, header: list[str], rows) -> None:
    """Write a CSV atomically (temporary file in the same folder, then rename)."""
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", dir=path.parent)
    with os.fdopen(fd, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows(rows)
    os.replace(tmp, path)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=".", help="output folder")
    args = parser.parse_args()
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    quick = os.environ.get("IMPACTWEAR_QUICK") == "1"

    sand = Material(E=94e9, nu=0.17, density=2650.0, name="silica sand")
    steel = Material(E=200e9, nu=0.3, density=7850.0, yield_strength=350e6, name="carbon steel")
    law = WearLaw(K=1e-11, alpha=1.0, beta=0.3, K_units="m^(0.7) s^(-0.7) Pa^(-1)")
    response = ImpactResponse(radius=150e-6, ball=sand, plate=steel, friction=0.3, law=law, pressure="paper")
    grid = 128 if quick else 256
    exposure = 2.0 if quick else 20.0  # s

    rows = []
    for angle in (30.0, 45.0, 60.0):
        vn, angles = table_axes(20.0, angle, angle_margin=10.0, angle_step=5.0 if quick else 2.5, speeds=3)
        table = build_response_table(response, vn, angles, points_per_length=8 if quick else 12)
        result = erode(table, Stream(20.0, angle, exposure, concentration=0.464), grid=grid, seed=1)
        print(
            f"{angle:4.0f} deg: {result.n_impacts:7d} impacts on a {result.patch_size * 1e3:.3g} mm patch, "
            f"mass loss {result.mass_loss_kg[-1]:.4g} kg, erosion rate {result.final_erosion_rate:.4g} kg/kg, "
            f"deepest {result.max_depth_m[-1] * 1e6:.3g} um"
        )
        print(f"          table: {table.resolution}")
        rows.append((angle, result.final_erosion_rate, float(result.mass_loss_kg[-1])))
        if angle == 45.0:
            write_csv(
                out / "erosion_stream.csv",
                ["time_s", "impacts", "mass_loss_kg", "erosion_rate_kg_per_kg"],
                zip(result.time, result.impacts, result.mass_loss_kg, result.erosion_rate, strict=True),
            )
    write_csv(out / "erosion_angles.csv", ["angle_deg", "erosion_rate_kg_per_kg", "mass_loss_kg"], rows)


if __name__ == "__main__":
    main()
