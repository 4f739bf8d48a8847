"""``python -m meshes``: rewrite the default plate mesh."""

from meshes import regenerate

print(regenerate())
