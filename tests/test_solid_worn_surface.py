"""Wear moves the 3-D plate's surface (:meth:`fem.solid.plate.SolidPlate.move_surface`): the next impact's contact gap
is measured to the worn surface, and the plate written to a file has its surface lowered by the wear.

Reference: geometry. A surface lowered uniformly by w is first touched by the sphere's tip at δ = w (overlaps from
the original plane); lowered by a bowl w(ρ) = w₀(1 − ρ²/b²) about the tip, at δ = w₀ (the sphere's own height
ρ²/2R and the bowl's rise both grow off the axis). Pressed elastically, the worn plate carries Hertz's force at the
overlap δ − w from the worn surface (Johnson Eq. 4.23), as the unworn plate at δ.
"""

import math

import numpy as np
import pytest

from contact import Material
from fem.solid.plate import SolidPlate, press_path

STEEL = Material(E=210e9, nu=0.3, density=7850.0)
RADIUS = 10e-3
OVERLAP = 1e-6


@pytest.fixture()
def plate():
    return SolidPlate(RADIUS, STEEL, OVERLAP, contact_elements=3, box_depth=0.3)


def test_first_contact_is_at_the_worn_surface(plate):
    xy = plate.surface_xy
    assert plate.first_contact_overlap(0.0) == 0.0
    plate.move_surface(np.full(xy.shape[0], 2e-8))
    assert plate.first_contact_overlap(0.0) == pytest.approx(2e-8, rel=1e-9)
    bowl = 3e-8 * np.clip(1.0 - (np.hypot(xy[:, 0], xy[:, 1]) / 2e-4) ** 2, 0.0, None)
    plate.move_surface(bowl)
    assert plate.first_contact_overlap(0.0) == pytest.approx(5e-8, rel=1e-9)
    np.testing.assert_allclose(plate.wear_depth, 2e-8 + bowl, rtol=1e-12)
    with pytest.raises(ValueError, match="depth"):
        plate.move_surface(-np.ones(xy.shape[0]))


def test_worn_plate_carries_hertzs_force_from_its_worn_surface(plate):
    """Uniform wear w = 0.3 δ: pressed to δ + w, the plate carries the force the unworn plate carries at δ (the same
    FE plate, within the contact set's tolerance at the edge: measured 0.06%; a gap not moved by the wear would carry
    (1.3)^{3/2} = 1.48 times the force), and the written plate's surface vertices sit w below the plane."""
    fresh = SolidPlate(RADIUS, STEEL, OVERLAP, contact_elements=3, box_depth=0.3)
    worn = 0.3 * OVERLAP
    plate.move_surface(np.full(plate.surface_xy.shape[0], worn))
    path = np.array([0.5, 1.0]) * OVERLAP
    zeros = np.zeros(2)
    on_fresh, _ = press_path(fresh.solver, fresh.start_state(0.0, 0.0), path, zeros, zeros)
    on_worn, _ = press_path(plate.solver, plate.start_state(0.0, 0.0), path + worn, zeros, zeros)
    np.testing.assert_allclose(on_worn.normal_force, on_fresh.normal_force, rtol=1e-3)
    e_star = STEEL.E / (1.0 - STEEL.nu**2)
    hertz = 4.0 / 3.0 * e_star * math.sqrt(RADIUS) * OVERLAP**1.5
    assert on_worn.normal_force[-1] == pytest.approx(hertz, rel=0.05)  # the coarse mesh's Hertz force
    plate.commit(on_worn)
    mesh = plate.to_meshio()
    on_surface = mesh.point_data["surface"] > 0.0
    np.testing.assert_allclose(mesh.point_data["wear_depth"][on_surface], worn, rtol=1e-12)
    np.testing.assert_allclose(mesh.points[on_surface, 2], -worn, rtol=1e-12)
    assert np.all(mesh.point_data["wear_depth"][~on_surface] == 0.0)
