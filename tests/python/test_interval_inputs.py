"""Exact inputs: ints enclosed outward, integral float exponents (issue 12, items 3 and 4)."""
import math
import sys

import numpy as np

from sillage import Function, Interval

MAX = sys.float_info.max
INF = math.inf


def test_integral_float_exponent_is_the_integer_power():
    x = Interval(-2, -1)
    assert x ** 2.0 == Interval(1, 4) == x ** 2
    assert x ** np.float64(2) == Interval(1, 4)
    assert x ** 3.0 == Interval(-8, -1)
    assert x ** -2.0 == Interval(0.25, 1)
    assert (x ** 0.5).is_empty()  # a real exponent needs x >= 0
    assert Function(["x"], "x^2.0").eval([[-2, -1]]) == x ** 2.0


def test_big_int_exponents_keep_their_parity():
    m = Interval(-1)
    assert m ** (2 ** 40) == Interval(1) and m ** (2 ** 40 + 1) == Interval(-1)
    assert m ** (2 ** 80) == Interval(1) and m ** (2 ** 80 + 1) == Interval(-1)
    assert m ** (-(2 ** 80) - 1) == Interval(-1)
    assert Interval(-2) ** (2 ** 80 + 1) == Interval(-INF, -MAX)


def test_ints_are_enclosed_outward():
    n = 2 ** 53
    assert Interval(n) == Interval(float(n))
    assert Interval(n + 1) == Interval(float(n), float(n + 2))
    assert Interval(-n - 1) == Interval(-float(n + 2), -float(n))
    assert Interval(np.int64(n + 1)) == Interval(float(n), float(n + 2))
    assert Interval(10 ** 400) == Interval(MAX, INF)
    assert Interval(-10 ** 400) == Interval(-INF, -MAX)
    assert Interval(n + 1, n + 1) == Interval(float(n), float(n + 2))
    assert Interval(n + 1, 1e300) == Interval(float(n), 1e300)
    assert Interval(0.5, 3) == Interval(0.5, 3.0)
    # ints reach an interval through arithmetic too, on either side
    assert (Interval(0) + (n + 1)).contains(float(n)) and not (Interval(0) + (n + 1)).is_degenerate()
    assert not ((n + 1) + Interval(0)).is_degenerate() and not ((n + 1) - Interval(0)).is_degenerate()
    assert not ((n + 1) * Interval(1)).is_degenerate()
    assert Interval(float(n)) != n + 1


def test_bad_bounds_are_type_errors():
    import pytest
    with pytest.raises(TypeError):
        Interval("a", 1)


def test_ints_in_pairs_and_expressions_are_enclosed_outward():
    from sillage import ExprVar, IntervalVector
    n = 2 ** 53
    wide = Interval(float(n), float(n + 2))
    assert IntervalVector([n + 1, [0, n + 1]]) == IntervalVector([wide, Interval(0, float(n + 2))])
    x = ExprVar("x")
    zero, one, m1 = [[0, 0]], [[1, 1]], [[-1, -1]]
    assert Function([x], x + (n + 1)).eval(zero) == wide
    assert Function([x], (n + 1) + x).eval(zero) == wide
    assert Function([x], (n + 1) * x).eval(one) == wide
    assert Function([x], x - (n + 1)).eval(zero) == -wide
    # huge int exponents keep their parity
    assert Function([x], x ** (n + 1)).eval(m1) == Interval(-1)
    assert Function([x], x ** (2 ** 80)).eval(m1) == Interval(1)
    assert Function([x], x ** (2 ** 80 + 1)).eval(m1) == Interval(-1)
