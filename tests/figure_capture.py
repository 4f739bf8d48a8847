"""The figures the toolkit's plotting functions would save, kept instead (matplotlib Agg), so that a test can
inspect their artists: shared by the figure tests. Every figure kept is checked as ``save_figure`` checks it: no
text of it overlaps another or runs off its edge (:func:`wear.app.figures.common.overlapping_texts`)."""

from __future__ import annotations

from types import ModuleType

from matplotlib.figure import Figure

from wear.app.figures.common import overlapping_texts


def capture_figures(monkeypatch, *modules: ModuleType) -> dict[str, Figure]:
    """Replace ``save_figure`` in each of ``modules`` for the test: the figures it would write are kept in the
    returned dict, keyed by file name. A figure whose texts overlap fails the test there."""
    figures: dict[str, Figure] = {}

    def keep(fig, path, *args, **kwargs):
        name = str(path).rsplit("/", 1)[-1]
        found = overlapping_texts(fig)
        assert not found, f"{name}: {found}"
        figures[name] = fig
        return path

    for module in modules:
        monkeypatch.setattr(module, "save_figure", keep)
    return figures
