"""Budgets and cancellation of the long algorithms from Python: BudgetExceeded
with a message that says how to raise the budget, a CancelToken set from
another thread (sillage.Cancelled), and Ctrl-C (SIGINT) stopping a SIVIA, a
t-plane computation, a problem's solve, CtcIvp or CtcPImpliesZ (they run
without the GIL) within a second."""
import math
import os
from pathlib import Path
import signal
import threading
import time

import pytest

import sillage as sl


def sphere(n):
    names = [f"x{i}" for i in range(n)]
    return sl.Function(names, " + ".join(v + "^2" for v in names)), sl.IntervalVector([[-2, 2]] * n)


def test_budget_objects():
    b = sl.Budget()
    assert b.max_boxes == 10_000_000 and b.max_bytes == 2**30 and b.max_seconds == 0 and not b.cancel.cancelled()
    assert repr(sl.SiviaOptions()) == ("SiviaOptions(parallel=True, budget=Budget(max_boxes=10000000, "
                                       "max_bytes=1073741824, max_seconds=0))")
    o = sl.SiviaOptions(parallel=False, budget=sl.Budget(max_boxes=5, max_seconds=1.5))
    assert (o.parallel, o.budget.max_boxes, o.budget.max_seconds) == (False, 5, 1.5)
    o.budget.max_boxes = 7  # the options' own budget, not a copy
    assert o.budget.max_boxes == 7
    with pytest.raises(sl.Error, match=r"^Budget: budget.max_seconds must be >= 0 \(0: no limit\), got -1$"):
        sl.Budget(max_seconds=-1)
    assert issubclass(sl.BudgetExceeded, sl.Error) and issubclass(sl.Cancelled, KeyboardInterrupt)


def test_sivia_budget_exceeded():
    f, x0 = sphere(10)
    o = sl.SiviaOptions(budget=sl.Budget(max_boxes=20000))
    with pytest.raises(sl.BudgetExceeded) as e:
        sl.sivia(x0, f, sl.Interval(0, 1), 1e-3, o)
    assert str(e.value) == ("sivia: budget exceeded: 20001 boxes > max_boxes = 20000; raise "
                            "options.budget.max_boxes (0: no limit) or use a larger eps")
    # Python callables count too (they run on the calling thread).
    o = sl.SiviaOptions(budget=sl.Budget(max_boxes=50))
    with pytest.raises(sl.BudgetExceeded, match="51 boxes > max_boxes = 50"):
        sl.sivia(sl.IntervalVector([[-2, 2], [-2, 2]]), lambda b: b[0] ** 2 + b[1] ** 2, sl.Interval(0, 1), 1e-3, o)
    with pytest.raises(sl.BudgetExceeded, match=r"max_seconds = 0.10000000000000001 \(after \d+ boxes\)"):
        sl.sivia(x0, f, sl.Interval(0, 1), 1e-3,
                 sl.SiviaOptions(budget=sl.Budget(max_boxes=0, max_bytes=0, max_seconds=0.1)))
    with pytest.raises(sl.BudgetExceeded, match=r"^sivia: budget exceeded: 101 boxes of 168 bytes > max_bytes = 16800; "
                                                r"raise options.budget.max_bytes \(0: no limit\) or use a larger eps$"):
        sl.sivia(x0, f, sl.Interval(0, 1), 1e-3, sl.SiviaOptions(budget=sl.Budget(max_boxes=0, max_bytes=16800)))


def test_tplane_budget_exceeded():
    td = sl.TDomain(0.3, 2 * math.pi - 0.3, 0.001)
    v = sl.TubeVector(td, "(-sin(t) - 2*sin(2*t) + [-0.01,0.01], cos(t) + 2*cos(2*t) + [-0.01,0.01])")
    tp = sl.TPlane(td)
    with pytest.raises(sl.BudgetExceeded) as e:
        tp.compute_detections(1e-9, v, sl.Budget(max_boxes=1000))
    assert str(e.value) == ("TPlane::compute_detections: budget exceeded: 1001 boxes > max_boxes = 1000; raise "
                            "budget.max_boxes (0: no limit) or use a larger eps")
    tp.compute_detections(0.05, v)
    options = sl.ProofOptions()
    options.budget.max_boxes = 2
    with pytest.raises(sl.BudgetExceeded, match="^TPlane::compute_proofs: budget exceeded: 3 boxes"):
        tp.compute_proofs(v, options)
    tp.compute_proofs(v)
    assert tp.nb_proofs() == 1


def test_cancel_token_from_another_thread():
    f, x0 = sphere(10)
    token = sl.CancelToken()
    o = sl.SiviaOptions(budget=sl.Budget(max_boxes=0, max_bytes=2 << 30, cancel=token))  # 2 GB: a guard, as below
    threading.Timer(0.2, token.cancel).start()
    start = time.monotonic()
    with pytest.raises(sl.Cancelled, match="^sivia: cancelled$"):
        sl.sivia(x0, f, sl.Interval(0, 1), 1e-3, o)
    assert time.monotonic() - start < 2
    assert token.cancelled()
    token.reset()
    assert sl.sivia(sl.IntervalVector([[-2, 2]] * 2), sphere(2)[0], sl.Interval(0, 1), 0.5, o).nb_leaves() > 0


def interrupt_after(seconds):
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    return timer


@pytest.mark.parametrize("parallel", [True, False])
def test_ctrl_c_stops_sivia(parallel, sigint_raises):
    f, x0 = sphere(10)
    # No box limit, so that only Ctrl-C stops it; 2 GB of boxes as a guard (Ctrl-C comes at about
    # 0.1 GB): a missed interrupt fails the test instead of exhausting the machine's memory.
    o = sl.SiviaOptions(parallel=parallel, budget=sl.Budget(max_boxes=0, max_bytes=2 << 30))
    interrupt_after(0.3)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        sl.sivia(x0, f, sl.Interval(0, 1), 1e-3, o)
    assert time.monotonic() - start < 2
    # The module is usable afterwards.
    assert sl.sivia(sl.IntervalVector([[-2, 2]] * 2), sphere(2)[0], sl.Interval(0, 1), 0.5).nb_leaves() > 0


def test_ctrl_c_stops_tplane_detections(sigint_raises):
    td = sl.TDomain(0.3, 2 * math.pi - 0.3, 0.001)
    v = sl.TubeVector(td, "(-sin(t) - 2*sin(2*t) + [-0.01,0.01], cos(t) + 2*cos(2*t) + [-0.01,0.01])")
    tp = sl.TPlane(td)
    interrupt_after(0.3)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        tp.compute_detections(1e-9, v, sl.Budget(max_boxes=0, max_bytes=2 << 30))  # 2 GB: a guard, as above
    assert time.monotonic() - start < 2
    assert tp.nb_detections() == 0


def test_ctrl_c_stops_a_problem_solve(sigint_raises, tmp_path):
    """sillage.solve runs on a worker thread: Ctrl-C stops its contraction (a budget too)."""
    slow = tmp_path / "slow.toml"  # x = y and y = 0.99999 x from [0, 10^6]: millions of contractor runs
    slow.write_text('[time]\ndomain = [0, 1]\ndelta = 0.5\n[network]\nratio = 0\n[var.x]\nkind = "interval"\n'
                    'value = "[0, 1000000]"\n[var.y]\nkind = "interval"\nvalue = "[0, 1000000]"\n'
                    '[[constraint]]\nkind = "expr"\nexpr = "x - y"\n'
                    '[[constraint]]\nkind = "expr"\nexpr = "y - 0.99999*x"\n')
    interrupt_after(0.3)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        sl.solve(str(slow), budget=sl.Budget(max_boxes=0, max_seconds=60))  # 60 s: a guard
    assert time.monotonic() - start < 2
    # A budget spent is an answer: the domains so far (enclosures), and why they are not the fixed point.
    r = sl.solve_problem(sl.load_problem(str(slow)), budget=sl.Budget(max_boxes=1000))
    assert "1001 contractor calls > max_boxes = 1000" in r.stopped and not r.empty and "stopped" in repr(r)
    x = r.domains["x"]
    assert x.contains(0.0) and x.ub() < 1e6  # contracted, not to the fixed point
    problems = Path(__file__).resolve().parents[2] / "examples" / "problems"
    assert not sl.solve(str(problems / "line_ranges.toml")).empty  # usable afterwards



def ivp_tube():
    """x' = -sin x over 10^5 slices: about ten seconds of validated integration."""
    x = sl.Tube(sl.TDomain(0.0, 1000.0, 0.01))
    x.set_gate(0, sl.Interval(1))
    return sl.CtcIvp(sl.Function(["x"], "-sin(x)")), x


def slow_slam():
    """The figure eight of test_slam.py on 5000 slices, t-boxes of 0.0005 s: about ten seconds."""
    td = sl.TDomain(0.0, 5.0, 0.001)
    w = sl.TubeVector([sl.Tube(td, "10*cos(t - 0.5) + [-0.2,0.2]"), sl.Tube(td, "10*cos(2*t - 1) + [-0.2,0.2]")])
    z = sl.Tube(td, "sin(10*sin(t - 0.5)/3) + cos(5*sin(2*t - 1)/4) + sin(t - 0.5) + [-0.01,0.01]")
    p = sl.TubeVector(td, 2)
    p.set_gate(0, sl.IntervalVector([sl.Interval(-4.85, -4.75), sl.Interval(-4.26, -4.16)]))
    sl.CtcDeriv().contract(p, w)
    return sl.CtcPImpliesZ(0.0005), p, w, z


def test_ctrl_c_stops_ctc_ivp(sigint_raises):
    ctc, x = ivp_tube()
    interrupt_after(0.3)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        ctc.contract(x)
    assert time.monotonic() - start < 2
    assert ctc.contract(sl.Tube(sl.TDomain(0.0, 1.0, 0.5))) is True  # usable afterwards


def test_ctrl_c_stops_ctc_p_implies_z(sigint_raises):
    ctc, p, w, z = slow_slam()
    before = p.copy()
    interrupt_after(0.3)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        ctc.contract(p, w, z)
    assert time.monotonic() - start < 2
    assert p.is_subset(before)


def test_token_stops_ctc_ivp_and_ctc_p_implies_z():
    """A token cancelled from another thread: sillage.Cancelled."""
    ctc, x = ivp_tube()
    slam, p, w, z = slow_slam()
    for run in (lambda t: ctc.contract(x, cancel=t), lambda t: slam.contract(p, w, z, cancel=t)):
        token = sl.CancelToken()
        threading.Timer(0.3, token.cancel).start()
        start = time.monotonic()
        with pytest.raises(sl.Cancelled, match="cancelled"):
            run(token)
        assert time.monotonic() - start < 2


def test_ctrl_c_and_token_stop_temporal_slam(sigint_raises):
    """temporal_slam on the slow figure eight (x = p, x' = the velocity w): Ctrl-C gives
    KeyboardInterrupt, a token sillage.Cancelled, both well within 2 s; x stays an enclosure."""
    _, p, w, z1 = slow_slam()
    z = sl.TubeVector([z1])
    f, h = sl.Function(["x1", "x2", "u1", "u2"], "(u1, u2)"), sl.Function(["x1", "x2"], "(x1, x2)")
    o = sl.TemporalSlamOptions()
    o.eps = 0.0005
    x = p.copy()
    interrupt_after(0.3)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        sl.temporal_slam(x, w.copy(), w, z, f, h, o)
    assert time.monotonic() - start < 2
    assert x.is_subset(p)
    o.cancel = sl.CancelToken()
    threading.Timer(0.3, o.cancel.cancel).start()
    start = time.monotonic()
    with pytest.raises(sl.Cancelled, match="cancelled"):
        sl.temporal_slam(p.copy(), w.copy(), w, z, f, h, o)
    assert time.monotonic() - start < 2
