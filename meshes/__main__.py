"""``python -m meshes``: rewrite the default plate mesh from :data:`fem.axisymmetric.mesh.DEFAULT_PARAMETERS`."""

from fem.axisymmetric.mesh import DEFAULT_MESH_FILE, DEFAULT_PARAMETERS, generate_mesh

generate_mesh(**DEFAULT_PARAMETERS).save(str(DEFAULT_MESH_FILE))
print(DEFAULT_MESH_FILE)
