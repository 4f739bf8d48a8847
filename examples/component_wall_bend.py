"""Erosion of a pipe bend from a real OpenFOAM run
===============================================

From the impacts a CFD run recorded on a component's wall to where the wall wears through and when: the Python
side of ``impactwear wall`` (:func:`wear.wall.erode_component`).

The records are those of a real OpenFOAM v1912 run installed with the toolkit
(:data:`wear.app.data.OPENFOAM_BEND`; its case and the script that regenerates it are in ``examples/openfoam_bend``).
Air at 20 m/s flows through a 90° bend of a 50 mm pipe of bend radius 1.5 D, carrying quartz sand of 100–300 µm at
0.01 kg/s; OpenFOAM's ``patchPostProcessing`` cloud function recorded the 4528 parcel hits on the walls, and its
``particleErosion`` cloud function the Finnie eroded volume ``Q`` of each wall face. First the toolkit's ``finnie`` law
with OpenFOAM's constants is checked against ``Q`` face by face; then DNV-RP-O501's law for steel gives the
thickness-loss rate in mm/year, the hot spot, the remaining life of a 5 mm wall and the worn wall. SI units; angles in
degrees from the wall normal.
"""

# %%
# The wall and the records
# ------------------------
# The wall is the OpenFOAM case's wall patches (its polyMesh); the records are the ``patchPostProcessing`` folder
# (one file per wall patch and write time). A hit's angle is measured against the normal OpenFOAM used: that of the
# triangle of the face the parcel crossed, recorded with each hit.

import os
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from wear.app.data import OPENFOAM_BEND
from wear.app.figures.wall import WALL_FIGSIZE, draw_wall_rate
from wear.app.outputs.wall import write_wall
from wear.case import default_case
from wear.wall import erode_component, read_patch_field, read_wall

RUN = OPENFOAM_BEND  # the run's outputs, installed with the toolkit
# where the outputs go
OUT = Path(os.environ.get("IMPACTWEAR_EXAMPLE_OUT", ".")) / "component_wall_bend"
OUT.mkdir(parents=True, exist_ok=True)

wall = read_wall(RUN)
records = RUN / "patchPostProcessing1"
print(
    f"the wall: {len(wall)} faces on the patches {', '.join(wall.patch_names)}, "
    f"{wall.area.sum():.4g} m^2"
)

# %%
# OpenFOAM's own eroded volume, reproduced
# ----------------------------------------
# OpenFOAM's ``particleErosion`` is Finnie's law with its flow pressure p = 1e9 Pa, ψ = 2, K = 2 (the run's
# ``kinematicCloudProperties``). The toolkit's ``finnie`` law with the same constants (the flow pressure given as
# the plate's hardness, the cutting fraction 1) on the same records gives each face's volume; ``Q`` is the volume
# OpenFOAM summed on each face.

finnie = default_case("wall").with_(
    wear={
        "law": "finnie",
        "cutting_fraction": 1.0,
        "force_ratio": 2.0,
        "depth_ratio": 2.0,
    },
    plate={"hardness": 1e9},
    wall={"exposure": 0.05},
)
check = erode_component(finnie, records, wall, progress=False)
q = read_patch_field(RUN / "kinematicCloudQ", wall)
hit = q > 0
worst = np.max(np.abs(check.wear.volume_m3[hit] / q[hit] - 1.0))
print(
    f"finnie against OpenFOAM's Q on {hit.sum()} faces: largest relative difference "
    f"{worst:.2g}"
)

# %%
# DNV-RP-O501's law on a steel bend
# ---------------------------------
# The default case of ``impactwear wall`` is silica sand on carbon steel with DNV-RP-O501's law for steel
# (K = 2e-9, n = 2.6). The run injected 5e-4 kg of sand at 0.01 kg/s, so its hits stand for an exposure of
# 5e-4 / 0.01 = 0.05 s; the wall is 5 mm thick; the worn wall is written after 2 days.

case = default_case("wall").with_(
    wall={"exposure": 0.05, "thickness": 5e-3, "service_time": 2 * 86400.0}
)
bend = erode_component(case, records, wall, progress=False)
spots = bend.hot_spots(3)
x, y, z = spots.position_m[0]
print(
    f"hot spot: {spots.thickness_loss_mm_year[0]:.4g} mm/year on patch "
    f"{spots.patch[0]} at ({x:.4g}, {y:.4g}, "
    f"{z:.4g}) m; a 5 mm wall lasts {spots.remaining_life_year[0] * 365.25:.3g} days "
    "there"
)
summary = write_wall(bend, OUT / "dnv", figures=False)
print(
    f"eroded mass {summary['results']['eroded_mass_kg']:.4g} kg over "
    f"{bend.exposure_s:g} s of sand"
)

# %%
# The wall coloured by its thickness-loss rate
# --------------------------------------------
# The sand goes straight on at the bend (its Stokes number is about 130) and hits the outer wall of the bend's
# second half; the hot spot is marked.

fig = plt.figure(figsize=WALL_FIGSIZE)
draw_wall_rate(
    fig, wall, bend.wear.thickness_loss_mm_year, int(spots.face[0]), "DNV law, steel"
)
fig.savefig(OUT / "wall.png", dpi=120)

# %%
# Along the bend
# --------------
# The mean thickness-loss rate of the bend's outer quarter (within 45° of the extrados line) against the angle into
# the bend: the bend turns the flow from +z to +x about the axis through (0.075, 0, 0) parallel to y.

on_bend = np.array([wall.patch_names[p] == "bend" for p in wall.patch])
centre = wall.centre - np.array([0.075, 0.0, 0.0])
# 0 at the bend's start, 90 at its end
into_bend = np.degrees(np.arctan2(centre[:, 2], -centre[:, 0]))
radial = np.hypot(centre[:, 0], centre[:, 2]) - 0.075
around = np.degrees(np.arctan2(np.abs(centre[:, 1]), radial))  # 0 on the extrados line
outer = on_bend & (around < 45.0)
edges = np.arange(0.0, 91.0, 10.0)
rate = bend.wear.thickness_loss_mm_year
mean = [
    rate[outer & (into_bend >= a) & (into_bend < b)].mean()
    for a, b in zip(edges[:-1], edges[1:], strict=True)
]
fig, ax = plt.subplots(figsize=(6, 4), layout="constrained")
ax.stairs(mean, edges, fill=True, alpha=0.7)
ax.set_xlabel("angle into the bend (deg)")
ax.set_ylabel("mean thickness-loss rate (mm/year)")
ax.set_xlim(0, 90)
fig.savefig(OUT / "along_the_bend.png", dpi=120)
