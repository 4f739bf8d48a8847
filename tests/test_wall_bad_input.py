"""Bad impact records and walls: each is one line naming the file, the row and the column (the command layer
turns it into exit 2), found before any sum."""

from __future__ import annotations

import gzip

import meshio
import numpy as np
import pytest
from wall_cases import OUTPUTS, RECORDS, flat_mesh, write_csv

from wear.wall import hits_on_wall, read_patch_post_processing, read_polymesh, read_surface, read_table
from wear.wall.options import WallOptions

HEADER = ["x_m", "y_m", "z_m", "u_m_s", "v_m_s", "w_m_s", "diameter_m", "density_kg_m3", "particles", "face"]
GOOD = ["0.01", "0.01", "0", "3", "0", "-20", "2e-4", "2650", "10", "-1"]


def _row(**change):
    row = dict(zip(HEADER, GOOD, strict=True))
    row.update({k: str(v) for k, v in change.items()})
    return [row[h] for h in HEADER]


@pytest.fixture(scope="module")
def flat(tmp_path_factory):
    path = tmp_path_factory.mktemp("wall") / "plate.vtu"
    meshio.write(path, flat_mesh())
    return read_surface(path)


def _fails(message: str, file: str, row: int | str, column: str) -> None:
    assert "\n" not in message
    where = f"{file}, row {row}, column" if isinstance(row, int) else f"{file}, {row}"
    assert message.startswith(where) and column in message, message


# (column changed on row 3, its value, what the message says); the row of a table is counted after the header
TABLE_CASES = [
    ("diameter_m", "nan", "is not a finite number"),
    ("diameter_m", "-2e-4", "is out of range: give the diameter in m"),
    ("diameter_m", "200", "is out of range: give the diameter in m"),  # µm given as m
    ("density_kg_m3", "0", r"is out of range: give the particle density in kg/m\^3"),
    ("particles", "-5", "particles per record must be > 0"),
    ("u_m_s", "fast", "'fast' is not a number"),
    ("x_m", "inf", "is not a finite number"),
    ("face", "1.5", "'1.5' is not an integer"),
    ("face", "-3", "is out of range: a face index is >= 0"),
]


@pytest.mark.parametrize(("column", "value", "says"), TABLE_CASES)
def test_a_bad_value_in_the_table_names_file_row_and_column(tmp_path, column, value, says):
    path = write_csv(tmp_path / "hits.csv", HEADER, [_row(), _row(), _row(**{column: value}), _row()])
    with pytest.raises(ValueError, match=says) as err:
        read_table(path)
    _fails(str(err.value), str(path), 3, column)


def test_a_zero_velocity_names_the_velocity_columns(tmp_path):
    path = write_csv(tmp_path / "hits.csv", HEADER, [_row(), _row(u_m_s=0, w_m_s=0)])
    with pytest.raises(ValueError, match="columns u_m_s v_m_s w_m_s: .* must not be zero") as err:
        read_table(path)
    _fails(str(err.value), str(path), 2, "u_m_s")


def test_a_normal_that_is_not_a_unit_vector_names_its_row(tmp_path):
    header = [*HEADER, "nx", "ny", "nz"]
    path = write_csv(tmp_path / "hits.csv", header, [[*_row(), "0", "0", "-1"], [*_row(), "0", "0", "-2"]])
    with pytest.raises(ValueError, match=r"\(0 0 -2\) is not a unit vector") as err:
        read_table(path)
    _fails(str(err.value), str(path), 2, "nx ny nz")


def test_a_row_with_a_missing_value_and_an_unknown_column_are_refused(tmp_path):
    path = write_csv(tmp_path / "short.csv", HEADER, [_row(), _row()[:-1]])
    with pytest.raises(ValueError, match=r"short\.csv, row 2: 9 values for the header's 10 columns"):
        read_table(path)
    path = write_csv(tmp_path / "extra.csv", [*HEADER, "speed"], [[*_row(), "20"]])
    with pytest.raises(ValueError, match=r"extra\.csv, header: column 'speed' is not one of x_m"):
        read_table(path)
    path = write_csv(tmp_path / "partial.csv", HEADER[:-1] + ["nx"], [_row()[:-1] + ["0"]])
    with pytest.raises(ValueError, match=r"partial\.csv, header: column 'ny' is missing \(give nx, ny, nz together\)"):
        read_table(path)


def test_a_velocity_pointing_out_of_the_wall_names_its_row(tmp_path, flat):
    path = write_csv(tmp_path / "hits.csv", HEADER, [_row(), _row(w_m_s=20)])
    records = read_table(path)
    with pytest.raises(ValueError, match=r"\(3 0 20\) points out of the wall \(171\.\d+ deg from the normal") as err:
        hits_on_wall(records, flat)
    _fails(str(err.value), str(path), 2, "u_m_s v_m_s w_m_s")
    hits = hits_on_wall(records, flat, WallOptions(skip_bad=True))  # counted, left out of every sum
    assert hits.skipped == {"leaving_wall": 1} and hits.face[1] == -1 and hits.face[0] >= 0


def test_a_hit_far_from_every_wall_face_names_its_row(tmp_path, flat):
    # 1 cm above a mesh of 1 cm squares cut in two: the default tolerance is a quarter of sqrt(0.5 cm^2) = 1.77 mm
    path = write_csv(tmp_path / "hits.csv", HEADER, [_row(), _row(), _row(z_m=0.01)])
    with pytest.raises(
        ValueError,
        match=r"lies 0\.01 m from the nearest wall face, face \d+ \(label \d+\) of patch plate, farther than "
        r"tolerance=0\.00176777 m",
    ) as err:
        hits_on_wall(read_table(path), flat)
    _fails(str(err.value), str(path), 3, "x_m y_m z_m")
    # on the wall but 3 cm from the face the row gives (face 0: the square at the origin)
    path = write_csv(tmp_path / "given.csv", HEADER, [_row(x_m=0.035, y_m=0.025, face=0)])
    with pytest.raises(ValueError, match=r"lies 0\.0\d+ m from its face, face 0 \(label 0\) of patch plate") as err:
        hits_on_wall(read_table(path), flat)
    _fails(str(err.value), str(path), 1, "x_m y_m z_m")


def test_a_face_beyond_the_wall_names_its_row(tmp_path, flat):
    path = write_csv(tmp_path / "hits.csv", HEADER, [_row(face=99)])
    with pytest.raises(ValueError, match="99 is out of range: the wall has 24 faces") as err:
        hits_on_wall(read_table(path), flat)
    _fails(str(err.value), str(path), 1, "face")


@pytest.fixture(scope="module")
def bend_wall():
    return read_polymesh(OUTPUTS)


def _post(tmp_path, edit) -> str:
    """A copy of the 0.02 s bend records with ``edit(fields of row 2)`` applied; the path."""
    lines = gzip.decompress((RECORDS / "0.02" / "bend.post.gz").read_bytes()).decode().splitlines()
    lines[2] = edit(lines[2])
    path = tmp_path / "bend.post"
    path.write_text("\n".join(lines) + "\n")
    return str(path)


def _token(line: str, k: int, value: str) -> str:
    """``line`` with its k-th value (counting the header's columns, parentheses ignored) replaced."""
    out, n = [], 0
    for token in line.split(" "):
        core = token.strip("()")
        if core:
            if n == k:
                token = token.replace(core, value)
            n += 1
        out.append(token)
    return " ".join(out)


HEADER_POST = gzip.decompress((RECORDS / "0.02" / "bend.post.gz").read_bytes()).decode().splitlines()[0]
POST_COLUMNS = HEADER_POST[1:].replace("(", " ").replace(")", " ").split()


@pytest.mark.parametrize(
    ("column", "value", "says"),
    [
        ("d", "-1e-4", "is out of range: give the diameter in m"),
        ("rho", "nan", "is not a finite number"),
        ("nParticle", "0", "particles per record must be > 0"),
        ("facei", "100", "100 is not a face of the wall's patches wallIn, bend, wallOut"),
        ("tetPti", "7", "no triangle of face .* puts the hit's barycentric coordinates at its position"),
        ("position0", "0.5", "no triangle of face .* puts the hit's barycentric coordinates at its position"),
        ("U1", "1e", "'1e' is not a number"),
    ],
)
def test_a_bad_openfoam_record_names_file_row_and_column(tmp_path, bend_wall, column, value, says):
    path = _post(tmp_path, lambda line: _token(line, POST_COLUMNS.index(column), value))
    with pytest.raises(ValueError, match=says) as err:
        read_patch_post_processing(path, bend_wall)
    _fails(str(err.value), path, 2, column if column not in ("position0",) else "coordinates1")


def test_an_openfoam_file_without_a_needed_column_or_with_a_short_row_is_refused(tmp_path, bend_wall):
    path = _post(tmp_path, lambda line: line.rsplit(" ", 3)[0])
    with pytest.raises(ValueError, match=r"column torque0: the row has 36 values for the header's 39 columns") as err:
        read_patch_post_processing(path, bend_wall)
    _fails(str(err.value), path, 2, "torque0")
    text = (tmp_path / "bend.post").read_text().replace(" d dTarget", " dTarget", 1)
    (tmp_path / "bend.post").write_text(text)
    with pytest.raises(ValueError, match=r"bend\.post, header: no column d \(the header names Time currentProc"):
        read_patch_post_processing(path, bend_wall)


def test_a_bad_wall_is_refused(tmp_path):
    tetra = meshio.Mesh(np.eye(4)[:, :3], [("tetra", np.array([[0, 1, 2, 3]]))])
    meshio.write(tmp_path / "volume.vtu", tetra)
    with pytest.raises(ValueError, match=r"volume\.vtu' is a volume mesh \(tetra cells\): give the wall's surface"):
        read_surface(tmp_path / "volume.vtu")
    (tmp_path / "junk.stl").write_text("not a mesh\n")
    with pytest.raises(ValueError, match=r"junk\.stl' is not a surface meshio reads"):
        read_surface(tmp_path / "junk.stl")
    with pytest.raises(ValueError, match=r"patches=\['pipe'\] are not in .*boundary: its patches are \['inlet'"):
        read_polymesh(OUTPUTS, patches=["pipe"])
