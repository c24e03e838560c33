"""The expression builder from Python: ExprVar, Expr, operators, the elementary
functions on expressions, and Function([x1, x2], expr)."""
import math
import random

import pytest

import sillage
from sillage import Expr, ExprVar, Function, Interval, IntervalVector

x1, x2 = ExprVar("x1"), ExprVar("x2")

# (builder expression, the same expression as text). Constants are exact doubles,
# so that the text and the builder give the same constant nodes.
PAIRS = [
    (sillage.sqrt(sillage.sqr(x1 - 1) + sillage.sqr(x2 - 2)), "sqrt(sqr(x1 - 1) + sqr(x2 - 2))"),
    (sillage.sqrt((x1 - 1) ** 2 + (x2 - 2) ** 2), "sqrt((x1 - 1)^2 + (x2 - 2)^2)"),
    (x1 * x2 - x1 / x2 + -x1, "x1 * x2 - x1 / x2 + -x1"),
    (2 * x1 + 1 - 3 / x2, "2 * x1 + 1 - 3 / x2"),
    (1 - x1 * 0.5, "1 - x1 * 0.5"),
    (Interval(1, 2) * x1 + Interval(-1, 0), "[1, 2] * x1 + [-1, 0]"),
    (Interval(1, 2) - x2 / Interval(2, 4), "[1, 2] - x2 / [2, 4]"),
    (x1 ** 3 - x2 ** -1, "x1^3 - x2^-1"),
    (x1 ** 0.5 + x2 ** 2.0, "x1^0.5 + x2^2"),
    (x1 ** x2 + 2 ** x1, "x1^x2 + 2^x1"),
    (sillage.pow(x1, 3) + sillage.pow(x1, 0.5) + sillage.pow(x1, x2), "pow(x1, 3) + pow(x1, 0.5) + pow(x1, x2)"),
    (sillage.root(x1, 3) + sillage.root(x2, 4), "root(x1, 3) + root(x2, 4)"),
    (sillage.exp(x1) * sillage.log(x2), "exp(x1) * log(x2)"),
    (sillage.sin(x1) + sillage.cos(x2) - sillage.tan(x1 * x2), "sin(x1) + cos(x2) - tan(x1 * x2)"),
    (sillage.asin(x1 / 4) + sillage.acos(x2 / 4) + sillage.atan(x1), "asin(x1 / 4) + acos(x2 / 4) + atan(x1)"),
    (sillage.atan2(x2, x1) + sillage.atan2(x1, 1), "atan2(x2, x1) + atan2(x1, 1)"),
    (sillage.sinh(x1) - sillage.cosh(x2) * sillage.tanh(x1), "sinh(x1) - cosh(x2) * tanh(x1)"),
    (sillage.abs(x1) + abs(x2) + sillage.sign(x1 - x2), "abs(x1) + abs(x2) + sign(x1 - x2)"),
    (sillage.min(x1, x2) * sillage.max(x1, 0), "min(x1, x2) * max(x1, 0)"),
    (x1 * sillage.expr_pi(), "x1 * pi"),
]


def random_boxes(rng, n):
    boxes = []
    for _ in range(n):
        b = []
        for _ in range(2):
            a, c = sorted(rng.uniform(-4, 4) for _ in range(2))
            b.append(Interval(a, c) if rng.random() < 0.8 else Interval(a))
        boxes.append(IntervalVector(b))
    return boxes


@pytest.mark.parametrize("built, text", PAIRS, ids=[t for _, t in PAIRS])
def test_builder_evaluates_like_the_parsed_text(built, text):
    f = Function([x1, x2], built)
    g = Function(["x1", "x2"], text)
    assert f.var_names() == ["x1", "x2"] and f.image_dim() == 1
    for b in random_boxes(random.Random(text), 200):
        fy, gy = f.eval(b), g.eval(b)
        assert fy == gy or (fy.is_empty() and gy.is_empty()), (text, b)
    # Hash-consing: the builder and the parser give the very same node.
    assert f.exprs()[0] == g.exprs()[0]
    assert f.tape_size() == g.tape_size()


def test_vector_function_from_a_list():
    f = Function([x1, x2], [x1 + x2, x1 * x2, 3.0])
    g = Function(["x1", "x2"], "(x1 + x2, x1 * x2, 3)")
    b = IntervalVector([[1, 2], [3, 4]])
    assert f.image_dim() == 3
    r = f.eval(b)
    assert isinstance(r, IntervalVector) and r == g.eval(b)
    assert r[0] == Interval(4, 6) and r[1] == Interval(3, 8) and r[2] == Interval(3)
    assert f.jacobian(b) == g.jacobian(b)
    assert f.diff().eval(b) == g.diff().eval(b)
    assert f[1].eval(b) == Interval(3, 8)


def test_shared_nodes():
    a, b = sillage.sqr(x1 - 1), sillage.sqr(x1 - 1)
    assert a == b and hash(a) == hash(b) and not (a != b)
    assert a != sillage.sqr(x1 - 2)
    assert ExprVar("x1") == x1
    assert len({a, b, x1 - 1}) == 2
    # sqr(x1 - 1) is one node used twice: 1, x1 - 1, sqr, + (as the parsed text).
    f = Function([x1], a + b)
    assert f.tape_size() == Function(["x1"], "sqr(x1-1) + sqr(x1-1)").tape_size() == 4
    assert f.tape_size() < Function([x1], a + sillage.sqr(x1 - 2)).tape_size()
    # HC4 intersects the projections that reach the shared node: 2 sqr(x1 - 1) in [0, 2].
    box = IntervalVector([[-10, 10]])
    assert f.hc4_revise(box, Interval(0, 2))
    assert Interval(0, 2).is_subset(box[0]) and box[0].is_subset(Interval(-0.5, 2.5))


def test_reflected_operators_and_constants():
    b = IntervalVector([[1, 2], [3, 4]])
    assert Function([x1, x2], 2 + x1).eval(b) == Interval(3, 4)
    assert Function([x1, x2], 2 - x1).eval(b) == Interval(0, 1)
    assert Function([x1, x2], 2 * x1).eval(b) == Interval(2, 4)
    assert Function([x1, x2], 2 / x1).eval(b) == Interval(1, 2)
    assert Function([x1, x2], Interval(0, 1) + x1).eval(b) == Interval(1, 3)
    assert Function([x1, x2], Interval(4) - x2).eval(b) == Interval(0, 1)
    assert Function([x1, x2], Interval(1, 2) * x1).eval(b) == Interval(1, 4)
    assert Function([x1, x2], Interval(4) / x1).eval(b) == Interval(2, 4)
    assert Function([x1, x2], 2 ** x1).eval(b) == Interval(2, 4)
    assert Function([x1, x2], x1 ** 2).eval(IntervalVector([[-2, 1], [0, 0]])) == Interval(0, 4)
    assert Function([x1, x2], x1 ** 3).eval(IntervalVector([[-2, 1], [0, 0]])) == Interval(-8, 1)
    # Constant operands are folded with interval arithmetic; Expr(c) is a constant.
    c = Expr(1) + Interval(0, 1) * 2
    assert c.is_const() and c.op() == sillage.Op.Const
    assert Function([x1], c).eval([0]) == Interval(1, 3)
    assert Function([x1], 2.5).eval([0]) == Interval(2.5)
    assert not (x1 + 1).is_const() and (x1 + 1).op() == sillage.Op.Add
    assert (x1 ** 3).op() == sillage.Op.PowInt and (x1 ** 0.5).op() == sillage.Op.Pow
    assert (x1 ** 2).op() == sillage.Op.Sqr and (x1 ** 2) == sillage.sqr(x1)
    assert (x1 ** Expr(3)).op() == sillage.Op.PowInt and (+x1) == x1
    # x += y rebinds x, as in C++.
    e = x1
    e += 1
    e *= x2
    assert e == (x1 + 1) * x2 and x1.op() == sillage.Op.Var


def test_str_and_repr():
    e = sillage.sqrt(sillage.sqr(x1 - 1) + sillage.sqr(x2 - 2))
    f = Function([x1, x2], e)
    assert str(e) == f.expr_str()
    assert repr(e) == "Expr(" + str(e) + ")"
    assert str(x1) == "x1" and repr(x1) == "ExprVar('x1')" and x1.name() == "x1"
    assert str(f).startswith("(x1, x2) -> ")
    # The printed text parses back to the same node.
    assert Function(["x1", "x2"], str(e)).exprs()[0] == e


def test_interval_functions_still_work():
    assert isinstance(sillage.sqrt(Interval(4)), Interval) and sillage.sqrt(Interval(4)) == Interval(2)
    assert isinstance(sillage.sqrt(4.0), Interval)
    assert sillage.pow(Interval(-2, 1), 2) == Interval(0, 4)
    assert sillage.pow(Interval(4), 0.5) == Interval(2)
    assert sillage.atan2(Interval(1), Interval(1)).contains(math.pi / 4)
    assert sillage.abs(IntervalVector([[-2, 1]]))[0] == Interval(0, 2)
    assert sillage.min(Interval(1, 3), 2) == Interval(1, 2)
    assert isinstance(sillage.sin(x1), Expr) and isinstance(sillage.pow(x1, 2), Expr)
    # Mixed Expr / Interval / number arguments build expressions.
    assert sillage.min(Interval(0, 1), x1) == sillage.min(Expr(Interval(0, 1)), x1)
    assert sillage.pow(2.0, x1) == 2 ** x1
    # `from sillage import *` still leaves the builtins abs/min/max/pow alone.
    ns = {}
    exec("from sillage import *", ns)
    assert "abs" not in ns and "min" not in ns and "max" not in ns and "pow" not in ns
    assert ns["ExprVar"] is ExprVar and ns["sqrt"] is sillage.sqrt and ns["Variable"] is ExprVar


def test_builder_function_in_ctc_function_and_sivia():
    # The two beacons of test_paving.py (2.25 rather than 2.2: a decimal literal of a text is
    # enclosed by two doubles, a float of the builder is one double).
    built = Function([x1, x2], [sillage.sqrt((x1 - 8) ** 2 + (x2 - 5) ** 2),
                                sillage.sqrt((x1 - 7) ** 2 + (x2 - 2.25) ** 2)])
    parsed = Function(["x1", "x2"], "(sqrt((x1 - 8)^2 + (x2 - 5)^2), sqrt((x1 - 7)^2 + (x2 - 2.25)^2))")
    assert built.exprs() == parsed.exprs()
    y = IntervalVector([[9.03, 9.83], [6.94, 7.74]])
    x0 = IntervalVector([[-10, 10], [-10, 10]])
    a, b = x0.copy(), x0.copy()
    sillage.CtcFunction(built, y).contract(a)
    sillage.CtcFunction(parsed, y).contract(b)
    assert a == b and a.is_subset(x0) and a != x0
    p = sillage.sivia(x0, built, y, 0.1)
    assert p == sillage.sivia(x0, parsed, y, 0.1)
    assert p.count(sillage.PavingTag.Inner) > 0
    q = sillage.sivia(x0, built, y, sillage.CtcFunction(built, y), 0.1)
    assert q == sillage.sivia(x0, parsed, y, sillage.CtcFunction(parsed, y), 0.1)
    s = sillage.sivia(x0, sillage.SepFunction(built, y), 0.1)
    assert s == sillage.sivia(x0, sillage.SepFunction(parsed, y), 0.1)


def test_builder_errors():
    with pytest.raises(sillage.Error):
        ExprVar("1x")
    with pytest.raises(sillage.Error):
        Function([x1], x1 + x2)  # x2 is not a variable of the function
    with pytest.raises(sillage.Error):
        sillage.root(x1, 0)
    with pytest.raises(sillage.Error):
        Function([x1], [])
    with pytest.raises(TypeError):
        Function([x1 + 1], x1)  # variables must be ExprVar
    with pytest.raises(TypeError):
        x1 + "a"
    assert (x1 == "a") is False


def test_long_chain_does_not_overflow_the_stack():
    e = x1
    for i in range(100000):
        e = e + i
    del e
