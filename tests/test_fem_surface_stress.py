"""The 3-D plate's surface stress (fem.solid.surface_stress) against closed forms: Johnson's (1985) Hertz surface
stresses and Hamilton's (1983) under a sliding Hertz contact, where first yield is at the surface for μ > 0.3.

Both on the default block refined to 16 elements across a in a band around the contact edge (the surface stresses
peak there); the band puts vertices on r = a.
"""

import math

import numpy as np
import pytest
from reference_tables import read_table

from contact.materials import Material
from fem.core.assembly import assemble, element_matrices, strain
from fem.core.linear import factorise
from fem.core.plasticity import J2Material, von_mises
from fem.solid.forms import discretise_solid
from fem.solid.indentation import indent_solid
from fem.solid.mesh import generate_block, scale_block
from fem.solid.surface_stress import surface_stress, vertex_stress

E, NU = 210e9, 0.3
E_STAR = E / (1.0 - NU**2)
EDGE_ELEMENTS = 16


def hertz_surface_stress(r: np.ndarray) -> np.ndarray:
    """(σ_r, σ_θ, σ_z) / p0 on the surface of a Hertz contact at r / a (Johnson 1985, Eqs. 3.45; tension +)."""
    r = np.asarray(r, dtype=float)
    inside = r < 1.0
    root = np.sqrt(np.clip(1.0 - r**2, 0.0, None))
    with np.errstate(divide="ignore", invalid="ignore"):
        ring = np.where(inside, (1.0 - 2.0 * NU) / 3.0 / r**2 * (1.0 - root**3), (1.0 - 2.0 * NU) / 3.0 / r**2)
    radial = np.where(r == 0.0, -(1.0 + 2.0 * NU) / 2.0, ring - root)
    hoop = np.where(r == 0.0, -(1.0 + 2.0 * NU) / 2.0, -ring - 2.0 * NU * root)
    return np.stack([radial, hoop, -root])


def test_vertex_stress_is_exact_for_a_linear_field():
    """A displacement quadratic in x, y, z has a linear stress, which a P2 tetrahedron holds exactly: the vertex
    stresses equal Hooke's law of the exact strain at every vertex (to rounding)."""
    mesh = scale_block(generate_block(2), 1e-4)
    d = discretise_solid(mesh)
    x, y, z = d.nodes / 1e-4
    u = 1e-6 * np.stack([x * z + 0.3 * y**2, 0.2 * x * y - z**2, 0.5 * x**2 + y * z], axis=1).ravel()
    tangent = J2Material(E, NU).elastic_tangent_of(6)
    stress = vertex_stress(d, strain(d, u) @ tangent.T)
    px, py, pz = mesh.p / 1e-4
    # Mandel strains (ε_xx, ε_yy, ε_zz, √2 ε_yz, √2 ε_xz, √2 ε_xy) of u, in 1e-2
    exact_strain = 1e-2 * np.stack(
        [pz, 0.2 * px, py, -np.sqrt(2.0) / 2.0 * pz, np.sqrt(2.0) * px, np.sqrt(2.0) * 0.4 * py], axis=1
    )
    np.testing.assert_allclose(stress, exact_strain @ tangent.T, atol=1e-9 * np.abs(stress).max())


@pytest.mark.slow
def test_hertz_surface_stress_matches_johnson():
    """A frictionless Hertz contact on the 3-D plate (the contact solved; 6 elements across a, 16 in the edge band):
    the surface stresses along the plane y = 0 — σ_r, σ_θ and σ_z = −p — against Johnson (1985) Eqs. 3.45 within
    0.02 p0 at every surface vertex up to 2a but the edge vertex r = a (the pressure's √ edge there is one element
    wide). Outside the contact this is the radial tension (1 − 2ν) p0 a² / (3 r²) where ring cracks start."""
    R = 0.01
    plate = Material(E=E, nu=NU, density=7800.0)
    delta = (1e-4) ** 2 / R
    result = indent_solid(R, plate, [delta], contact_elements=6, edge_elements=EDGE_ELEMENTS)
    P = result.normal_force[-1]
    a = (3.0 * P * R / (4.0 * E_STAR)) ** (1.0 / 3.0)
    p0 = 3.0 * P / (2.0 * math.pi * a**2)
    stress = result.surface_stress()
    x, y = result.surface_vertices[:, 0], result.surface_vertices[:, 1]
    line = np.flatnonzero((np.abs(y) < 1e-9 * a) & (x >= 0.0) & (x <= 2.0 * a))
    r = x[line] / a
    away = np.abs(r - 1.0) > 0.5 / EDGE_ELEMENTS
    assert away.sum() >= 15 and np.any((r > 1.0) & away)
    np.testing.assert_allclose(stress[line, :3].T[:, away] / p0, hertz_surface_stress(r)[:, away], atol=0.02)


def test_first_yield_at_the_surface_matches_hamilton():
    """Hamilton's (1983) sliding Hertz contact as he poses it — the Hertz pressure p0 √(1 − r²/a²) and the traction
    μp along +x, μ = 0.5, applied to the elastic plate — against his closed-form stresses
    (tests/data/hamilton_surface_mu05.csv, tests/data/hamilton_first_yield.csv; ν = 0.3). Hamilton's tractions
    leave out the normal–tangential coupling of a rigid ball on a compressible plate, which the contact solution
    has (docs/fem-record.md): prescribing them compares the plate's stresses with his for the same load.

    * First yield: the largest surface von Mises stress gives p0/Y within 3% of Hamilton's 1.045, in the trailing
      half within two edge elements of the trailing edge (Hamilton: at it, x = −a).
    * The surface von Mises stress along y = 0 in the trailing half, −1.5a ≤ x ≤ 0, within 3% at every vertex
      but those within one edge element of x = −a (Hamilton's cusp there, 0.957 p0, is 0.02a wide).
    * The quadrature points alone (a_max/64 deep in the band) give first yield 7–9% late: the recovery is needed."""
    mu, a, p0 = 0.5, 1e-4, 1e9
    mesh = scale_block(generate_block(4, depth=0.3, edge_elements=EDGE_ELEMENTS), a)
    d = discretise_solid(mesh)
    tangent = J2Material(E, NU).elastic_tangent_of(6)
    stiffness = assemble(d, element_matrices(d, tangent))
    free = np.setdiff1d(np.arange(d.ndofs), d.fixed_dofs)
    x, y = d.nodes[:2, d.surface_vertex_nodes] / a
    pressure = p0 * np.sqrt(np.clip(1.0 - x**2 - y**2, 0.0, None))
    loads = np.zeros(d.ndofs)
    loads[3 * d.surface_nodes + 2] = -(d.surface_loads @ pressure)
    loads[3 * d.surface_nodes] = mu * (d.surface_loads @ pressure)
    u = np.zeros(d.ndofs)
    u[free] = factorise(stiffness[free][:, free].tocsr()).solve(loads[free])
    stress = strain(d, u) @ tangent.T
    surface = von_mises(surface_stress(d, stress, pressure, np.column_stack([mu * pressure, 0.0 * x]))) / p0

    first_yield = read_table("hamilton_first_yield.csv")
    hamilton = first_yield["p0_over_Y"][first_yield["mu"] == mu][0]
    worst = int(np.argmax(surface))
    assert 1.0 / surface[worst] / hamilton - 1.0 == pytest.approx(0.0, abs=0.03)
    assert x[worst] < 0.0 and 1.0 - 2.0 / EDGE_ELEMENTS <= math.hypot(x[worst], y[worst]) <= 1.0 + 1e-9
    qp_first_yield = 1.0 / von_mises(stress).max() * p0
    assert qp_first_yield / hamilton - 1.0 > 0.05

    column = read_table("hamilton_surface_mu05.csv")
    line = np.flatnonzero((np.abs(y) < 1e-9) & (x >= -1.5) & (x <= 0.0) & (np.abs(x + 1.0) > 1.5 / EDGE_ELEMENTS))
    assert line.size >= 12
    reference = np.interp(x[line], column["x_over_a"], column["vm"])
    on_grid = np.isin(np.round(x[line] * 64.0, 9), np.round(column["x_over_a"] * 64.0, 9))
    assert on_grid.all()
    np.testing.assert_allclose(surface[line], reference, rtol=0.03)
