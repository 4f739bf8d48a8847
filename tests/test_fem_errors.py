"""Acceptance 6 of issue 3: bad input fails early with a ValueError naming the parameter."""

import math

import numpy as np
import pytest

import fem
from contact.materials import Material

PLATE = Material(E=210e9, nu=0.3, density=7850.0, yield_strength=210e6)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"overlaps": [1e-7, -1e-8]}, r"overlaps\[1\]=-1e-08 is out of range"),
        ({"overlaps": [1e-7, math.nan]}, r"overlaps\[1\]=nan"),
        ({"overlaps": [0.0, 0.0]}, "overlaps are all 0"),
        ({"radius": -1e-3}, "radius=-0.001 is out of range"),
        ({"radius": math.inf}, "radius=inf is not finite"),
        ({"overlaps": [2e-3]}, "small strain"),  # a ≈ 0.45 R on a 10 mm ball
        ({"hardening": -1.0}, "hardening=-1 is out of range"),
        ({"mesh": 42}, "mesh=42"),
        ({"mesh": "/nonexistent/plate.msh"}, "is not a file"),
        ({"ball": "steel"}, "ball='steel'"),
        ({"plate": "steel"}, "plate='steel'"),
    ],
)
def test_bad_input_names_the_parameter(kwargs, match):
    args = {"radius": 10e-3, "plate": PLATE, "overlaps": [1e-7]}
    args.update(kwargs)
    with pytest.raises(ValueError, match=match):
        fem.indent(**args)


def test_modulus_out_of_range_names_E():
    with pytest.raises(ValueError, match="E=210 is out of range"):
        fem.indent(10e-3, Material(E=210.0, nu=0.3, density=7850.0), [1e-7])


def test_unload_from_needs_kept_states():
    plate = Material(E=210e9, nu=0.3, density=7850.0)
    mesh = fem.plate_mesh(10e-3, plate, 1e-7, contact_elements=6, yield_elements=0)
    res = fem.indent(10e-3, plate, np.array([1e-7]), mesh=mesh)
    with pytest.raises(ValueError, match="keep_states=True"):
        res.unload_from(1e-7)
    with pytest.raises(ValueError, match="force_law needs an unloading"):
        res.force_law()
