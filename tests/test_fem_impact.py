"""``fem.indent_impact`` along contact's impact history (issue 3).

Elastic steel ball on an elastic steel plate, normal impact: the FE force at each picked step must equal the
impact model's own
Hertz force at that overlap (Johnson 1985 Eq. 4.23: F = 4/3 E* √R δ^{3/2}) within 2% (reduced mesh: 12
elements across the largest contact radius; F converges to ~0.5% there), the steps carry the impact times,
and they are denser near the maximum overlap.
"""

import numpy as np

import fem
from contact.impact import simulate_impact
from contact.materials import Material, effective_modulus
from contact.theory import hertz_force

R = 5e-3
BALL = Material(E=210e9, nu=0.3, density=7850.0)  # elastic: enters through E* (errata Eq. 5)
PLATE = Material(E=210e9, nu=0.3, density=7850.0)


def test_indent_impact_follows_the_impact_history():
    imp = simulate_impact(R, BALL, PLATE, speed=0.05, angle=0.0, friction=0.0)
    d_max = float(np.max(imp.history.overlap))
    mesh = fem.plate_mesh(R, PLATE, d_max, contact_elements=12, yield_elements=0)
    res = fem.indent_impact(imp, PLATE, steps=9, mesh=mesh)
    assert res.time is not None and res.time.shape == res.overlap.shape
    assert np.all(np.diff(res.time) > 0.0)
    np.testing.assert_allclose(
        np.interp(res.time, imp.history.t, imp.history.overlap), res.overlap, rtol=0.0, atol=1e-3 * d_max
    )
    e_star = effective_modulus(BALL, PLATE)
    inside = res.overlap > 0.05 * d_max
    np.testing.assert_allclose(res.force[inside], hertz_force(res.overlap[inside], R, e_star), rtol=0.02)
    load = np.diff(res.overlap[: int(np.argmax(res.overlap)) + 1])
    assert load[-1] < load[0]  # denser near the maximum
