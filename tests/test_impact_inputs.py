"""Acceptance 7 (issue 2): malformed inputs raise ValueError naming the parameter (and its value/range)."""

import math

import numpy as np
import pytest

from contact import Material, TabulatedLaw, simulate_impact, simulate_impacts

BALL = Material(E=210e9, nu=0.3, density=7800.0)
RIGID = Material.rigid()
GOOD = dict(radius=5e-3, ball=BALL, plate=RIGID, speed=2.0, angle=30.0, friction=0.3)


def _law():
    lo = np.linspace(0, 1e-6, 5)
    return TabulatedLaw(
        lo,
        lo * 1e8,
        np.sqrt(5e-3 * lo),
        np.array([1e-6]),
        np.array([[1e-6, 0.0]]),
        np.array([[100.0, 0.0]]),
        np.array([[7e-5, 0.0]]),
    )


@pytest.mark.parametrize(
    "change, name",
    [
        (dict(radius=-1e-3), "radius"),
        (dict(radius=0.0), "radius"),
        (dict(radius=float("nan")), "radius"),
        (dict(speed=float("nan")), "speed"),
        (dict(speed=-1.0), "speed"),
        (dict(speed=0.0), "speed"),
        (dict(speed=5000.0), "speed"),
        (dict(angle=95.0), "angle"),
        (dict(angle=90.0), "angle"),
        (dict(angle=-5.0), "angle"),
        (dict(friction=-0.1), "friction"),
        (dict(friction=math.inf), "friction"),
        (dict(friction="0.3"), "friction"),
        (dict(restitution=0.0), "restitution"),
        (dict(restitution=1.2), "restitution"),
        (dict(normal_model="jkr"), "normal_model"),
        (dict(tangential_model="linear"), "tangential_model"),
        (dict(scheme="rk4"), "scheme"),
        (dict(time_step=-1e-9), "time_step"),
        (dict(time_step=1e-3), "time_step"),
        (dict(ball="steel"), "ball"),
        (dict(plate=None), "plate"),
        (dict(ball=RIGID), "ball"),
        (dict(normal_model="thornton"), "yield_strength"),
        (dict(normal_model="thornton", limiting_pressure=-5.0), "limiting_pressure"),
        (dict(limiting_pressure=1e9), "limiting_pressure"),
        (dict(normal_model="tabulated"), "force_law"),
        (dict(force_law=_law()), "force_law"),
        (dict(normal_model="thornton", restitution=0.5, limiting_pressure=1e9), "restitution"),
        (dict(history="yes"), "history"),
        (dict(history_every=0), "history_every"),
    ],
)
def test_malformed_input_names_parameter(change, name):
    with pytest.raises(ValueError, match=name):
        simulate_impact(**{**GOOD, **change})


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(E=210.0, nu=0.3, density=7800.0), "E"),  # E given in GPa
        (dict(E=210e9, nu=0.5, density=7800.0), "nu"),
        (dict(E=210e9, nu=0.3, density=-1.0), "density"),
        (dict(E=210e9, nu=0.3, density=7800.0, yield_strength=250.0), "yield_strength"),  # MPa by mistake
    ],
)
def test_malformed_material(kwargs, name):
    with pytest.raises(ValueError, match=f"{name}="):
        Material(**kwargs)


def test_batch_shapes_and_values():
    with pytest.raises(ValueError, match="broadcast"):
        simulate_impacts(**{**GOOD, "speed": [1.0, 2.0], "angle": [10.0, 20.0, 30.0]})
    with pytest.raises(ValueError, match=r"angle\[1\]=nan"):
        simulate_impacts(**{**GOOD, "angle": [10.0, float("nan")]})
    with pytest.raises(ValueError, match="angle=120 is out of range"):
        simulate_impacts(**{**GOOD, "angle": [10.0, 120.0]})
