"""The impact ⇄ plate coupling (fem.couple).

The coupling machinery (loading once, unloading from the converged maximum, the tabulated law, the FE pressure
placed on the impact's time axis) is first checked with stand-in "plates" whose force laws are closed forms
(Hertz 1882; Thornton 1997), so the coupled impact must reproduce those closed forms. The same checks on the
real FE plate (fem.indent) run when fem is available.
"""

import math
from types import SimpleNamespace

import numpy as np
import pytest

import fem
from contact import Material, effective_modulus
from contact.theory import (
    default_limiting_pressure,
    hertz_force,
    hertz_impact,
    hertz_surface_displacement,
    sphere_mass,
    thornton_restitution,
    yield_velocity,
)
from fem.coupling import fixed_point
from wear import Case, restitution_sweep, run
from wear.app.figures.run import restitution_comparison
from wear.chain.estimate import estimate_impact
from wear.chain.plate import coupling_settings, impact_on_law

BALL = Material(E=210e9, nu=0.3, density=7850.0, name="steel")


def closed_form_indent(radius, e_star, p_y=None):
    """A stand-in FE result along a path of overlaps: Hertz loading (elastic) or Thornton (1997) elastic-perfectly
    plastic loading F = F_y + π p_y R (δ − δ_y), with Thornton's elastic unloading of enlarged radius R_p; the
    pressure is Hertz's over the current radius."""

    def indent(overlaps) -> fem.IndentationResult:
        overlaps = np.asarray(overlaps, float)
        k = int(np.argmax(overlaps))
        d_star = overlaps[k]
        if k < overlaps.size - 1:  # replace the unloading by a dense one so the table resolves the curve
            overlaps = np.concatenate([overlaps[: k + 1], d_star * (1 - np.linspace(0, 1, 400)[1:] ** 1.2)])
        F = np.zeros_like(overlaps)
        a = np.zeros_like(overlaps)
        if p_y is None:
            F = hertz_force(overlaps, radius, e_star)
            a = np.sqrt(radius * overlaps)
            f_star, d_p, r_p = float(hertz_force(d_star, radius, e_star)), 0.0, radius
        else:
            d_y = (math.pi * p_y / (2 * e_star)) ** 2 * radius
            f_y = float(hertz_force(d_y, radius, e_star))
            load = overlaps[: k + 1]
            F[: k + 1] = np.where(
                load <= d_y, hertz_force(load, radius, e_star), f_y + math.pi * p_y * radius * (load - d_y)
            )
            a[: k + 1] = np.sqrt(radius * load)
            f_star = float(F[k])
            if d_star <= d_y:
                d_p, r_p = 0.0, radius
            else:
                r_p = 4 * e_star / (3 * f_star) * ((2 * f_star + f_y) / (2 * math.pi * p_y)) ** 1.5
                d_p = d_star - (3 * f_star / (4 * e_star * math.sqrt(r_p))) ** (2 / 3)
        un = overlaps[k + 1 :]
        F[k + 1 :] = 4 / 3 * e_star * math.sqrt(r_p) * np.maximum(un - d_p, 0) ** 1.5
        a[k + 1 :] = np.sqrt(r_p * np.maximum(un - d_p, 0))
        a_max = a.max()
        r = np.linspace(0, 3 * a_max, 121)
        with np.errstate(invalid="ignore", divide="ignore"):
            p0 = np.where(a > 0, 3 * F / (2 * math.pi * np.maximum(a, 1e-300) ** 2), 0.0)
        ratio = np.divide(r[None, :], a[:, None], out=np.full((a.size, r.size), 2.0), where=a[:, None] > 0)
        p = p0[:, None] * np.sqrt(np.maximum(1 - ratio**2, 0))
        n = overlaps.size
        return fem.IndentationResult(
            overlaps,
            F,
            a,
            p.max(axis=1),
            p0 * 2 / 3,
            r,
            p,
            np.zeros_like(p),  # the surface's radial displacement: not read by the coupling
            None,
            np.zeros_like(r),
            np.zeros(n),
            ["elastic"] * n,
            np.zeros(n, int),
            radius,
            e_star,
        )

    return indent


class ClosedFormPlate:
    """A stand-in of :class:`fem.Plate` whose force law is a closed form (:func:`closed_form_indent`): virgin and
    flat, loading along the path, unloading densely from the requested maximum."""

    def __init__(self, radius, e_star, p_y=None):
        self.effective_modulus = e_star
        self.state = None  # no field: the closed forms carry no plastic strain
        self._indent = closed_form_indent(radius, e_star, p_y)

    def plastic_work(self, since) -> float:
        return 0.0

    def surface_radial_displacement(self):
        return np.zeros(121)  # the closed forms' surface (121 radii) does not move radially

    def first_contact_overlap(self) -> float:
        return 0.0

    def first_yield_overlap(self) -> None:
        return None

    def load(self, overlaps):
        return self._indent(overlaps)

    def unload(self, loading, max_overlap, steps=8):
        return self._indent(np.array([max_overlap, 0.5 * max_overlap]))


def _case(plate: Material, speed: float, angle: float = 0.0, **fem):
    return Case.from_dict(
        {
            "ball": {"radius": 5e-3, "E": BALL.E, "nu": BALL.nu, "density": BALL.density, "name": "steel"},
            "plate": {"E": plate.E, "nu": plate.nu, "density": plate.density, "yield_strength": plate.yield_strength},
            "impact": {"speed": speed, "angle": angle, "friction": 0.3, "normal_model": "thornton"},
            "fem": fem,
        }
    )


def _couple(case, plate):
    estimate = estimate_impact(case)
    return fem.couple(plate, impact_on_law(case), estimate.max_overlap, coupling_settings(case))


def test_coupling_on_hertz_plate_reproduces_hertz_impact():
    """Stand-in elastic plate (Hertz law tabulated): the coupled impact's max force and contact time equal the
    closed-form Hertz impact (errata Eqs. 4, 10–11) within 1%, e_n = 1 within 1%; converges in ≤ 3 impact runs."""
    plate = Material(E=210e9, nu=0.3, density=7850.0)
    case = _case(plate, 1.0, angle=30.0)
    e_star = effective_modulus(BALL, plate)
    res = _couple(case, ClosedFormPlate(5e-3, e_star))
    ref = hertz_impact(sphere_mass(5e-3, BALL.density), 5e-3, e_star, math.cos(math.radians(30.0)))
    assert res.converged and res.iterations <= 3 and res.change < 0.005
    assert res.impact.max_force == pytest.approx(ref.max_force, rel=0.01)
    assert res.impact.contact_time == pytest.approx(ref.contact_time, rel=0.01)
    assert res.impact.normal_restitution == pytest.approx(1.0, rel=0.01)
    # FE pressure placed on the impact time axis: its peak force history integrates back to max force
    t, r, p = res.pressure_table
    assert np.all(np.diff(t) > 0)
    force = 2 * math.pi * np.trapezoid(p * r, r, axis=1)
    assert force.max() == pytest.approx(ref.max_force, rel=0.02)


@pytest.mark.parametrize("ratio", [1.5, 2.0, 5.0])
def test_coupling_on_thornton_plate_reproduces_thornton_restitution(ratio):
    """Stand-in elastic-perfectly plastic plate with Thornton's (1997) loading/unloading laws: the coupled normal
    restitution equals Thornton's closed form e(V/V_y) (contact.theory.thornton_restitution) within 1%."""
    plate = Material(E=210e9, nu=0.3, density=7850.0, yield_strength=400e6)
    e_star = effective_modulus(BALL, plate)
    v_y = yield_velocity(5e-3, BALL, plate)
    p_y = default_limiting_pressure(BALL, plate)
    case = _case(plate, ratio * v_y)
    res = _couple(case, ClosedFormPlate(5e-3, e_star, p_y))
    assert res.converged
    assert res.impact.normal_restitution == pytest.approx(float(thornton_restitution(ratio)), rel=0.01)


# --------------------------------------------------------------------------- the real FE plate (fem.indent)
FE_QUICK = {"mesh_scale": 4.0, "load_steps": 10, "unload_steps": 6}


def _fe_case(plate: Material, speed: float, angle: float = 0.0, **fem_options):
    return _case(plate, speed, angle, **{**FE_QUICK, **fem_options}).with_(
        wear={"pressure": "fe"}, output={"render": False, "figures": False}
    )


@pytest.mark.filterwarnings("ignore:elastic ball")
def test_fe_coupling_elastic_plate_matches_hertz():
    """Issue 4 acceptance 5 (elastic): two-way coupling on the elastic FE plate (fem.indent, coarse mesh) gives the
    closed-form Hertz impact's max force and contact time (errata Eqs. 4, 10–11) within 1%, and e_n = 1 within 1%."""
    plate = Material(E=210e9, nu=0.3, density=7850.0)
    case = _fe_case(plate, 1.0, angle=30.0).with_(impact={"normal_model": "hertz"})
    result = run(case)
    v_n = case.impact.speed * math.cos(math.radians(case.impact.angle))
    ref = hertz_impact(sphere_mass(5e-3, BALL.density), 5e-3, effective_modulus(BALL, plate), v_n)
    assert result.coupling.converged and result.coupling.change < 0.005
    assert result.impact.normal_model == "tabulated"
    assert result.impact.max_force == pytest.approx(ref.max_force, rel=0.01)
    assert result.impact.contact_time == pytest.approx(ref.contact_time, rel=0.01)
    assert result.impact.normal_restitution == pytest.approx(1.0, abs=0.01)
    # no plastic strain: the residual dent is nil (< 1e-3 of the max overlap)
    assert result.surface.max_dent_depth < 1e-3 * ref.max_overlap


@pytest.mark.filterwarnings("ignore:elastic ball")
def test_fe_coupling_plastic_plate_converges_and_matches_thornton(tmp_path):
    """Issue 4 acceptance 5 (plastic): on the elastic-perfectly plastic FE plate (steel, Y = 400 MPa, coarse mesh)
    the coupled iteration converges (< 0.5%) and e_n is within 5% of Thornton (1997) (contact.theory.
    thornton_restitution) for V_n/V_y = 1.2, 1.5, 2. Measured (this mesh): +0.4%, +2.0%, +4.9% (finer mesh,
    mesh_scale 2: +0.5%, +2.1%, +5.0%, so the 5% bound of the issue is nearly reached at V/V_y = 2 by the physics,
    not the mesh): the FE plate dissipates less than Thornton's flat-topped
    pressure at p_y, and the gap grows with V/V_y. The side-by-side figure is written by
    wear.app.figures.run.restitution_comparison (reused by the validation report)."""
    plate = Material(E=210e9, nu=0.3, density=7850.0, yield_strength=400e6)
    case = _fe_case(plate, 1.0)
    sweep = restitution_sweep(case, [1.2, 1.5, 2.0])
    assert np.all(sweep.change < 0.005)
    assert np.all(np.abs(sweep.difference) < 0.05), sweep.difference
    assert np.all(sweep.restitution < 1.0)  # the plate yields: energy is lost
    path = restitution_comparison(sweep.speed_ratio, sweep.restitution, tmp_path / "e_vs_vy.png")
    assert path.stat().st_size > 10_000


def test_hertz_surface_displacement_closed_forms():
    """The elastic displacement removed from a truncated FE unloading (Johnson 1985, Eqs. 3.41): at r = 0 it is the
    Hertz overlap a²/R when p0 = 2aE*/(πR) (all compliance in one body); far away it tends to Boussinesq's point load
    F/(πE*r) (within 0.1% at r = 30a); it is continuous at r = a."""
    R, e_star, a = 5e-3, 1e11, 1e-4
    p0 = 2 * a * e_star / (math.pi * R)
    force = 2 * math.pi * a * a * p0 / 3
    u = hertz_surface_displacement(np.array([0.0, a * (1 - 1e-9), a * (1 + 1e-9), 30 * a]), force, a, e_star)
    assert u[0] == pytest.approx(a * a / R, rel=1e-12)
    assert u[1] == pytest.approx(u[2], rel=1e-6)
    assert u[3] == pytest.approx(force / (math.pi * e_star * 30 * a), rel=1e-3)


class _ToyPlate:
    """A plate whose force law is a number: each cycle moves the impact's δ_max halfway to 1 µm (a contraction)."""

    def __init__(self):
        self.cycles = 0

    def cycle(self, impact):
        self.cycles += 1
        return self.cycles, 0.5 * (impact.max_overlap + 1e-6)

    def change(self, before, after):
        return abs(after.max_overlap - before.max_overlap) / before.max_overlap


def _impact_on(target):
    return SimpleNamespace(max_overlap=target, tangential_restitution=float("nan"))


def test_fixed_point_stops_at_the_tolerance_and_at_max_cycles():
    """The one coupling loop (fem.coupling.fixed_point): a contraction halving the distance to 1 µm from 2 µm
    changes δ_max by 1/4, 1/6, 1/10, 1/18, ... (closed form 1/(2^k + 2) at cycle k): it stops at the first change
    below the tolerance, or after max_cycles with converged False."""
    plate = _ToyPlate()
    point = fixed_point(plate, _impact_on, _impact_on(2e-6), tolerance=0.1, max_cycles=10)
    assert point.converged and plate.cycles == 4 and point.cycle == 4
    assert point.change == pytest.approx(1 / 18)
    assert point.max_overlaps == pytest.approx((2e-6, 1.5e-6, 1.25e-6, 1.125e-6, 1.0625e-6))
    plate = _ToyPlate()
    point = fixed_point(plate, _impact_on, _impact_on(2e-6), tolerance=0.1, max_cycles=2)
    assert not point.converged and plate.cycles == 2 and point.change == pytest.approx(1 / 6)
    with pytest.raises(ValueError, match="max_cycles=0"):
        fixed_point(_ToyPlate(), _impact_on, _impact_on(2e-6), tolerance=0.1, max_cycles=0)
