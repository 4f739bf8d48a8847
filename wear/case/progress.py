"""The progress bar of long work: a tqdm bar on stderr, shown unless asked to be quiet or stderr is not a terminal
(so that logs and pipes stay clean)."""

from __future__ import annotations

import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager

from tqdm import tqdm

__all__ = ["progress_bar", "show_progress"]


def show_progress(quiet: bool) -> bool:
    """A progress bar is shown unless ``quiet`` or stderr is not a terminal."""
    return not quiet and sys.stderr.isatty()


@contextmanager
def progress_bar(total: int, desc: str, unit: str, quiet: bool) -> Iterator[Callable[[int, str], None]]:
    """Yield ``update(done, label)`` drawing a bar on stderr (nothing when quiet or not on a terminal)."""
    bar = tqdm(total=total, desc=desc, unit=unit, file=sys.stderr, leave=False, disable=not show_progress(quiet))

    def update(done: int, label: str = "") -> None:
        bar.update(done - bar.n)
        if label:
            bar.set_postfix_str(label)

    try:
        yield update
    finally:
        bar.close()
