"""Pointwise tube contractors from Python: CtcFunction.contract on Tubes and on
a TubeVector (thesis 3.2.3), next to the unchanged box form."""
import math
import random

import pytest
import sillage
from sillage import CtcFunction, Function, Interval, IntervalVector, TDomain, Tube, TubeVector


def td012():
    return TDomain([0.0, 1.0, 2.0])


def test_box_form_unchanged():
    c = CtcFunction(Function(["x", "y"], "x - y"))
    x = IntervalVector([[0, 1], [0.5, 3]])
    r = c.contract(x)
    assert r is x
    assert x[1] == Interval(0.5, 1)
    r = c.contract(x=IntervalVector([[0, 1], [0.5, 3]]))  # keyword form of Ctc.contract
    assert r[1] == Interval(0.5, 1)
    assert c.contract([[0, 1], [2, 3]]).is_empty()  # implicit conversion kept
    with pytest.raises(sillage.Error):
        c.contract(IntervalVector(3))


def test_tubes_addition():
    td = td012()
    x, y, a = Tube(td, Interval(0, 1)), Tube(td, Interval(0, 1)), Tube(td, Interval(-10, 10))
    a.set(Interval(1.5, 5), 1)
    c = CtcFunction(Function(["x", "y", "a"], "x + y - a"))
    assert c.contract(x, y, a) is True
    assert a.slice(0) == Interval(0, 2)
    assert a.slice(1) == Interval(1.5, 2)
    assert x.slice(1) == Interval(0.5, 1)
    assert x.gate(1) == Interval(0.5, 1)


def test_speed_heading():
    td = TDomain(0.0, 1.0, 0.25)
    x3, x4, v = Tube(td, "t/10 + [-0.01, 0.01]"), Tube(td, "2 + t + [-0.01, 0.01]"), Tube(td)
    c = CtcFunction(Function(["x3", "x4", "v"], "x4*cos(x3) - v"))
    c.contract(x3, x4, v)
    # Up to rounding: the pointwise cos rows (batch kernel) may differ from cos by a few ulps.
    for k in range(td.nb_slices()):
        got, expected = v.slice(k), x4.slice(k) * sillage.cos(x3.slice(k))
        assert abs(got.lb() - expected.lb()) <= 1e-14 * abs(expected.lb())
        assert abs(got.ub() - expected.ub()) <= 1e-14 * abs(expected.ub())


def test_tubevector_and_components():
    td = td012()
    x = TubeVector(td, 2, Interval(-5, 5))
    c = CtcFunction(Function(["x", "y"], "(x - y, x)"), IntervalVector([[0, 0], [1, 2]]))
    assert c.contract(x)
    assert x[0].codomain() == Interval(1, 2)
    assert x[1].codomain() == Interval(1, 2)
    y = TubeVector(td, 2, Interval(-5, 5))
    c.contract(y[0], y[1])  # live components
    assert y[1].codomain() == Interval(1, 2)


def test_empty():
    td = td012()
    x, y = Tube(td, Interval(0, 1)), Tube(td, Interval(0, 1))
    y.set(Interval(2, 3), 1)
    assert CtcFunction(Function(["x", "y"], "x - y")).contract(x, y) is False
    assert x.is_empty() and y.is_empty()


def test_errors():
    td = td012()
    c = CtcFunction(Function(["x", "y"], "x - y"))
    x, y = Tube(td, Interval(0, 1)), Tube(td, Interval(0, 1))
    with pytest.raises(sillage.Error):
        c.contract(x)
    with pytest.raises(sillage.Error):
        c.contract(x, Tube(TDomain([0.0, 1.0, 2.0]), Interval(0, 1)))
    with pytest.raises(sillage.Error):
        c.contract(x, x)
    with pytest.raises(sillage.Error):
        c.contract(x, IntervalVector(1))
    with pytest.raises(sillage.Error):
        c.contract(TubeVector(td, 3))


def test_property_dyadic():
    """Exact solutions (dyadic values) at gates and inside slices are never removed."""
    rng = random.Random(3)
    c = CtcFunction(Function(["a", "b", "r"], "a*b - a - r"))
    for _ in range(40):
        n = rng.randint(1, 8)
        td = TDomain(0.0, 1.0, 1.0 / n)
        n = td.nb_slices()
        pts = []  # (is_gate, k, (a, b, r))
        for k in range(n + 1):
            a, b = rng.randint(-64, 64) / 16, rng.randint(-64, 64) / 16
            pts.append((True, k, (a, b, a * b - a)))
        for k in range(n):
            for _ in range(2):
                a, b = rng.randint(-64, 64) / 16, rng.randint(-64, 64) / 16
                pts.append((False, k, (a, b, a * b - a)))
        tubes = []
        for j in range(3):
            slices = []
            for k in range(n):
                vals = [p[2][j] for p in pts if (p[0] and p[1] in (k, k + 1)) or (not p[0] and p[1] == k)]
                slices.append(Interval(min(vals), max(vals)).inflate(rng.randint(0, 8) / 16))
            gates = []
            for k in range(n + 1):
                g = Interval(pts[k][2][j]).inflate(rng.randint(0, 8) / 16)
                g &= slices[min(k, n - 1)]
                if k > 0:
                    g &= slices[k - 1]
                gates.append(g)
            tubes.append(Tube(td, slices, gates))
        before = [t.copy() for t in tubes]
        assert c.contract(*tubes)
        for j in range(3):
            assert tubes[j].is_subset(before[j])
            for is_gate, k, vals in pts:
                box = tubes[j].gate(k) if is_gate else tubes[j].slice(k)
                assert box.contains(vals[j])


def test_continuous_sin():
    td = TDomain(0.0, 10.0, 0.1)
    x1, x2 = Tube(td, "t"), Tube(td, Interval(-3, 3))
    CtcFunction(Function(["a", "b"], "sin(a) - b")).contract(x1, x2)
    assert x2.max_thickness() < 0.11
    for k in range(td.nb_slices()):
        t = 0.5 * (td.t(k) + td.t(k + 1))
        assert x2.slice(k).contains(math.sin(t))


def test_any_contractor():
    """CtcCompo and a Python contractor on tubes: one call per slice and gate."""
    td = td012()
    x, y = Tube(td, Interval(0, 3)), Tube(td, Interval(1, 1.5))
    c = sillage.CtcCompo([CtcFunction(Function(["x", "y"], "x - y")),
                          CtcFunction(Function(["x", "y"], "x + y - 2"))])
    assert c.contract(x, y)
    assert y.codomain() == Interval(1)

    class Halve(sillage.Ctc):
        calls = 0

        def __init__(self):
            super().__init__(1)

        def contract(self, box):
            Halve.calls += 1
            box[0] = box[0] & Interval(0, 1)
            return box

    z = Tube(td, Interval(-5, 5))
    h = Halve()
    assert h.contract(IntervalVector(1))[0] == Interval(0, 1)  # the Python override, on a box
    assert Halve.calls == 1
    assert sillage.Ctc.contract(h, z)  # the tube form of the base class
    assert Halve.calls == 1 + 2 + 3
    assert z.codomain() == Interval(0, 1)
