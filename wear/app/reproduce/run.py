"""``impactwear reproduce``: every reproduced figure (:mod:`wear.app.reproduce.paper`, the paper's own;
:mod:`wear.app.reproduce.fe` and :mod:`wear.app.reproduce.coupled`, those of the FE plate;
:mod:`wear.app.reproduce.laws`, the wear laws side by side) into ``DIR/figures/*.png`` and ``DIR/reproduce.md``."""

from __future__ import annotations

import os
import time
import warnings
from collections.abc import Callable
from pathlib import Path

from wear.app.outputs.writer import write_text
from wear.app.reproduce import coupled, fe, laws, paper
from wear.app.reproduce.report import FigureReport, render_markdown

__all__ = ["FIGURES", "reproduce"]

#: name → function(out_dir, quick) -> FigureReport, in the order of reproduce.md.
FIGURES: dict[str, Callable[[Path, bool], FigureReport]] = {
    **paper.FIGURES,
    **fe.FIGURES,
    **coupled.FIGURES,
    **laws.FIGURES,
}


def reproduce(out: str | os.PathLike, *, quick: bool = False, only=None, progress=None) -> list[FigureReport]:
    """Compute every figure of :data:`FIGURES` (or those named in ``only``) into ``out/figures/`` and write
    ``out/reproduce.md``. ``progress(name)`` is called before each figure. A figure whose computation raises is
    listed in reproduce.md as not produced, with the error. Returns the reports."""
    out = Path(out)
    names = list(FIGURES)
    if only:
        unknown = [n for n in only if n not in names]
        if unknown:
            raise ValueError(f"only={unknown[0]!r} is not a figure: choose from {', '.join(names)}")
        names = [n for n in names if n in only]
    (out / "figures").mkdir(parents=True, exist_ok=True)
    reports = []
    for name in names:
        if progress is not None:
            progress(name)
        start = time.perf_counter()
        try:
            with warnings.catch_warnings():
                # the FE stands for an elastic ball by its effective modulus: stated in the figures' sources
                warnings.filterwarnings("ignore", message="elastic ball: represented by a rigid sphere")
                rep = FIGURES[name](out / "figures", quick)
        except Exception as exc:  # one failed figure (e.g. an FE run that does not converge) is reported
            rep = FigureReport(name, name, missing=f"failed: {type(exc).__name__}: {exc}")
        rep.seconds = time.perf_counter() - start
        reports.append(rep)
    write_text(out / "reproduce.md", render_markdown(reports, quick))
    return reports
