"""The axisymmetric (r, z) frictionless elastic–plastic plate: its mesh (:mod:`fem.axisymmetric.mesh`), forms
(:mod:`fem.axisymmetric.forms`), Newton solver (:mod:`fem.axisymmetric.solver`), results
(:mod:`fem.axisymmetric.result`), indentation (:mod:`fem.axisymmetric.indent`), its elastic reloading
(:mod:`fem.axisymmetric.reload`) and the stateful plate of repeated impacts (:mod:`fem.axisymmetric.plate`). Imports
:mod:`fem.core`, never the 3-D plate."""
