"""The two worked examples of thesis chapter 5 (examples/python/lowcost_beacons.py
and drifting_clock.py) on coarse slicings: the truth stays inside, the result
is a fixed point, and the key values of the examples are reproduced."""
import math
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples" / "python"))
lb = pytest.importorskip("lowcost_beacons")
dc = pytest.importorskip("drifting_clock")
from sillage import (ContractorNetwork, CtcDeriv, CtcEval, CtcFunction, DomainRef, Function,  # noqa: E402
                     Interval, TDomain, Trajectory, Tube, TubeVector)


def snapshot(p, keys):
    """Copies of the domains of a solved network (tubes, and lists of intervals)."""
    out = {}
    for k in keys:
        d = p[k]
        out[k] = [Interval(i.lb(), i.ub()) for i in d] if isinstance(d, list) and isinstance(d[0], Interval) \
            else ([t.copy() for t in d] if isinstance(d, list) else d.copy())
    return out


@pytest.fixture(scope="module")
def beacons_coarse():
    dt = 0.2
    td = lb.domain(dt)
    p = lb.build(td)
    s = p["cn"].contract()
    return dt, td, p, s


def test_beacons_truth_inside(beacons_coarse):
    dt, td, p, s = beacons_coarse
    assert not s.empty
    h = dt / 10
    path = lb.truth(h, round(lb.TF / h))
    assert lb.excess(p["x"], path, h) == 0.0
    moved = path.copy()
    moved[:, 0] += 40.0  # the check itself sees a path outside
    assert lb.excess(p["x"], moved, h) > 1.0
    for i, (k, t, z) in enumerate(lb.MEASUREMENTS):
        tt = lb.truth_times(path, h, k, t, z)
        assert tt is not None and p["t"][i].contains(tt[0]) and p["t"][i].contains(tt[1])


def test_beacons_key_values(beacons_coarse):
    _, td, p, s = beacons_coarse
    x0 = p["x"].gate(0)
    # x(0), unknown a priori, is bounded around the true (0, 0) (values of the example at dt = 0.2)
    assert abs(x0[0].lb() + 11.579) < 1e-3 and abs(x0[0].ub() - 15.890) < 1e-3
    assert abs(x0[1].lb() + 19.911) < 1e-3 and abs(x0[1].ub() - 23.471) < 1e-3
    # the [t_i] bounds are gates (exact decimals enclosed outward, then sampled)
    for t in p["t"]:
        assert td.is_time_point(t.lb()) and td.is_time_point(t.ub())
    # heading and speed stay those of the dead reckoning
    assert p["x"][2].gate(0).is_subset(Interval(math.pi / 2 - 0.0101, math.pi / 2 + 0.0101))


def test_beacons_is_a_fixed_point(beacons_coarse):
    _, _, p, _ = beacons_coarse
    before = snapshot(p, ["x", "y", "t", "z"])
    s = p["cn"].contract()  # one round of every contractor: nothing may change
    assert not s.empty and s.iterations == 1
    for k in ("x",):
        assert p[k] == before[k]
    for a, b in zip(p["y"], before["y"]):
        assert a == b
    for a, b in zip(p["t"] + p["z"], before["t"] + before["z"]):
        assert a == b


def test_beacons_same_fixed_point_with_separate_contractors(beacons_coarse):
    """One contractor per equation instead of one per beacon: the same fixed point."""
    _, td, p, _ = beacons_coarse
    split = lb.build(td, 0.0, split=True)
    assert not split["cn"].contract().empty
    assert split["x"] == p["x"]


@pytest.fixture(scope="module")
def clock_fine():
    td = TDomain(0.0, dc.TF, 0.01)
    p = dc.build(td)
    s = p["cn"].contract()
    return td, p, s


def test_clock_truth_inside(clock_fine):
    td, p, s = clock_fine
    assert not s.empty
    dom = td.t0_tf()
    assert p["h"].contains(Trajectory(dc.H_TRUE, dom))
    assert p["x"].contains([Trajectory("90 + 100*cos(t)", dom), Trajectory("20 + 100*sin(t)", dom)])
    for i, tau in enumerate(dc.TAU):
        assert p["t"][i].contains(dc.true_time(tau))


def test_clock_contracts_the_times(clock_fine):
    td, p, _ = clock_fine
    h0, phi0 = dc.a_priori(td)
    w0 = w1 = 0.0
    for i, tau in enumerate(dc.TAU):
        a = h0.inverse(dc.cents(tau, tau), phi0)
        assert p["t"][i].is_subset(a)
        w0 += a.diam()
        w1 += p["t"][i].diam()
    assert w1 < 0.35 * w0  # 0.959 -> 0.286 on average
    # key values of the example (dt = 0.01)
    t8 = p["t"][7]
    assert abs(t8.lb() - 11.8781) < 1e-3 and abs(t8.ub() - 12.2595) < 1e-3  # CtcEval exact inside slices
    assert p["h"].max_thickness() < 1.5 < h0.max_thickness()


def test_clock_coarse_still_holds_the_truth():
    td = TDomain(0.0, dc.TF, 0.1)
    p = dc.build(td)
    assert not p["cn"].contract().empty
    assert p["h"].contains(Trajectory(dc.H_TRUE, td.t0_tf()))
    assert all(p["t"][i].contains(dc.true_time(tau)) for i, tau in enumerate(dc.TAU))
