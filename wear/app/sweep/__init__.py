"""Parameter sweeps: the sweep file (:mod:`wear.app.sweep.spec`), a stage (:mod:`wear.app.sweep.stage`) and the
stages listed with their functions (:mod:`wear.app.sweep.stages`), the resumable runner
(:mod:`wear.app.sweep.runner`), where its cases run (:mod:`wear.app.sweep.execution`) and its tables
(:mod:`wear.app.sweep.results`)."""
