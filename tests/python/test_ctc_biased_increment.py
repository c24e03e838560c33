"""CtcBiasedIncrement (increments with one unknown constant bias b0 and an in-run drift d) in
Python: the contractor laws (sillage.testing) on sums of sines measured with a bias, exact
values, a brute force over every pair of gates, the network form and errors."""
import pytest
from sillage import ContractorNetwork, CtcBiasedIncrement, Interval, TDomain, Tube

from sillage import testing as kit


def measured(rng, f, td, b, drift, noise):
    """The increments x(t_{k+1}) - x(t_k) + (b - d_k) delta_k, |d_k| <= drift, enclosed and widened."""
    n = td.nb_slices()
    inc = []
    for k in range(n):
        dx = f.x(Interval(td.t(k + 1))) - f.x(Interval(td.t(k)))
        inc.append(kit.around(dx + (Interval(b) - Interval(rng.uniform(-drift, drift))) * td.slice_width(k), rng, noise))
    return Tube(td, inc, [Interval()] * (n + 1))


def biased_case(rng):
    f, td, b = kit.SineSum(rng), kit.random_tdomain(rng, 12), rng.uniform(-1, 1)
    x = kit.tube_around(td, f.x, rng, 1.0, 0.2)
    return kit.Case([x, kit.around(Interval(b), rng, 2.0, 0.2), measured(rng, f, td, b, 0.1, 0.02)], [f.x, Interval(b), None])


def test_ctc_biased_increment_laws():
    kit.check_laws(lambda d: CtcBiasedIncrement(0.1).contract(d[0], d[1], d[2]), biased_case, cases=10, outputs=[0, 1])


def test_exact_bias_and_gates():
    # increments of 1 per unit time, x(0) = 0, x(10) = 5, no drift: b0 = 0.5 and x(t_k) = 0.5 k
    td = TDomain(0.0, 10.0, 1.0)
    x, b = Tube(td), Interval(-1, 1)
    x.set_gate(0, Interval(0))
    x.set_gate(10, Interval(5))
    assert CtcBiasedIncrement().contract(x, b, Tube(td, Interval(1)))
    assert b == Interval(0.5)
    assert all(abs(x.gate(k).mid() - 0.5 * k) < 1e-13 and x.gate(k).diam() < 1e-13 for k in range(11))


def test_against_brute_force_over_every_pair():
    """b0 in (S_ij - ([x]_j - [x]_i)) / (t_j - t_i) over every pair, then the gates from b0, to the fixed point."""
    import random
    rng = random.Random(5)
    for _ in range(10):
        f, td, b, drift = kit.SineSum(rng), kit.random_tdomain(rng, 8), rng.uniform(-1, 1), rng.uniform(0, 0.1)
        inc = measured(rng, f, td, b, drift, 0.01)
        x = kit.tube_around(td, f.x, rng, 0.5, 0.3)
        g, bb = [x.gate(k) for k in range(9)], Interval(-5, 5)
        s = [inc.slice(k) + Interval(-drift, drift) * td.slice_width(k) for k in range(8)]

        def span(i, j):
            r = Interval(0)
            for k in range(i, j):
                r = r + s[k]
            return r

        for _ in range(10):
            for i in range(9):
                for j in range(i + 1, 9):
                    bb = bb & ((span(i, j) - (g[j] - g[i])) / (Interval(td.t(j)) - Interval(td.t(i))))
            for i in range(9):
                for j in range(9):
                    if i < j:
                        g[j] = g[j] & (g[i] + span(i, j) - bb * (Interval(td.t(j)) - Interval(td.t(i))))
                    if j < i:
                        g[j] = g[j] & (g[i] - span(j, i) + bb * (Interval(td.t(i)) - Interval(td.t(j))))
        c = Interval(-5, 5)
        assert CtcBiasedIncrement(drift).contract(x, c, inc)
        assert c.contains(b) and abs(c.lb() - bb.lb()) < 1e-9 and abs(c.ub() - bb.ub()) < 1e-9
        for k in range(9):
            assert abs(x.gate(k).lb() - g[k].lb()) < 1e-9 and abs(x.gate(k).ub() - g[k].ub()) < 1e-9


def test_network_learns_the_bias_and_reports_emptiness():
    td = TDomain(0.0, 100.0, 1.0)
    x, b = Tube(td), Interval(-1, 1)
    x.set_gate(0, Interval(-0.1, 0.1))
    x.set_gate(100, Interval(69.9, 70.1))
    cn = ContractorNetwork()
    cn.add(CtcBiasedIncrement(0.01), [x, b, Tube(td, Interval(1))])
    assert not cn.contract().empty
    assert b.contains(0.3) and b.diam() < 0.025
    assert x.gate(50).contains(35) and x.gate(50).diam() < 2.5
    y, c = Tube(td), Interval(-1, 1)
    y.set_gate(0, Interval(0))
    y.set_gate(100, Interval(500))  # a bias of -4 would be needed
    cn = ContractorNetwork()
    cn.add(CtcBiasedIncrement(), [y, c, Tube(td, Interval(1))])
    cn.set_name(c, "b0")
    stats = cn.contract()
    assert stats.empty and "CtcBiasedIncrement" in stats.emptiness and "b0" in stats.emptiness
    assert repr(CtcBiasedIncrement(0.5)) == "CtcBiasedIncrement(drift=0.5)"
    with pytest.raises(Exception):
        CtcBiasedIncrement(-1.0)


def test_true_increments_narrowed_by_the_bias():
    # the bias from the two ends, [0.4, 0.6], narrows j (the true increments) to 1 - [0.4, 0.6] +- 0.1
    td = TDomain(0.0, 10.0, 1.0)
    x, b, j = Tube(td), Interval(-1, 1), Tube(td, Interval(0, 2))
    x.set_gate(0, Interval(0))
    x.set_gate(10, Interval(5))
    assert CtcBiasedIncrement(0.1).contract(x, b, Tube(td, Interval(1)), j)
    assert all(abs(j.slice(k).lb() - 0.3) < 1e-13 and abs(j.slice(k).ub() - 0.7) < 1e-13 for k in range(10))
