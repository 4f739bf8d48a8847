"""The figures the toolkit's plotting functions would save, kept instead (matplotlib Agg), so that a test can
inspect their artists: shared by the figure tests."""

from __future__ import annotations

from types import ModuleType

from matplotlib.figure import Figure


def capture_figures(monkeypatch, *modules: ModuleType) -> dict[str, Figure]:
    """Replace ``save_figure`` in each of ``modules`` for the test: the figures it would write are kept in the
    returned dict, keyed by file name."""
    figures: dict[str, Figure] = {}

    def keep(fig, path, *args, **kwargs):
        figures[str(path).rsplit("/", 1)[-1]] = fig
        return path

    for module in modules:
        monkeypatch.setattr(module, "save_figure", keep)
    return figures
