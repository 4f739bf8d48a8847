"""The output-folder commands with small, fast inputs, shared by the output-folder tests."""

from __future__ import annotations

from pathlib import Path

import meshio
import numpy as np

#: Each output-folder command with small, fast inputs (a few seconds each).
FAST = {
    "run": [
        "run",
        "--quiet",
        "--set",
        'fem.coupling="none"',
        "--set",
        'wear.pressure="hertz"',
        "--set",
        'wear.speed="sliding"',
        "--set",
        "output.figures=false",
        "--set",
        "output.render=false",
    ],
    "indent": [
        "indent",
        "--quiet",
        "--no-figures",
        "--load-steps",
        "3",
        "--unload-steps",
        "2",
        "--set",
        "fem.mesh_scale=4",
    ],
    "erode": [
        "erode",
        "--quiet",
        "--set",
        "erosion.grid=128",
        "--set",
        "erosion.angle_step=10.0",
        "--set",
        "erosion.table_speeds=2",
        "--set",
        "erosion.points_per_length=6",
        "--set",
        "erosion.frames=2",
        "--set",
        "erosion.samples=5",
        "--set",
        "erosion.exposure_time=60.0",
    ],
    "repeat": [
        "repeat",
        "--quiet",
        "--impacts",
        "1",
        "--set",
        "fem.mesh_scale=4",
        "--set",
        "plate.yield_strength=inf",
        "--set",
        "output.figures=false",
    ],
    "calibrate": ["calibrate", "DATA", "--law", "dnv", "--free", "dnv_K", "--quiet"],
    "wall": ["wall", "RECORDS", "WALL", "--set", "wall.exposure=1.0", "--quiet"],
}

SWEEP = """
[sweep]
stage = "impact"
[base]
[grid]
"impact.angle" = [0, 30]
"""


def command_args(command: str, tmp_path: Path) -> list[str]:
    """``command``'s fast arguments (the calibration data, the wall's records and wall, and the sweep file written
    into ``tmp_path``); for
    ``reproduce`` and ``validate``, which write in place, only the command."""
    if command == "sweep":
        spec = tmp_path / "sweep.toml"
        spec.write_text(SWEEP)
        return ["sweep", str(spec), "--quiet", "--workers", "1"]
    if command in ("reproduce", "validate"):
        return [command, "--quiet"]
    args = list(FAST[command])
    if command == "calibrate":
        data = tmp_path / "data.csv"
        rows = [(a, v, 2e-9 * v**2.6 * (0.5 + np.sin(np.radians(90 - a)))) for a in (15, 45, 75) for v in (20, 40)]
        data.write_text("angle_deg,speed_m_s,erosion_kg_per_kg\n" + "".join(f"{a},{v},{e:.6g}\n" for a, v, e in rows))
        args[1] = str(data)
    if command == "wall":
        wall = tmp_path / "plate.stl"
        points = np.array([[0, 0, 0], [0.01, 0, 0], [0, 0.01, 0]], float)
        meshio.write(wall, meshio.Mesh(points, [("triangle", np.array([[0, 2, 1]]))]))  # normal -z: into the wall
        records = tmp_path / "hits.csv"
        records.write_text("x_m,y_m,z_m,u_m_s,v_m_s,w_m_s,diameter_m,density_kg_m3\n0.002,0.002,0,5,0,-10,3e-4,2650\n")
        args[1:3] = [str(records), str(wall)]
    return args
