"""CtcHeadingWindow (the displacement over windows of slices against the heading at the window's
middle, both ways) in Python: the contractor laws (sillage.testing) with an exact turning
vehicle, alone and in a network, exact straight windows, emptiness named and errors."""
import math

import pytest
import sillage
from sillage import (ContractorNetwork, CtcDeriv, CtcHeadingWindow, CtcIncrement, Interval, IntervalVector, TDomain,
                     Tube, TubeVector)

from sillage import testing as kit
from turning_vehicle import turning

TRACK, WINDOW, ACCEL = 0.05, 2.0, 1.0


def window_case(rng):
    """The turning vehicle of turning_vehicle.py inside the domains p, psi, d (distance per slice),
    dpsi (heading increment per slice), w (psi')."""
    v = turning(rng, TRACK)
    s, b, psi, px, py = v.s, v.b, v.psi, v.px, v.py
    td = kit.random_tdomain(rng, 20)
    n = td.nb_slices()
    free = [Interval()] * (n + 1)
    dist = [kit.around(Interval(s) * td.slice_width(k), rng, 0.05) for k in range(n)]
    dpsi = [kit.around(Interval(b) * td.slice_width(k), rng, 0.02) for k in range(n)]
    p = TubeVector([kit.tube_around(td, px, rng, 2.0, 0.3), kit.tube_around(td, py, rng, 2.0, 0.3)])
    doms = [p, kit.tube_around(td, psi, rng, 1.5, 0.3), Tube(td, dist, free), Tube(td, dpsi, free),
            Tube(td, kit.around(Interval(b), rng, 0.2))]
    return kit.Case(doms, [[px, py], psi, None, None, None])


def test_ctc_heading_window_laws():
    ctc = CtcHeadingWindow(WINDOW, TRACK, ACCEL)
    kit.check_laws(lambda d: ctc.contract(d[0], d[1], d[2], d[3], d[4]), window_case, cases=10,
                   idempotence="contraction", outputs=[0, 1])


def test_ctc_heading_window_in_a_network_laws():
    def contract(d):
        cn = ContractorNetwork()
        cn.add(CtcHeadingWindow(WINDOW, TRACK, ACCEL, 2), [d[0], d[1], d[2], d[3], d[4]])
        cn.add(CtcIncrement(), [d[1], d[3]])
        cn.add(CtcDeriv(), [d[1], d[4]])
        cn.contract()

    kit.check_laws(contract, window_case, cases=6, idempotence="contraction", outputs=[0, 1], empty_any=True,
                   threads=False)


def straight():
    """Ten slices of 1 s along +x at 1 m/s, no turn; p(0) = 0."""
    td = TDomain(0.0, 10.0, 1.0)
    p = TubeVector(td, 2)
    p.set_gate(0, IntervalVector([Interval(0), Interval(0)]))
    return td, p, Tube(td), Tube(td, Interval(1)), Tube(td, Interval(0)), Tube(td, Interval(0))


def test_ctc_heading_window_straight_both_ways():
    # heading from the positions: 10 (cos, sin) psi(t_5) must meet [9, 11] x [-1, 1]
    td, p, psi, d, dpsi, w = straight()
    psi.set_gate(5, Interval(-3, 3))
    p.set_gate(10, IntervalVector([Interval(9, 11), Interval(-1, 1)]))
    assert CtcHeadingWindow(10.0).contract(p, psi, d, dpsi, w)
    h = psi.gate(5)
    assert h.contains(math.asin(0.1)) and h.contains(-math.asin(0.1))
    assert -math.atan2(1, 9) - 1e-12 <= h.lb() and h.ub() <= math.atan2(1, 9) + 1e-12
    # positions from the heading: psi(t_5) = pi/2 exactly, p(t_10) = (0, 10)
    td, p, psi, d, dpsi, w = straight()
    psi.set_gate(5, sillage.Interval.half_pi())
    assert CtcHeadingWindow(10.0).contract(p, psi, d, dpsi, w)
    assert p[0].gate(10).contains(0.0) and p[1].gate(10).contains(10.0) and p.gate(10).max_diam() < 1e-12


def test_ctc_heading_window_inconsistent_is_named():
    td, p, psi, d, dpsi, w = straight()
    psi.set_gate(5, Interval(-0.1, 0.1))
    p.set_gate(10, IntervalVector([Interval(-2, -1), Interval(-0.5, 0.5)]))
    cn = ContractorNetwork()
    cn.add(CtcHeadingWindow(10.0), [p, psi, d, dpsi, w])
    stats = cn.contract()
    assert stats.empty and "CtcHeadingWindow" in stats.emptiness


def test_ctc_heading_window_errors_and_repr():
    for args in [(0.0,), (math.inf,), (1.0, -0.1), (1.0, 0.0, 0.0), (1.0, 0.0, math.nan)]:
        with pytest.raises(sillage.Error):
            CtcHeadingWindow(*args)
    c = CtcHeadingWindow(40.0, 0.05, 20.0, 25)
    assert (c.window(), c.track(), c.turn_accel(), c.stride()) == (40.0, 0.05, 20.0, 25)
    assert repr(c) == "CtcHeadingWindow(window=40.0, track=0.05, turn_accel=20.0, stride=25)"
    td = TDomain(0.0, 2.0, 1.0)
    with pytest.raises(sillage.DimensionError):
        CtcHeadingWindow(1.0).contract(TubeVector(td, 3), Tube(td), Tube(td), Tube(td), Tube(td))
