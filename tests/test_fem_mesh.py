"""Meshes of issue 3: the shipped default mesh is what the documented generator produces, meets the
issue's resolution rules, and user mesh files need the named boundaries."""

import meshio
import numpy as np
import pytest
from skfem import MeshTri

import fem
from contact.materials import Material
from fem.axisymmetric.mesh import DEFAULT_MESH_FILE, DEFAULT_PARAMETERS, generate_mesh, load_mesh


def test_regenerating_the_default_mesh_reproduces_the_file():
    shipped = MeshTri.load(str(DEFAULT_MESH_FILE))
    fresh = generate_mesh(**DEFAULT_PARAMETERS)
    assert shipped.p.shape == fresh.p.shape and shipped.t.shape == fresh.t.shape
    np.testing.assert_allclose(shipped.p, fresh.p, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(shipped.t, fresh.t)
    for name in ("axis", "surface", "bottom", "side"):
        np.testing.assert_array_equal(np.sort(shipped.boundaries[name]), np.sort(fresh.boundaries[name]))


def test_default_mesh_resolution_rules():
    # Issue 3: L ≥ 30 a_max; ≥ 30 elements across a_max; ~20 across the first-yield radius (a_max/5.5).
    m = generate_mesh(**DEFAULT_PARAMETERS)
    assert m.p[0].max() >= 30.0 and m.p[1].min() <= -30.0
    surface = np.sort(np.unique(m.facets[:, m.boundaries["surface"]]))
    r = np.sort(m.p[0, surface])
    assert np.count_nonzero(r < 1.0) >= 30
    assert np.count_nonzero(r < 1.0 / 5.5) >= 20
    assert m.t.shape[1] < 8000  # locally refined, not a tensor grid


def test_mesh_file_without_boundary_names_is_rejected(tmp_path):
    m = MeshTri.init_sqsymmetric()
    path = tmp_path / "plain.vtu"
    meshio.write(str(path), meshio.Mesh(np.column_stack([m.p.T, np.zeros(m.p.shape[1])]), [("triangle", m.t.T)]))
    with pytest.raises(ValueError, match="boundary named"):
        load_mesh(path)


def test_user_mesh_file_with_boundaries_is_used(tmp_path):
    plate = Material(E=210e9, nu=0.3, density=7850.0)
    m = fem.plate_mesh(10e-3, plate, 1e-7, contact_elements=8, yield_elements=0)
    path = tmp_path / "plate.msh"
    m.save(str(path))
    loaded = load_mesh(path)
    assert loaded.p.shape == m.p.shape


def test_growth_box_keeps_the_contact_resolution_of_a_widened_contact():
    """generate_mesh(growth=g): the surface elements out to r = 1.2 g (units of a_max) are no larger than
    g / contact_elements, so a contact grown to g·a_max has as many elements across as the first one (the issue's
    rule of ≥ 30 across the contact, scaled); growth = 1 is the mesh without the box."""
    import numpy as np

    from fem.axisymmetric.mesh import generate_mesh

    plain = generate_mesh(contact_elements=8, yield_elements=4)
    grown = generate_mesh(contact_elements=8, yield_elements=4, growth=3.0)
    assert np.array_equal(generate_mesh(contact_elements=8, yield_elements=4, growth=1.0).p, plain.p)

    def largest_surface_facet(mesh, r_max):
        facets = mesh.facets[:, mesh.boundaries["surface"]]
        r0, r1 = mesh.p[0, facets[0]], mesh.p[0, facets[1]]
        inside = np.maximum(r0, r1) <= r_max
        return float(np.max(np.abs(r1 - r0)[inside]))

    assert largest_surface_facet(grown, 3.6) <= 3.0 / 8 * (1 + 1e-9)
    assert largest_surface_facet(plain, 3.6) > 3.0 / 8  # the graded mesh is coarser there
