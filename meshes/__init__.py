"""Plate meshes shipped with impactwear (data only).

``indent_default.msh``: the default dimensionless plate mesh (unit length = the largest contact radius of the
path; scaled by :func:`fem.axisymmetric.mesh.default_mesh`, found through
:data:`fem.axisymmetric.mesh.DEFAULT_MESH_FILE`), generated from :data:`fem.axisymmetric.mesh.DEFAULT_PARAMETERS`. Run
``python -m fem.axisymmetric.regenerate_mesh`` to rewrite it. The package imports nothing: the generator is
:mod:`fem`'s.
"""
