"""What both plates share and that knows no plate: batched assembly on a fixed pattern (:mod:`fem.core.assembly`),
J2 return mapping (:mod:`fem.core.plasticity`), the rigid sphere (:mod:`fem.core.sphere`), sparse solves
(:mod:`fem.core.linear`), the kept factor (:mod:`fem.core.kept_factor`), Anderson mixing (:mod:`fem.core.anderson`),
the plate's material (:mod:`fem.core.material`) and the increment driver with its work counters
(:mod:`fem.core.increments`). Imports no plate."""
