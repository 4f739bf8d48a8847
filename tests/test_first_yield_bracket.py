"""First yield of the FE plate is found inside the step in which it occurs, not at that step's end.

The case: ``impactwear indent``'s default (a rigid ball, R 10 mm, on steel E 210 GPa, ν 0.3, Y 210 MPa) on the
mesh of a path to 100 N. With 12 load steps the first step already reaches 1.9 δ_c and yields; scaled from the
plastic step's elastic stress capped at Y the FE reported 0.997 N against the exact 0.377 N (Johnson 1985, Contact
Mechanics §6.2, F_c = π³C³Y³R²/(6E*²) with C(0.3) = 1.6128: contact.theory.first_yield). Tolerance: 3% in force,
that of tests/test_fem_yield.py for this mesh resolution (1% in the largest von Mises stress is 3% in F_y).
Only the loading up to the first yielded step is run: first yield depends on nothing after it.
"""

import numpy as np
import pytest

import fem
from contact import effective_modulus
from contact.theory import first_yield
from fem.axisymmetric.indent import FIRST_YIELD_RTOL
from fem.core.plasticity import von_mises
from wear.case import default_case
from wear.chain.indent import _overlap_for_force
from wear.chain.plate import case_mesh

CASE = default_case("indent")
R = CASE.ball.radius
PLATE = CASE.plate.material()
E_STAR = effective_modulus(CASE.ball.material(), PLATE)
EXACT = first_yield(R, E_STAR, PLATE.yield_strength, PLATE.nu)
D_MAX = _overlap_for_force(100.0, R, E_STAR, EXACT)  # the overlap `impactwear indent --max-force 100` loads to
TOLERANCE = 0.03


@pytest.fixture(scope="module")
def mesh():
    return case_mesh(CASE, D_MAX)


def _to_first_yield(mesh, steps: int) -> fem.IndentationResult:
    """``indent_case``'s loading path of ``steps`` steps to 100 N, up to and including its first yielded step."""
    loading = D_MAX * np.linspace(0.0, 1.0, steps + 1)[1:] ** 1.5
    k = int(np.argmax(loading > EXACT.overlap)) + 1
    return fem.indent(R, PLATE, loading[:k], mesh=mesh, keep_states=True)


def test_first_step_yields_and_first_yield_is_bracketed(mesh):
    res = _to_first_yield(mesh, 12)
    assert res.overlap.size == 1 and res.max_equivalent_plastic_strain[0] > 0.0  # the first step yielded
    fy = res.first_yield
    print(f"12 steps: F_y(FE) = {fy.force:.4g} N, exact {EXACT.force:.4g} N ({fy.force / EXACT.force - 1:+.2%})")
    assert fy.force == pytest.approx(EXACT.force, rel=TOLERANCE)
    assert fy.overlap == pytest.approx(EXACT.overlap, rel=TOLERANCE)
    assert fy.force < res.force[0]  # inside the step, not at its end
    # on the axis at z ≈ 0.48 a (Johnson 1985 Eq. 3.45); 0.1 a is one element of this mesh at first yield
    assert abs(fy.depth / fy.contact_radius - 0.481) < 0.1
    # a few elastic re-solves, no more: one at the yielded overlap, one at the scaled first yield
    assert res.run.solver.stats.increments <= 1 + 3


def test_many_steps_unchanged_and_coarse_steps_agree(mesh):
    fine = _to_first_yield(mesh, 40)
    assert fine.regime[-2] == "elastic" and fine.regime[-1] != "elastic"
    # the former estimate: the last elastic step's state scaled to first yield by the self-similar Hertz field
    solver, state = fine.run.solver, fine.run.kept[-2]
    ratio = PLATE.yield_strength / float(von_mises(solver.stress_update(state).stress).max())
    before = fine.force[-2] * ratio**3
    after = fine.first_yield.force
    print(f"40 steps: F_y(FE) = {after:.4g} N, scaled from the last elastic step {before:.4g} N")
    assert after == pytest.approx(before, rel=TOLERANCE)
    assert after == pytest.approx(EXACT.force, rel=TOLERANCE)
    coarse = _to_first_yield(mesh, 12).first_yield.force
    assert coarse == pytest.approx(after, rel=2 * FIRST_YIELD_RTOL)  # the same mesh's first yield, to the tolerance
