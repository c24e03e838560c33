"""CtcDeriv (thesis 4.2) and the derivative forms of Tube.eval / Tube.inverse
from Python: hand cases, the restricted forms, TubeVectors, errors, and the
truth kept on a random tube around sin."""
import math
import random

import pytest
import sillage
from sillage import CtcDeriv, Interval, TDomain, TimePropag, Tube, TubeVector

INF = math.inf


def five():
    """x(0) = 0, v = [0.5, 1] on [0, 5], unit slices."""
    td = TDomain(0.0, 5.0, 1.0)
    x = Tube(td)
    x.set_gate(0, Interval(0))
    return td, x, Tube(td, Interval(0.5, 1))


def test_time_propag_flags():
    assert TimePropag.FORWARD | TimePropag.BACKWARD == TimePropag.FWD_BWD
    assert CtcDeriv().time_propag() == TimePropag.FWD_BWD
    assert CtcDeriv(TimePropag.FORWARD).time_propag() == TimePropag.FORWARD
    assert "FORWARD" in repr(CtcDeriv(TimePropag.FORWARD))
    # Only both sweeps reach x' = v's fixed point (a network's CtcEval then leaves its fronts to it).
    assert CtcDeriv().enforces_derivative()
    assert not CtcDeriv(TimePropag.FORWARD).enforces_derivative()


def test_diamond_slice():
    td = TDomain([0.0, 1.0])
    x = Tube(td, [Interval()], [Interval(0), Interval(0)])
    v = Tube(td, Interval(-1, 1))
    assert CtcDeriv().contract(x, v) is True
    assert x.slice(0) == Interval(-0.5, 0.5)


def test_forward_backward_exact_values():
    td, x, v = five()
    x.set_gate(5, Interval(3))
    assert CtcDeriv().contract(x, v)
    expected = [Interval(0), Interval(0.5, 1), Interval(1, 1.5), Interval(1.5, 2), Interval(2, 2.5), Interval(3)]
    for k, g in enumerate(expected):
        assert x.gate(k) == g
    for k in range(5):
        assert x.slice(k) == expected[k] | expected[k + 1]
    # A second call is a fixed point.
    before = x.copy()
    assert CtcDeriv().contract(x, v)
    assert x == before


def test_forward_only_and_backward_only():
    td, x, v = five()
    CtcDeriv(TimePropag.FORWARD).contract(x, v)
    assert x.gate(5) == Interval(2.5, 5)
    td, y, v = five()
    y.set_gate(5, Interval(3))
    CtcDeriv(TimePropag.BACKWARD).contract(y, v)
    assert y.gate(4) == Interval(2, 2.5)
    assert y.gate(1) == Interval(-1, 1)


def test_restricted_forms():
    td, x, v = five()
    x.set_gate(2, Interval(1))
    y = x.copy()
    assert CtcDeriv().contract(x, v, 2, 3)
    assert x.gate(4) == Interval(2, 3)
    assert x.gate(1) == y.gate(1)  # outside the range: untouched
    z = y.copy()
    assert CtcDeriv().contract(z, v, Interval(2.5, 3.5))
    assert z == x
    with pytest.raises(sillage.Error):
        CtcDeriv().contract(x, v, 3, 1)
    with pytest.raises(sillage.Error):
        CtcDeriv().contract(x, v, Interval(4, 7))


def test_unbounded_derivative_and_empty():
    td = TDomain([0.0, 1.0])
    x = Tube(td, [Interval()], [Interval(1, 2), Interval()])
    CtcDeriv().contract(x, Tube(td, Interval(0, INF)))
    assert x.gate(1) == Interval(1, INF)
    assert x.slice(0) == Interval(1, INF)
    y = Tube(td, [Interval()], [Interval(0), Interval(2)])
    assert CtcDeriv().contract(y, Tube(td, Interval(1))) is False
    assert y.is_empty()


def test_tube_vector_and_errors():
    td = TDomain(0.0, 5.0, 1.0)
    x, v = TubeVector(td, 2), TubeVector(td, 2, Interval(-1, 1))
    x[0].set_gate(0, Interval(0))
    assert CtcDeriv().contract(x, v)
    assert x[0].gate(5) == Interval(-5, 5)
    with pytest.raises(sillage.Error):  # DimensionError is an Error
        CtcDeriv().contract(x, TubeVector(td, 3))
    with pytest.raises(sillage.Error):
        CtcDeriv().contract(Tube(td), Tube(TDomain(0.0, 5.0, 1.0)))


def test_eval_and_inverse_with_derivative():
    td = TDomain([0.0, 1.0])
    x = Tube(td, [Interval()], [Interval(0), Interval(0)])
    v = Tube(td, Interval(-1, 1))
    assert x.eval(0.25, v) == Interval(-0.25, 0.25)
    assert x.eval(Interval(0.25, 0.75), v) == Interval(-0.5, 0.5)
    assert x(0.25) == Interval()  # the slice box alone
    assert x.inverse(Interval(0.25, 1), v) == Interval(0.25, 0.75)
    assert x.inverse(Interval(0.25, 1)) == Interval(0, 1)  # the old form is still there
    assert x.inverse(Interval(2, 3), v).is_empty()
    with pytest.raises(sillage.Error):
        x.eval(2.0, v)


def test_random_tube_keeps_sin():
    rng = random.Random(4)
    td = TDomain(0.0, 6.0, 0.1)
    n = td.nb_slices()
    ts = [td.t(k) for k in range(n + 1)]
    # Slices of sin inflated by 0.05 (sin is 1-Lipschitz: a slice of width
    # 0.1 varies by 0.1 at most), v = cos inflated.
    slices = [Interval(min(math.sin(ts[k]), math.sin(ts[k + 1])) - 0.15 - rng.random() * 0.1,
                       max(math.sin(ts[k]), math.sin(ts[k + 1])) + 0.15 + rng.random() * 0.1) for k in range(n)]
    x = Tube(td, slices)
    x.set_gate(0, Interval(-0.01, 0.01))
    v = Tube(td, "cos(t) + [-0.05, 0.05]")
    volume = x.volume()
    assert CtcDeriv().contract(x, v)
    assert x.volume() < volume
    for i in range(200):
        t = rng.uniform(0.0, 6.0)
        assert x.eval(t, v).contains(math.sin(t))
        assert x.eval(t, v).is_subset(x(t))
    # Next to the known gate: 0.02 + 0.1·(spread of v over slice 0, 0.105).
    assert x.gate(1).diam() < 0.035
