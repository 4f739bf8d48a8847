"""Repeated impacts at one site: shakedown, re-impact on a conforming dent, N × one impact, pressure
relief by the dented surface, bad input. Reduced FE meshes (``fem.mesh_scale`` 3–4) and few impacts."""

import math

import numpy as np
import pytest
from refusal import refused

from contact import effective_modulus
from contact.theory import yield_velocity
from wear import Case, repeat, run
from wear.app.cli import main
from wear.case import JOBS, RepeatSpec, dump_case

pytestmark = pytest.mark.filterwarnings("ignore:elastic ball", "ignore:contact radius")


def _case(ratio: float, angle: float = 0.0, K: float = 1e-11, elastic: bool = False, scale: float = 3.0) -> Case:
    """The default case (alumina R 2.5 mm on Ti-6Al-4V) at V_n = ``ratio`` × Thornton's yield speed V_y."""
    case = Case()
    v_y = yield_velocity(case.ball.radius, case.ball.material(), case.plate.material())
    speed = ratio * v_y / math.cos(math.radians(angle))
    plate = {"yield_strength": None} if elastic else {}
    return case.with_(
        impact={"speed": speed, "angle": angle},
        wear={"K": K},
        fem={"mesh_scale": scale},
        plate=plate,
        output={"figures": False, "render": False},
    )


def _hertz_p0(force: float, radius: float, e_star: float) -> float:
    """Hertz peak pressure (Johnson 1985, Eq. 4.24): p0 = (6 F E*² / (π³ R²))^(1/3)."""
    return (6.0 * force * e_star**2 / (math.pi**3 * radius**2)) ** (1.0 / 3.0)


@pytest.fixture(scope="module")
def below_shakedown():
    """Normal impacts, wear off, at V_n = 2.2 V_y: the Hertz p0 of the elastic estimate lies between first yield
    (p0 = C(ν)·Y ≈ 1.61 Y = 2.78 k, k = Y/√3) and the shakedown limit of frictionless point contact
    (p0 = 4.7 k: Ponter, Hearle & Johnson 1985; Johnson, Contact Mechanics 1985, §9.2–9.3)."""
    case = _case(2.2, K=0.0)
    dents = {}

    def keep(impact, plate):
        dents[impact] = (plate.surface_r, plate.dent_depth.copy())

    result = repeat(case.with_(repeat=dict(impacts=6, geometry_update=True, max_plastic_impacts=10)), on_computed=keep)
    return case, result, dents


def test_hertz_p0_of_the_chosen_impact_lies_between_first_yield_and_shakedown(below_shakedown):
    case, result, _ = below_shakedown
    ball, plate = case.ball.material(), case.plate.material()
    e_star = effective_modulus(ball, plate)
    k = plate.yield_strength / math.sqrt(3.0)
    # elastic (Hertz) estimate of the impact: δ = (15 m V² / (16 E* √R))^(2/5), p0 = (2E*/π)√(δ/R) (Johnson 11.2)
    m = 4.0 / 3.0 * math.pi * case.ball.radius**3 * ball.density
    delta = (15.0 * m * case.impact.speed**2 / (16.0 * e_star * math.sqrt(case.ball.radius))) ** 0.4
    p0 = 2.0 * e_star / math.pi * math.sqrt(delta / case.ball.radius)
    print(f"Hertz p0/k of the chosen impact: {p0 / k:.3f}")
    assert 2.78 < p0 / k < 4.7


def test_plate_hit_below_shakedown_stops_accumulating_plastic_strain(below_shakedown):
    """Impact 1 yields; the increments of ᾱ then fall at least 4-fold per impact (each re-impact reaches a little
    higher force on the seat it made: a decaying sequence, not ratcheting) and drop below the shakedown tolerance
    1e-3 Y/E by impact 5 (reference: this impact's Hertz p0 ≈ 3.9 k is below the shakedown limit p0 = 4.7 k of
    Ponter, Hearle & Johnson 1985, above which the increments would not vanish)."""
    case, result, _ = below_shakedown
    plate = case.plate.material()
    tolerance = 1e-3 * plate.yield_strength / plate.E
    inc = [r.plastic_strain_increment for r in result.records if r.kind == "computed"]
    print("plastic strain increments per impact:", inc, "tolerance", tolerance, "shakedown", result.shakedown_impact)
    assert inc[0] > 100 * tolerance  # the first impact yields
    assert all(b < 0.25 * a for a, b in zip(inc[:3], inc[1:4], strict=True))
    assert result.shakedown_impact is not None and result.shakedown_impact <= 5
    assert all(r.plastic_strain_increment < tolerance for r in result.records[result.shakedown_impact - 1 :])


def test_second_impact_pressure_is_hertz_on_the_conforming_dent(below_shakedown):
    """Reference: Hertz (Johnson 1985 §4.2) with the relative curvature of ball and seat, 1/R_eff = 1/R − 1/R_dent,
    R_dent fitted to the FE residual dent of impact 1 inside the contact of impact 2 (a nearly elastic re-impact:
    residual stresses do not change the linear elastic increment). Tolerance 10%: FE peak pressure on the reduced
    mesh (mesh_scale 3, ~10 elements across the contact: a few %) plus the dent being only nearly spherical."""
    case, result, dents = below_shakedown
    ball, plate = case.ball.material(), case.plate.material()
    e_star = effective_modulus(ball, plate)
    r, depth = dents[1]
    second = [rec for rec in result.records if rec.kind == "computed"][1]
    inside = r <= second.contact_radius
    slope = np.polyfit(r[inside] ** 2, depth[inside], 1)[0]  # depth = c0 − r²/(2 R_dent)
    r_dent = -1.0 / (2.0 * slope)
    r_eff = 1.0 / (1.0 / case.ball.radius - 1.0 / r_dent)
    expected = _hertz_p0(second.max_force, r_eff, e_star)
    flat = _hertz_p0(second.max_force, case.ball.radius, e_star)
    print(
        f"R_dent = {r_dent * 1e3:.3f} mm, R_eff = {r_eff * 1e3:.3f} mm; impact 2 p_max FE {second.max_pressure:.4g} "
        f"Pa, Hertz on the seat {expected:.4g} Pa ({second.max_pressure / expected - 1:+.2%}), on a flat {flat:.4g}"
    )
    assert r_dent > case.ball.radius
    assert second.max_pressure == pytest.approx(expected, rel=0.10)


def test_second_impact_pressure_is_the_halfspace_pressure_of_the_dented_surface(below_shakedown):
    """Reference: the elastic contact of the ball with the exact dented surface left by impact 1, solved by the
    half-space boundary-element method (contact.halfspace: Love 1929 influence coefficients, Polonsky & Keer 1999;
    checked against Hertz in tests/test_halfspace.py) at impact 2's max force: an elastic re-impact's pressure is
    the elastic contact pressure of the current surface (residual stresses drop out by superposition). Impact 2
    still yields a little (Δᾱ ≈ 5e-4), and the FE mesh is reduced (mesh_scale 3): tolerance 3%."""
    from contact.halfspace import sphere_on_axisymmetric_surface

    case, result, dents = below_shakedown
    e_star = effective_modulus(case.ball.material(), case.plate.material())
    r, depth = dents[1]
    second = [rec for rec in result.records if rec.kind == "computed"][1]
    R = case.ball.radius

    def dent(rho):
        return np.interp(rho, r, depth)

    bem, _ = sphere_on_axisymmetric_surface(R, dent, second.max_force, e_star, 2.0 * second.contact_radius, 96)
    flat = _hertz_p0(second.max_force, R, e_star)
    print(
        f"impact 2 p_max: FE {second.max_pressure:.4g} Pa, half-space on the dent {bem.max_pressure:.4g} Pa "
        f"({second.max_pressure / bem.max_pressure - 1:+.2%}), Hertz on a flat {flat:.4g} Pa"
    )
    assert second.max_pressure == pytest.approx(bem.max_pressure, rel=0.03)  # measured -0.75%
    assert bem.max_pressure < 0.95 * flat  # the conforming dent spreads the load (Hertz flat would be 15% off)
    # at the first impact's max force (equal force, not equal energy): again the half-space pressure of the
    # dented surface, and the first impact's own peak pressure — an elastic reload retraces the elastic unloading
    # from that maximum (Johnson 1985, ch. 6, unloading of a plastic indentation; Mesarovic & Johnson 2000), so
    # the conforming dent brings the pressure back to the plastic first impact's, 16% below Hertz on a flat, not
    # lower (measured −1.0%)
    first = result.records[0]
    at_first = sphere_on_axisymmetric_surface(R, dent, first.max_force, e_star, 2.0 * second.contact_radius, 96)[0]
    at_first = at_first.max_pressure
    print(
        f"at impact 1's max force {first.max_force:.4g} N: impact 2 p_max FE {second.max_pressure_at_first_force:.4g}"
        f" Pa, half-space {at_first:.4g} Pa; impact 1 p_max {first.max_pressure:.4g} Pa "
        f"({second.max_pressure_at_first_force / first.max_pressure - 1:+.1%})"
    )
    assert second.max_pressure_at_first_force == pytest.approx(at_first, rel=0.03)
    assert second.max_pressure_at_first_force == pytest.approx(first.max_pressure, rel=0.03)


def test_without_geometry_update_n_impacts_wear_n_times_one():
    """Elastic plate, geometry update off: 7 impacts (1 computed + a cycle-jump block of 6) wear exactly 7 × the
    first; and the first equals the single-impact pipeline's (``wear.run``, same FE coupling; reference validated
    by the impulse identity in tests/test_wear_integrate.py) within 1%."""
    case = _case(1.0, angle=30.0, elastic=True, scale=4.0)
    result = repeat(case.with_(repeat=dict(impacts=7, geometry_update=False)))
    assert [r.kind for r in result.records] == ["computed", "block"]
    one = result.records[0].wear_volume
    assert result.records[-1].total_wear_volume == pytest.approx(7 * one, rel=1e-12)
    assert result.wear.volume_m3 == pytest.approx(7 * one, rel=1e-9)
    single = run(case).wear.volume_m3
    print(f"one impact {one:.6g} m^3 vs wear.run {single:.6g} m^3 ({one / single - 1:+.2e})")
    assert one == pytest.approx(single, rel=0.01)


def test_with_geometry_update_a_later_impact_meets_lower_pressure():
    """Geometry update on: the worn, conforming surface lowers the max pressure of a later impact below the first's
    (elastic plate, so the only change is the wear moving the FE surface; oblique impact, since a normal one does
    not slide and does not wear). Qualitative reference: Hertz with the relative curvature of ball and seat,
    p0 ∝ (1/R − 1/R_seat)^(2/3) (Johnson 1985 §4.2), lower on any concave seat; the size of the drop is reported.
    A control run without geometry update keeps the first pressure."""
    case = _case(1.0, angle=30.0, elastic=True, scale=3.0)
    # blocks of at most 0.05 × the approach (half the default): three computed impacts in six
    result = repeat(case.with_(repeat=dict(impacts=6, geometry_update=True, surface_fraction=0.05)))
    computed = [r for r in result.records if r.kind == "computed"]
    p = [r.max_pressure for r in computed]
    print(
        f"max pressure at impacts {[r.first for r in computed]}: {p}; impact {computed[-1].first} vs 1: "
        f"{p[-1] / p[0] - 1:+.2%}; worn depth {result.records[-1].surface_depth:.3g} m"
    )
    assert len(p) >= 3
    assert p[-1] < p[0]
    assert result.records[-1].surface_depth > 0.0  # the wear moved the FE surface
    control = repeat(case.with_(repeat=dict(impacts=2, geometry_update=False)))
    assert control.records[0].max_pressure == p[0]
    # the last impact's pressure is the elastic half-space pressure of the worn surface it met (wear.chain.check;
    # contact.halfspace checked against Hertz in tests/test_halfspace.py): measured +0.05%; reduced mesh: 3%.
    # Without the wear profile's filter (repeat.wear_smoothing = 0) a node-scale ripple grows and the FE peak was
    # 26% above the half-space value by impact 6
    from wear.chain.check import halfspace_check

    check = halfspace_check(result)
    print({k: f"{v:.4g}" for k, v in check.items()})
    assert check["fe_max_pressure_Pa"] == pytest.approx(check["halfspace_max_pressure_Pa"], rel=0.03)


def test_elastic_response_after_shakedown_is_the_elastic_plastic_fe():
    """After a shaken-down impact the next computed impact is solved on the plate's elastic response (fem.
    elastic_reload) instead of the elastic–plastic FE: on an elastic plate the two are the same discrete solution
    (tests/test_fem_reload.py), so every record agrees; the worn-surface pressure of the elastic path is checked
    against the half-space solution in test_with_geometry_update_a_later_impact_meets_lower_pressure."""
    case = _case(1.0, angle=30.0, elastic=True, scale=4.0)
    case = case.with_(repeat={"impacts": 4, "geometry_update": True, "surface_fraction": 0.05})
    fast = repeat(case)
    full = repeat(case.with_(repeat={"elastic_after_shakedown": False}))
    assert [r.elastic_response for r in fast.records if r.kind == "computed"] == [False, True]
    assert fast.elastic_computed == 1 and full.elastic_computed == 0
    for a, b in zip(fast.records, full.records, strict=True):
        assert (a.first, a.count) == (b.first, b.count)
        for name in ("max_pressure", "max_force", "wear_volume", "contact_radius", "surface_depth"):
            assert getattr(a, name) == pytest.approx(getattr(b, name), rel=1e-4), name
        assert a.normal_restitution == pytest.approx(b.normal_restitution, abs=1e-6)


@pytest.mark.parametrize(
    "kwargs, text",
    [
        ({"impacts": 0}, "repeat.impacts=0"),
        ({"impacts": -3}, "repeat.impacts=-3"),
        ({"impacts": 2.5}, "repeat.impacts=2.5"),
        ({"surface_fraction": 0.0}, "repeat.surface_fraction=0"),
        ({"surface_fraction": 1.5}, "repeat.surface_fraction=1.5"),
        ({"shakedown_tolerance": -1e-3}, "repeat.shakedown_tolerance=-0.001"),
        ({"geometry_update": "yes"}, "repeat.geometry_update"),
        ({"save_every": -1}, "repeat.save_every=-1"),
        ({"max_plastic_impacts": 0}, "repeat.max_plastic_impacts=0"),
        ({"elastic_after_shakedown": 1}, "repeat.elastic_after_shakedown"),
    ],
)
def test_bad_repeat_spec_names_the_parameter(kwargs, text):
    with pytest.raises(ValueError, match=None) as err:
        RepeatSpec(**kwargs)
    assert text in str(err.value)


@pytest.mark.parametrize(
    "argv, text",
    [
        (["--impacts", "0"], "--impacts=0 is out of range"),
        (["--impacts", "2.5"], "--impacts=2.5 is not an integer"),
        (["--impacts", "many"], "--impacts='many' is not a number"),
    ],
)
def test_cli_bad_input_one_line_exit_2(argv, text, tmp_path, capsys):
    assert text in refused(["repeat", *argv], tmp_path, capsys)


def test_cli_bad_repeat_table(tmp_path, capsys):
    path = tmp_path / "case.toml"
    path.write_text(dump_case(Case(), JOBS["run"].tables) + "\n[repeat]\nsurface_fraction = 3.0\n")
    assert main(["repeat", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "repeat.surface_fraction=3" in err


def test_cli_writes_outputs(tmp_path, capsys):
    """A tiny run (elastic plate, 4 impacts, coarse mesh): repeat.csv, the .pvd series and figures, readable."""
    import json

    import meshio

    elastic = Case().with_(plate={"yield_strength": None}, fem={"mesh_scale": 4.0}, output={"render": False})
    path = tmp_path / "case.toml"
    path.write_text(dump_case(elastic, JOBS["run"].tables) + "\n[repeat]\nimpacts = 2\n")
    out = tmp_path / "out"
    assert main(["repeat", str(path), "--impacts", "4", "--out", str(out), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["impacts"] == 4
    rows = np.genfromtxt(out / "repeat.csv", delimiter=",", names=True)
    assert rows["impact_last"][-1] == 4
    assert rows["total_wear_volume_m3"][-1] == pytest.approx(summary["after_last_impact"]["total_wear_volume_m3"])
    assert (out / "repeat.png").is_file() and (out / "repeat.pvd").is_file()
    frames = sorted((out / "frames").glob("*.vtu"))
    mesh = meshio.read(frames[-1])
    assert {"displacement_m", "wear_depth_m", "on_surface"} <= set(mesh.point_data)
    assert {"equivalent_plastic_strain", "von_mises_stress_Pa"} <= set(mesh.cell_data)


def test_wear_profile_filter_follows_the_gaussian_transfer_function():
    """smooth_profile (wear.chain.axisymmetric_repeat): a Gaussian filter of standard deviation σ multiplies a ripple of
    wavelength λ by exp(−(2πσ/λ)²/2) (the Fourier transform of the Gaussian); a constant stays constant; the axis is a
    mirror."""
    from wear.chain.axisymmetric_repeat import smooth_profile

    r = np.linspace(0.0, 1e-3, 2001)
    sigma = 1e-5
    assert np.allclose(smooth_profile(r, np.full_like(r, 2e-7), sigma), 2e-7, rtol=1e-12)
    inner = (r > 0.2e-3) & (r < 0.8e-3)
    for wavelength in (2e-5, 1e-4, 2e-4):
        ripple = np.cos(2 * math.pi * r / wavelength)
        kept = smooth_profile(r, ripple, sigma)[inner].max()
        expected = math.exp(-0.5 * (2 * math.pi * sigma / wavelength) ** 2)
        assert kept == pytest.approx(expected, abs=0.01)
    even = smooth_profile(r, np.exp(-((r / 1e-4) ** 2)), sigma)
    assert even[1] == pytest.approx(even[0], rel=1e-3)  # zero slope on the axis


def test_wear_accumulator_grows_with_the_scar():
    """The cumulative 2-D map keeps the volume of a later impact whose map reaches past the first impact's padded
    grid (the scar widens as the seat conforms): before, the wear outside was dropped. Reference: the volumes of the
    maps added (Gaussian bumps, zero at their edges; bilinear transfer between grids of the same spacing)."""
    from wear.chain.wear_accumulator import WearAccumulator
    from wear.integrate import wear_map

    h = 1e-5

    def bump(half_x: int, half_y: int, width: float):
        x, y = np.arange(-half_x, half_x + 1) * h, np.arange(-half_y, half_y + 1) * h
        depth = 1e-7 * np.exp(-(x[None, :] ** 2 + y[:, None] ** 2) / width**2)
        return wear_map(x, y, depth, 4430.0, 0.01)

    small, large = bump(20, 20, 4 * h), bump(80, 80, 16 * h)
    acc = WearAccumulator(small)
    acc.add(small, 3)
    acc.add(large, 2)
    assert acc.x[0] <= large.x[0] and acc.x[-1] >= large.x[-1] and acc.y[-1] >= large.y[-1]
    assert acc.map().volume_m3 == pytest.approx(3 * small.volume_m3 + 2 * large.volume_m3, rel=1e-6)


def test_surface_profile_is_the_p2_interpolant():
    """fem.surface_profile reads the FE surface as its P2 elements carry it: exact for any quadratic on
    (vertex, mid-side, vertex) triples (Lagrange interpolation), and linear when the nodes do not alternate so."""
    from fem import surface_profile

    r = np.r_[0.0, np.cumsum(np.repeat([0.1, 0.3, 0.2], 2))]  # vertices 0, .2, .8, 1.2 with their mid-sides
    q = np.linspace(0.0, r[-1], 301)
    quadratic = lambda x: 3.0 * x**2 - x + 0.5  # noqa: E731
    np.testing.assert_allclose(surface_profile(r, quadratic(r), q), quadratic(q), atol=1e-12)
    uneven = np.array([0.0, 0.1, 0.3, 0.35, 1.0])
    np.testing.assert_allclose(surface_profile(uneven, uneven**2, np.array([0.2])), [0.05])
    assert surface_profile(r, quadratic(r), np.array([2.0]))[0] == 0.0
