"""Every summary a command writes (``summary.json``; ``calibration.json`` of ``calibrate``) starts with the one
``schema_version`` of the writer, and docs/commands.md ("The summary file") lists exactly its top-level fields.

Tiny runs of each command (the physics of each is tested in its own file); the references here are the writer's
constant and the docs' lists.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import meshio
import numpy as np
import pytest

from wear.app.cli import main
from wear.app.outputs.writer import SCHEMA_VERSION
from wear.case import JOBS, Case, dump_case

DOCS = Path(__file__).resolve().parents[1] / "docs" / "commands.md"

#: command → its arguments (a tiny case) and the summary file it writes; "{tmp}" is the test's folder
RUNS = {
    "run": "{tmp}/run.toml --out {tmp}/run".split(),
    "indent": (
        "--yield-strength inf --max-overlap 1e-7 --load-steps 3 --unload-steps 2 --set fem.mesh_scale=4 --no-figures"
        " --out {tmp}/indent"
    ).split(),
    "repeat": "{tmp}/repeat.toml --out {tmp}/repeat".split(),
    "erode": (
        "--set erosion.grid=128 --set erosion.angle_step=10.0 --set erosion.table_speeds=2"
        " --set erosion.points_per_length=6 --set erosion.frames=2 --set erosion.samples=5"
        " --set erosion.exposure_time=600.0 --out {tmp}/erode"
    ).split(),
    "calibrate": "{tmp}/data.csv --law finnie --set plate.hardness=1.4e9 --out {tmp}/calibrate".split(),
    "wall": "{tmp}/hits.csv {tmp}/plate.stl --set wall.exposure=1.0 --no-figures --out {tmp}/wall".split(),
}
FILES = {name: "calibration.json" if name == "calibrate" else "summary.json" for name in RUNS}


@pytest.fixture(scope="module")
def summaries(tmp_path_factory) -> dict[str, list]:
    """command → its summary's (key, value) pairs in file order."""
    tmp = tmp_path_factory.mktemp("summaries")
    # run: no FE plate, no figures (the chain's plumbing only)
    quick = Case().with_(
        wear={"pressure": "thornton", "speed": "sliding"},
        fem={"coupling": "none"},
        output={"render": False, "figures": False},
    )
    (tmp / "run.toml").write_text(dump_case(quick, JOBS["run"].tables))
    # repeat: one elastic impact on a coarse plate
    elastic = Case().with_(
        plate={"yield_strength": None},
        fem={"mesh_scale": 8.0, "load_steps": 4, "unload_steps": 2},
        output={"render": False, "figures": False},
    )
    (tmp / "repeat.toml").write_text(
        dump_case(elastic, JOBS["run"].tables) + "\n[repeat]\nimpacts = 1\nsave_every = 0\n"
    )
    # calibrate: Finnie's law fitted to a made-up curve (any positive wear at several angles)
    rows = ["angle_deg,speed_m_s,erosion_kg_per_kg"] + [f"{a},30,{1e-4 * (1 + a / 30):.6g}" for a in range(15, 90, 15)]
    (tmp / "data.csv").write_text("\n".join(rows) + "\n")
    # wall: one hit on a one-triangle wall (normal -z, into the wall)
    points = np.array([[0.0, 0.0, 0.0], [0.01, 0.0, 0.0], [0.0, 0.01, 0.0]])
    meshio.write(tmp / "plate.stl", meshio.Mesh(points, [("triangle", np.array([[0, 2, 1]]))]))
    (tmp / "hits.csv").write_text(
        "x_m,y_m,z_m,u_m_s,v_m_s,w_m_s,diameter_m,density_kg_m3\n0.002,0.002,0,5,0,-10,3e-4,2650\n"
    )
    out = {}
    for name, argv in RUNS.items():
        assert main([name, *(a.format(tmp=tmp) for a in argv), "--quiet"]) == 0, name
        text = (tmp / name / FILES[name]).read_text(encoding="utf-8")
        out[name] = json.loads(text, object_pairs_hook=list)
    return out


def _documented_fields() -> dict[str, set[str]]:
    """command → the top-level fields docs/commands.md lists for it: the names in backticks of each item, outside
    parentheses and before the item's first colon."""
    text = DOCS.read_text(encoding="utf-8")
    section = text[text.index("## The summary file") :]
    section = section[: section.index("\n## ", 1)]
    fields: dict[str, set[str]] = {}
    for block in re.split(r"^### ", section, flags=re.MULTILINE)[1:]:
        command = re.match(r"`impactwear (\w+)`", block).group(1)
        items = re.split(r"^- ", block, flags=re.MULTILINE)[1:]
        names = set()
        for item in items:
            item = " ".join(item.split("\n\n")[0].split())
            while re.search(r"\([^()]*\)", item):
                item = re.sub(r"\([^()]*\)", "", item)
            names |= set(re.findall(r"`([^`]+)`", item.split(": ")[0]))
        fields[command] = names
    return fields


def test_every_summary_starts_with_the_schema_version(summaries):
    assert isinstance(SCHEMA_VERSION, int) and SCHEMA_VERSION >= 1
    for name, pairs in summaries.items():
        assert pairs[0] == ("schema_version", SCHEMA_VERSION), name


def test_docs_list_every_top_level_field(summaries):
    documented = _documented_fields()
    assert set(documented) == set(RUNS)
    for name, pairs in summaries.items():
        assert documented[name] == {key for key, _ in pairs}, name


def test_json_option_prints_the_summary_written(tmp_path, capsys):
    out = tmp_path / "erode"
    argv = [a.format(tmp=tmp_path) for a in RUNS["erode"]]
    assert main(["erode", *argv, "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    assert printed["schema_version"] == SCHEMA_VERSION
    assert printed == json.loads((out / "summary.json").read_text(encoding="utf-8"))
