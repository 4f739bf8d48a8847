"""``python -m fem.axisymmetric.regenerate_mesh``: rewrite the shipped default plate mesh
(:data:`fem.axisymmetric.mesh.DEFAULT_MESH_FILE`, dimensionless: unit length = the largest contact radius a_max) from
:data:`fem.axisymmetric.mesh.DEFAULT_PARAMETERS`.

A module of its own rather than a main block of :mod:`fem.axisymmetric.mesh`: importing :mod:`fem` loads that module,
which ``python -m`` would then run a second time.
"""

from __future__ import annotations

from pathlib import Path

from fem.axisymmetric.mesh import DEFAULT_MESH_FILE, DEFAULT_PARAMETERS, generate_mesh

__all__ = ["regenerate_default_mesh"]


def regenerate_default_mesh() -> Path:
    """Write the default mesh generated from :data:`fem.axisymmetric.mesh.DEFAULT_PARAMETERS` over the shipped file
    and return its path."""
    generate_mesh(**DEFAULT_PARAMETERS).save(str(DEFAULT_MESH_FILE))
    return DEFAULT_MESH_FILE


if __name__ == "__main__":
    print(regenerate_default_mesh())
