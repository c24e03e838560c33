"""Function: parsing, evaluation (natural, centered, batch), diff, HC4-revise."""
import math
import random

import numpy as np
import pytest

import sillage
from sillage import Function, Interval, IntervalVector

RANGE = "sqrt((x1 - 1)^2 + (x2 - 2)^2)"


def box(*bounds):
    return IntervalVector([Interval(a, b) for a, b in bounds])


def test_eval_scalar_returns_interval():
    f = Function(["x1", "x2"], RANGE)
    assert f.nb_vars() == 2 and f.image_dim() == 1
    y = f.eval(box((4, 4), (6, 6)))
    assert isinstance(y, Interval)
    assert y == Interval(5.0)
    assert f.eval(box((1, 4), (2, 6))) == Interval(0, 5)
    assert f.eval([Interval(4.0), Interval(6.0)]) == Interval(5.0)  # any IntervalVector(...) argument


def test_eval_vector_function_returns_interval_vector():
    f = Function(["x", "y"], "(x + y, x * y)")
    assert f.image_dim() == 2
    y = f.eval(box((2, 2), (3, 3)))
    assert isinstance(y, IntervalVector)
    assert y[0] == Interval(5.0) and y[1] == Interval(6.0)
    assert f.eval_vector(box((2, 2), (3, 3)))[1] == Interval(6.0)
    assert f[1].eval(box((2, 2), (3, 3))) == Interval(6.0)


def test_decimal_constants_are_enclosed():
    f = Function(["x"], "x * 0.1")
    y = f.eval(box((1, 1)))
    assert y.lb() < 0.1 <= y.ub() and y.diam() > 0


def test_diff_returns_a_function():
    f = Function(["x1", "x2"], RANGE)
    g = f.diff()
    assert isinstance(g, Function)
    assert g.image_dim() == 2
    r = g.eval(box((4, 4), (6, 6)))
    assert r[0].contains(0.6) and r[1].contains(0.8)
    j = Function(["x", "y"], "(x * y, sin(x))").jacobian(box((0, 0), (3, 3)))
    assert j.rows() == 2 and j.cols() == 2


def test_hc4_revise_contracts_in_place():
    f = Function(["x1", "x2"], "sqrt((x1 + 0.5)^2 + (x2 - 4.0)^2)")
    x = IntervalVector(2)
    assert f.hc4_revise(x, Interval(3.63, 4.43)) is True
    assert x[0].lb() == pytest.approx(-4.93) and x[0].ub() == pytest.approx(3.93)
    assert x[1].lb() == pytest.approx(-0.43) and x[1].ub() == pytest.approx(8.43)
    z = box((10, 11), (10, 11))
    assert f.hc4_revise(z, Interval(0, 1)) is False
    assert z.is_empty()
    v = Function(["x", "y"], "(x + y, x - y)")
    w = box((0, 10), (0, 10))
    assert v.hc4_revise(w, IntervalVector([Interval(0, 1), Interval(0, 1)]))
    assert w[0] == Interval(0, 1)


def test_hc4_never_removes_a_solution():
    f = Function(["x1", "x2"], "sin(x1) * x2 + exp(-x1^2) - x2^2")
    rng = random.Random(4)
    for _ in range(200):
        a, b = rng.uniform(-3, 3), rng.uniform(-3, 3)
        b0 = box((a, a + rng.uniform(0, 2)), (b, b + rng.uniform(0, 2)))
        y = Interval(-1, 0.5)
        x = IntervalVector(b0)
        f.hc4_revise(x, y)
        for _ in range(20):
            p = [rng.uniform(b0[i].lb(), b0[i].ub()) for i in range(2)]
            fp = f.eval(box((p[0], p[0]), (p[1], p[1])))
            if fp.is_subset(y):
                assert x[0].contains(p[0]) and x[1].contains(p[1])


def test_centered_eval_at_domain_boundary():
    # f is defined there, its derivative is not: the natural form is kept.
    assert Function(["y"], "sqrt(y)").centered_eval([[0, 0]])[0] == Interval(0)
    assert Function(["x1", "x2"], RANGE).centered_eval([[1, 1], [2, 2]])[0] == Interval(0)
    assert Function(["y"], "acos(y)").centered_eval([[1, 1]])[0] == Interval(0)
    assert Function(["y"], "asin(y)").centered_eval([[1, 1]])[0].is_superset(Interval.half_pi())
    assert Function(["y"], "root(y, 4)").centered_eval([[0, 0]])[0] == Interval(0)
    assert Function(["y"], "log(1 + sqrt(y))").centered_eval([[0, 0]])[0] == Interval(0)


def test_centered_eval():
    f = Function(["x1", "x2"], "x1 * x1 - 2 * x1 * x2 + x2 * x2")
    b = box((1, 1.01), (2, 2.01))
    c = f.centered_eval(b)
    assert isinstance(c, IntervalVector)
    assert c[0].is_subset(f.eval(b)) and c[0].contains(1.0)
    assert c[0].diam() < 0.5 * f.eval(b).diam()


def test_eval_batch_numpy_and_list():
    f = Function(["x", "y"], "(x + y, x * y)")
    xs = np.array([[[0, 1], [2, 3]], [[1, 1], [-1, 2]], [[-2, -1], [4, 4]]], dtype=float)
    out = f.eval_batch(xs)
    assert out.shape == (3, 2, 2)
    assert out[0, 0].tolist() == [2, 4]
    assert out[1, 1].tolist() == [-1, 2]
    assert out[2, 1].tolist() == [-8, -4]
    same = f.eval_batch([box(*row) for row in xs.tolist()])
    assert np.array_equal(out, same)
    for k in range(3):
        ref = f.eval(box(*xs[k].tolist()))
        assert [ref[0].lb(), ref[0].ub()] == out[k, 0].tolist()
    empty = Function(["x"], "sqrt(x)").eval_batch(np.array([[[-2.0, -1.0]]]))
    assert np.isnan(empty).all()  # an empty interval is (nan, nan)


def test_repr_and_str():
    f = Function(["x1", "x2"], "sqrt((x1-1)^2+(x2-2)^2)")
    assert str(f) == "(x1, x2) -> sqrt((x1 - 1)^2 + (x2 - 2)^2)"
    assert repr(f) == "Function((x1, x2) -> sqrt((x1 - 1)^2 + (x2 - 2)^2))"


@pytest.mark.parametrize("text, fragment", [
    ("sqrt((x1-1)^2", "expected ')' at column 14"),
    ("x1 +", "expected an operand"),
    ("x1 + z", "unknown identifier 'z'"),
    ("[2,1]", "lower bound above upper bound"),
    ("nan", "NaN"),
    ("x1 x2", "expected an operator or the end"),
    ("atan2(x1)", "takes 2 arguments"),
])
def test_parse_errors(text, fragment):
    with pytest.raises(sillage.Error, match=fragment.replace("(", r"\(").replace(")", r"\)")):
        Function(["x1", "x2"], text)


def test_errors_are_value_errors_with_dimensions():
    f = Function(["x1", "x2"], "x1 + x2")
    with pytest.raises(ValueError, match="expected a box of size 2, got 3"):
        f.eval(IntervalVector(3))
    with pytest.raises(sillage.Error):
        f.hc4_revise(IntervalVector(3), Interval(0, 1))
    with pytest.raises(sillage.Error):
        f.eval_batch(np.zeros((4, 3, 2)))
    with pytest.raises(sillage.Error):
        f.eval_batch(np.array([[[math.nan, 1.0], [0.0, 1.0]]]))
    with pytest.raises(sillage.Error):
        f.eval_batch(np.array([[[2.0, 1.0], [0.0, 1.0]]]))
    with pytest.raises(sillage.Error):
        Function(["x", "x"], "x")
