"""Primitives from Taylor increments from Python: exact on a linear integrand,
truth kept with noise, tighter than the plain primitive."""
import math

import pytest
import sillage
from sillage import Interval, TDomain, Tube


def test_linear_integrand_exact():
    td = TDomain(0.0, 1.0, 0.5)
    w, dw = Tube(td, "t"), Tube(td, Interval(1.0))
    inc = sillage.taylor_increments(w, dw)
    assert inc[0] == Interval(0.125) and inc[1] == Interval(0.375)
    p = sillage.primitive_taylor(w, dw, Interval(0.0))
    assert p.gate(2) == Interval(0.5) and p.slice(0) == Interval(0.0, 0.125)


def test_noise_truth_and_tightness():
    td = TDomain(0.0, 10.0, 0.01)
    noise = Interval(-0.01, 0.01)
    p = sillage.primitive_taylor(Tube(td, "sin(t)"), Tube(td, "cos(t)"), Interval(0.0), noise)
    for a in (-0.01, 0.0, 0.004, 0.01):
        truth = sillage.Trajectory(f"1 - cos(t) + {a}*(1 - cos(7*t))/7", Interval(0, 10))
        assert p.contains(truth)
    plain = Tube(td, "sin(t) + [-0.01, 0.01]").primitive(Interval(0.0))
    n = td.nb_slices()
    assert p.gate(n).diam() < plain.gate(n).diam() - 0.05
    assert p.gate(n).contains(1 - math.cos(10.0))


def test_known_gates_and_errors():
    td = TDomain(0.0, 1.0, 0.25)
    gates = [Interval()] * 4 + [Interval(0.0)]
    p = sillage.primitive_from_increments(Tube(td, Interval(-1, 1)), [Interval(-0.25, 0.25)] * 4, Interval(0.0), gates)
    assert p.gate(3) == Interval(-0.25, 0.25)
    with pytest.raises(sillage.DimensionError):
        sillage.primitive_from_increments(Tube(td), [Interval(0.0)] * 3, Interval(0.0))
    with pytest.raises(sillage.DimensionError):
        sillage.taylor_increments(Tube(td), Tube(TDomain(0.0, 1.0, 0.5)))
