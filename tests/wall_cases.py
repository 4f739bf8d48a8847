"""Shared inputs of the wall tests: the committed OpenFOAM run, a flat wall of triangles (meshio) and Finnie's
closed form coded from the paper (Finnie 1960, Wear 3: 87–103)."""

from __future__ import annotations

import csv
import math
import re
from pathlib import Path

import meshio
import numpy as np

from wear.app.data import OPENFOAM_BEND
from wear.case import Case

BEND = Path(__file__).resolve().parents[1] / "examples" / "openfoam_bend"
OUTPUTS = OPENFOAM_BEND  # installed with the package
RECORDS = OUTPUTS / "patchPostProcessing1"


def erosion_constants() -> dict[str, float]:
    """p (Pa), psi, K of the run's particleErosion1 entry, read from its case dictionary."""
    text = (BEND / "particles" / "constant" / "kinematicCloudProperties").read_text()
    block = text[text.index("particleErosion1") :]
    return {k: float(re.search(rf"\b{k}\s+([^;\s]+);", block)[1]) for k in ("p", "psi", "K")}


def openfoam_finnie_case() -> Case:
    """The case whose ``finnie`` law is OpenFOAM's particleErosion of the run: Finnie with c = 1, its p (the plate's
    flow pressure, given as its hardness), psi and K."""
    c = erosion_constants()
    return Case().with_(
        wear={"law": "finnie", "cutting_fraction": 1.0, "force_ratio": c["K"], "depth_ratio": c["psi"]},
        plate={"hardness": c["p"]},
    )


#: Finnie's constants of the flat-wall tests: the flow pressure p (Pa), ψ, K and the cutting fraction c.
P, PSI, K, C = 3e9, 2.0, 2.0, 0.5


def finnie_1960(mass: float, speed: float, alpha_deg: float) -> float:
    a = math.radians(alpha_deg)
    scale = C * mass * speed**2 / (P * PSI * K)
    if math.tan(a) <= K / 6.0:
        return scale * (math.sin(2 * a) - 6.0 / K * math.sin(a) ** 2)
    return scale * K * math.cos(a) ** 2 / 6.0


def flat_mesh(nx: int = 4, ny: int = 3, width: float = 0.04, height: float = 0.03) -> meshio.Mesh:
    """A width × height (m) rectangle in the plane z = 0 cut into 2 nx ny triangles, oriented so that their
    right-hand normal is −z: the fluid is above (z > 0), the wall material below."""
    x, y = np.meshgrid(np.linspace(0, width, nx + 1), np.linspace(0, height, ny + 1), indexing="ij")
    points = np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)])
    node = np.arange(points.shape[0]).reshape(nx + 1, ny + 1)
    a, b, c, d = node[:-1, :-1].ravel(), node[1:, :-1].ravel(), node[1:, 1:].ravel(), node[:-1, 1:].ravel()
    # (a, d, c) and (a, c, b) run clockwise seen from +z: normal -z
    triangles = np.concatenate([np.column_stack([a, d, c]), np.column_stack([a, c, b])])
    return meshio.Mesh(points, [("triangle", triangles)])


def write_csv(path: Path, header: list[str], rows: list[list]) -> Path:
    with path.open("w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows(rows)
    return path
