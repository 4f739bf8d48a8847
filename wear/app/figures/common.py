"""What every figure module shares: pyplot on the Agg backend (no display needed) and the atomic PNG save."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from wear.app.outputs.writer import atomic_write  # noqa: E402

__all__ = ["plt", "save_figure"]


def save_figure(fig: matplotlib.figure.Figure, path: str | os.PathLike, dpi: int = 120, **savefig: Any) -> Path:
    """Write ``fig`` to ``path`` as PNG (``savefig`` options passed on; through the one atomic writer) and close
    it."""
    try:
        return atomic_write(path, lambda name: fig.savefig(name, dpi=dpi, format="png", **savefig), mode="path")
    finally:
        plt.close(fig)
