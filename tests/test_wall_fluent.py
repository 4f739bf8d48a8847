"""Fluent DPM sample files (wear.wall.fluent) against the values they were written from.

The files of tests/data/fluent were written from the rule coded again in ``_written`` below (see its README): record
k's point, angle, speed, diameter, density and particles. The reader plus :func:`wear.wall.hits.hits_on_wall` must
give back that angle, speed, particle mass (ρ π d³ / 6) and count, within the 7 printed digits, and each face's
Finnie volume must be the closed form of Finnie (1960), Wear 3: 87–103, coded here from the paper (W = c m V²/(p ψ
K) · (sin 2α − (6/K) sin² α) for tan α ≤ K/6, else · K cos² α / 6), summed over the records on the face.
"""

from __future__ import annotations

import gzip
import math
import re
from pathlib import Path

import meshio
import numpy as np
import pytest
from wall_cases import flat_mesh

from wear.laws.finnie import finnie_volume
from wear.wall import face_sum, hits_on_wall, read_surface
from wear.wall.fluent import count_fluent_rows, read_fluent_dpm

DATA = Path(__file__).resolve().parent / "data" / "fluent"
UNSTEADY = DATA / "plate_unsteady.dpm"
N = 30
P, PSI, K, C = 1e9, 2.0, 2.0, 0.5


def _written() -> dict[str, np.ndarray]:
    """The values record k of the files was written from (tests/data/fluent/README.md)."""
    mesh = flat_mesh()
    tri, pts = mesh.cells[0].data, mesh.points
    k = np.arange(N)
    t = k % len(tri)
    theta = np.array([10.0, 30.0, 45.0, 60.0, 75.0, 80.0])[k % 6]
    diameter = np.array([100e-6, 250e-6, 400e-6])[k % 3]
    density = np.array([2650.0, 7800.0])[k % 2]
    return {
        "triangle": t,
        "position": 0.2 * pts[tri[t, 0]] + 0.3 * pts[tri[t, 1]] + 0.5 * pts[tri[t, 2]],
        "theta": theta,
        "speed": np.array([5.0, 12.5, 25.0, 40.0])[k % 4],
        "mass": density * math.pi * diameter**3 / 6.0,
        "count": np.array([1.0, 7.5, 40.0, 123.25])[k % 4],
        "flow_time": 1e-3 * (k + 1),
    }


def finnie_1960(mass: float, speed: float, theta_deg: float) -> float:
    """Finnie's volume of one particle (m³), α = 90° − θ from the surface."""
    a = math.radians(90.0 - theta_deg)
    scale = C * mass * speed**2 / (P * PSI * K)
    if math.tan(a) <= K / 6.0:
        return scale * (math.sin(2 * a) - 6.0 / K * math.sin(a) ** 2)
    return scale * K * math.cos(a) ** 2 / 6.0


@pytest.fixture(scope="module")
def wall(tmp_path_factory):
    path = tmp_path_factory.mktemp("wall") / "plate.vtu"
    meshio.write(path, flat_mesh())
    wall = read_surface(path)
    # the wall's face f is the mesh's triangle f, so the face of record k is known from how it was written
    tri = flat_mesh().cells[0].data
    for f in range(len(wall)):
        assert sorted(wall.face_points[wall.face_offsets[f] : wall.face_offsets[f + 1]]) == sorted(tri[f])
    return wall


def test_the_written_stream_comes_back_record_by_record(wall):
    records = read_fluent_dpm(UNSTEADY, wall)
    hits = hits_on_wall(records, wall)
    w = _written()
    assert len(records) == N and np.array_equal(records.row, np.arange(1, N + 1))
    assert np.array_equal(hits.face, w["triangle"])
    assert np.allclose(records.position, w["position"], rtol=0.0, atol=1e-9)
    assert np.allclose(hits.angle, w["theta"], rtol=0.0, atol=1e-4)  # 7 digits: 1e-6 rad at most
    assert np.allclose(hits.speed, w["speed"], rtol=2e-6, atol=0.0)
    assert np.allclose(records.mass, w["mass"], rtol=2e-6, atol=0.0)
    assert np.array_equal(records.count, w["count"])
    assert np.allclose(records.time, w["flow_time"], rtol=1e-6, atol=0.0)


def test_each_face_s_finnie_volume_is_the_closed_form_summed_over_its_records(wall):
    records = read_fluent_dpm(UNSTEADY, wall)
    hits = hits_on_wall(records, wall)
    volume = records.count * finnie_volume(records.mass, hits.speed, hits.angle, P, K, PSI, C)
    per_face = face_sum(len(wall), hits, volume)
    w = _written()
    expected = np.zeros(len(wall))
    for k in range(N):
        expected[w["triangle"][k]] += w["count"][k] * finnie_1960(w["mass"][k], w["speed"][k], w["theta"][k])
    assert np.all(expected > 0.0)  # every face hit: 30 records on 24 faces
    assert np.allclose(per_face, expected, rtol=1e-5, atol=0.0)


def test_steady_no_name_and_gzipped_files_give_the_same_records(tmp_path):
    unsteady = read_fluent_dpm(UNSTEADY)
    packed = tmp_path / "plate_unsteady.dpm.gz"
    packed.write_bytes(gzip.compress(UNSTEADY.read_bytes()))
    for path in (DATA / "plate_steady.dpm", DATA / "plate_no_name.dpm", packed):
        other = read_fluent_dpm(path)
        for name in ("position", "velocity", "diameter", "density", "count"):
            assert np.array_equal(getattr(other, name), getattr(unsteady, name)), (path.name, name)
        assert other.files == (str(path),)
    assert np.array_equal(read_fluent_dpm(DATA / "plate_steady.dpm").time, np.zeros(N))  # no flow time


def test_rows_read_in_chunks_are_the_whole_file_and_keep_their_row_numbers():
    whole = read_fluent_dpm(UNSTEADY)
    assert count_fluent_rows(UNSTEADY) == N
    chunks = [read_fluent_dpm(UNSTEADY, None, start, 7) for start in range(0, N, 7)]
    assert [len(c) for c in chunks] == [7, 7, 7, 7, 2]
    assert np.array_equal(np.concatenate([c.row for c in chunks]), whole.row)
    assert np.array_equal(np.concatenate([c.velocity for c in chunks]), whole.velocity)
    assert len(read_fluent_dpm(UNSTEADY, None, N)) == 0
    assert np.array_equal(read_fluent_dpm(UNSTEADY, None, np.int64(28), np.int64(5)).row, [29, 30])


def test_a_closing_line_blank_lines_fewer_printed_digits_and_no_rows_are_read(tmp_path):
    lines = UNSTEADY.read_text().splitlines()
    path = tmp_path / "short.dpm"
    # 4 significant digits (a %.3e writer): parcel-mass vs n × mass then agrees to 1.5e-3, not 1.5e-6
    rounded = [_edit(line, {c: f"{float(_value(line, c)):.3e}" for c in MASS}) for line in lines[2:]]
    path.write_text("\n".join([lines[0], "", lines[1], *rounded, ")", ""]))
    records = read_fluent_dpm(path)
    assert len(records) == N
    assert np.allclose(records.mass, _written()["mass"], rtol=1e-3, atol=0.0)
    path.write_text("\n".join(lines[:2]) + "\n")  # sampling started, no hit yet
    assert len(read_fluent_dpm(path)) == 0 and count_fluent_rows(path) == 0


COLUMNS = "x y z u v w diameter t parcel-mass mass n-in-parcel time flow-time".split()
MASS = ("parcel-mass", "mass", "n-in-parcel")


def _value(line: str, column: str) -> str:
    return line[2 : line.index(")")].split()[COLUMNS.index(column)]


def _edit(line: str, values: dict[str, str]) -> str:
    """A row with some columns' text replaced."""
    close = line.index(")")
    tokens = line[2:close].split()
    for column, text in values.items():
        tokens[COLUMNS.index(column)] = text
    return "((" + " ".join(tokens) + line[close:]


def _times(line: str, column: str, factor: float) -> dict[str, str]:
    return {column: f"{float(_value(line, column)) * factor:.6e}"}


# (what, row, edit of the row, the column(s) the message names, its words)
BAD_ROWS = [
    ("NaN", 5, lambda s: _edit(s, {"u": "nan"}), "columns u v w", "not a finite number"),
    ("negative diameter", 6, lambda s: _edit(s, {"diameter": "-2.5e-04"}), "column diameter", "out of range"),
    ("diameter in µm", 7, lambda s: _edit(s, {"diameter": "400"}), "column diameter", "give the diameter in m"),
    (
        "short row",
        8,
        lambda s: "((" + " ".join(s[2 : s.index(")")].split()[:11]) + ") injection-0:7)",
        "column time",
        "11 values for the header's 13",
    ),
    ("long row", 9, lambda s: s.replace(") inj", " 1.0) inj"), "column flow-time", "14 values for the header's 13"),
    ("unparsable number", 10, lambda s: _edit(s, {"v": "1.2.3e-3"}), "column v", "'1.2.3e-3' is not a number"),
    (
        "parcel mass",
        11,
        lambda s: _edit(s, _times(s, "parcel-mass", 1.01)),
        "column parcel-mass",
        "is not n-in-parcel × mass = 40 × 2.16803e-08 kg",
    ),
    ("no particles", 12, lambda s: _edit(s, {"n-in-parcel": "0.000000e+00"}), "column n-in-parcel", "must be > 0"),
    ("zero velocity", 13, lambda s: _edit(s, {c: "0.0" for c in "uvw"}), "columns u v w", "must not be zero"),
    (
        "mass in g",
        14,
        lambda s: _edit(s, {**_times(s, "mass", 1e3), **_times(s, "parcel-mass", 1e3)}),
        "column mass",
        "density m / (π d³ / 6) = 7.8e+06 kg/m^3",
    ),
    (
        "negative mass",
        16,
        lambda s: _edit(s, {"mass": "-1.0e-09", "parcel-mass": "-1.0e-09", "n-in-parcel": "1.0"}),
        "column mass",
        "out of (0, 30000]",
    ),
    (
        "no inner parentheses",
        15,
        lambda s: s.replace("((", "(", 1).replace(") inj", " inj"),
        "column x",
        "is not a sample row",
    ),
]
# (what, edit of the header line, words)
BAD_HEADERS = [
    ("missing w", lambda h: h.replace(" w ", "   "), "no column w (a required column"),
    ("one mass column", lambda h: h.replace("parcel-mass", "p").replace(" mass ", " q "), "give two of the columns"),
    ("duplicate", lambda h: h.replace("time    flow-time", "time    time"), "column 'time' appears 2 times"),
]


@pytest.mark.parametrize("what, row, edit, column, words", BAD_ROWS, ids=[b[0] for b in BAD_ROWS])
def test_a_bad_row_is_one_line_naming_the_file_row_and_column(tmp_path, what, row, edit, column, words):
    lines = UNSTEADY.read_text().splitlines()
    lines[row + 1] = edit(lines[row + 1])  # row r is line r + 2: after the surface and the column lines
    path = tmp_path / UNSTEADY.name
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError) as err:
        read_fluent_dpm(path)
    message = str(err.value)
    assert message.startswith(f"{path}, row {row}, {column}: "), message
    assert words in message and "\n" not in message


@pytest.mark.parametrize("what, edit, words", BAD_HEADERS, ids=[b[0] for b in BAD_HEADERS])
def test_a_bad_header_is_one_line_naming_the_file_and_the_column(tmp_path, what, edit, words):
    lines = UNSTEADY.read_text().splitlines()
    lines[1] = edit(lines[1])
    path = tmp_path / UNSTEADY.name
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError) as err:
        read_fluent_dpm(path)
    message = str(err.value)
    assert message.startswith(f"{path}, header: ") and words in message and "\n" not in message, message


@pytest.mark.parametrize(
    "z, flip, words",
    [(0.004, False, "columns x y z: .* lies 0.004 m from"), (0.0, True, "columns u v w: .* points out")],
)
def test_a_record_off_the_wall_or_leaving_it_is_refused_with_its_row(tmp_path, wall, z, flip, words):
    """The face comes from the position: a hit 4 mm above the plate, or one whose velocity points back into the
    fluid (a rebound velocity), is refused by hits_on_wall naming the file, row and columns."""
    lines = UNSTEADY.read_text().splitlines()
    line = lines[2 + 3]  # row 4
    lines[2 + 3] = _edit(line, {"z": f"{z:.6e}", "w": f"{(-1.0 if flip else 1.0) * float(_value(line, 'w')):.6e}"})
    path = tmp_path / UNSTEADY.name
    path.write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError, match=rf"^{re.escape(str(path))}, row 4, {words}"):
        hits_on_wall(read_fluent_dpm(path, wall), wall)


@pytest.mark.parametrize("start_row, max_rows", [(-1, None), (0, 0), (1.5, None), (True, None)])
def test_a_bad_row_range_is_refused(start_row, max_rows):
    with pytest.raises(ValueError, match=r"^(start_row|max_rows)=.* is out of range"):
        read_fluent_dpm(UNSTEADY, None, start_row, max_rows)


def test_a_file_that_is_not_a_sample_file_is_refused(tmp_path):
    path = tmp_path / "other.dpm"
    path.write_text("x,y,z\n1,2,3\n")
    with pytest.raises(ValueError, match=rf"^{re.escape(str(path))}, header: no column line"):
        read_fluent_dpm(path)
    with pytest.raises(ValueError, match=r"is not a Fluent DPM sample text file"):
        read_fluent_dpm(tmp_path / "missing.dpm")
