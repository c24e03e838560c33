"""Contractors and separators from Python: in-place contraction, the algebra,
Python subclasses, errors, and the separator laws on sampled points."""
import math
import random

import pytest
import sillage
from sillage import Interval, IntervalVector, Function


def box(*bounds):
    return IntervalVector([Interval(a, b) for a, b in bounds])


def bounds(x):
    return [(x[i].lb(), x[i].ub()) for i in range(x.size())]


def test_ctc_add_thesis_example_in_place():
    # C+([4,5],[0,3],[-2,2]) = ([4,5],[2,3],[1,2]) (2.31), box (a, x, y) with a = x + y
    b = box((4, 5), (0, 3), (-2, 2))
    r = sillage.CtcAdd().contract(b)
    assert r is b
    assert bounds(b) == [(4, 5), (2, 3), (1, 2)]


def test_ctc_unary_exp():
    b = box((-math.inf, 1), (-math.inf, math.inf))
    sillage.CtcUnary("exp").contract(b)
    assert b[0].lb() == 0 and b[0].ub() == 1
    assert b[1].lb() == -math.inf and 0 <= b[1].ub() < 1e-15
    b = box((8, 27), (-math.inf, math.inf))
    sillage.CtcUnary("pow", 3).contract(b)
    assert b[1].contains(2) and b[1].contains(3) and b[1].diam() < 1 + 1e-12


def test_ctc_function_scalar_vector_and_zero():
    f = Function(["x", "y"], "x + y")
    b = box((0, 3), (-2, 2))
    assert sillage.CtcFunction(f, Interval(4, 5)).contract(b) is b
    assert bounds(b) == [(2, 3), (1, 2)]
    g = Function(["x", "y"], "(x + y, x - y)")
    v = box((0, 10), (0, 10))
    sillage.CtcFunction(g, box((2, 2), (0, 0))).contract(v)
    assert v[0].contains(1) and v[1].contains(1) and v[0].diam() <= 2
    z = box((0, 10))
    sillage.CtcFunction(Function(["x"], "x^2 - 4")).contract(z)
    assert z[0].contains(2) and z[0].diam() < 1e-12


def test_algebra_operators_and_classes():
    c1 = sillage.CtcBox(box((0, 2), (0, 2)))
    c2 = sillage.CtcBox(box((1, 3), (1, 3)))
    a, u, c = box((-9, 9), (-9, 9)), box((-9, 9), (-9, 9)), box((-9, 9), (-9, 9))
    (c1 & c2).contract(a)
    (c1 | c2).contract(u)
    sillage.CtcCompo([c1, c2]).contract(c)
    assert bounds(a) == [(1, 2), (1, 2)]
    assert bounds(u) == [(0, 3), (0, 3)]
    assert bounds(c) == [(1, 2), (1, 2)]
    assert isinstance(c1 & c2, sillage.CtcInter) and isinstance(c1 | c2, sillage.CtcUnion)
    i = sillage.CtcInter([c1, c2, c1])
    assert i.nb_vars() == 2


def test_fixpoint():
    c1 = sillage.CtcFunction(Function(["x", "y"], "x - y"))
    c2 = sillage.CtcFunction(Function(["x", "y"], "y - x / 2 - 1"))
    b = box((0, 10), (0, 10))
    sillage.CtcFixPoint(sillage.CtcCompo([c1, c2]), 0.0).contract(b)
    assert b[0].contains(2) and b[1].contains(2) and b[0].diam() < 1e-12


def test_errors_are_sillage_errors():
    f = Function(["x", "y"], "x + y")
    with pytest.raises(sillage.Error, match="CtcFunction"):
        sillage.CtcFunction(f, Interval(0, 1)).contract(box((0, 1)))
    with pytest.raises(ValueError):
        sillage.CtcFunction(Function(["x", "y"], "(x, y)"), Interval(0, 1))
    with pytest.raises(sillage.Error):
        sillage.CtcBox(box((0, 1))) & sillage.CtcBox(box((0, 1), (0, 1)))
    with pytest.raises(sillage.Error):
        sillage.CtcUnary("erf")
    with pytest.raises(sillage.Error):
        sillage.CtcFixPoint(sillage.CtcAdd(), 1.5)
    with pytest.raises(sillage.Error):
        sillage.CtcInter([])


class Halve(sillage.Ctc):
    """Keeps the lower half of component 0 (not a real constraint: a test double)."""

    def __init__(self):
        super().__init__(1)
        self.calls = 0

    def contract(self, x):
        self.calls += 1
        x[0] = Interval(x[0].lb(), x[0].mid())


class ReturnsWide(sillage.Ctc):
    """Returns a larger box: the result must still be intersected with the input."""

    def __init__(self):
        super().__init__(1)

    def contract(self, x):
        return box((-100, 0.5))


def test_python_subclass_in_combinations():
    h = Halve()
    b = box((0, 8))
    h.contract(b)  # direct call: plain Python
    assert bounds(b) == [(0, 4)]
    b = box((0, 8))
    sillage.CtcCompo([h, h]).contract(b)  # through C++: the override runs in place
    assert bounds(b) == [(0, 2)]
    assert h.calls == 3
    b = box((0, 8))
    sillage.CtcCompo([ReturnsWide()]).contract(b)  # the temporary must stay alive too
    assert bounds(b) == [(0, 0.5)]
    assert h.name() == "Halve"  # the C++ name() of a Python subclass is its class name
    with pytest.raises(sillage.Error, match="Halve"):
        sillage.ContractorNetwork().add(h, [Interval(), Interval()])


def test_python_subclass_outlives_its_variable():
    c = sillage.CtcInter([Halve()])  # the only reference is inside c
    import gc
    gc.collect()
    b = box((0, 8))
    c.contract(b)
    assert bounds(b) == [(0, 4)]


def test_separator_disk_and_algebra():
    f = Function(["x", "y"], "x^2 + y^2")
    s = sillage.SepFunction(f, Interval(-math.inf, 1))
    x_in, x_out = box((-0.5, 0.5), (-0.5, 0.5)), box((-0.5, 0.5), (-0.5, 0.5))
    r = s.separate(x_in, x_out)
    assert r[0] is x_in and r[1] is x_out
    assert x_in.is_empty() and not x_out.is_empty()
    x_in, x_out = box((2, 3), (2, 3)), box((2, 3), (2, 3))
    (~s).separate(x_in, x_out)  # complement: the box is inside
    assert x_in.is_empty() and not x_out.is_empty()
    pair = sillage.SepCtcPair(sillage.CtcBox(box((0, 1))), sillage.CtcBox(box((2, 3))))
    a, b = box((-5, 5)), box((-5, 5))
    pair.separate(a, b)
    assert bounds(a) == [(0, 1)] and bounds(b) == [(2, 3)]
    assert isinstance(s & s, sillage.SepInter) and isinstance(s | s, sillage.SepUnion)
    assert isinstance(sillage.SepNot(s), sillage.SepNot)


def test_separator_laws_on_samples():
    # X = { (x, y) : sqrt(x) + y^2 <= 2 }: sqrt is partial, x < 0 is outside X.
    f = Function(["x", "y"], "sqrt(x) + y^2")
    y = Interval(-math.inf, 2)
    seps = [sillage.SepFunction(f, y)]

    def member(p):
        if p[0] < 0:
            return -1
        v = math.sqrt(p[0]) + p[1] ** 2
        return 1 if v < 2 - 1e-9 else (-1 if v > 2 + 1e-9 else 0)

    rng = random.Random(3)
    removed_in = removed_out = 0
    for _ in range(300):
        lx, ly = rng.uniform(-3, 3), rng.uniform(-3, 3)
        wx, wy = rng.uniform(0, 3), rng.uniform(0, 3)
        x_in, x_out = box((lx, lx + wx), (ly, ly + wy)), box((lx, lx + wx), (ly, ly + wy))
        seps[0].separate(x_in, x_out)
        for _ in range(30):
            p = (rng.uniform(lx, lx + wx), rng.uniform(ly, ly + wy))
            m = member(p)
            if not (x_out[0].contains(p[0]) and x_out[1].contains(p[1])):
                removed_out += 1
                assert m != 1, (p, bounds(x_out))
            if not (x_in[0].contains(p[0]) and x_in[1].contains(p[1])):
                removed_in += 1
                assert m != -1, (p, bounds(x_in))
    assert removed_in > 500 and removed_out > 500


def test_definition_check():
    d = sillage.DefinitionCheck(Function(["x"], "sqrt(x)"))
    assert not d.is_total()
    assert d.defined_on(box((1, 2))) is True
    assert d.defined_on(box((-1, 2))) is False
    assert d.defined_on(box((0, 2))) is True
    assert d.defined_on([[4, 9]]) is True  # any IntervalVector(...) argument
    assert d.defined_on(IntervalVector([Interval.empty()])) is True
    total = sillage.DefinitionCheck(Function(["x", "y"], "x^2 + sin(y) * exp(x)"))
    assert total.is_total() and total.defined_on(box((-1e300, 1e300), (-5, 5)))
    x, y = sillage.ExprVar("x"), sillage.ExprVar("y")
    d2 = sillage.DefinitionCheck(Function([x, y], sillage.log(x) + 1 / y))
    assert not d2.is_total()
    assert d2.defined_on(box((1, 2), (1, 2)))
    assert not d2.defined_on(box((1, 2), (-1, 2)))
    assert not d2.defined_on(box((0, 2), (1, 2)))
    with pytest.raises(sillage.Error):
        d.defined_on(box((1, 2), (1, 2)))
