"""Borda's double weighing (thesis 7.1.3, (7.5)): the Python twin of tests/cpp/slam/test_borda.cpp.

p is the mass in the right pan of a balance with arms of unknown lengths (h = identity, a scalar
configuration); slices of 1/64 s:
  [0, 1]  the unknown object, m = 6.3 kg (stated [0.5, 9.5] kg), |w| <= 1 g/s;
  [1, 2]  lifted off: w in [-10, 0] kg/s, the pan seen empty at t = 2;
  [2, 3]  a calibrated flow pours the reference: w in 10 kg/s +- 0.5 %.
z is the pointer angle g(p) +- 5 mrad with g unknown to the solver. CtcPImpliesZ with the
scalar existence test (scalar_loops) gives m from the reference, whatever g.
"""
import random

import pytest

import sillage
from sillage import CtcDeriv, CtcPImpliesZ, Interval, IntervalVector, TDomain, TubeVector

from sillage import testing as kit

MASS = 6.3
EPS = 1.0 / 64


def true_mass(t, m=MASS):
    """The true mass over the time interval t: the hull of the phases' linear pieces over t."""
    phases = [(Interval(0.0, 1.0), lambda u: Interval(m) + 0.0 * u),
              (Interval(1.0, 2.0), lambda u: Interval(m) * (Interval(2.0) - u)),
              (Interval(2.0, 3.0), lambda u: Interval(10.0) * (u - Interval(2.0)))]
    out = Interval.empty()
    for span, f in phases:
        u = t & span
        if not u.is_empty():
            out = out | f(u)
    return out


def arms(x):
    return Interval(0.5) * sillage.atan((x - Interval(5.0)) / Interval(3.0))


def borda(g=arms, bias=0.0, m=MASS):
    """(td, p, w, z): dead reckoning done."""
    td = TDomain(0.0, 3.0, EPS)
    n = td.nb_slices()
    p, w, z = TubeVector(td, 1), TubeVector(td, 1), TubeVector(td, 1)
    noise = Interval(-5e-3, 5e-3)
    for k in range(n):
        t = Interval(td.t(k), td.t(k + 1))
        wk = (Interval(-1e-3, 1e-3) if t.ub() <= 1.0 else Interval(-10.0, 0.0) if t.ub() <= 2.0
              else Interval(10.0) * Interval(0.995, 1.005))
        w[0].set(wk, k)
        z[0].set(g(true_mass(t, m)) + Interval(bias) + noise, k)
    for k in range(n + 1):
        w[0].set_gate(k, w[0].slice(0) if k == 0 else w[0].slice(n - 1) if k == n
                      else w[0].slice(k - 1) | w[0].slice(k))
        z[0].set_gate(k, g(true_mass(Interval(td.t(k)), m)) + Interval(bias) + noise)
    p[0].set_gate(0, Interval(0.5, 9.5))
    p[0].set_gate(2 * 64, Interval(0.0))
    CtcDeriv().contract(p, w)
    return td, p, w, z


def holds_truth(td, p, m=MASS):
    n = td.nb_slices()
    return (all(true_mass(Interval(td.t(k), td.t(k + 1)), m).is_subset(p[0].slice(k)) for k in range(n)) and
            all(p[0].gate(k).contains(true_mass(Interval(td.t(k)), m).mid()) for k in range(n + 1)))


def test_the_implication_weighs_the_object():
    td, p, w, z = borda()
    assert p[0].gate(0).diam() > 8.9  # dead reckoning knows nothing of the mass
    dr = TubeVector(p)
    rows = CtcPImpliesZ(EPS).contract(p, w, z)
    assert rows[0].nb_proofs > 0
    assert p.is_subset(dr) and holds_truth(td, p)
    m = p[0].gate(0)
    assert m.contains(MASS) and m.diam() < 0.8
    assert rows[-1].contraction_t0 > 0.9


def test_any_balance_any_bias():
    other = lambda x: Interval(2.0) * sillage.atan(x - Interval(4.0))  # noqa: E731
    td, p, w, z = borda(other)
    _, q, wq, zq = borda(other, bias=0.75)
    CtcPImpliesZ(EPS).contract(p, w, z)
    CtcPImpliesZ(EPS).contract(q, wq, zq)
    assert holds_truth(td, p) and p[0].gate(0).diam() < 0.8
    assert all(p[0].gate(k) == q[0].gate(k) for k in range(td.nb_slices() + 1))  # bit for bit


def test_in_a_network_as_contract():
    td, p, w, z = borda()
    _, q, wq, zq = borda()
    CtcPImpliesZ(EPS).contract(p, w, z)
    cn = sillage.ContractorNetwork()
    cn.add(CtcPImpliesZ(EPS), [q, wq, zq])  # a scalar p: 1 + 1 + 1 tubes
    assert not cn.contract().empty
    assert holds_truth(td, q) and q[0].gate(0).diam() < 0.8
    assert all(q[0].gate(k) == p[0].gate(k) for k in range(td.nb_slices() + 1))


def test_in_a_network_bad_dimensions():
    td, p, w, z = borda()
    cn = sillage.ContractorNetwork()
    with pytest.raises(sillage.DimensionError):
        cn.add(CtcPImpliesZ(EPS), [p, TubeVector([w[0], w[0]]), z])


def test_iterate_one_step_at_a_time():
    """CtcPImpliesZ.iterate: one iteration, its row filled in place; to the fixed point as contract."""
    td, p, w, z = borda()
    _, q, wq, zq = borda()
    ctc = CtcPImpliesZ(EPS)
    rows = ctc.contract(p, w, z)
    row = sillage.SlamRow()
    assert ctc.iterate(q, wq, zq, row)  # the first iteration contracts
    assert row.nb_proofs == rows[0].nb_proofs and row.nb_detections == rows[0].nb_detections
    assert row.nb_atoms_touched > 0 and not row.fast
    assert holds_truth(td, q)
    steps = 1
    while ctc.iterate(q, wq, zq, sillage.SlamRow()):
        steps += 1
    assert steps == len(rows) - 1  # contract stops at the first iteration that shrinks nothing
    assert all(q[0].gate(k) == p[0].gate(k) for k in range(td.nb_slices() + 1))


def test_a_pointer_that_never_comes_back_empties_p():
    td, p, w, z = borda()
    for k in range(2 * 64, td.nb_slices()):
        z[0].set(Interval(5.0, 6.0), k)
    for k in range(2 * 64 + 1, td.nb_slices() + 1):
        z[0].set_gate(k, Interval(5.0, 6.0))
    CtcPImpliesZ(EPS).contract(p, w, z)
    assert p.is_empty()


def test_scalar_loop_exists():
    _, p, w, _ = borda()
    column = [IntervalVector([Interval(0.5, 0.6), Interval(2.0, 2.5)]),
              IntervalVector([Interval(0.5, 0.6), Interval(2.5, 3.0)])]
    assert sillage.scalar_loop_exists(column, p, w)
    assert not sillage.scalar_loop_exists([IntervalVector([Interval(0.5, 0.6), Interval(2.0, 2.04)])], p, w)
    assert not sillage.scalar_loop_exists([IntervalVector([Interval(0.5, 2.5), Interval(2.0, 3.0)])], p, w)
    with pytest.raises(sillage.Error, match="leaves the TDomain"):
        sillage.scalar_loop_exists([IntervalVector([Interval(0, 1), Interval(2, 4)])], p, w)


def test_scalar_loops_pieces():
    _, p, w, _ = borda()
    loops = sillage.scalar_loops(EPS, p, w)
    proven = [l for l in loops if l.proven and l.hull[0].ub() <= 1.0]
    assert len(proven) >= 60
    assert all(l.hull[1].contains(2.0 + MASS / 10) for l in proven)
    assert repr(loops[0]).startswith("ScalarLoop(boxes=")
    with pytest.raises(sillage.DimensionError):
        sillage.scalar_loops(0.1, TubeVector(p.tdomain(), 2), w)


def test_temporal_slam_with_a_scalar_h():
    _, p, w, z = borda()
    x, v = TubeVector(p), TubeVector(w)
    o = sillage.TemporalSlamOptions()
    o.eps = EPS
    rows = sillage.temporal_slam(x, v, w, z, sillage.Function(["x", "u"], "u"), sillage.Function(["x"], "x"), o)
    assert rows and x[0].gate(0).contains(MASS) and x[0].gate(0).diam() < 0.8


def test_contraction_and_truth_on_random_masses():
    """The kit's laws (a) contraction and (b) truth kept, on a few random objects."""
    rng = random.Random(13)
    for _ in range(2):
        m = rng.uniform(1.0, 9.0)
        td, p, w, z = borda(m=m)
        before = [p.copy(), w.copy(), z.copy()]
        after = kit.copy_domains(before)
        CtcPImpliesZ(EPS).contract(*after)
        kit.check_contracted(after, before)
        kit.check_truth(after, [[lambda t, m=m: true_mass(t, m)], None, None])
        assert after[0][0].gate(0).contains(m) and after[0][0].gate(0).diam() < 1.0
