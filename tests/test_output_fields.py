"""Every field a user opens carries its unit, one quantity has one name across files, and the documented one-liners
(docs/commands.md, "Reading the outputs") read the files.

Tiny runs of the fast commands (run with the axisymmetric FE plate, indent, repeat, erode, erode over angles,
calibrate, an impact sweep); the 3-D plate's mesh and arrays through their writers on small synthetic fields (no 3-D
run). The reference is the list of allowed unit suffixes and the SI names of the quantities (docs/commands.md), not
the writers' own output.
"""

from __future__ import annotations

import ast
import csv
import importlib.util
import re
import shutil
from pathlib import Path
from types import SimpleNamespace

import meshio
import numpy as np
import pytest

from wear.app.cli import main
from wear.app.outputs.fields import UNITLESS, named_mesh
from wear.app.outputs.writer import write_mesh, write_npz
from wear.case import JOBS, TABLES, Case, dump_case
from wear.chain.solid_run import SolidRun

#: The unit suffixes a name may end in (the summaries' convention: m/s is ``_m_s``, kg/kg ``_kg_per_kg``).
SUFFIXES = (
    *("m", "m2", "m3", "s", "m_s", "rad_s", "per_s", "N", "Pa", "J", "J_m3"),
    *("kg", "kg_per_kg", "kg_m2", "kg_m3", "kg_m2_s", "deg", "SI"),
)

#: Quantity → its one name; and names that must not appear (the same quantity under another name, or no unit).
CANONICAL = {
    "displacement": "displacement_m",
    "worn depth": "wear_depth_m",
    "normal force": "normal_force_N",
    "equivalent stress": "von_mises_stress_Pa",
    "erosion rate": "erosion_rate_kg_per_kg",
}
FORBIDDEN = {"u", "displacement", "depth", "wear", "wear_depth", "force_N", "von_mises", "erosion_rate", "x", "y"}

DOCS = Path(__file__).resolve().parents[1] / "docs" / "commands.md"


def _tiny_runs(tmp: Path) -> None:
    quiet = ["--quiet"]
    axisymmetric = Case().with_(
        plate={"yield_strength": None},
        fem={"mesh_scale": 8.0, "load_steps": 4, "unload_steps": 2, "coupling": "one-way"},
        wear={"pressure": "fe"},
        output={"render": False, "figures": False},
    )
    (tmp / "run.toml").write_text(dump_case(axisymmetric, JOBS["run"].tables))
    assert main(["run", str(tmp / "run.toml"), "--out", str(tmp / "run"), *quiet]) == 0
    (tmp / "repeat.toml").write_text(
        dump_case(axisymmetric.with_(fem={"coupling": "two-way"}), JOBS["run"].tables)
        + "\n[repeat]\nimpacts = 2\nsave_every = 1\n"
    )
    assert main(["repeat", str(tmp / "repeat.toml"), "--out", str(tmp / "repeat"), *quiet]) == 0
    indent = "--yield-strength inf --max-overlap 1e-7 --load-steps 3 --unload-steps 2 --set fem.mesh_scale=4"
    assert main(["indent", *indent.split(), "--no-figures", "--out", str(tmp / "indent"), *quiet]) == 0
    erode = (
        "--set erosion.grid=128 --set erosion.angle_step=10.0 --set erosion.table_speeds=2"
        " --set erosion.points_per_length=6 --set erosion.frames=2 --set erosion.samples=5"
        " --set erosion.exposure_time=600.0"
    ).split()
    assert main(["erode", *erode, "--out", str(tmp / "erode"), *quiet]) == 0
    assert main(["erode", *erode, "--angles", "20,30", "--out", str(tmp / "angles"), *quiet]) == 0
    rows = ["angle_deg,speed_m_s,erosion_kg_per_kg"] + [f"{a},30,{1e-4 * (1 + a / 30):.6g}" for a in range(15, 90, 15)]
    (tmp / "data.csv").write_text("\n".join(rows) + "\n")
    calibrate = ["calibrate", str(tmp / "data.csv"), "--law", "finnie", "--set", "plate.hardness=1.4e9"]
    assert main([*calibrate, "--out", str(tmp / "calibrate"), *quiet]) == 0
    sweep = '[sweep]\nstage = "impact"\n[grid]\n"impact.angle" = [10, 40]\n'
    (tmp / "sweep.toml").write_text(sweep)
    assert main(["sweep", str(tmp / "sweep.toml"), "--out", str(tmp / "sweep"), "--workers", "1", *quiet]) == 0


def _solid_files(tmp: Path) -> None:
    """The 3-D plate's files through their writers: the mesh as :meth:`fem.solid.indentation.SolidIndentation.
    to_meshio` builds it and the arrays of :meth:`wear.chain.solid_run.SolidRun.pressure_arrays`, on small made-up
    fields (2 tetrahedra, 3 surface vertices, 2 steps)."""
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, -1], [1, 1, -1]], float) * 1e-3
    mesh = meshio.Mesh(
        points,
        [("tetra", np.array([[0, 1, 2, 3], [1, 2, 3, 4]]))],
        point_data={"u": np.zeros((5, 3))},
        cell_data={"von_mises": [np.ones(2)], "equivalent_plastic_strain": [np.zeros(2)]},
    )
    (tmp / "solid").mkdir()
    write_mesh(tmp / "solid" / "plate_fe.vtu", mesh)
    solid = SimpleNamespace(
        surface_vertices=points[:3],
        pressure=np.zeros((2, 3)),
        shear=np.zeros((2, 3, 2)),
        sticking=np.zeros((2, 3), bool),
        slip=np.zeros((2, 3, 2)),
    )
    fake = SimpleNamespace(
        start=SimpleNamespace(pressure_arrays=dict), coupled=SimpleNamespace(times=np.zeros(2), solid=solid)
    )
    write_npz(tmp / "solid" / "pressure.npz", SolidRun.pressure_arrays(fake))


@pytest.fixture(scope="module")
def outputs(tmp_path_factory) -> Path:
    tmp = tmp_path_factory.mktemp("outputs")
    _tiny_runs(tmp)
    _solid_files(tmp)
    return tmp


def _names(path: Path) -> list[str]:
    """The field names a user sees in ``path``: mesh point and cell data, CSV columns, NPZ arrays."""
    if path.suffix == ".vtu":
        mesh = meshio.read(path)
        return [*mesh.point_data, *mesh.cell_data]
    if path.suffix == ".csv":
        with path.open(newline="", encoding="utf-8") as f:
            return next(csv.reader(f))
    with np.load(path) as npz:
        return list(npz.files)


def _all_names(root: Path) -> dict[str, list[str]]:
    files = sorted(p for ext in ("vtu", "csv", "npz") for p in root.rglob(f"*.{ext}"))
    files = [p for p in files if p.name != "data.csv"]  # the test's own input
    return {str(p.relative_to(root)): _names(p) for p in files}


def _schema_unit(column: str) -> str | None:
    """The schema's unit of a sweep input column ``table.key`` (None if the column is not a case key)."""
    table, _, name = column.partition(".")
    key = TABLES[table].keys().get(name) if table in TABLES else None
    return None if key is None else key.units


def test_every_field_name_ends_in_its_unit(outputs):
    names = _all_names(outputs)
    assert {"run/plate_fe.vtu", "repeat/wear_map.npz", "sweep/results.csv", "solid/plate_fe.vtu"} <= set(names)
    unit = re.compile(r"_(" + "|".join(SUFFIXES) + r")$")
    missing = []
    for file, fields in names.items():
        for name in fields:
            if file == "calibrate/calibration.csv" and name.startswith(("measured_", "predicted_")):
                name = name.replace("erosion_kg_per_kg", "erosion_rate_kg_per_kg")  # the data's own column
            if re.fullmatch(r"step\d+_Pa", name) or unit.search(name) or name.rpartition(".")[2] in UNITLESS:
                continue
            if file.startswith("sweep/") and _schema_unit(name) == "":
                continue  # a case key without a unit (a ratio, a model name)
            missing.append(f"{file}: {name}")
    assert not missing, missing


def test_one_quantity_one_name_across_files(outputs):
    names = _all_names(outputs)
    seen = {n for fields in names.values() for n in fields}
    assert not seen & FORBIDDEN, seen & FORBIDDEN
    assert not {n for n in seen if n.endswith(("_m_per_s", "_rad_per_s"))}
    for file in ("run/plate.vtu", "run/plate_fe.vtu", "solid/plate_fe.vtu", "repeat/frames/plate_000001.vtu"):
        assert CANONICAL["displacement"] in names[file], file
    for file in ("run/surface.vtu", "run/plate.vtu", "erode/surface.vtu", "repeat/wear_map.npz"):
        assert CANONICAL["worn depth"] in names[file], file
    assert CANONICAL["normal force"] in names["run/history.csv"]
    assert CANONICAL["normal force"] in names["indent/force_overlap.csv"]
    for file in ("run/plate_fe.vtu", "indent/plate.vtu", "solid/plate_fe.vtu"):
        assert CANONICAL["equivalent stress"] in names[file], file
    for file in ("erode/erosion.csv", "angles/erosion_vs_angle.csv"):
        assert CANONICAL["erosion rate"] in names[file], file
    # the same stem never carries two different units
    stems: dict[str, set[str]] = {}
    for n in seen:
        m = re.match(r"(.+?)_(" + "|".join(SUFFIXES) + r")$", n.rpartition(".")[2])
        if m:
            stems.setdefault(m.group(1), set()).add(n.rpartition(".")[2])
    assert all(len(v) == 1 for v in stems.values()), {k: v for k, v in stems.items() if len(v) > 1}


def test_named_mesh_keeps_a_users_own_fields():
    mesh = meshio.Mesh(np.zeros((1, 3)), [("vertex", np.array([[0]]))], point_data={"u": [[0, 0, 0]], "mine": [1]})
    assert list(named_mesh(mesh).point_data) == ["displacement_m", "mine"]


def _one_liners() -> list[ast.stmt]:
    """The statements of the Python block of the docs' "Reading the outputs"."""
    text = DOCS.read_text(encoding="utf-8")
    section = text[text.index("## Reading the outputs") :]
    return ast.parse(re.search(r"```python\n(.*?)```", section, flags=re.DOTALL).group(1)).body


def test_documented_one_liners_read_the_outputs(outputs, monkeypatch):
    """The documented lines run on the files of real output folders; a line that needs a module that is not installed
    (pandas and xarray are not dependencies), or a name such a line would have bound, is left out."""
    statements = _one_liners()
    code = [ast.unparse(s) for s in statements]
    assert any("pandas.read_csv" in c for c in code) and any("xarray.Dataset" in c for c in code)
    folder = outputs / "docs"
    folder.mkdir()
    for name in ("run/history.csv", "run/surface.vtu", "run/summary.json", "repeat/repeat.csv", "repeat/wear_map.npz"):
        shutil.copy(outputs / name, folder)
    monkeypatch.chdir(folder)
    unavailable: set[str] = set()
    namespace: dict = {}
    for statement in statements:
        if isinstance(statement, ast.Import):
            missing = {a.asname or a.name for a in statement.names if importlib.util.find_spec(a.name) is None}
            unavailable |= missing
            if missing:
                continue
        names = {n.id: n.ctx for n in ast.walk(statement) if isinstance(n, ast.Name)}
        if unavailable & set(names):
            unavailable |= {name for name, ctx in names.items() if isinstance(ctx, ast.Store)}
            continue
        exec(compile(ast.Module([statement], []), "docs/commands.md", "exec"), namespace)
    assert namespace["history"]["normal_force_N"].size > 1
    assert namespace["summary"]["schema_version"] >= 2
    assert namespace["z"]["wear_depth_m"].shape == (namespace["z"]["y_m"].size, namespace["z"]["x_m"].size)
    assert "wear_depth_m" in namespace["mesh"].point_data and "wear_depth_m" in namespace["grid"].point_data
    if "table" in namespace:
        assert "max_force_N" in namespace["table"].columns
    if "wear" in namespace:
        assert namespace["wear"]["wear_depth_m"].dims == ("y_m", "x_m")


def test_sweep_folder_of_the_earlier_names_is_resumed(outputs):
    """A sweep folder written before the units joined the names (its case records are the same; its results.csv had
    bare names) is resumed without recomputing a case, and its table rewritten with the names with units."""
    sweep = outputs / "sweep"
    old = (sweep / "results.csv").read_text().replace("impact.angle_deg", "impact.angle")
    (sweep / "results.csv").write_text(old.replace("max_force_N", "max_force"))
    stamps = {p: p.stat().st_mtime_ns for p in (sweep / "cases").glob("*.json")}
    assert main(["sweep", str(outputs / "sweep.toml"), "--out", str(sweep), "--workers", "1", "--quiet"]) == 0
    assert {p: p.stat().st_mtime_ns for p in (sweep / "cases").glob("*.json")} == stamps  # nothing recomputed
    header = (sweep / "results.csv").read_text().splitlines()[0].split(",")
    assert "impact.angle_deg" in header and "max_force_N" in header and "max_force" not in header
