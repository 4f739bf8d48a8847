"""Validation against independent references: the checks (:mod:`wear.app.validation.checks`), the groups of each
area (``contact``, ``fem``, ``wear``), the published references (:mod:`wear.app.validation.references`) and the
report (:mod:`wear.app.validation.runner`)."""
