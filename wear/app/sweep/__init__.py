"""Parameter sweeps: the sweep file (:mod:`wear.app.sweep.spec`), the stages (:mod:`wear.app.sweep.stages`) and
the resumable runner (:mod:`wear.app.sweep.runner`)."""
