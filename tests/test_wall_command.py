"""``impactwear wall``: the command from impact records to the output folder, against independent references.

- OpenFOAM's own eroded volume Q (particleErosion, Finnie) of the committed bend run, face by face, through the
  command's ``faces.csv`` and ``wall.vtu`` (examples/openfoam_bend).
- A uniform stream on a flat wall: every face's volume, erosion rate, thickness-loss rate, remaining life and worn
  depth from Finnie's closed form (Finnie 1960, coded in wall_cases) and the definitions of the rates (volume over
  area and exposure time; a year of 365.25 days), with the exposure taken from the records' time span and the
  volumes scaled by the sand rates; the worn STL's points moved by that depth; the wall split into two files.
"""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import meshio
import numpy as np
import pytest
from wall_cases import OUTPUTS, PSI, RECORDS, C, K, P, erosion_constants, finnie_1960, flat_mesh, write_csv

from wear.app.cli import main
from wear.app.outputs.fields import UNITLESS, unit_of
from wear.wall import read_patch_field, read_polymesh

YEAR = 365.25 * 86400.0
SPEED, DIAMETER, DENSITY, PER_FACE, PARTICLES, THETA = 25.0, 300e-6, 2650.0, 5, 40.0, 35.0
FINNIE = [
    "--set",
    'wear.law="finnie"',
    "--set",
    f"wear.cutting_fraction={C}",
    "--set",
    f"wear.force_ratio={K}",
    "--set",
    f"wear.depth_ratio={PSI}",
    "--set",
    f"plate.hardness={P}",
]


def _faces(out: Path) -> dict[str, np.ndarray]:
    with (out / "faces.csv").open() as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([r[k] for r in rows]) for k in rows[0]}


def _floats(column: np.ndarray) -> np.ndarray:
    return column.astype(float)


def test_the_command_reproduces_openfoams_eroded_volume_on_every_face(tmp_path, capsys):
    """OpenFOAM v1912's particleErosion Q against the command's ``finnie`` law with the run's constants (p, ψ, K
    read from its kinematicCloudProperties; c = 1), on the normal OpenFOAM used (the recorded one)."""
    c = erosion_constants()
    out = tmp_path / "bend"
    argv = [
        "wall",
        str(RECORDS),
        str(OUTPUTS),
        "--set",
        'wear.law="finnie"',
        "--set",
        "wear.cutting_fraction=1.0",
        "--set",
        f"wear.force_ratio={c['K']}",
        "--set",
        f"wear.depth_ratio={c['psi']}",
        "--set",
        f"plate.hardness={c['p']}",
        "--set",
        "wall.exposure=0.05",
        "--no-figures",
        "--quiet",
        "--out",
        str(out),
    ]
    assert main(argv) == 0
    wall = read_polymesh(OUTPUTS)
    q = read_patch_field(OUTPUTS / "kinematicCloudQ", wall)
    faces = _faces(out)
    volume = _floats(faces["eroded_volume_m3"])
    assert np.array_equal(faces["label"].astype(int), wall.labels)
    hit = q > 0
    assert hit.sum() > 700 and np.all(volume[~hit] == 0.0)
    assert np.max(np.abs(volume[hit] / q[hit] - 1.0)) < 1e-6
    vtu = meshio.read(out / "wall.vtu")  # every face a quad: one block, in face order
    assert np.allclose(vtu.cell_data["eroded_volume_m3"][0], volume, rtol=1e-9, atol=0)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["records"]["read"] == summary["records"]["on_wall"] == 4528
    assert summary["results"]["eroded_volume_m3"] == pytest.approx(q.sum(), rel=1e-9)


def _stream_csv(path: Path, wall_mesh: meshio.Mesh, times: tuple[float, float]) -> Path:
    """PER_FACE hits at fixed points inside every triangle of the flat wall, at THETA from the normal (−z), their
    hit times spread evenly over ``times`` (s)."""
    tri = wall_mesh.cells[0].data
    weights = np.array([[0.2, 0.3, 0.5], [0.6, 0.2, 0.2], [1 / 3, 1 / 3, 1 / 3], [0.1, 0.1, 0.8], [0.45, 0.45, 0.1]])
    position = np.einsum("kj,tjx->tkx", weights[:PER_FACE], wall_mesh.points[tri]).reshape(-1, 3)
    t = math.radians(THETA)
    u = [repr(SPEED * math.sin(t)), "0.0", repr(-SPEED * math.cos(t))]
    time = np.linspace(*times, len(position))
    header = ["x_m", "y_m", "z_m", "u_m_s", "v_m_s", "w_m_s", "diameter_m", "density_kg_m3", "particles", "time_s"]
    rows = [
        [*(repr(float(x)) for x in p), *u, repr(DIAMETER), repr(DENSITY), repr(PARTICLES), repr(float(s))]
        for p, s in zip(position, time, strict=True)
    ]
    return write_csv(path, header, rows)


@pytest.fixture
def flat(tmp_path):
    mesh = flat_mesh()
    meshio.write(tmp_path / "plate.stl", mesh)
    records = _stream_csv(tmp_path / "hits.csv", mesh, (0.5, 2.5))
    return tmp_path / "plate.stl", records, mesh


def test_a_uniform_stream_on_a_flat_wall_gives_the_closed_forms_on_every_face(flat, tmp_path):
    wall_file, records, mesh = flat
    out = tmp_path / "out"
    thickness, service, density = 0.004, 3.0e6, 7850.0
    scale = 3.0 / 1.5  # sand_rate / cfd_sand_rate
    argv = [
        "wall",
        str(records),
        str(wall_file),
        *FINNIE,
        "--set",
        f"wall.thickness={thickness}",
        "--set",
        f"wall.service_time={service}",
        "--set",
        "wall.sand_rate=3.0",
        "--set",
        "wall.cfd_sand_rate=1.5",
        "--set",
        "wall.loss_budget=2e-4",
        "--quiet",
        "--out",
        str(out),
    ]
    assert main(argv) == 0
    faces = _faces(out)
    exposure = 2.0  # the records' time span, 0.5 to 2.5 s
    area = 0.04 * 0.03 / len(mesh.cells[0].data)
    mass = DENSITY * math.pi * DIAMETER**3 / 6.0
    volume = scale * PER_FACE * PARTICLES * finnie_1960(mass, SPEED, 90.0 - THETA)
    rate = volume / (area * exposure)  # m/s
    n = len(mesh.cells[0].data)
    assert _floats(faces["impacts"]) == pytest.approx(np.full(n, PER_FACE), abs=0)
    assert _floats(faces["eroded_volume_m3"]) == pytest.approx(np.full(n, volume), rel=1e-9)
    assert _floats(faces["eroded_mass_kg"]) == pytest.approx(np.full(n, density * volume), rel=1e-9)
    assert _floats(faces["erosion_rate_kg_m2_s"]) == pytest.approx(np.full(n, density * rate), rel=1e-9)
    assert _floats(faces["thickness_loss_mm_year"]) == pytest.approx(np.full(n, rate * 1e3 * YEAR), rel=1e-9)
    assert _floats(faces["remaining_life_s"]) == pytest.approx(np.full(n, thickness / rate), rel=1e-9)
    assert _floats(faces["mean_speed_m_s"]) == pytest.approx(np.full(n, SPEED), rel=1e-12)
    angle_bin = "particles_angle_30_40_deg"
    assert _floats(faces[angle_bin]) == pytest.approx(np.full(n, PER_FACE * PARTICLES), rel=1e-12)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["exposure_s"] == pytest.approx(exposure, rel=1e-12)
    assert summary["exposure_source"] == "the records' time span"
    assert summary["results"]["eroded_volume_m3"] == pytest.approx(n * volume, rel=1e-9)
    # the depths scale with the sand rate: the rate that wears 0.2 mm in the service time
    assert summary["results"]["allowable_sand_rate_kg_s"] == pytest.approx(3.0 * 2e-4 / (rate * service), rel=1e-9)
    # the worn wall: every point of a flat wall of equal depths moved by that depth into the wall (−z)
    depth = rate * service
    worn = meshio.read(out / "worn_wall.stl")
    assert worn.points[:, 2] == pytest.approx(np.full(len(worn.points), -depth), rel=1e-6)
    xy = np.unique(np.round(worn.points[:, :2], 9), axis=0)  # an STL repeats each triangle's corners
    assert np.allclose(xy, np.unique(mesh.points[:, :2], axis=0), rtol=0, atol=1e-7)  # in float32
    vtu = meshio.read(out / "worn_wall.vtu")
    assert vtu.point_data["wear_depth_m"] == pytest.approx(np.full(len(vtu.points), depth), rel=1e-12)


def test_a_wall_split_into_two_files_gives_the_same_faces_as_one(flat, tmp_path):
    wall_file, records, mesh = flat
    parts = tmp_path / "parts"
    parts.mkdir()
    triangles = mesh.cells[0].data
    half = len(triangles) // 2
    meshio.write(parts / "a_left.vtu", meshio.Mesh(mesh.points, [("triangle", triangles[:half])]))
    meshio.write(parts / "b_right.obj", meshio.Mesh(mesh.points, [("triangle", triangles[half:])]))
    common = [*FINNIE, "--set", "wall.exposure=1.0", "--no-figures", "--quiet"]
    assert main(["wall", str(records), str(wall_file), *common, "--out", str(tmp_path / "one")]) == 0
    assert main(["wall", str(records), str(parts), *common, "--out", str(tmp_path / "two")]) == 0
    one, two = _faces(tmp_path / "one"), _faces(tmp_path / "two")
    assert list(two["patch"][[0, -1]]) == ["a_left", "b_right"]
    assert _floats(two["eroded_volume_m3"]) == pytest.approx(_floats(one["eroded_volume_m3"]), rel=1e-12)


def test_every_field_the_command_writes_names_its_unit(flat, tmp_path):
    wall_file, records, _ = flat
    out = tmp_path / "out"
    assert (
        main(["wall", str(records), str(wall_file), "--set", "wall.thickness=0.01", "--quiet", "--out", str(out)]) == 0
    )
    names = set(_faces(out))
    names |= set(meshio.read(out / "wall.vtu").cell_data) | set(meshio.read(out / "worn_wall.vtu").cell_data)
    for table in ("hot_spots.csv", "speed_histogram.csv", "angle_histogram.csv"):
        names |= set((out / table).read_text().splitlines()[0].split(","))
    without = sorted(n for n in names if not unit_of(n) and n not in UNITLESS and not n.startswith("particles_angle"))
    assert without == [], without
    assert {"wall.png", "impacts.png", "worn_wall.stl"} <= {p.name for p in out.iterdir()}


def test_the_paths_in_a_case_file_and_a_sweep_of_the_wall_material(flat, tmp_path):
    """``wall.records`` and ``wall.surface`` in the case: the command needs no arguments, and a sweep over the wall's
    density gives the same volume (Finnie's closed form) and masses in proportion to the density."""
    wall_file, records, mesh = flat
    case = tmp_path / "case.toml"
    finnie = f'law = "finnie"\ncutting_fraction = {C}\nforce_ratio = {K}\ndepth_ratio = {PSI}\n'
    case.write_text(
        f"[wear]\n{finnie}[plate]\nhardness = {P}\n[wall]\nrecords = '{records}'\nsurface = '{wall_file}'\n"
    )
    assert (
        main(
            ["wall", str(case), "--set", "wall.exposure=1.0", "--quiet", "--no-figures", "--out", str(tmp_path / "one")]
        )
        == 0
    )
    one = _faces(tmp_path / "one")
    sweep = tmp_path / "sweep.toml"
    sweep.write_text(
        f'[sweep]\nstage = "wall"\n[base]\nwear.law = "finnie"\nwear.cutting_fraction = {C}\n'
        f"wear.force_ratio = {K}\nwear.depth_ratio = {PSI}\nplate.hardness = {P}\n"
        f"wall.records = '{records}'\nwall.surface = '{wall_file}'\n"
        '[grid]\n"plate.density" = [7800.0, 2700.0]\n'
    )
    assert main(["sweep", str(sweep), "--out", str(tmp_path / "sweep"), "--workers", "1", "--quiet"]) == 0
    with (tmp_path / "sweep" / "results.csv").open() as f:
        rows = list(csv.DictReader(f))
    mass = DENSITY * math.pi * DIAMETER**3 / 6.0
    n = len(mesh.cells[0].data)
    volume = n * PER_FACE * PARTICLES * finnie_1960(mass, SPEED, 90.0 - THETA)
    assert _floats(one["eroded_volume_m3"]).sum() == pytest.approx(volume, rel=1e-9)
    assert len(rows) == 2
    for row in rows:
        assert float(row["results.eroded_volume_m3"]) == pytest.approx(volume, rel=1e-9)
        density = float(row["plate.density_kg_m3"])
        assert float(row["results.eroded_mass_kg"]) == pytest.approx(density * volume, rel=1e-9)
