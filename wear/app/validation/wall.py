r"""Validation checks of a component's wall erosion (:mod:`wear.wall`), for ``impactwear validate``.

References: OpenFOAM v1912's own eroded volume ``Q`` of the installed bend run
(:data:`wear.app.data.OPENFOAM_BEND`; its ``particleErosion`` cloud function, Finnie's law with p = 1e9 Pa, ψ = 2,
K = 2 of the run's ``kinematicCloudProperties``), the particle mass of its records counted directly, and Finnie's
(1960) closed form evaluated by hand for a uniform stream on a flat wall:

.. math:: W = \frac{c\,m V^2}{p\,\psi K}\Bigl(\sin 2\alpha - \frac{6}{K}\sin^2\alpha\Bigr),
          \qquad \tan\alpha \le K/6,

α the angle from the surface.
"""

from __future__ import annotations

import math

import numpy as np

from wear.app.data import OPENFOAM_BEND
from wear.app.validation.checks import Check, relative
from wear.case import default_case
from wear.wall import ImpactRecords, Wall, erode_component, read_patch_field, read_wall
from wear.wall.engine import chunk_sums
from wear.wall.per_record import wall_law
from wear.wall.sources import plan_chunks, read_chunk

#: OpenFOAM's particleErosion constants of the bend run (its kinematicCloudProperties): p (Pa), ψ, K.
FOAM_P, FOAM_PSI, FOAM_K = 1e9, 2.0, 2.0
BEND = "OpenFOAM v1912 bend run, 4528 hits, Finnie p 1e9 Pa, psi 2, K 2"


def _finnie_case(p: float, psi: float, k: float, c: float):
    return default_case("wall").with_(
        wear={"law": "finnie", "cutting_fraction": c, "force_ratio": k, "depth_ratio": psi},
        plate={"hardness": p},
        wall={"exposure": 0.05},
    )


def wall_against_openfoam(quick: bool) -> list[Check]:
    """The ``finnie`` law on the bend run's recorded hits (angles from the normal OpenFOAM used) against OpenFOAM's
    eroded volume Q face by face and in total; the particle mass summed per face against the records' mass read
    directly."""
    wall = read_wall(OPENFOAM_BEND)
    records = OPENFOAM_BEND / "patchPostProcessing1"
    run = erode_component(_finnie_case(FOAM_P, FOAM_PSI, FOAM_K, 1.0), records, wall, progress=False)
    q = read_patch_field(OPENFOAM_BEND / "kinematicCloudQ", wall)
    hit = q > 0.0
    worst = float(np.max(np.abs(run.wear.volume_m3[hit] / q[hit] - 1.0)))
    zero = bool(np.all(run.wear.volume_m3[~hit] == 0.0))
    mass = sum(float((r.count * r.mass).sum()) for r in (read_chunk(c, wall) for c in plan_chunks(records, 10**6)))
    return [
        Check(
            "wear",
            f"eroded volume of each of the {int(hit.sum())} faces hit (0 on the others: {zero})",
            BEND,
            "OpenFOAM's Q",
            "OpenFOAM v1912 particleErosion (the run's Q field)",
            f"max |V/Q - 1| {worst:.2g}",
            worst if zero else math.inf,
            1e-6,
            "max |V/Q - 1| over faces",
        ),
        relative(
            "wear",
            "eroded volume of the wall",
            BEND,
            float(q.sum()),
            "OpenFOAM v1912 particleErosion (the run's Q field)",
            float(run.wear.volume_m3.sum()),
            1e-9,
            "m^3",
        ),
        relative(
            "wear",
            "particle mass delivered to the wall faces",
            BEND,
            mass,
            "the records' n d^3 pi rho / 6, summed directly",
            float(run.sums.mass_kg.sum()),
            1e-12,
            "kg",
        ),
    ]


def _flat_wall(n: int, size: float) -> Wall:
    """A square of side ``size`` (m) in z = 0 cut into 2 n² triangles, normals −z (the fluid above)."""
    x, y = np.meshgrid(np.linspace(0.0, size, n + 1), np.linspace(0.0, size, n + 1), indexing="ij")
    points = np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)])
    node = np.arange(len(points)).reshape(n + 1, n + 1)
    a, b, c, d = node[:-1, :-1].ravel(), node[1:, :-1].ravel(), node[1:, 1:].ravel(), node[:-1, 1:].ravel()
    tri = np.concatenate([np.column_stack([a, d, c]), np.column_stack([a, c, b])])
    return Wall(
        points, tri.ravel(), np.arange(0, 3 * len(tri) + 1, 3), np.zeros(len(tri), int), ("flat",), np.arange(len(tri))
    )


def wall_uniform_stream(quick: bool) -> list[Check]:
    """A uniform stream at 30° from the normal (α = 60° from the surface, both Finnie branches' boundary far) on a
    flat wall of triangles, the same hits in every face: each face's volume against Finnie's closed form × its
    impacts (worst face)."""
    n, per_face, particles = (4 if quick else 16), 5, 40.0
    p, psi, k, c = 3e9, 2.0, 2.0, 0.5
    speed, diameter, density, theta = 25.0, 300e-6, 2650.0, 30.0
    wall = _flat_wall(n, 0.04)
    tri, _ = wall.triangles
    weights = np.array([[0.2, 0.3, 0.5], [0.6, 0.2, 0.2], [1 / 3, 1 / 3, 1 / 3], [0.1, 0.1, 0.8], [0.45, 0.45, 0.1]])
    position = np.einsum("kj,tjx->tkx", weights, wall.points[tri]).reshape(-1, 3)
    t = math.radians(theta)
    m = len(position)
    records = ImpactRecords(
        position=position,
        velocity=np.tile([speed * math.sin(t), 0.0, -speed * math.cos(t)], (m, 1)),
        diameter=np.full(m, diameter),
        density=np.full(m, density),
        count=np.full(m, particles),
        time=np.zeros(m),
        face=np.full(m, -1),
    )
    volume = chunk_sums(records, wall, wall_law(_finnie_case(p, psi, k, c))).volume_m3
    mass = density * math.pi * diameter**3 / 6.0
    alpha = math.radians(90.0 - theta)
    scale = c * mass * speed**2 / (p * psi * k)
    one = scale * k * math.cos(alpha) ** 2 / 6.0 if math.tan(alpha) > k / 6.0 else math.nan
    expected = per_face * particles * one
    worst = float(np.max(np.abs(volume / expected - 1.0)))
    return [
        Check(
            "wear",
            f"eroded volume of each of {len(wall)} wall faces",
            "uniform sand stream, 25 m/s at 30 deg, Finnie p 3 GPa, psi 2, K 2, c 0.5",
            f"{expected:.5g} m^3",
            "Finnie 1960, Wear 3:87 (tan a > K/6 branch)",
            f"max |V/W - 1| {worst:.2g}",
            worst,
            1e-12,
            "max |V/W - 1| over faces",
        )
    ]
