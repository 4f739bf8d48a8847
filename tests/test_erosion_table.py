"""The response table of the stream erosion (wear.erosion.response): resolution, the plug-in hook, Bitter's term."""

import math

import numpy as np
import pytest
from scipy.interpolate import RegularGridInterpolator

from contact import Material, yield_velocity
from contact.theory import sphere_mass, thornton_restitution
from wear import WearLaw
from wear.erosion import Footprint, ImpactResponse, Stream, build_response_table, erode, table_axes
from wear.laws.deformation import bitter_threshold_velocity

SAND = Material(E=94e9, nu=0.17, density=2650.0, name="silica")
STEEL = Material(E=200e9, nu=0.3, density=7850.0, yield_strength=350e6, name="steel")
LAW = WearLaw(K=1e-11, alpha=1.0, beta=0.3)
RADIUS, SPEED = 100e-6, 20.0


def _physical(table_shape, u, v, volume, length, x, y):
    """Depth (m) of a normalised footprint at physical points x, y (m)."""
    f = RegularGridInterpolator((v, u), table_shape, bounds_error=False, fill_value=0.0)
    return volume / length**2 * f(np.column_stack([y.ravel() / length, x.ravel() / length])).reshape(x.shape)


def test_table_interpolation_error_between_nodes():
    """Footprint interpolated half-way between table nodes vs computed there directly by the same chain.

    Default angle step (2.5°), 5 normal speeds over V cos 65° .. V cos 25°. Measured at (mid speed, 46.25°):
    volume 0.04%, contact radius 0.05%, depth map 0.63% in L1 norm; tolerances 1%, 1% and 3% (a wrong axis,
    a swapped weight or an unscaled L gives tens of %). Along the stream's curve v_n = V cos θ the volume
    error of this table stays below 0.35% for θ ≤ 59.5° (0.51% before the power-law interpolation) and reaches
    1.2% at 60.5° and 0.5% at 61.5–63.5°, the angle steps around the kink of this law's volume in θ near 61°
    (1% at 63.5° before)."""
    response = ImpactResponse(RADIUS, SAND, STEEL, 0.3, LAW, points_across=48)
    vn, angles = table_axes(SPEED, 45.0, angle_margin=20.0, angle_step=2.5, speeds=5)
    table = build_response_table(response, vn, angles, points_per_length=12)
    assert table.shape.shape[:2] == (5, 17)
    s_mid, a_mid = 0.5 * (vn[2] + vn[3]), 0.5 * (angles[8] + angles[9])
    shape, volume, length = table.interpolate(s_mid, a_mid)
    direct = response(s_mid, a_mid)
    assert abs(volume / direct.volume_m3 - 1.0) < 1e-2
    assert abs(length / direct.length_scale - 1.0) < 1e-2
    x, y = np.meshgrid(direct.x, direct.y)
    interp = _physical(shape, table.u, table.v, volume, length, x, y)
    l1 = np.abs(interp - direct.wear).sum() / direct.wear.sum()
    assert l1 < 0.03, l1
    # the resolution line reports the axes
    assert "5 normal speeds" in table.resolution and "17 local angles" in table.resolution


def test_plain_callable_with_dent_plugs_in():
    """Any per-impact model (e.g. the coupled FE pipeline) plugs in as a callable (normal_speed, angle) ->
    Footprint. With a synthetic model of known volume V_w and a dent of known volume V_d, the stream removes
    exactly N V_w ρ (mass) and the dent field holds N V_d (reference: the synthetic volumes, closed form)."""
    L = 20e-6
    x = np.linspace(-3 * L, 3 * L, 61)
    y = np.linspace(-2 * L, 2 * L, 41)
    xx, yy = np.meshgrid(x, y)
    bowl = np.maximum(1 - (xx**2 + yy**2) / L**2, 0.0)
    spacing = x[1] - x[0]

    def model(normal_speed, angle):
        wear = 1e-9 * normal_speed * bowl  # arbitrary, scales with the speed
        return Footprint(
            x=x, y=y, wear=wear, length_scale=L, cutting_volume_m3=float(wear.sum() * spacing**2), dent=0.5e-9 * bowl
        )

    m_p = 4 / 3 * math.pi * RADIUS**3 * 2650.0
    vn, angles = table_axes(SPEED, 30.0, angle_margin=10.0, angle_step=5.0, speeds=2)
    table = build_response_table(model, vn, angles, particle_radius=RADIUS, particle_mass=m_p, plate_density=7850.0)
    assert table.dent is not None
    result = erode(table, Stream(SPEED, 30.0, 2.0, concentration=0.464), grid=128, samples=2, frames=1)
    assert result.n_impacts > 500
    v_wear = 1e-9 * SPEED * math.cos(math.radians(30.0)) * bowl.sum() * spacing**2
    v_dent = 0.5e-9 * bowl.sum() * spacing**2
    np.testing.assert_allclose(result.mass_loss_kg[-1], result.n_impacts * v_wear * 7850.0, rtol=2e-3)
    h = result.spacing
    # the dent is not renormalised: its volume follows the bilinear resampling (measured −0.14%; tolerance 1%)
    np.testing.assert_allclose(result.dent.sum() * h * h, result.n_impacts * v_dent, rtol=1e-2)
    np.testing.assert_allclose(result.surface, result.wear + result.dent)


def test_bitter_threshold_is_thornton_yield_speed_at_1_59_Y():
    """Bitter's (1963) elastic-limit speed K = π²/(2√10) (1.59 Y)^{5/2} ρ^{-1/2} (k₁ + k₂)² is Thornton's
    (1997) yield speed V_y = √(π⁵/30 R³/m p_y⁵/E*⁴) with p_y = 1.59 Y (two independent derivations of the
    speed at which the Hertz peak pressure reaches p_y). Tolerance 1e-12."""
    vb = bitter_threshold_velocity(SAND, STEEL)
    vy = yield_velocity(RADIUS, SAND, STEEL, limiting_pressure=1.59 * 350e6)
    assert vb == pytest.approx(vy, rel=1e-12)


def test_deformation_wear_at_normal_incidence_is_thorntons_plastic_work():
    """The combined law (Eq. 15 + Bitter's deformation wear, volume = plastic work / ε) on a normal stream with
    Thornton's (1997) normal law: the sliding term wears nothing at 0° on a flat plate, and each impact wears
    ½ m V² (1 − e²)/ε with e Thornton's closed-form restitution at V/V_y (contact.theory.thornton_restitution,
    an independent evaluation). Measured: −0.2% (200 impacts; the bowls tilt the surface, so later particles meet
    it slightly off normal); tolerance 1%."""
    eps = 5e9  # J/m^3, an illustrative value (no default in the toolkit)
    response = ImpactResponse(
        RADIUS,
        SAND,
        STEEL,
        0.3,
        LAW,
        points_across=48,
        normal_model="thornton",
        wear_law="combined",
        constants={"cutting": "local", "deformation_factor": eps},
    )
    vn, angles = table_axes(SPEED, 0.0, angle_margin=10.0, angle_step=5.0, speeds=3)
    table = build_response_table(response, vn, angles, points_per_length=8)
    assert table.cutting_volume_m3[-1, 0] == 0.0
    result = erode(table, Stream(SPEED, 0.0, 2.0, concentration=0.464), grid=96, samples=2, frames=1)
    ratio = SPEED / yield_velocity(RADIUS, SAND, STEEL)
    assert ratio > 1.0  # the plate yields: there is plastic work
    mass = sphere_mass(RADIUS, SAND.density)
    w_d = 0.5 * mass * SPEED**2 * (1.0 - float(thornton_restitution(ratio)) ** 2) / eps
    np.testing.assert_allclose(result.mass_loss_kg[-1], result.n_impacts * w_d * 7850.0, rtol=1e-2)


def test_response_input_errors():
    with pytest.raises(ValueError, match=r"^wear.deformation_factor=None"):
        ImpactResponse(RADIUS, SAND, STEEL, 0.3, LAW, normal_model="thornton", wear_law="deformation")(SPEED, 0.0)
    with pytest.raises(ValueError, match=r"impact.normal_model='hertz' is elastic"):
        ImpactResponse(RADIUS, SAND, STEEL, 0.3, LAW, wear_law="deformation", constants={"deformation_factor": 1e9})(
            SPEED, 0.0
        )
    with pytest.raises(ValueError, match=r"^wear_law='archard' is not a valid choice"):
        ImpactResponse(RADIUS, SAND, Material(E=200e9, nu=0.3, density=7850.0), 0.3, LAW, wear_law="archard")
    with pytest.raises(ValueError, match=r"^pressure='fe' is not a valid choice"):
        ImpactResponse(RADIUS, SAND, STEEL, 0.3, LAW, pressure="fe")
    with pytest.raises(ValueError, match=r"^particle_radius=None"):
        build_response_table(lambda s, a: None, [10.0, 20.0], [0.0, 10.0])
