"""The OpenFOAM file formats users' cases are in, read as the ascii original is.

Source: the committed v1912 bend run's polyMesh and its Q field (``kinematicCloudQ``, OpenFOAM's own Finnie eroded
volume per face), ascii with gzipped points/faces/owner (wear/app/data/openfoam_bend), rewritten by OpenFOAM v1912
itself (Debian's openfoam 1912.200626, ``foamFormatConvert -constant``; examples/openfoam_bend/convert_formats.sh)
as ``writeFormat binary`` (tests/data/openfoam_bend_binary: a ``faceCompactList``; v1912 writes binary uncompressed)
and as ``writeFormat ascii; writeCompression on`` (tests/data/openfoam_bend_compressed: every file ``.gz``, the
boundary too). Each gives the same wall (points to round-off, faces, face order, labels, patches exactly), the same Q
and, through ``impactwear wall``, the same eroded volume on every face. A decomposed case (processor folders and no
mesh or field at the root) is refused in one line naming the OpenFOAM command that reconstructs it.
"""

from __future__ import annotations

import csv
import gzip
import shutil
from pathlib import Path

import numpy as np
import pytest
from refusal import refused
from wall_cases import OUTPUTS, RECORDS, erosion_constants, openfoam_finnie_case

from wear.app.cli import main
from wear.wall import (
    face_sum,
    hits_on_wall,
    read_patch_field,
    read_patch_post_processing,
    read_polymesh,
    record_volumes,
    wall_law,
)
from wear.wall.component import read_wall
from wear.wall.foam import DecomposedCaseError
from wear.wall.options import WallOptions

DATA = Path(__file__).resolve().parent / "data"
CASES = {"binary": DATA / "openfoam_bend_binary", "compressed": DATA / "openfoam_bend_compressed"}
FIELD = Path("0.12") / "kinematicCloudQ"


@pytest.fixture(scope="module")
def reference():
    """The wall, OpenFOAM's Q and impactwear's per-face volume (Finnie with OpenFOAM's constants, the recorded
    normal) of the ascii original."""
    wall = read_polymesh(OUTPUTS)
    records = read_patch_post_processing(RECORDS, wall)
    hits = hits_on_wall(records, wall, WallOptions(normal="recorded"))
    volume = face_sum(len(wall), hits, record_volumes(wall_law(openfoam_finnie_case()), records, hits))
    return wall, read_patch_field(OUTPUTS / "kinematicCloudQ", wall), volume


def _same_wall(wall, ascii_wall) -> None:
    assert wall.patch_names == ascii_wall.patch_names == ("wallIn", "bend", "wallOut")
    for name in ("labels", "patch", "face_offsets", "face_points"):
        assert np.array_equal(getattr(wall, name), getattr(ascii_wall, name)), name
    # the binary points are the doubles OpenFOAM parsed from the 17-digit ascii: equal or one ulp off (m)
    assert np.allclose(wall.points, ascii_wall.points, rtol=1e-15, atol=0)
    assert np.allclose(wall.area, ascii_wall.area, rtol=1e-13, atol=0)


def test_the_data_are_openfoams_binary_and_compressed_writes():
    """What convert_formats.sh keeps (foamFormatConvert v1912): binary headers and a faceCompactList; every file
    of the compressed case gzipped, none plain."""
    faces = (CASES["binary"] / "constant" / "polyMesh" / "faces").read_bytes()[:1000]
    assert b"format      binary;" in faces and b"class       faceCompactList;" in faces
    assert b'arch        "LSB;label=32;scalar=64";' in faces
    assert b"format      binary;" in (CASES["binary"] / FIELD).read_bytes()[:1000]
    files = [p for p in CASES["compressed"].rglob("*") if p.is_file()]
    assert len(files) == 4 and all(p.suffix == ".gz" for p in files)
    boundary = gzip.decompress((CASES["compressed"] / "constant" / "polyMesh" / "boundary.gz").read_bytes())
    assert b"format      ascii;" in boundary[:1000]


@pytest.mark.parametrize("form", CASES)
def test_the_converted_mesh_gives_the_ascii_wall_and_field(form, reference):
    """Source: OpenFOAM v1912 foamFormatConvert of the shipped ascii mesh and Q (binary; ascii + writeCompression)."""
    ascii_wall, q, _ = reference
    wall = read_polymesh(CASES[form])
    _same_wall(wall, ascii_wall)
    _same_wall(read_wall(CASES[form] / "constant"), ascii_wall)  # the case, its constant, its polyMesh
    assert np.allclose(read_patch_field(CASES[form] / FIELD, wall), q, rtol=1e-15, atol=0)


def test_a_gzipped_binary_mesh_reads_as_the_plain_one(tmp_path, reference):
    """OpenFOAM v1912 foamFormatConvert's binary mesh, gzipped here (v1912 will not write compressed binary; OpenFOAM
    reads it, and other versions write it)."""
    case = tmp_path / "case"
    shutil.copytree(CASES["binary"], case)
    for path in [*case.rglob("faces"), *case.rglob("points"), *case.rglob("kinematicCloudQ")]:
        path.with_name(f"{path.name}.gz").write_bytes(gzip.compress(path.read_bytes()))
        path.unlink()
    wall = read_polymesh(case)
    _same_wall(wall, reference[0])
    assert np.allclose(read_patch_field(case / FIELD, wall), reference[1], rtol=1e-15, atol=0)


def _faces_csv(out: Path) -> dict[str, np.ndarray]:
    with (out / "faces.csv").open() as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([r[k] for r in rows]) for k in ("label", "eroded_volume_m3")}


@pytest.mark.parametrize("form", CASES)
def test_impactwear_wall_erodes_the_converted_case_as_the_ascii_one(form, reference, tmp_path):
    """``impactwear wall`` on the run's records with the converted case (OpenFOAM v1912 foamFormatConvert) as the
    wall: every face's eroded volume that of the ascii original to the digits written, and within 1e-6 of the Q OpenFOAM
    wrote (tests/test_wall_openfoam.py's bound), read from the converted field."""
    ascii_wall, _, volume = reference
    c = erosion_constants()
    argv = ["wall", str(RECORDS), str(CASES[form]), "--set", 'wear.law="finnie"', "--set", "wear.cutting_fraction=1.0"]
    argv += ["--set", f"wear.force_ratio={c['K']}", "--set", f"wear.depth_ratio={c['psi']}"]
    argv += ["--set", f"plate.hardness={c['p']}", "--set", "wall.exposure=0.05"]
    out = tmp_path / "out"
    assert main([*argv, "--no-figures", "--quiet", "--out", str(out)]) == 0
    faces = _faces_csv(out)
    assert np.array_equal(faces["label"].astype(int), ascii_wall.labels)
    eroded = faces["eroded_volume_m3"].astype(float)
    assert np.allclose(eroded, volume, rtol=1e-9, atol=0)  # faces.csv holds 10 significant digits
    q = read_patch_field(CASES[form] / FIELD, read_polymesh(CASES[form]))
    hit = q > 0
    assert hit.sum() == 756 and np.all(eroded[~hit] == 0.0)
    assert np.max(np.abs(eroded[hit] / q[hit] - 1.0)) < 1e-6


def _decomposed(root: Path, parts: int = 2, mesh: bool = False) -> Path:
    """A decomposed case's layout (the files decomposePar writes that matter here): processor<i>/constant/polyMesh
    (the shipped mesh as a stand-in for each part), and constant/polyMesh at the root only if ``mesh``."""
    case = root / "case"
    for i in range(parts):
        shutil.copytree(OUTPUTS / "polyMesh", case / f"processor{i}" / "constant" / "polyMesh")
    (case / "system").mkdir()
    if mesh:
        shutil.copytree(OUTPUTS / "polyMesh", case / "constant" / "polyMesh")
    return case


def test_impactwear_wall_refuses_a_decomposed_case_naming_reconstructparmesh(tmp_path, capsys):
    """Before: 'holds no OpenFOAM polyMesh and no surface file'. OpenFOAM v1912 rebuilds constant/polyMesh from the
    processor folders with reconstructParMesh -constant (reconstructPar needs that mesh: tried)."""
    case = _decomposed(tmp_path)
    line = refused(["wall", str(RECORDS), str(case), "--set", "wall.exposure=1.0"], tmp_path, capsys)
    assert str(case) in line and "decomposed" in line and "2 processor folders" in line, line
    assert f"cd {case} && reconstructParMesh -constant" in line, line
    for path in (case, case / "constant"):
        with pytest.raises(DecomposedCaseError, match="reconstructParMesh -constant"):
            read_polymesh(path)


@pytest.mark.parametrize("mesh", [True, False])
def test_a_field_only_in_the_processor_folders_names_reconstructpar(tmp_path, mesh):
    """The field of a time written by a parallel run is in processor*/<time>: reconstructPar -time <time> (OpenFOAM
    v1912), after reconstructParMesh -constant when the root has no mesh."""
    case = _decomposed(tmp_path, mesh=True)
    wall = read_polymesh(case)
    for i in range(2):
        (case / f"processor{i}" / "0.12").mkdir()
        shutil.copy(OUTPUTS / "kinematicCloudQ.gz", case / f"processor{i}" / "0.12")
    if not mesh:
        shutil.rmtree(case / "constant")
    with pytest.raises(ValueError) as err:
        read_patch_field(case / FIELD, wall)
    message = str(err.value)
    assert "\n" not in message and str(case / FIELD) in message and "processor0/0.12" in message
    rebuild = "reconstructPar -time 0.12" if mesh else "reconstructParMesh -constant && reconstructPar -time 0.12"
    assert message.endswith(f"(cd {case} && {rebuild})"), message


def test_a_small_polyhedral_mesh_in_every_face_format_gives_one_wall(tmp_path):
    """Hand-written to OpenFOAM's layouts (v1912 Ostream: a faceList ``N(k(p0 ... pk-1) ...)``; a faceCompactList
    of N + 1 offsets then the flat points, ascii or binary with the header's arch): a pentagon and a triangle, faces
    of 5 and 3 points as a polyhedral (snappyHexMesh, polyDualMesh) mesh has, read alike, the binary one with 64-bit
    labels."""
    header = "FoamFile\n{{\n    format      {form};\n    class       {cls};\n"
    header += '    arch        "LSB;label={bits};scalar=64";\n}}\n'
    points = np.array([[0, 0, 0], [2, 0, 0], [3, 1, 0], [1, 2, 0], [-1, 1, 0], [1, -1, 0]], dtype=float) * 0.01
    boundary = "2\n(\n    plate\n    {\n        type wall;\n        nFaces 2;\n        startFace 1;\n    }\n"
    boundary += "    other\n    {\n        type patch;\n        nFaces 0;\n        startFace 3;\n    }\n)\n"
    faces = [[0, 1, 2], [4, 3, 2, 1, 0], [0, 1, 5]]  # face 0 an internal one, not read; both -z
    offsets = np.cumsum([0] + [len(f) for f in faces])
    flat = np.concatenate(faces)
    layouts = {
        "faceList": "3\n(\n" + "\n".join(f"{len(f)}({' '.join(map(str, f))})" for f in faces) + "\n)\n",
        "ascii compact": f"4\n({' '.join(map(str, offsets))})\n\n{len(flat)}\n({' '.join(map(str, flat))})\n",
    }
    walls = []
    for name, body in [*layouts.items(), ("binary compact", None)]:
        mesh = tmp_path / name.replace(" ", "_") / "constant" / "polyMesh"
        mesh.mkdir(parents=True)
        ascii_points = header.format(form="ascii", cls="vectorField", bits=32) + "6\n(\n"
        (mesh / "points").write_text(ascii_points + "\n".join(f"({x} {y} {z})" for x, y, z in points) + "\n)\n")
        (mesh / "boundary").write_text(header.format(form="ascii", cls="polyBoundaryMesh", bits=32) + boundary)
        cls = "faceList" if name == "faceList" else "faceCompactList"
        if body is not None:
            (mesh / "faces").write_text(header.format(form="ascii", cls=cls, bits=32) + body)
        else:
            data = header.format(form="binary", cls=cls, bits=64).encode()
            data += (
                b"4(" + offsets.astype("<i8").tobytes() + b")\n%d(" % len(flat) + flat.astype("<i8").tobytes() + b")\n"
            )
            (mesh / "faces").write_bytes(data)
        walls.append(read_polymesh(mesh.parent.parent))
    for wall in walls:
        assert wall.patch_names == ("plate",) and wall.labels.tolist() == [1, 2]
        assert wall.sizes.tolist() == [5, 3] and wall.other_patches == (("other", 3, 0),)
        assert np.allclose(wall.area, [5e-4, 1e-4], rtol=1e-12, atol=0)  # shoelace: 5 cm², 1 cm²
        assert np.allclose(wall.normal, [[0, 0, -1], [0, 0, -1]], rtol=0, atol=1e-15)
        assert np.array_equal(wall.points[wall.face_points], walls[0].points[walls[0].face_points])


@pytest.mark.parametrize(
    ("damage", "says"),
    [
        (lambda b: b[:-500], r"points: the binary list of 17745 does not end after its 53235 numbers of 8 bytes"),
        (lambda b: b.replace(b"format      binary;", b"format      hdf5;"), r"format hdf5: rerun foamFormatConvert"),
        (lambda b: b.replace(b"FoamFile", b"FoamFil"), r"points has no FoamFile header"),
    ],
)
def test_a_damaged_binary_file_is_refused_in_one_line_naming_it(tmp_path, damage, says):
    case = tmp_path / "case"
    shutil.copytree(CASES["binary"], case)
    points = case / "constant" / "polyMesh" / "points"
    points.write_bytes(damage(points.read_bytes()))
    with pytest.raises(ValueError, match=says) as err:
        read_polymesh(case)
    assert "\n" not in str(err.value) and str(points) in str(err.value)
