"""sphinx-gallery helpers for the impactwear docs (imported by name from docs/conf.py).

The examples are sphinx-gallery scripts (``# %%`` cells) with no command-line arguments: each writes its output files
into a folder of its own under the one named by ``IMPACTWEAR_EXAMPLE_OUT`` (docs/conf.py sets a temporary folder),
and leaves its matplotlib figures open for the matplotlib scraper, which shows each under the cell that drew it.

A script that calls ``sys.exit`` would end sphinx-build itself, silently and with status 0 (the rest of the site
never built). :func:`guard_exit` replaces ``sys.exit`` while an example runs: ``sys.exit(0)`` / ``sys.exit()``
return, any other status raises ``RuntimeError``, so sphinx-gallery reports the example as failed and the build
fails.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

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
