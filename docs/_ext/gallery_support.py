"""sphinx-gallery helpers for the impactwear docs (imported by name from docs/conf.py).

The examples are sphinx-gallery scripts (``# %%`` cells) with no command-line arguments: each writes its output files
into a folder of its own under the one named by ``IMPACTWEAR_EXAMPLE_OUT`` (docs/conf.py sets a temporary folder),
and leaves its matplotlib figures open for the matplotlib scraper, which shows each under the cell that drew it.

A script that calls ``sys.exit`` would end sphinx-build itself, silently and with status 0 (the rest of the site
never built). :func:`guard_exit` replaces ``sys.exit`` while an example runs: ``sys.exit(0)`` / ``sys.exit()``
return, any other status raises ``RuntimeError``, so sphinx-gallery reports the example as failed and the build
fails.

:func:`checked_matplotlib_scraper` is sphinx-gallery's matplotlib scraper after a check of every figure an example
leaves open: a text that overlaps another or runs off the figure (:func:`wear.app.figures.common.overlapping_texts`,
the check the toolkit's own figures pass when saved) is a warning of the build, so an error with ``-W``.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import matplotlib.pyplot as plt
from sphinx.util import logging
from sphinx_gallery.scrapers import matplotlib_scraper

from wear.app.figures.common import overlapping_texts

logger = logging.getLogger(__name__)

#: The examples shown first, in this order (the others follow by file name).
FIRST = ("tutorial_case_to_figure.py", "calibrate_your_data.py")

_REAL_EXIT = sys.exit


def _example_exit(status: object = None) -> None:
    if status is None or status == 0:
        return
    raise RuntimeError(f"the example called sys.exit({status!r})")


def guard_exit(gallery_conf: dict[str, Any], fname: str | None, when: str) -> None:
    """``reset_modules`` hook: ``sys.exit`` guarded while an example runs, restored after it."""
    sys.exit = _example_exit if (when == "before" and fname is not None) else _REAL_EXIT


def example_order(filename: str) -> tuple[int, str]:
    """``within_subsection_order``: the examples of :data:`FIRST` first, then the others by file name."""
    name = Path(filename).name
    return (FIRST.index(name) if name in FIRST else len(FIRST), name)


def figure_text_problems(name: str) -> list[str]:
    """What :func:`~wear.app.figures.common.overlapping_texts` finds in each figure pyplot holds open, each naming
    the example ``name`` and the figure's number."""
    return [
        f"{name}, figure {num}: {problem}"
        for num in plt.get_fignums()
        for problem in overlapping_texts(plt.figure(num))
    ]


def checked_matplotlib_scraper(block: Any, block_vars: dict[str, Any], gallery_conf: dict[str, Any]) -> str:
    """``image_scrapers``: a warning for each overlapping or clipped text of the figures a cell leaves open, then
    sphinx-gallery's matplotlib scraper (which saves and closes them)."""
    for problem in figure_text_problems(Path(block_vars["src_file"]).name):
        logger.warning(f"{problem} (a figure whose text overlaps)")
    return matplotlib_scraper(block, block_vars, gallery_conf)
