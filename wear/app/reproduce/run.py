"""``impactwear reproduce``: every reproduced figure (:mod:`wear.app.reproduce.paper`, the paper's own;
:mod:`wear.app.reproduce.fe` and :mod:`wear.app.reproduce.coupled`, those of the FE plate;
:mod:`wear.app.reproduce.laws`, the wear laws side by side) into ``DIR/figures/*.png`` and ``DIR/reproduce.md``."""

from __future__ import annotations

import os
import time
import warnings
from collections.abc import Callable
from pathlib import Path

from wear.app.outputs.folder import check_named_file
from wear.app.outputs.writer import WRITE_ERRORS, write_text
from wear.app.reproduce import coupled, fe, laws, paper
from wear.app.reproduce.report import HEADER, FigureReport, render_markdown

__all__ = ["FIGURES", "check_outputs", "reproduce"]

#: name → function(out_dir, quick) -> FigureReport, in the order of reproduce.md.
FIGURES: dict[str, Callable[[Path, bool], FigureReport]] = {
    **paper.FIGURES,
    **fe.FIGURES,
    **coupled.FIGURES,
    **laws.FIGURES,
}


def check_outputs(out: str | os.PathLike, names: list[str]) -> None:
    """Before any work: ``out/reproduce.md`` is absent or impactwear's, and so are the figures ``names`` will
    write (``out/figures/NAME.png``: impactwear's when reproduce.md is); ValueError naming ``--out`` otherwise."""
    out = Path(out)
    shown = f"--out={str(out)!r}"
    report = out / "reproduce.md"
    check_named_file(report, "reproduce", HEADER, shown)
    if report.exists():
        return
    taken = [f"figures/{n}.png" for n in names if (out / "figures" / f"{n}.png").exists()]
    if taken:
        raise ValueError(
            f"{shown} holds {taken[0]!r}, which impactwear did not write (there is no reproduce.md of "
            "impactwear's beside it) and `impactwear reproduce` would replace: move it, or give another folder"
        )


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
            if isinstance(exc, OSError) and exc.errno in WRITE_ERRORS:  # a folder that takes no figure: stop
                raise
            rep = FigureReport(name, name, missing=f"failed: {type(exc).__name__}: {exc}")
        rep.seconds = time.perf_counter() - start
        reports.append(rep)
    write_text(out / "reproduce.md", render_markdown(reports, quick))
    return reports
