"""Outliers from Python: q_inter on intervals (hand cases and brute force),
CtcQInter (q = 0 is CtcInter, q >= m is the identity, sampled points kept),
gomne on a 20-beacon range-only localisation with injected outliers, errors;
CtcQEval and gomne_tube on fixes of a tube; the outliers_ranges example."""
import math
import random
import subprocess
import sys
from pathlib import Path

import pytest
import sillage
from sillage import Interval, IntervalVector, Function


def box(*bounds):
    return IntervalVector([Interval(a, b) for a, b in bounds])


def bounds(x):
    return [(x[i].lb(), x[i].ub()) for i in range(x.size())]


def test_q_inter_hand_cases():
    xs = [Interval(0, 4), Interval(1, 5), Interval(3, 8), Interval(6, 9)]
    assert sillage.q_inter(xs, 0).is_empty()
    assert sillage.q_inter(xs, 1) == Interval(3, 4)
    assert sillage.q_inter(xs, 2) == Interval(1, 8)
    assert sillage.q_inter(xs, 3) == Interval(0, 9)
    assert sillage.q_inter(xs, 4).is_all_reals()
    # no point in two of them, although the 2nd lower and 2nd upper bounds cross
    assert sillage.q_inter([Interval(0, 1), Interval(2, 3), Interval(4, 5)], 1).is_empty()
    assert sillage.q_inter([Interval(0, 2), Interval.empty(), Interval(1, 3)], 1) == Interval(1, 2)


def test_q_inter_brute_force():
    rng = random.Random(4)
    for _ in range(300):
        m = rng.randint(1, 6)
        xs = []
        for _ in range(m):
            a, b = sorted((rng.randint(0, 10), rng.randint(0, 10)))
            xs.append(Interval.empty() if rng.random() < 0.1 else Interval(a, b))
        for q in range(m):
            grid = [k / 2 for k in range(-2, 25) if sum(x.contains(k / 2) for x in xs) >= m - q]
            got = sillage.q_inter(xs, q)
            if grid:
                assert (got.lb(), got.ub()) == (min(grid), max(grid))
            else:
                assert got.is_empty()


def test_ctc_qinter_bounds_and_laws():
    ctcs = [sillage.CtcBox(box((0, 2), (0, 2))), sillage.CtcBox(box((1, 3), (1, 3))),
            sillage.CtcBox(box((5, 6), (5, 6)))]
    c = sillage.CtcQInter(ctcs, 1)
    assert c.name() == "CtcQInter" and c.q() == 1 and c.nb_vars() == 2
    x = box((-10, 10), (-10, 10))
    assert c.contract(x) is x
    assert bounds(x) == [(1, 2), (1, 2)]
    strict, relaxed = box((-10, 10), (-10, 10)), box((-10, 10), (-10, 10))
    sillage.CtcInter(ctcs).contract(strict)
    sillage.CtcQInter(ctcs, 0).contract(relaxed)
    assert strict.is_empty() and relaxed.is_empty()
    same = box((-10, 10), (-10, 10))
    sillage.CtcQInter(ctcs, 3).contract(same)
    assert bounds(same) == [(-10, 10), (-10, 10)]


def test_ctc_qinter_keeps_points_with_enough_constraints():
    rng = random.Random(8)
    for _ in range(40):
        m = rng.randint(2, 5)
        sets = []
        for _ in range(m):
            a, b = sorted((rng.uniform(-5, 5), rng.uniform(-5, 5)))
            c, d = sorted((rng.uniform(-5, 5), rng.uniform(-5, 5)))
            sets.append(box((a, b), (c, d)))
        for q in range(m + 1):
            x = box((-4, 4), (-4, 4))
            sillage.CtcQInter([sillage.CtcBox(s) for s in sets], q).contract(x)
            for _ in range(100):
                p = [rng.uniform(-4, 4), rng.uniform(-4, 4)]
                if sum(s.contains(p) for s in sets) >= m - q:
                    assert x.contains(p)


def test_ctc_qinter_in_sivia_and_in_a_network():
    ctcs = [sillage.CtcBox(box((1, 3))), sillage.CtcBox(box((2, 4))), sillage.CtcBox(box((10, 11)))]
    c = sillage.CtcQInter(ctcs, 1)
    assert bounds(sillage.sivia(box((0, 20)), c, 0.1).hull()) == [(2, 3)]
    cn = sillage.ContractorNetwork()
    x = box((0, 20))
    cn.add(c, [x])
    cn.contract()
    assert bounds(x) == [(2, 3)]


def ranges(wrong, seed=42):
    """20 beacons, truth (3.25, -1.5), ranges +-0.1; those at `wrong` shifted by 5 to 15."""
    rng = random.Random(seed)
    truth = [3.25, -1.5]
    ctcs = []
    for i in range(20):
        bx, by = rng.randint(-40, 40), rng.randint(-40, 40)
        d = math.hypot(truth[0] - bx, truth[1] - by) + rng.uniform(-0.05, 0.05)
        if i in wrong:
            d += (-1 if i % 2 else 1) * rng.uniform(5, 15)
        f = Function(["x1", "x2"], f"sqrt((x1 - ({bx}))^2 + (x2 - ({by}))^2)")
        ctcs.append(sillage.CtcFunction(f, Interval(max(0.0, d - 0.1), d + 0.1)))
    return truth, ctcs


@pytest.mark.parametrize("wrong", [[], [6], [1, 12], [3, 8, 19]])
def test_gomne_finds_the_injected_outliers(wrong):
    truth, ctcs = ranges(wrong)
    r = sillage.gomne(ctcs, box((-50, 50), (-50, 50)), eps=0.5)
    assert r.q == len(wrong)
    assert r.outliers == wrong
    assert r.box.contains(truth) and r.box.max_diam() < 1
    assert any(leaf.contains(truth) for leaf in r.leaves)
    assert "GomneResult q=" in repr(r)


def test_gomne_without_outliers_is_the_strict_intersection():
    truth, ctcs = ranges([], seed=7)
    x0 = box((-50, 50), (-50, 50))
    r = sillage.gomne(ctcs, x0)
    strict = box((-50, 50), (-50, 50))
    sillage.CtcFixPoint(sillage.CtcInter(ctcs), 0.01).contract(strict)
    assert r.q == 0 and r.outliers == [] and r.box == strict and r.box.contains(truth)


def test_gomne_q_max_and_python_contractors():
    class Interval1(sillage.Ctc):  # a Python contractor: x in [lo, hi]
        def __init__(self, lo, hi):
            super().__init__(1)
            self.b = IntervalVector([Interval(lo, hi)])

        def contract(self, x):
            x &= self.b

    ctcs = [Interval1(1, 3), Interval1(2, 4), Interval1(10, 11), Interval1(2.5, 5)]
    r = sillage.gomne(ctcs, box((0, 20)))
    assert r.q == 1 and r.outliers == [2] and bounds(r.box) == [(2.5, 3)]
    none = sillage.gomne(ctcs, box((0, 20)), q_max=0)
    assert none.q == 1 and none.is_empty() and none.leaves == []


def test_errors():
    c = sillage.CtcBox(box((0, 1), (0, 1)))
    with pytest.raises(sillage.Error, match="CtcQInter"):
        sillage.CtcQInter([], 0)
    with pytest.raises(sillage.Error, match="q must be >= 0"):
        sillage.CtcQInter([c], -1)
    with pytest.raises(sillage.Error):
        sillage.CtcQInter([c, sillage.CtcBox(box((0, 1)))], 0)
    with pytest.raises(sillage.Error, match="gomne"):
        sillage.gomne([], box((0, 1), (0, 1)))
    with pytest.raises(sillage.Error, match="eps"):
        sillage.gomne([c], box((0, 1), (0, 1)), eps=0)
    with pytest.raises(sillage.Error, match="q_max"):
        sillage.gomne([c], box((0, 1), (0, 1)), q_max=-1)
    with pytest.raises(sillage.Error, match="gomne"):
        sillage.gomne([c], box((0, 1)))
    with pytest.raises(sillage.Error):
        sillage.q_inter([], 0)


def fixes(wrong):
    """x(t) = (cos t, sin t) through its derivative +-0.01; ten fixes +-0.05, those at `wrong` off by (2, -1)."""
    td = sillage.TDomain(0.0, 10.0, 0.05)
    x = sillage.TubeVector(td, box((-10, 10), (-10, 10)))
    v = sillage.TubeVector(td, "(-sin(t), cos(t))")
    for j in range(2):
        v[j] += Interval(-0.01, 0.01)
    obs = []
    for i in range(10):
        t = 0.5 + i
        dx, dy = (2.0, -1.0) if i in wrong else (0.0, 0.0)
        z = box((math.cos(t) + dx - 0.05, math.cos(t) + dx + 0.05), (math.sin(t) + dy - 0.05, math.sin(t) + dy + 0.05))
        obs.append(sillage.TubeObservation(Interval(t - 0.01, t + 0.01), z))
    return x, v, obs


def test_ctc_qeval_two_wrong_fixes():
    for q in (0, 1):
        x, v, obs = fixes([3, 7])
        sillage.CtcQEval(q).contract(x, v, obs)
        assert x.is_empty()
    x, v, obs = fixes([3, 7])
    before = x.copy()
    c = sillage.CtcQEval(2)
    assert c.q() == 2 and c.contract(x, v, obs) == []
    assert x.is_subset(before) and x.max_thickness() < 0.3
    assert all(x(k / 10).contains([math.cos(k / 10), math.sin(k / 10)]) for k in range(101))
    assert c.contract(x, v, obs) == [3, 7]  # on the contracted tube the wrong fixes are violated everywhere
    with pytest.raises(sillage.Error, match="q must be >= 0"):
        sillage.CtcQEval(-1)
    with pytest.raises(sillage.Error, match="observation"):
        c.contract(x, v, [])


def test_gomne_tube_range_fixes():
    td = sillage.TDomain(0.0, 10.0, 0.05)
    x = sillage.TubeVector(td, box((-10, 10), (-10, 10)))
    v = sillage.TubeVector(td, "(-sin(t), cos(t))")
    for j in range(2):
        v[j] += Interval(-0.01, 0.01)
    beacons = [(3, 0), (0, 3), (-3, 0), (0, -3)]
    obs = []
    for i in range(10):
        t = 0.5 + i
        b = beacons[i % 4]
        r = math.hypot(math.cos(t) - b[0], math.sin(t) - b[1]) + (1.0 if i in (2, 6) else 0.0)
        d = Function(["z1", "z2"], f"sqrt((z1 - ({b[0]}))^2 + (z2 - ({b[1]}))^2)")
        obs.append(sillage.TubeObservation(Interval(t - 0.01, t + 0.01), IntervalVector(2),
                                           sillage.CtcFunction(d, Interval(r - 0.05, r + 0.05))))
    res = sillage.gomne_tube(x, v, obs)
    assert res.q == 2 and res.outliers == [2, 6]
    assert all(res.x(k / 10).contains([math.cos(k / 10), math.sin(k / 10)]) for k in range(101))
    assert res.x.max_thickness() < 0.5
    none = sillage.gomne_tube(x, v, obs, q_max=1)
    assert none.q == 2 and none.x.is_empty() and none.outliers == []
    with pytest.raises(sillage.Error, match="max_passes"):
        sillage.gomne_tube(x, v, obs, max_passes=0)


def test_example_outliers_ranges(tmp_path):
    pytest.importorskip("matplotlib")
    script = Path(__file__).resolve().parents[2] / "examples" / "python" / "outliers_ranges.py"
    run = subprocess.run([sys.executable, str(script), "--out", str(tmp_path)], capture_output=True, text=True,
                         cwd=script.parent)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "q = 3, outliers [4, 11, 16]" in run.stdout and (tmp_path / "outliers_ranges_py.png").exists()
