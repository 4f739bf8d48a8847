"""The commands of ``impactwear`` (one module each; see :mod:`wear.app.cli`)."""
