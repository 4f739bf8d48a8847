"""fem.Plate: a stateful plate for sequences of indentations (issue 6 §1). Reduced meshes."""

import math

import numpy as np
import pytest

import fem
from contact import Material
from fem.axisymmetric.mesh import generate_mesh, scale_mesh

TI = Material(114e9, 0.34, 4430.0, None, "Ti-6Al-4V elastic")
R = 2.5e-3
DELTA = 2e-6


def _plate(plate=TI):
    a = math.sqrt(R * DELTA)
    mesh = scale_mesh(generate_mesh(contact_elements=12, yield_elements=8), 1.2 * a)
    return fem.Plate(R, plate, 1.2 * DELTA, mesh=mesh)


def _hertz_force(delta):
    """Hertz (Johnson 1985, Eq. 4.23): F = (4/3) E* √R δ^(3/2), rigid ball: E* = E/(1 − ν²)."""
    e_star = TI.E / (1.0 - TI.nu**2)
    return 4.0 / 3.0 * e_star * math.sqrt(R) * delta**1.5


def test_elastic_cycle_leaves_no_dent_and_reindents_like_hertz():
    """An elastic plate unloaded leaves no dent and the same Hertz force on re-indentation (reference: Hertz;
    1.5% on this coarse mesh, where fem's own Hertz test gives < 1% at the default mesh)."""
    plate = _plate()
    res = plate.load(np.linspace(0.25, 1.0, 4) * DELTA)
    plate.unload(res, DELTA, steps=4)
    assert np.max(np.abs(plate.dent_depth)) < 1e-4 * DELTA
    assert plate.first_contact_overlap() == pytest.approx(0.0, abs=1e-4 * DELTA)
    again = plate.load(np.array([0.5, 1.0]) * DELTA)
    assert again.force[-1] == pytest.approx(_hertz_force(DELTA), rel=0.015)
    assert again.force[-1] == pytest.approx(res.force[-1], rel=1e-6)


def test_uniform_wear_translates_the_contact():
    """Removing a uniform layer W moves first contact to δ = W and the force law by W (translation invariance of
    a half-space; reference: Hertz F(δ − W)); the moved top rows stiffen the response by < 0.2% (W/H = 0.05)."""
    plate = _plate()
    depth = 0.05 * plate.taper_depth
    plate.move_surface(np.full(plate.surface_r.size, depth))
    assert plate.first_contact_overlap() == pytest.approx(depth, rel=1e-9)
    assert np.allclose(plate.surface_height, -depth)
    res = plate.load(depth + np.array([0.5, 1.0]) * DELTA)
    assert res.force[-1] == pytest.approx(_hertz_force(DELTA), rel=0.015)
    fresh = _plate().load(np.array([0.5, 1.0]) * DELTA)
    assert res.force[-1] == pytest.approx(fresh.force[-1], rel=2e-3)


def test_plastic_state_is_kept_between_indentations():
    """A yielding plate keeps its dent and plastic strain; re-indenting to the same overlap adds (almost) no plastic
    strain (the unloading and reloading are elastic: Johnson 1985 §6.7)."""
    plate_material = Material(114e9, 0.34, 4430.0, 880e6, "Ti-6Al-4V")
    plate = _plate(plate_material)
    path = np.linspace(0.1, 1.0, 8) * DELTA
    res = plate.load(path)
    plate.unload(res, DELTA, steps=6)
    alpha1 = plate.state.alpha.max()
    dent = plate.dent_depth.max()
    assert alpha1 > 0.0 and dent > 0.0
    assert plate.first_contact_overlap() == pytest.approx(dent, rel=0.05)
    res2 = plate.load(plate.first_contact_overlap() + np.linspace(0.2, 1.0, 5) * (DELTA - dent))
    plate.unload(res2, DELTA, steps=6)
    assert np.max(plate.state.alpha - 0.0) == pytest.approx(alpha1, rel=1e-2)
    assert plate.dent_depth.max() == pytest.approx(dent, rel=1e-2)


@pytest.mark.parametrize(
    "depth, text",
    [(-1e-9, "depth"), (np.nan, "depth")],
)
def test_move_surface_bad_input(depth, text):
    plate = _plate()
    with pytest.raises(ValueError, match=text):
        plate.move_surface(np.full(plate.surface_r.size, depth))
    with pytest.raises(ValueError, match="one value per surface node"):
        plate.move_surface(np.zeros(3))
