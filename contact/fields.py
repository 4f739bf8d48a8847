"""The surface field a plate hands the wear law: plain arrays on surface points × plate steps (SI units).

A plate (the FE plates of :mod:`fem`) reports, at each of its steps placed at an impact time, the contact tractions
at points of its surface, which surface points stick and how far the ball slid over each; and, after the impact,
its residual surface. The wear law (:mod:`wear.solid_wear`) integrates Eq. 15 over these arrays and never needs the
plate itself.

>>> import numpy as np
>>> field = SurfaceField(
...     time=np.array([0.0, 1e-6]), points=np.array([[0.0, 0.0], [1e-4, 0.0]]),
...     pressure=np.array([[1e9, 0.0], [2e9, 5e8]]), shear=np.zeros((2, 2, 2)), slip=np.zeros((2, 2, 2)),
...     sticking=np.zeros((2, 2), bool), centre=np.zeros(2), contact_radius=np.array([5e-5, 1e-4]),
...     dent_points=np.array([[0.0, 0.0]]), dent=np.array([1e-6]), mirrored=True)
>>> field.steps, field.size
(2, 2)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["SurfaceField"]


@dataclass(frozen=True, eq=False)
class SurfaceField:
    """A plate's surface fields along an impact.

    Per plate step k placed at the impact ``time`` (s, (k,)) and surface point j of ``points`` (m, (n, 2): x along
    the impact, y across): the contact ``pressure`` (Pa, (k, n)), the ``shear`` traction on the plate (Pa,
    (k, n, 2), x and y), the ball's ``slip`` over the point in the step ending at k (m, (k, n, 2); zero in stick and
    out of contact), ``sticking`` (bool, (k, n)); per step the contact ``centre`` (m, x, (k,)) and
    ``contact_radius`` (m, (k,)). After the impact the residual surface: ``dent`` (m, positive into the plate,
    pile-up negative) at ``dent_points`` (m, (q, 2)). ``mirrored``: the points cover the half plate y ≥ 0 of a
    plate symmetric about the plane of incidence y = 0, whose other half is their mirror image. ``triangles``
    ((t, 3), rows of ``points``) and ``dent_triangles`` (rows of ``dent_points``): the plate's own triangles, over
    which the fields are linear (None: a Delaunay triangulation of the points, whose choice between cocircular
    points a structured mesh leaves to round-off).
    """

    time: np.ndarray
    points: np.ndarray
    pressure: np.ndarray
    shear: np.ndarray
    slip: np.ndarray
    sticking: np.ndarray
    centre: np.ndarray
    contact_radius: np.ndarray
    dent_points: np.ndarray
    dent: np.ndarray
    mirrored: bool = False
    triangles: np.ndarray | None = None
    dent_triangles: np.ndarray | None = None

    @property
    def steps(self) -> int:
        """Plate steps."""
        return int(self.time.size)

    @property
    def size(self) -> int:
        """Surface points."""
        return int(self.points.shape[0])
