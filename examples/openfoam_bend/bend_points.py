"""Bend the straight O-grid pipe that blockMesh made into the 90 deg bend (rewrites constant/polyMesh/points).

blockMesh meshes a straight pipe along z (axis x = y = 0): 0 <= s = z <= L1 straight in, L1 <= s <= L1 + R pi/2 the
bend, then L2 straight out. After bending, the inlet is the plane z = -L1, the bend starts at z = 0 and the outlet is
the plane x = R + L2. Each point (x, y, s = z) goes to the point at distance x, y from the bend's centre line
at arc length s, so every mesh point of the wall lies exactly on the pipe (circle x^2 + y^2 = r^2 of each cross
section, torus in the bend):

    centre line  C(t) = (R - R cos t, 0, R sin t),  t = (s - L1)/R  in the bend,
    tangent      T(t) = (sin t, 0, cos t),  in-plane normal E(t) = (cos t, 0, -sin t),  Y = (0, 1, 0),
    point        C(t) + x E(t) + y Y.

The O-grid is also twisted about the pipe axis, by TWIST over the whole length (a cross section at arc length s
is turned by TWIST s / (L1 + R pi/2 + L2)): without it every wall face of a pipe or a torus is a plane trapezium,
with it the wall faces are slightly warped, as the faces of most real meshes are, so that the normal of the
triangle a parcel crosses differs from the face normal (ParticleErosion uses the triangle's).

The flow enters along +z and leaves along +x; the bend's centre of curvature is (R, 0, 0) (x > 0 is the intrados,
x < 0 the extrados). Usage: python3 bend_points.py CASE_DIR
"""

import math
import re
import sys
from pathlib import Path

import numpy as np

L1 = 0.25  # m, straight pipe before the bend (5 D)
R = 0.075  # m, bend centre-line radius (1.5 D)
L2 = 0.25  # m, straight pipe after the bend (5 D)
TWIST = 90.0  # deg, rotation of the O-grid about the pipe axis from inlet to outlet


def bend(p: np.ndarray) -> np.ndarray:
    lb = R * math.pi / 2.0
    s = p[:, 2]
    w = np.radians(TWIST) * s / (L1 + lb + L2)
    x = p[:, 0] * np.cos(w) - p[:, 1] * np.sin(w)
    y = p[:, 0] * np.sin(w) + p[:, 1] * np.cos(w)
    t = np.clip((s - L1) / R, 0.0, math.pi / 2.0)
    # straight run past either end
    along = np.where(s < L1, s - L1, np.where(s > L1 + lb, s - L1 - lb, 0.0))
    cx, cz = R - R * np.cos(t), R * np.sin(t)
    tx, tz = np.sin(t), np.cos(t)
    ex, ez = np.cos(t), -np.sin(t)
    return np.column_stack([cx + along * tx + x * ex, y, cz + along * tz + x * ez])


def main(case: Path) -> None:
    path = case / "constant" / "polyMesh" / "points"
    text = path.read_text()
    start = (
        text.index("\n(", text.index("FoamFile"))
        if "FoamFile" in text
        else text.index("(")
    )
    head, body = text[:start], text[start:]
    n = int(head.strip().split()[-1])
    nums = np.array(re.findall(r"\(([^()]*)\)", body)[:n], dtype=object)
    p = np.array([[float(v) for v in row.split()] for row in nums])
    if p.shape != (n, 3):
        raise SystemExit(f"{path}: expected {n} points, read {p.shape}")
    q = bend(p)
    out = (
        head
        + "\n(\n"
        + "\n".join(f"({float(a)!r} {float(b)!r} {float(c)!r})" for a, b, c in q)
        + "\n)\n\n"
    )
    out += "// ************************************************************************* //\n"
    path.write_text(out)


if __name__ == "__main__":
    main(Path(sys.argv[1]))
