"""The README's Python example runs as written (the README is the first page a user reads)."""

import re
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"


@pytest.mark.filterwarnings("ignore:elastic ball")
def test_readme_python_example_runs():
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)
    assert len(blocks) == 1, "the README holds one Python example"
    namespace: dict = {}
    exec(compile(blocks[0], str(README), "exec"), namespace)  # noqa: S102 - the README's own example
    # what it computes is what it says: the whole chain at 45° wore the plate and left a dent
    assert namespace["result"].wear.volume_m3 > 0 and namespace["result"].surface.max_dent_depth > 0
    assert namespace["law"].unloading_max_overlap[0] == pytest.approx(1e-6)
