"""Acceptance 5 of issue 3: mesh convergence. Refining the mesh twice (8 → 16 → 32 P2 elements across the
contact radius) changes F and p0 by amounts that shrink; the observed order is printed.

Case: elastic Hertz indentation at a = 0.01 R (Johnson 1985 §4.2), one increment, no first-yield box. The
closed form is also checked at the finest mesh (1%), so a method converging to a wrong limit fails too.
"""

import math

import numpy as np

import fem
from contact.materials import Material, effective_modulus
from contact.theory import hertz_force

R = 10e-3
PLATE = Material(E=210e9, nu=0.3, density=7850.0)


def test_refining_twice_shrinks_the_changes():
    d = (0.01 * R) ** 2 / R
    forces, peaks = [], []
    for n in (8, 16, 32):
        mesh = fem.plate_mesh(R, PLATE, d, contact_elements=n, yield_elements=0)
        res = fem.indent(R, PLATE, [d], mesh=mesh)
        forces.append(res.force[0])
        peaks.append(res.max_pressure[0])
    forces, peaks = np.array(forces), np.array(peaks)
    dF = np.abs(np.diff(forces))
    dp = np.abs(np.diff(peaks))
    order_F = math.log2(dF[0] / dF[1])
    order_p = math.log2(dp[0] / dp[1])
    print(f"F: {forces} (changes {dF}, observed order {order_F:.2f}); p0: {peaks} (changes {dp}, order {order_p:.2f})")
    assert dF[1] < dF[0]
    assert dp[1] < dp[0]
    e_star = effective_modulus(Material.rigid(), PLATE)
    assert abs(forces[-1] / hertz_force(d, R, e_star) - 1.0) < 0.01
