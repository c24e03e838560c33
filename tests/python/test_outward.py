"""sillage.outward: numpy bounds moved outward by whole floats, so that a bound computed with
numpy's rounded-to-nearest arithmetic encloses the true one."""
from fractions import Fraction

import numpy as np
import pytest

import sillage


def test_one_ulp_outward_encloses_a_rounded_sum():
    lb, ub = sillage.outward(np.array([0.1 + 0.2, -1.0]), np.array([0.1 + 0.2, 2.0]))
    assert lb[0] == np.nextafter(0.30000000000000004, -np.inf) and ub[0] == np.nextafter(0.30000000000000004, np.inf)
    exact = Fraction(0.1) + Fraction(0.2)  # the sum of the two doubles, which + rounded up
    assert Fraction(lb[0]) < exact < Fraction(ub[0]) and Fraction(0.1 + 0.2) > exact
    assert lb[1] == np.nextafter(-1.0, -np.inf) and ub[1] == np.nextafter(2.0, np.inf)


def test_ulps_infinities_and_errors():
    lb, ub = sillage.outward([1.0, -np.inf], [1.0, np.inf], ulps=3)
    assert lb[0] == 1.0 - 3 * np.spacing(0.5) and ub[0] == 1.0 + 3 * np.spacing(1.0)
    assert lb[1] == -np.inf and ub[1] == np.inf
    same = sillage.outward(1.5, 2.5, ulps=0)
    assert same[0] == 1.5 and same[1] == 2.5
    with pytest.raises(ValueError, match="ulps must be an integer >= 0"):
        sillage.outward(0.0, 1.0, ulps=-1)
