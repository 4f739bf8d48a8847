"""The output files: the one atomic writer (:mod:`wear.app.outputs.writer`) and each command's output folder."""
