"""ContractorNetwork from Python: the thesis' Table 2.1 example on the user's
own Interval / IntervalVector objects, parts of boxes, statistics, errors."""
import math

import pytest
import sillage
from sillage import Interval, IntervalVector, Function

BEACONS = [((-0.5, 4.0), (3.63, 4.43)), ((-2.5, -2.5), (3.13, 3.93)), ((2.5, -0.5), (2.15, 2.95))]


def range_ctc(bx, by):
    f = Function(["x1", "x2", "rho"], f"sqrt((x1 - {bx})^2 + (x2 - {by})^2) - rho")
    return sillage.CtcFunction(f)


def test_table_2_1_in_place():
    cn = sillage.ContractorNetwork()
    x = IntervalVector(2)  # [-inf, inf]^2, the user's own object
    rhos = [Interval(*r) for _, r in BEACONS]
    for (b, _), rho in zip(BEACONS, rhos):
        cn.add(range_ctc(*b), [x, rho])
    assert cn.nb_ctc() == 3 and cn.nb_dom() == 4
    s = cn.contract()
    assert not s.empty
    assert s.iterations >= 2 and s.contractor_calls >= 3 and s.time >= 0
    assert x[0].contains(0) and x[1].contains(0)
    assert -1 < x[0].lb() and x[0].ub() < 1 and -1 < x[1].lb() and x[1].ub() < 1
    for (b, _), rho in zip(BEACONS, rhos):
        assert rho.contains(math.hypot(*b))
    print("Table 2.1:", s, x)


def test_create_dom_and_components():
    cn = sillage.ContractorNetwork()
    x = cn.create_dom(IntervalVector([Interval(0, 10), Interval(-5, 5), Interval(0, 10)]))
    r = cn.create_dom(Interval(2, 3))
    cn.add(sillage.CtcFunction(Function(["a", "b"], "a - b")), [sillage.DomainRef.component(x, 2), r])
    cn.add(sillage.CtcFunction(Function(["a", "b"], "a + b"), Interval(0, 1)), [sillage.DomainRef.subvector(x, 1, 2)])
    assert cn.nb_dom() == 2
    s = cn.contract()
    assert not s.empty
    assert (x[2].lb(), x[2].ub()) == (2, 3)
    assert (x[1].lb(), x[1].ub()) == (-3, -1)
    assert (x[0].lb(), x[0].ub()) == (0, 10)


def test_python_contractor_in_network():
    class Shift(sillage.Ctc):
        """b = a + 1 written in Python."""

        def __init__(self):
            super().__init__(2)

        def contract(self, x):
            x[1] = x[1] & (x[0] + Interval(1))
            x[0] = x[0] & (x[1] - Interval(1))

    cn = sillage.ContractorNetwork()
    xs = [Interval(0, 0)] + [Interval() for _ in range(4)]
    for i in range(4):
        cn.add(Shift(), [xs[i], xs[i + 1]])
    s = cn.contract()
    assert [(v.lb(), v.ub()) for v in xs] == [(i, i) for i in range(5)]
    assert s.iterations == 1 and s.contractor_calls == 4


def test_empty_and_errors():
    cn = sillage.ContractorNetwork()
    a, b = Interval(0, 1), Interval(2, 3)
    cn.add(sillage.CtcFunction(Function(["a", "b"], "a - b")), [a, b])
    s = cn.contract()
    assert s.empty and s.empty_domain and a.is_empty()
    with pytest.raises(sillage.Error, match="CtcFunction"):
        cn.add(sillage.CtcFunction(Function(["a", "b"], "a - b")), [a])
    with pytest.raises(sillage.Error):
        cn.add(sillage.CtcAdd(), [a, b, "c"])
    with pytest.raises(sillage.Error):
        cn.set_ratio(2)
    with pytest.raises(sillage.Error):
        sillage.DomainRef.component(IntervalVector(2), 5)
    assert cn.nb_ctc() == 1
