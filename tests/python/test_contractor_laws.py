"""The generic contractor laws (sillage.testing) on the Python API: CtcFunction,
CtcQInter, CtcDeriv, CtcEval, CtcIncrement, CtcQEval and a ContractorNetwork
of tubes. The exact thesis values stay in each contractor's own tests."""
import math

import pytest
import sillage
from sillage import (CtcDeriv, CtcEval, CtcFunction, CtcIncrement, CtcQEval, CtcQInter, ContractorNetwork,
                     Function, Interval, IntervalVector, TimePropag, Tube, TubeObservation, TubeVector)

from sillage import testing as kit

F = Function(["x", "y", "z"], "x*y + sin(z) - exp(x/4)")


def function_case(rng):
    p = [rng.uniform(-3, 3) for _ in range(3)]
    x, y, z = (Interval(v) for v in p)
    fy = x * y + sillage.sin(z) - sillage.exp(x / Interval(4))
    box = IntervalVector([kit.around(Interval(v), rng, 2.0, 0.1) for v in p])
    return kit.Case([box, kit.around(fy, rng, 0.3)], [IntervalVector([x, y, z]), fy])


def test_ctc_function():
    def contract(d):
        CtcFunction(F, d[1]).contract(d[0])

    kit.check_laws(contract, function_case, cases=15, idempotence="contraction", outputs=[0])


def ranges_case(rng):
    p = [rng.uniform(-3, 3) for _ in range(2)]
    doms, truth = [IntervalVector([kit.around(Interval(v), rng, 2.0, 0.1) for v in p])], [IntervalVector(
        [Interval(v) for v in p])]
    outlier = rng.randrange(5)
    for i in range(5):
        b = [round(rng.uniform(-10, 10) * 8) / 8 for _ in range(2)]  # exact in decimal
        r = sillage.sqrt(sillage.sqr(Interval(p[0]) - Interval(b[0])) + sillage.sqr(Interval(p[1]) - Interval(b[1])))
        meas = Interval(r.ub() + 1, r.ub() + 4) if i == outlier else kit.around(r, rng, 0.2)
        doms.append(IntervalVector([Interval(b[0]), Interval(b[1]), meas]))
        truth.append(None)
    return kit.Case(doms, truth)


def test_ctc_qinter_with_an_outlier():
    def contract(d):
        ctcs = [CtcFunction(Function(["x", "y"], f"sqrt((x - {b[0].lb()!r})^2 + (y - {b[1].lb()!r})^2)"), b[2])
                for b in d[1:]]
        CtcQInter(ctcs, 1).contract(d[0])

    kit.check_laws(contract, ranges_case, cases=10, idempotence="contraction", outputs=[0],
                   skip_empty=range(1, 6), skip_unbounded=range(1, 6))


def deriv_case(rng):
    f = kit.SineSum(rng)
    td = kit.random_tdomain(rng, 15)
    return kit.Case([kit.tube_around(td, f.x, rng, 0.3, 0.5), kit.tube_around(td, f.v, rng, 0.5)], [f.x, f.v])


@pytest.mark.parametrize("propag, idem", [(TimePropag.FWD_BWD, "exact"), (TimePropag.FORWARD, "contraction"),
                                          (TimePropag.BACKWARD, "contraction")])
def test_ctc_deriv(propag, idem):
    kit.check_laws(lambda d: CtcDeriv(propag).contract(d[0], d[1]), deriv_case, cases=10, idempotence=idem,
                   outputs=[0])


def test_ctc_deriv_vector():
    def gen(rng):
        f, g = kit.SineSum(rng), kit.SineSum(rng)
        td = kit.random_tdomain(rng, 10)
        x = TubeVector([kit.tube_around(td, f.x, rng, 0.3, 0.5), kit.tube_around(td, g.x, rng, 0.3, 0.5)])
        v = TubeVector([kit.tube_around(td, f.v, rng, 0.5), kit.tube_around(td, g.v, rng, 0.5)])
        return kit.Case([x, v], [[f.x, g.x], [f.v, g.v]])

    kit.check_laws(lambda d: CtcDeriv().contract(d[0], d[1]), gen, cases=6, outputs=[0])


def eval_case(rng):
    f = kit.SineSum(rng)
    td = kit.random_tdomain(rng, 15)
    t0, tf = td.t(0), td.t(td.nb_slices())
    ts = t0 + rng.random() * (tf - t0)
    t = Interval(ts) if rng.random() < 0.25 else kit.around(Interval(ts), rng, 2.0)
    z = f.x(Interval(ts))
    return kit.Case([t, kit.around(z, rng, 0.3), kit.tube_around(td, f.x, rng, 0.5, 0.4),
                     kit.tube_around(td, f.v, rng, 0.5)], [Interval(ts), z, f.x, f.v])


@pytest.mark.parametrize("sampling", [False, True])
def test_ctc_eval(sampling):
    def contract(d):
        e = CtcEval()
        e.enable_time_sampling(sampling)
        e.contract(d[0], d[1], d[2], d[3])

    # CtcEval is not idempotent: [t] is contracted with [y] before the sweeps.
    kit.check_laws(contract, eval_case, cases=10, idempotence="contraction", outputs=[0, 1, 2])


def test_ctc_increment():
    def gen(rng):
        f = kit.SineSum(rng)
        td = kit.random_tdomain(rng, 15)
        n = td.nb_slices()
        inc = [kit.around(f.x(Interval(td.t(k + 1))) - f.x(Interval(td.t(k))), rng, 0.1) for k in range(n)]
        return kit.Case([kit.tube_around(td, f.x, rng, 0.5, 0.7), Tube(td, inc, [Interval()] * (n + 1))],
                        [f.x, None])

    kit.check_laws(lambda d: CtcIncrement().contract(d[0], d[1]), gen, cases=10, outputs=[0])


def qeval_case(rng):
    f, g = kit.SineSum(rng), kit.SineSum(rng)
    td = kit.random_tdomain(rng, 10)
    t0, tf = td.t(0), td.t(td.nb_slices())
    doms = [TubeVector([kit.tube_around(td, f.x, rng, 1.0, 0.3), kit.tube_around(td, g.x, rng, 1.0, 0.3)]),
            TubeVector([kit.tube_around(td, f.v, rng, 0.3), kit.tube_around(td, g.v, rng, 0.3)])]
    truth = [[f.x, g.x], [f.v, g.v]]
    wrong = rng.randrange(4)
    for i in range(4):
        ts = t0 + rng.random() * (tf - t0)
        doms.append(kit.around(Interval(ts), rng, 0.3) & Interval(t0, tf))
        if i == wrong:  # |x| <= 4.5: never true
            doms.append(IntervalVector([Interval(5, 6), Interval(-6, -5)]))
            truth += [None, None]
        else:
            z = IntervalVector([f.x(Interval(ts)), g.x(Interval(ts))])
            doms.append(IntervalVector([kit.around(z[0], rng, 0.2), kit.around(z[1], rng, 0.2)]))
            truth += [Interval(ts), z]
    return kit.Case(doms, truth)


def test_ctc_qeval_with_a_wrong_fix():
    def contract(d):
        obs = [TubeObservation(d[i], d[i + 1], None) for i in range(2, len(d), 2)]
        CtcQEval(1).contract(d[0], d[1], obs)

    # An empty fix is one wrong observation (q = 1 tolerates it).
    kit.check_laws(contract, qeval_case, cases=6, idempotence="contraction", outputs=[0], skip_empty=range(2, 10))


def network_case(rng):
    f = kit.SineSum(rng)
    td = kit.random_tdomain(rng, 12)
    t0, tf = td.t(0), td.t(td.nb_slices())
    y = lambda t: sillage.sqr(f.x(t))  # noqa: E731
    doms = [kit.tube_around(td, f.x, rng, 0.5, 0.6), kit.tube_around(td, f.v, rng, 0.3),
            kit.tube_around(td, y, rng, 1.0, 0.6)]
    truth = [f.x, f.v, y]
    for _ in range(2):
        ts = t0 + rng.random() * (tf - t0)
        doms += [kit.around(Interval(ts), rng, 0.5) & Interval(t0, tf), kit.around(f.x(Interval(ts)), rng, 0.1)]
        truth += [Interval(ts), f.x(Interval(ts))]
    return kit.Case(doms, truth)


def network(d, order, ratio=0.01):
    """x' = v, z_i = x(t_i), y = x^2 at every time; the domains are live."""
    x, v, y, t1, z1, t2, z2 = d
    cn = ContractorNetwork()
    cn.set_ratio(ratio)
    ev = CtcEval()
    for part in order:
        if part == 0:
            cn.add(CtcDeriv(), [x, v])
        elif part == 1:
            cn.add(ev, [t1, z1, x, v])
        elif part == 2:
            cn.add(ev, [t2, z2, x, v])
        else:
            cn.add(CtcFunction(Function(["x", "y"], "y - x^2")), [x, y])
    s = cn.contract()
    assert s.empty == any(dom.is_empty() for dom in d), "ContractStats.empty disagrees with the domains"


def test_network_of_tubes():
    kit.check_laws(lambda d: network(d, [0, 1, 2, 3]), network_case, cases=6, idempotence="contraction",
                   empty_any=True)


def test_network_of_tubes_two_orders():
    # The fixed point depends on the order (ratio, CtcEval not idempotent):
    # both orders keep the truth.
    kit.check_order_independent(network, network_case, [0, 1, 2, 3], [3, 2, 1, 0], False, cases=6)


def test_monotone_contractors():
    kit.check_monotone(lambda d: CtcDeriv().contract(d[0], d[1]), deriv_case, cases=8)
    kit.check_monotone(lambda d: CtcFunction(F, d[1]).contract(d[0]), function_case, cases=15)


def test_the_kit_names_the_broken_law():
    def grows(d):
        b = d[0]
        if not b.is_empty():
            for i in range(len(b)):
                b[i] = b[i] | Interval(100, 101)  # beyond every bounded input

    with pytest.raises(AssertionError, match=r"contraction: domain 0 component \d grew from"):
        kit.check_laws(grows, function_case, cases=2, outputs=[0])

    def loses(d):
        b = d[0]
        if not b.is_empty() and b[0].is_bounded():
            b[0] = Interval(b[0].ub())

    with pytest.raises(AssertionError, match=r"truth kept: domain 0 component 0"):
        kit.check_laws(loses, function_case, cases=2, outputs=[0])

    with pytest.raises(AssertionError, match=r"empty input \(domain 1 empty\): domain 0 is not empty"):
        kit.check_laws(lambda d: None, function_case, cases=2, outputs=[0])

    def nibbles(d):
        x = d[0]
        if x.is_empty():
            return
        g = x.gate(0)
        if g.is_bounded() and g.diam() > 0:
            x.set_gate(0, Interval(g.lb(), math.nextafter(g.ub(), -math.inf)))

    with pytest.raises(AssertionError, match=r"idempotence \(a second call changed the result\): domain 0 gate 0"):
        kit.check_laws(nibbles, deriv_case, cases=3, empty_inputs=False, unbounded_inputs=False)
