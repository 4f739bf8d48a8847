"""sphinx-gallery helpers for the impactwear docs (imported by name from docs/conf.py).

sphinx-gallery runs each example in the sphinx-build process with ``sys.argv = [script] + reset_argv(...)``, an
empty ``__doc__`` and no ``__file__``. The examples are ordinary command-line scripts: they take ``--out DIR``,
build their argparse description from ``__doc__`` and find their data files next to ``__file__``.
:func:`reset_argv` gives them what ``python examples/NAME.py --out DIR`` would.

A script that calls ``sys.exit`` would end sphinx-build itself, silently and with status 0 (the rest of the site
never built). :func:`guard_exit` replaces ``sys.exit`` while an example runs: ``sys.exit(0)`` / ``sys.exit()``
return (correct for a trailing ``sys.exit(main())``, the usual end of a script), any other status raises
``RuntimeError``, so sphinx-gallery reports the example as failed and the build fails.

The examples write their figures with the toolkit's own writers (PNG files in ``--out``), as ``impactwear`` does:
:func:`output_figures` shows them in the gallery (beside any matplotlib figure an example leaves open).
"""

from __future__ import annotations

import ast
import atexit
import shutil
import sys
import tempfile
from pathlib import Path
from typing import Any

from sphinx_gallery.scrapers import figure_rst

_OUT = Path(tempfile.mkdtemp(prefix="impactwear-gallery-"))
atexit.register(shutil.rmtree, _OUT, ignore_errors=True)
_REAL_EXIT = sys.exit


def reset_argv(gallery_conf: dict[str, Any], script_vars: dict[str, Any]) -> list[str]:
    """Arguments of one example: ``--out`` a fresh temporary folder (outputs stay out of the docs tree)."""
    src = Path(script_vars["src_file"])
    example_globals = script_vars.get("example_globals")
    if example_globals is not None:
        example_globals["__doc__"] = ast.get_docstring(ast.parse(src.read_text(encoding="utf-8")), clean=False)
        example_globals["__file__"] = str(src)
    out = _OUT / src.stem
    out.mkdir(parents=True, exist_ok=True)
    return ["--out", str(out)]


def _example_exit(status: object = None) -> None:
    if status is None or status == 0:
        return
    raise RuntimeError(f"the example called sys.exit({status!r})")


def guard_exit(gallery_conf: dict[str, Any], fname: str | None, when: str) -> None:
    """``reset_modules`` hook: ``sys.exit`` guarded while an example runs, restored after it."""
    sys.exit = _example_exit if (when == "before" and fname is not None) else _REAL_EXIT


_SHOWN: set[Path] = set()


def output_figures(block: Any, block_vars: dict[str, Any], gallery_conf: dict[str, Any]) -> str:
    """Image scraper: the PNG files the example wrote into its ``--out`` folder since the last call."""
    out = _OUT / Path(block_vars["src_file"]).stem
    new = sorted(p for p in out.rglob("*.png") if p not in _SHOWN)
    images = []
    for png, target in zip(new, block_vars["image_path_iterator"], strict=False):
        shutil.copyfile(png, target)
        _SHOWN.add(png)
        images.append(target)
    return figure_rst(images, gallery_conf["src_dir"])
