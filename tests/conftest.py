"""The suite's settings shared by every test module.

``pytest.approx`` accepts, besides its relative tolerance, any difference up to an absolute 1e-12 unless a test
gives ``abs``. In SI units that silences the comparison of the toolkit's smallest quantities: a worn volume of one
impact is 1e-15 m³, so ``approx(v, rel=0.1)`` accepted any volume within ±1e-12 m³, a thousand times the value (a
3-D worn volume 12% from its reference passed a 10% check). The default absolute tolerance is 0 here: a comparison
is relative unless the test states an absolute tolerance in the quantity's units.
"""

import pytest

type(pytest.approx(1.0)).DEFAULT_ABSOLUTE_TOLERANCE = 0.0
