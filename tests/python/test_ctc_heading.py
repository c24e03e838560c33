"""CtcHeading (the displacement over each slice from distance and heading, both ways) and the
network form of CtcQEval in Python: the contractor laws (sillage.testing) with an exact turning
vehicle, exact one-slice values, the network forms and errors."""
import math

import pytest
import sillage
from sillage import (ContractorNetwork, CtcDeriv, CtcHeading, CtcQEval, Interval, IntervalVector, TDomain, Tube,
                     TubeObservation, TubeVector)

from sillage import testing as kit
from turning_vehicle import turning
from test_contractor_laws import qeval_case

TRACK = 0.05


def heading_case(rng):
    """The turning vehicle of turning_vehicle.py inside its domains."""
    v = turning(rng, TRACK)
    s, b, psi, px, py = v.s, v.b, v.psi, v.px, v.py
    td = kit.random_tdomain(rng, 15)
    n = td.nb_slices()
    dist = [kit.around(Interval(s) * td.slice_width(k), rng, 0.05) for k in range(n)]
    p = TubeVector([kit.tube_around(td, px, rng, 2.0, 0.3), kit.tube_around(td, py, rng, 2.0, 0.3)])
    p.set_gate(0, IntervalVector([kit.around(px(Interval(0)), rng, 0.05), kit.around(py(Interval(0)), rng, 0.05)]))
    doms = [p, kit.tube_around(td, psi, rng, 1.5, 0.3), Tube(td, dist, [Interval()] * (n + 1)),
            Tube(td, kit.around(Interval(b), rng, 0.2))]
    return kit.Case(doms, [[px, py], psi, None, None])


def test_ctc_heading_laws():
    kit.check_laws(lambda d: CtcHeading(TRACK).contract(d[0], d[1], d[2], d[3]), heading_case, cases=10,
                   idempotence="contraction", outputs=[0, 1])


def test_ctc_heading_in_a_network_laws():
    def contract(d):
        cn = ContractorNetwork()
        cn.add(CtcHeading(TRACK), [d[0], d[1], d[2], d[3]])
        cn.add(CtcDeriv(), [d[1], d[3]])
        cn.contract()

    kit.check_laws(contract, heading_case, cases=6, idempotence="contraction", outputs=[0, 1], empty_any=True,
                   threads=False)


def one_slice():
    return TDomain([0.0, 1.0])


def test_ctc_heading_one_slice_both_ways():
    td = one_slice()
    p = TubeVector(td, 2)
    p.set_gate(0, IntervalVector([Interval(0), Interval(0)]))
    psi = Tube(td, Interval(0))
    assert CtcHeading().contract(p, psi, Tube(td, Interval(2)), Tube(td, Interval(0)))
    assert p[0].gate(1).contains(2.0) and p[0].gate(1).diam() < 1e-12
    # backward: the displacement in [0.9, 1.1]^2, turn rate within 0.1 rad/s over 1 s
    p.set_gate(1, IntervalVector([Interval(0.9, 1.1), Interval(0.9, 1.1)]))
    psi = Tube(td, Interval(-1, 2))
    assert CtcHeading().contract(p, psi, Tube(td, Interval(0, 10)), Tube(td, Interval(-0.1, 0.1)))
    lo, hi = math.atan2(0.9, 1.1) - 0.1, math.atan2(1.1, 0.9) + 0.1
    for h in (psi.slice(0), psi.gate(0), psi.gate(1)):
        assert h.contains(lo) and h.contains(hi) and h.diam() < hi - lo + 1e-9


def test_ctc_heading_inconsistent_and_errors():
    td = one_slice()
    p = TubeVector(td, 2)
    p.set_gate(0, IntervalVector([Interval(0), Interval(0)]))
    p.set_gate(1, IntervalVector([Interval(-2, -1.5), Interval(-0.5, 0.5)]))
    psi = Tube(td, Interval(0, 0.1))
    cn = ContractorNetwork()
    cn.add(CtcHeading(), [p, psi, Tube(td, Interval(1)), Tube(td, Interval(0))])
    stats = cn.contract()
    assert stats.empty and "CtcHeading" in stats.emptiness
    with pytest.raises(sillage.Error):
        CtcHeading(-1)
    with pytest.raises(sillage.DimensionError):
        CtcHeading().contract(TubeVector(td, 3), Tube(td), Tube(td), Tube(td))
    assert repr(CtcHeading(0.05)) == "CtcHeading(track=0.05)"


def test_ctc_qeval_network_form_laws():
    def contract(d):
        obs = [TubeObservation(d[i], d[i + 1], None) for i in range(2, len(d), 2)]
        cn = ContractorNetwork()
        cn.add(CtcQEval(1, obs), [d[0], d[1]])
        cn.contract()

    kit.check_laws(contract, qeval_case, cases=6, idempotence="contraction", outputs=[0], skip_empty=range(2, 10),
                   empty_any=True, threads=False)


def test_ctc_qeval_network_form_is_the_direct_call():
    rng = __import__("random").Random(3)
    case = qeval_case(rng)
    x, v = TubeVector(case.domains[0]), TubeVector(case.domains[1])
    obs = [TubeObservation(case.domains[i], case.domains[i + 1], None) for i in range(2, len(case.domains), 2)]
    direct = TubeVector(x)
    CtcQEval(1).contract(direct, v, obs)
    cn = ContractorNetwork()
    ctc = CtcQEval(1, obs)
    cn.add(ctc, [x, v])
    cn.add(CtcDeriv(), [x, v])  # the node's CtcEval carries its fronts only while they shrink gates
    assert not cn.contract().empty
    assert x.is_subset(direct)
    assert len(ctc.observations()) == 4 and "4 observations" in repr(ctc)
    with pytest.raises(sillage.Error):
        ContractorNetwork().add(CtcQEval(1), [x, v])  # no observations held
