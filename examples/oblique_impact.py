"""Oblique impacts of an alumina ball on soda-lime glass
=====================================================

Oblique impacts of an alumina ball on soda-lime glass (Kharaz, Gorham & Salman 2001), H-DD model.

Sweeps the impact angle at 3.9 m/s, prints the rebound against rigid-body theory (valid in gross sliding,
large angles), and writes ``oblique_impact.csv`` (the sweep) and ``history_30deg.csv`` (one impact's time
history) into ``--out`` (default: the current folder). SI units; angles in degrees from the plate normal.

Run: ``python examples/oblique_impact.py [--out DIR]`` (IMPACTWEAR_QUICK=1 for a coarser sweep).
"""

from __future__ import annotations

import argparse
import csv
import math
import os
import tempfile
from pathlib import Path

import numpy as np

from contact import Material, simulate_impact, simulate_impacts


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

    ball = Material(E=380e9, nu=0.23, density=4000.0, name="alumina")
    plate = Material(E=70e9, nu=0.25, density=2500.0, name="soda-lime glass")
    radius, speed, mu = 2.5e-3, 3.9, 0.092
    angles = np.arange(5.0, 86.0, 10.0 if quick else 2.5)
    batch = simulate_impacts(radius, ball, plate, speed, angles, mu)

    # rigid-body theory in gross sliding (e = 1): e_t = 1 - 2 mu / tan(theta), w' = 5 mu v cos(theta) / R
    theta = np.radians(angles)
    sliding = np.tan(theta) > 7 * mu  # rigid-body gross sliding throughout
    et_theory = np.where(sliding, 1 - 2 * mu / np.tan(theta), np.nan)
    print(
        f"{'angle':>6} {'e_t':>8} {'e_t rigid':>10} {'spin rad/s':>11} {'rebound':>8} {'cp rebound':>10} {'t_s/t_c':>8}"
    )
    for i, a in enumerate(angles):
        print(
            f"{a:6.1f} {batch.tangential_restitution[i]:8.4f} {et_theory[i]:10.4f} {batch.spin[i]:11.1f} "
            f"{batch.rebound_angle[i]:8.2f} {batch.contact_point_rebound_angle[i]:10.2f} "
            f"{batch.sliding_time[i] / batch.contact_time[i]:8.3f}"
        )
    write_csv(
        out / "oblique_impact.csv",
        [
            "angle_deg",
            "tangential_restitution",
            "spin_rad_s",
            "rebound_angle_deg",
            "contact_point_rebound_angle_deg",
            "contact_time_s",
            "sliding_time_s",
            "max_force_N",
        ],
        zip(
            angles,
            batch.tangential_restitution,
            batch.spin,
            batch.rebound_angle,
            batch.contact_point_rebound_angle,
            batch.contact_time,
            batch.sliding_time,
            batch.max_force,
            strict=True,
        ),
    )

    r = simulate_impact(radius, ball, plate, speed, 30.0, mu, history_every=10)
    h = r.history
    print(
        f"\n30 deg: contact {r.contact_time * 1e6:.2f} us, sliding {r.sliding_time * 1e6:.2f} us, "
        f"peak pressure {r.max_peak_pressure / 1e9:.2f} GPa, contact patch travels {h.contact_x[-1] * 1e6:.1f} um"
    )
    balance = r.energy_in - r.energy_out - r.normal_work - r.friction_work
    print(f"energy balance residual: {balance / r.energy_in:.1e} of the kinetic energy in")
    assert math.isfinite(balance) and abs(balance) < 1e-3 * r.energy_in
    write_csv(
        out / "history_30deg.csv",
        [
            "time_s",
            "overlap_m",
            "normal_force_N",
            "tangential_force_N",
            "contact_radius_m",
            "peak_pressure_Pa",
            "slip_velocity_m_s",
            "sliding",
            "contact_x_m",
        ],
        zip(
            h.t,
            h.overlap,
            h.normal_force,
            h.tangential_force,
            h.contact_radius,
            h.peak_pressure,
            h.slip_velocity,
            h.sliding.astype(int),
            h.contact_x,
            strict=True,
        ),
    )
    print(f"wrote {out / 'oblique_impact.csv'} and {out / 'history_30deg.csv'}")


if __name__ == "__main__":
    main()
