"""A sweep over the impact angle
=============================

Run examples/sweep_angles.toml (impact stage, 17 angles) and print the rebound angles from results.csv.

    python examples/sweep_angles.py --out DIR [--workers N]

Equivalent to ``impactwear sweep examples/sweep_angles.toml --out DIR``; rerunning skips finished cases.
"""

from __future__ import annotations

import argparse
import csv
import sys
from pathlib import Path

from wear.app import cli

HERE = Path(__file__).resolve().parent


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="sweep_angles", help="output folder")
    parser.add_argument("--workers", default="2", help="local worker processes")
    args = parser.parse_args()
    status = cli.main(["sweep", str(HERE / "sweep_angles.toml"), "--out", args.out, "--workers", args.workers])
    if status != 0:
        return status
    with open(Path(args.out) / "results.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    print(f"{'angle (deg)':>12} {'rebound (deg)':>14} {'contact pt (deg)':>17} {'spin (rad/s)':>13}")
    for r in rows:
        print(
            f"{float(r['impact.angle_deg']):12.1f} {float(r['rebound_angle_deg']):14.3f} "
            f"{float(r['contact_point_rebound_angle_deg']):17.3f} {float(r['spin_rad_s']):13.2f}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
