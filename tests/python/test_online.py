"""Online estimation from Python: a time domain that grows and forgets, a
network that contracts only what changed, and OnlineEstimator on a robot
whose truth is known (it must stay inside every estimate)."""
import math
import random

import pytest

import sillage as s


def truth(t):
    return [10 * math.cos(t / 10), 10 * math.sin(t / 5)]


def velocity(t):
    ti = s.Interval(t[0], t[1])
    return s.IntervalVector([-s.sin(ti / 10) + s.Interval(-0.05, 0.05), 2 * s.cos(ti / 5) + s.Interval(-0.05, 0.05)])


RANGE = s.CtcFunction(s.Function(["q0", "q1", "b0", "b1", "r"], "sqrt((q0 - b0)^2 + (q1 - b1)^2) - r"))
BEACONS = [(0.0, 0.0), (20.0, 5.0), (-5.0, 15.0)]


def estimator(**options):
    est = s.OnlineEstimator(0.0, s.OnlineOptions(**options))
    p0 = truth(0.0)
    est.add_state("p", 2, s.IntervalVector([s.Interval(p0[0] - 0.1, p0[0] + 0.1), s.Interval(p0[1] - 0.1, p0[1] + 0.1)]))
    est.add_input("v", 2)
    est.add_deriv("p", "v")
    return est


def run(est, steps, seed=1, check=None):
    rng = random.Random(seed)
    pending, next_range, dt = [], 0.5, 0.2
    for k in range(1, steps + 1):
        t = k * dt
        est.advance(t, {"v": velocity(((k - 1) * dt, t))})
        if check:
            check(est)
        while next_range < t - 0.3:  # a range arrives 0.3 s after it was taken
            b = BEACONS[rng.randrange(3)]
            p = truth(next_range)
            r = math.hypot(p[0] - b[0], p[1] - b[1]) + rng.uniform(-0.1, 0.1)
            stamp = next_range + rng.uniform(-0.1, 0.1)
            est.observe(s.Interval(stamp - 0.1, stamp + 0.1), "p", RANGE,
                        [s.IntervalVector([s.Interval(b[0]), s.Interval(b[1])]), s.Interval(r - 0.1, r + 0.1)])
            if check:
                check(est)
            next_range += 0.3 + rng.random()


def test_tdomain_extends_and_forgets():
    td = s.TDomain([0.0, 1.0])
    x = s.Tube(td, s.Interval(1, 2))
    assert td.extend(2.0) == 2
    assert x.nb_slices() == 2 and x.gate(1) == s.Interval(1, 2)
    assert td.forget_before(1.5) == 1 and td.nb_forgotten() == 1
    assert x.gate(0) == s.Interval(1, 2) and td.t0_tf() == s.Interval(1, 2)
    with pytest.raises(s.Error, match="not after the end"):
        td.extend(1.5)


def test_network_update_runs_only_what_changed():
    cn = s.ContractorNetwork()
    x, y = s.Interval(0, 10), s.Interval(0, 10)
    cn.add(s.CtcFunction(s.Function(["x", "y"], "x - y - 1")), [x, y])
    cn.contract()
    assert cn.update().contractor_calls == 0
    cn.add(s.CtcFunction(s.Function(["y"], "y - 2")), [y])
    st = cn.update()
    assert x == s.Interval(3) and st.contractor_calls == 2
    cn.retire([1])
    assert cn.nb_ctc() == 1
    cn.touched(x)
    assert cn.update().summary.status == s.Status.Converged


def test_the_truth_stays_inside_every_estimate():
    est = estimator()

    def check(e):
        assert e.now("p").contains(truth(e.now())), e.now()
        assert e.last_update().summary.status == s.Status.Converged

    run(est, 200, check=check)
    p = est.tube("p")
    for t in [0.05 * i for i in range(1, 800)]:
        assert p(t).contains(truth(t)), t
    st = est.stats()
    assert st.slices == 200 and st.updates == 200 + st.observations and st.forgotten == 0


def test_a_window_keeps_memory_flat():
    est = estimator(window=5.0)
    most = []

    def check(e):
        assert e.now("p").contains(truth(e.now()))
        most.append(e.stats().slices)

    run(est, 600, check=check)
    assert max(most) <= (5.0 + 5.0 / 8) / 0.2 + 2
    assert est.window_start() >= est.now() - 5.0 - 5.0 / 8 - 0.2
    st = est.stats()
    assert st.forgotten > 500 and st.retired > 0
    assert "OnlineEstimator(now=120" in repr(est)


def test_bad_input_is_refused():
    est = estimator(window=5.0)
    b, r = s.IntervalVector([s.Interval(0), s.Interval(0)]), s.Interval(9, 11)
    with pytest.raises(s.Error, match="advance"):
        est.observe(s.Interval(0, 0.1), "p", RANGE, [b, r])
    for k in range(1, 51):
        est.advance(0.2 * k, {"v": velocity((0.2 * (k - 1), 0.2 * k))})
    with pytest.raises(s.Error, match="future"):
        est.observe(s.Interval(10.5, 11), "p", RANGE, [b, r])
    with pytest.raises(s.Error, match="older than the window"):
        est.observe(s.Interval(0.1, 0.2), "p", RANGE, [b, r])
    with pytest.raises(s.Error, match="not after now"):
        est.advance(10.0)
    with pytest.raises(s.Error, match="no tube 'w'"):
        est.advance(10.2, {"w": velocity((10, 10.2))})
    with pytest.raises(s.Error, match="before the first advance"):
        est.add_input("u", 1)
    with pytest.raises(s.Error, match="window must be positive"):
        s.OnlineEstimator(0.0, s.OnlineOptions(window=0))
    assert est.now() == 10.0


ROOT = __import__("pathlib").Path(__file__).resolve().parents[2]
PLAZA1 = ROOT.parent / "shared" / "data" / "plaza1"


@pytest.mark.skipif(not (PLAZA1 / "odometry.csv").exists(), reason="no plaza1 data")
def test_plaza1_online_examples_keep_the_truth(tmp_path):
    """The plaza1 log replayed online (W = 60 s), in Python and in C++: the ground truth inside the
    box of the position now at every one of the 9657 periods, and a figure of the box sizes."""
    import subprocess
    import sys
    r = subprocess.run([sys.executable, str(ROOT / "examples" / "python" / "plaza1_online.py"), "--out",
                        str(tmp_path)], capture_output=True, text=True, timeout=600)
    assert r.returncode == 0, r.stdout[-2000:] + r.stderr[-2000:]
    assert "ground truth inside the online box at 9657 / 9657 times" in r.stdout
    assert (tmp_path / "plaza1_online_sizes_py.png").stat().st_size > 10000
    exe = __import__("pathlib").Path(s.__file__).resolve().parents[2] / "examples" / "example_plaza1_online"
    if not exe.exists():
        pytest.skip(f"{exe} is not built")
    r = subprocess.run([str(exe), "--out", str(tmp_path), "--window", "30"], capture_output=True, text=True,
                       timeout=600)
    assert r.returncode == 0, r.stdout[-2000:]
    assert "ground truth inside the online box at 9657 / 9657 times" in r.stdout
    assert "<svg" in (tmp_path / "plaza1_online_sizes.svg").read_text()


def test_ctc_deriv_contract_local_equals_the_whole_sweep():
    """After a change in a few slices of a fixed point, the local sweeps give contract()'s tube."""
    td = s.TDomain(0, 20, 0.1)
    v = s.Tube(td, s.Interval(-1, 1))
    x = s.Tube(td)
    x.set_gate(0, s.Interval(0))
    ctc = s.CtcDeriv()
    ctc.contract(x, v)
    x.set_gate(100, s.Interval(9.5, 10))
    whole = x.copy()
    ctc.contract(whole, v)
    ok, changed = ctc.contract_local(x, v, 99, 100)
    assert ok and x == whole
    assert 2 * 50 in changed  # gate 50 (t = 5) learnt x(5) >= 4.5
    assert x.gate(50) == s.Interval(4.5, 5)


@pytest.mark.parametrize("name", ["CtcIncrement", "CtcSecondDeriv"])
def test_pair_contract_local_equals_the_whole_contraction(name):
    """CtcIncrement and CtcSecondDeriv: local after a change of a fixed point = contract(), bit for bit."""
    td = s.TDomain(0, 10, 0.1)
    u = s.Tube(td, s.Interval(-0.2, 0.2))
    x = s.Tube(td, s.Interval(-5, 5))
    x.set_gate(0, s.Interval(0))
    ctc = getattr(s, name)()
    ctc.contract(x, u)
    for k in (59, 60, 61):
        x.set_gate(k, x.gate(k) & s.Interval(-0.5, 0.5))
    whole = x.copy()
    ctc.contract(whole, u)
    ok, changed = ctc.contract_local(x, u, 58, 61)
    assert ok and x == whole and changed


def test_heading_contract_local_equals_the_whole_contraction():
    td = s.TDomain(0, 10, 0.5)
    px, py = s.Tube(td), s.Tube(td)
    px.set_gate(0, s.Interval(0))
    py.set_gate(0, s.Interval(0))
    psi = s.Tube(td, s.Interval(-0.1, 0.1))
    d = s.Tube(td, s.Interval(0.4, 0.6))
    w = s.Tube(td, s.Interval(-0.05, 0.05))
    ctc = s.CtcHeading(0.01)
    p = s.TubeVector([px, py])
    for _ in range(100):  # a fixed point of contract() first
        before = (p[0].copy(), p[1].copy(), psi.copy())
        ctc.contract(p, psi, d, w)
        if (p[0], p[1], psi) == before:
            break
    px, py = p[0].copy(), p[1].copy()
    px.set_gate(10, px.gate(10) & s.Interval(4.6, 5.0))
    p_whole, psi_whole = s.TubeVector([px, py]), psi.copy()
    ctc.contract(p_whole, psi_whole, d, w)
    ok, cx, cy, cpsi = ctc.contract_local(px, py, psi, d, w, 9, 10)
    assert ok and px == p_whole[0] and py == p_whole[1] and psi == psi_whole


def test_figure_eight_loop_proven_online_once_the_robot_is_back():
    """The t-plane of the window's velocity, at any time (tests/cpp/online/test_online_loops.cpp)."""
    est = s.OnlineEstimator(0.0)
    est.add_bounded("v", s.Function(["t"], "(-10*sin(t) + [-0.01, 0.01], 10*cos(2*t) + [-0.01, 0.01])"))
    est.add_state("x", 2, s.IntervalVector([s.Interval(9.9, 10.1), s.Interval(-0.1, 0.1)]))
    est.add_deriv("x", "v")

    def proven():
        v = est.tube("v")
        tp = s.TPlane(v.tdomain())
        tp.compute_detections(0.01, v)
        tp.compute_proofs(v)
        return [l for l in tp.detections() if l.complete() and l.proven()]

    for k in range(1, 81):
        est.advance(0.05 * k)
    assert not proven()
    for k in range(81, 121):
        est.advance(0.05 * k)
    loops = proven()
    assert len(loops) == 1
    assert loops[0].t_box()[0].contains(math.pi / 2) and loops[0].t_box()[1].contains(3 * math.pi / 2)
