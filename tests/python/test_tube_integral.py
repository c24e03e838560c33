"""Integrals of tubes (3.7)-(3.9), the primitive tube and TubeAnalysis from Python."""
import math
import random
from fractions import Fraction

import pytest
import sillage
from sillage import Interval, TDomain, Tube, TubeAnalysis

INF = math.inf


def small():
    # Slices [1,2], [-1,3], [0,0.5], [2,4] on [0,4]: L = 0,1,0,0,2 and U = 0,2,5,5.5,9.5 at t = 0..4.
    return Tube(TDomain(0.0, 4.0, 1.0), [Interval(1, 2), Interval(-1, 3), Interval(0, 0.5), Interval(2, 4)])


def test_integral_hand_computed():
    x = small()
    assert x.integral(4.0) == Interval(2, 9.5)
    assert x.integral(2.5) == Interval(0, 5.25)
    assert x.integral(Interval(1, 3)) == Interval(0, 5.5)
    assert x.integral(1.0, 3.0) == Interval(-1, 3.5)
    assert x.integral(3.0, 1.0) == Interval(-3.5, 1)
    assert x.integral(Interval(0.5, 1.5), Interval(2.5, 4)) == Interval(-1, 8.5)
    lo, up = x.partial_integral(Interval(0.5, 1.5), Interval(2.5, 4))
    assert lo == Interval(-1, 1.5)
    assert up == Interval(1.75, 8.5)


def test_unbounded_and_empty():
    x = Tube(TDomain(0.0, 4.0, 1.0), [Interval(1, 1), Interval(-INF, 1), Interval(1, 1), Interval(1, 1)])
    assert x.integral(2.0, 4.0) == Interval(2, 2)
    assert x.integral(0.0, 4.0) == Interval(-INF, 4)
    e = small()
    e.set(Interval.empty(), 2)
    assert e.integral(1.0).is_empty()
    assert x.integral(Interval.empty()).is_empty()


def test_errors():
    x = small()
    with pytest.raises(sillage.Error):
        x.integral(5.0)
    with pytest.raises(sillage.Error):
        x.integral(Interval(-1, 1), Interval(2, 3))
    with pytest.raises(sillage.Error):
        x.partial_integral(Interval(0, 1), Interval(3, 4.5))
    with pytest.raises(ValueError):  # sillage.Error is a ValueError
        TubeAnalysis(x).integral(-0.1)


def exact_integral(times, slices, values, s1, s2):
    """∫_{s1}^{s2} of the piecewise-constant trajectory values[k] on slice k, in exact rationals."""
    sign = 1
    if s1 > s2:
        s1, s2, sign = s2, s1, -1
    total = Fraction(0)
    for k in range(len(slices)):
        a, b = max(Fraction(s1), Fraction(times[k])), min(Fraction(s2), Fraction(times[k + 1]))
        if a < b:
            total += (b - a) * Fraction(values[k])
    return sign * total


def inside(q, x):
    return not x.is_empty() and Fraction(x.lb()) <= q <= Fraction(x.ub())


def test_random_trajectories_inside_the_integral():
    rng = random.Random(3)
    for trial in range(10):
        td = TDomain(0.3, 0.3 + 0.1 * (5 + 7 * trial), 0.1)
        times = td.times()
        slices = []
        for _ in range(td.nb_slices()):
            a, b = sorted((rng.uniform(-3, 3), rng.uniform(-3, 3)))
            slices.append(Interval(a, b))
        x = Tube(td, slices)
        an = TubeAnalysis(x)
        assert an.nb_slices() == td.nb_slices()
        for _ in range(20):
            values = [rng.uniform(s.lb(), s.ub()) for s in slices]
            s1, s2 = rng.uniform(times[0], times[-1]), rng.uniform(times[0], times[-1])
            q = exact_integral(times, slices, values, s1, s2)
            assert inside(q, an.integral(s1, s2))
            assert inside(q, x.integral(Interval(min(s1, s2), max(s1, s2)), Interval(s2)))
            w1 = Interval(s1 - 0.05 if s1 - 0.05 > times[0] else times[0], s1)
            assert inside(q, an.integral(w1, Interval(s2)))
            lo, up = an.partial_integral(w1, Interval(s2))
            assert inside(exact_integral(times, slices, [s.lb() for s in slices], s1, s2), lo)
            assert inside(exact_integral(times, slices, [s.ub() for s in slices], s1, s2), up)


def test_primitive():
    x = small()
    p = x.primitive()
    assert [p.gate(k) for k in range(5)] == [Interval(0), Interval(1, 2), Interval(0, 5), Interval(0, 5.5),
                                             Interval(2, 9.5)]
    assert p.slice(1) == Interval(0, 5)
    q = x.primitive(x0=Interval(-1, 1))
    assert q.gate(0) == Interval(-1, 1)
    assert q.gate(4) == Interval(1, 10.5)
    td = TDomain(0.0, 2.0, 0.01)
    v = Tube(td, "2*t")
    p = v.primitive(x0=1.0)
    for k in range(0, td.nb_slices() + 1, 17):
        t = td.t(k)
        assert p.gate(k).contains(1 + t * t)


def test_analysis_follows_the_tube():
    x = small()
    an = TubeAnalysis(x)
    assert an.integral(4.0) == Interval(2, 9.5)
    x.set(Interval(0, 1), 3)
    assert an.integral(4.0) == Interval(0, 6.5)
    assert an.eval(Interval(0.5, 2.5)) == x(Interval(0.5, 2.5))
    del x  # the analysis keeps the tube alive
    assert an.integral(4.0) == Interval(0, 6.5)
