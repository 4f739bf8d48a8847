"""The paper's figures recomputed with this toolkit (:mod:`wear.app.reproduce.paper`), the FE plate's figures
(:mod:`wear.app.reproduce.fe`, :mod:`wear.app.reproduce.coupled`), each with a
:class:`~wear.app.reproduce.report.FigureReport`, and ``reproduce.md`` (:func:`wear.app.reproduce.run.reproduce`)."""
