"""The 3-D half plate with Coulomb friction: its mesh (:mod:`fem.solid.mesh`), forms (:mod:`fem.solid.forms`), its
state (:mod:`fem.solid.state`), the discrete Coulomb law of its surface (:mod:`fem.solid.friction`), Newton solver
(:mod:`fem.solid.solver`), the indentation along a path (:mod:`fem.solid.indentation`) and the stress on its
surface (:mod:`fem.solid.surface_stress`). Imports :mod:`fem.core`, never the axisymmetric plate."""
