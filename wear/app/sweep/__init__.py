"""Parameter sweeps: the sweep file (:mod:`wear.app.sweep.spec`), the stages (:mod:`wear.app.sweep.stages`) and
the resumable runner (:mod:`wear.app.sweep.runner`), where its cases run (:mod:`wear.app.sweep.execution`) and its
tables (:mod:`wear.app.sweep.results`)."""
