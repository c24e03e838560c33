"""CtcSecondDeriv (x'' in [a]: each slice within the chord of its gates, bowed by at most
|[a]| delta^2 / 8) in Python: the contractor laws (sillage.testing) on sums of sines, the exact
bow of a parabola, the network form and errors."""
import pytest
import sillage
from sillage import ContractorNetwork, CtcSecondDeriv, Interval, TDomain, Tube

from sillage import testing as kit


def second_case(rng):
    """x a sum of sines (slices wide, gates near the truth), a around x'' = -sum a w^2 sin(w t + p)."""
    f = kit.SineSum(rng)

    def accel(t):
        r = Interval(0)
        for a, w, p in zip(f.a, f.w, f.p):
            r = r - Interval(a) * Interval(w) * Interval(w) * sillage.sin(Interval(w) * t + Interval(p))
        return r

    td = kit.random_tdomain(rng, 15)
    n = td.nb_slices()
    x = kit.tube_around(td, f.x, rng, 1.0)
    for k in range(n + 1):
        x.set_gate(k, kit.around(f.x(Interval(td.t(k))), rng, 0.05))
    a = Tube(td, [kit.around(accel(td.slice_domain(k)), rng, 0.5, 0.1) for k in range(n)], [Interval()] * (n + 1))
    return kit.Case([x, a], [f.x, None])


def test_ctc_second_deriv_laws():
    kit.check_laws(lambda d: CtcSecondDeriv().contract(d[0], d[1]), second_case, cases=10, outputs=[0])


def test_ctc_second_deriv_parabola_and_network():
    # x = t^2 / 2 on [0, 1]: gates 0 and 1/2, x'' = 1, the slice is [0, 1/2] - [0, 1/8]
    td = TDomain([0.0, 1.0])
    x = Tube(td)
    x.set_gate(0, Interval(0))
    x.set_gate(1, Interval(0.5))
    assert CtcSecondDeriv().contract(x, Tube(td, Interval(1)))
    assert x.slice(0) == Interval(-0.125, 0.5)
    y = Tube(td)
    y.set_gate(0, Interval(0))
    y.set_gate(1, Interval(0.5))
    cn = ContractorNetwork()
    cn.add(CtcSecondDeriv(), [y, Tube(td, Interval(1))])
    assert not cn.contract().empty and y.slice(0) == x.slice(0)
    assert repr(CtcSecondDeriv()) == "CtcSecondDeriv()"


def test_ctc_second_deriv_empty_and_errors():
    td = TDomain([0.0, 1.0])
    x = Tube(td, Interval(1, 2))
    assert not CtcSecondDeriv().contract(x, Tube(td, Interval.empty()))
    assert x.is_empty()
    with pytest.raises(sillage.DimensionError):
        CtcSecondDeriv().contract(Tube(td), Tube(TDomain(0.0, 1.0, 0.5)))
