"""What a user of the installed package sees around the code: one version, type markers, the license, how to cite,
the changelog, the supported versions, and a matplotlib left as the user set it."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from importlib.metadata import version
from pathlib import Path

import pytest

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[1]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
PACKAGES = ("contact", "fem", "wear")
#: the seed paper's title, as its header gives it (the model the toolkit implements)
PAPER = "A Computational Wear Model of the Oblique Impact of a Ball on a Flat Plate"


def test_version_is_the_installed_one_in_every_package():
    import contact
    import fem
    import wear

    assert version("impactwear") == PYPROJECT["project"]["version"]
    assert contact.__version__ == fem.__version__ == wear.__version__ == version("impactwear")


def test_every_package_ships_a_py_typed_marker():
    package_data = PYPROJECT["tool"]["setuptools"]["package-data"]
    for name in PACKAGES:
        assert (ROOT / name / "py.typed").is_file(), name
        assert "py.typed" in package_data[name], name


def test_license_file_is_the_stated_license():
    assert PYPROJECT["project"]["license"] == "BSD-3-Clause"
    assert PYPROJECT["project"]["license-files"] == ["LICENSE"]
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("BSD 3-Clause License")
    assert "Neither the name of the copyright holder" in text  # the third clause


def test_citation_file_is_cff_1_2_with_the_paper_as_reference():
    yaml = pytest.importorskip("yaml")
    cff = yaml.safe_load((ROOT / "CITATION.cff").read_text(encoding="utf-8"))
    assert cff["cff-version"] == "1.2.0"
    for key in ("message", "title", "authors"):  # the keys CFF 1.2.0 requires
        assert cff[key], key
    assert cff["license"] == PYPROJECT["project"]["license"]
    paper = [r for r in cff["references"] if r["title"] == PAPER]
    assert len(paper) == 1 and paper[0]["type"] == "article" and paper[0]["authors"]
    assert PAPER.split(" of the ")[0] in (ROOT / "README.md").read_text(encoding="utf-8")


def test_changelog_has_the_current_version():
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert re.search(rf"^## \[{re.escape(PYPROJECT['project']['version'])}\]", text, re.MULTILINE)
    assert re.search(r"^## \[Unreleased\]", text, re.MULTILINE)


def test_readme_states_every_lower_bound_as_untested():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    section = readme[readme.index("## Supported versions") :]
    section = " ".join(section[: section.index("\n## ", 1)].split())
    assert "untested" in section
    assert f"Python ≥ {PYPROJECT['project']['requires-python'].removeprefix('>=')}" in section
    for requirement in PYPROJECT["project"]["dependencies"]:
        name, bound = re.match(r"([\w-]+)>=([\w.]+)", requirement).groups()
        assert f"{name} ≥ {bound}" in section, requirement


@pytest.mark.parametrize("backend", ["svg", "pdf"])
def test_importing_and_plotting_keep_the_users_matplotlib_backend(backend, tmp_path):
    """The user's backend survives ``import wear, wear.app.cli`` and a figure the toolkit writes (a fresh process:
    this one's backend is already chosen)."""
    code = f"""
import matplotlib
matplotlib.use({backend!r})
import wear, wear.app.cli
from wear.app.figures.erosion import plot_time_series
assert matplotlib.get_backend() == {backend!r}, matplotlib.get_backend()
plot_time_series([0.0, 1.0], [0.0, 1e-9], [0.0, 1e-6], {str(tmp_path / "e.png")!r}, "t")
assert matplotlib.get_backend() == {backend!r}, matplotlib.get_backend()
"""
    env = {k: v for k, v in os.environ.items() if k != "MPLBACKEND"}
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), *filter(None, [os.environ.get("PYTHONPATH")])])
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    assert (tmp_path / "e.png").stat().st_size > 0
