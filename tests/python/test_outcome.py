"""One outcome for the long computations (outcome.h): sivia_run and
kernel_sivia_run keep the paving so far when the budget is spent or the token
cancelled, with a Summary saying how the run ended; Budget.progress is called
every progress_every boxes, in order."""
import math
import threading
import time

import pytest

import sillage as sl

X0 = sl.IntervalVector([[-3, 3], [-3, 3]])
RING = sl.Function(["x", "y"], "x^2 + y^2")


def opts(max_boxes=0, parallel=False, **budget):
    return sl.SiviaOptions(parallel=parallel, budget=sl.Budget(max_boxes=max_boxes, **budget))


def ring_points():
    return [(r * math.cos(a), r * math.sin(a))
            for a in (2 * math.pi * i / 32 for i in range(32)) for r in (1.0001, 1.5, 1.9999)]


def encloses(paving):
    outer = paving.inner() + paving.boundary()
    pts = [sl.IntervalVector([[x, x], [y, y]]) for x, y in ring_points()]
    return all(any(b.intersects(p) for b in outer) for p in pts)


def test_status_and_summary_objects():
    assert [s.name for s in sl.Status.__members__.values()] == ["Converged", "Stopped", "Cancelled", "NoSolution"]
    s = sl.Summary()
    assert (s.status, s.reason, s.rounds, s.work, s.seconds, s.finished()) == (sl.Status.Converged, "", 0, 0, 0, True)
    b = sl.Budget()
    assert b.progress is None and b.progress_every == 65536


def test_converged_is_sivia():
    r = sl.sivia_run(X0, RING, sl.Interval(1, 4), 0.05, opts())
    assert r.summary.status == sl.Status.Converged and r.summary.reason == "" and r.summary.finished()
    assert r.summary.work == r.paving.nb_nodes()
    assert r.paving == sl.sivia(X0, RING, sl.Interval(1, 4), 0.05, opts())
    paving, summary = r
    assert paving == r.paving and summary.status == sl.Status.Converged
    assert r.take() == r.paving
    assert str(r.summary).startswith(f"converged after {r.paving.nb_nodes()} units of work, 0 progress rounds")


@pytest.mark.parametrize("parallel", [False, True])
def test_stopped_keeps_an_enclosure(parallel):
    r = sl.sivia_run(X0, RING, sl.Interval(1, 4), 0.01, opts(500, parallel))
    assert r.summary.status == sl.Status.Stopped and not r.summary.finished()
    assert r.summary.reason == ("sivia: budget exceeded: 501 boxes > max_boxes = 500; raise "
                                "options.budget.max_boxes (0: no limit) or use a larger eps")
    assert encloses(r.paving)
    with pytest.raises(sl.BudgetExceeded, match="501 boxes > max_boxes = 500"):
        r.take()
    with pytest.raises(sl.BudgetExceeded, match="501 boxes > max_boxes = 500"):
        sl.sivia(X0, RING, sl.Interval(1, 4), 0.01, opts(500, parallel))


def test_python_callable_and_kernel():
    r = sl.sivia_run(X0, lambda b: sl.sqr(b[0]) + sl.sqr(b[1]), sl.Interval(1, 4), 0.01, opts(300))
    assert r.summary.status == sl.Status.Stopped and encloses(r.paving)
    lo, hi = sl.Function(["x", "y"], "x^2 + y^2 - 4"), sl.Function(["x", "y"], "x^2 + y^2 - 1")
    k = sl.kernel_sivia_run(X0, lo, hi, 0.01, opts(300))
    assert k.summary.status == sl.Status.Stopped and k.summary.reason.startswith("kernel_sivia: budget exceeded: 301")
    assert encloses(k.paving)


def test_no_solution():
    r = sl.sivia_run(X0, RING, sl.Interval(20, 30), 0.01, opts())
    assert r.summary.status == sl.Status.NoSolution and r.summary.finished()
    assert r.summary.reason == "sivia: every box of the initial box is proven outside X (X ∩ x0 is empty)"
    assert r.take().boundary() == []


def test_cancelled_from_another_thread():
    o = opts(0, True, max_bytes=0)
    threading.Timer(0.2, o.budget.cancel.cancel).start()
    start = time.monotonic()
    r = sl.sivia_run(X0, RING, sl.Interval(1, 4), 1e-9, o)
    assert time.monotonic() - start < 5
    assert r.summary.status == sl.Status.Cancelled and r.summary.reason == "sivia: cancelled"
    assert encloses(r.paving)
    with pytest.raises(sl.Cancelled, match="^sivia: cancelled$"):
        r.take()


@pytest.mark.parametrize("parallel", [False, True])
def test_progress_hook(parallel):
    calls = []
    o = opts(0, parallel, progress=calls.append, progress_every=100)
    assert o.budget.progress is not None
    r = sl.sivia_run(X0, RING, sl.Interval(1, 4), 0.01, o)
    assert len(calls) == r.paving.nb_nodes() // 100 == r.summary.rounds > 0
    assert [c.round for c in calls] == list(range(1, len(calls) + 1))
    assert all(a.work <= b.work for a, b in zip(calls, calls[1:]))
    assert all(c.where == "sivia" for c in calls)
    if not parallel:
        assert [c.work for c in calls] == [100 * (i + 1) for i in range(len(calls))]
    assert r.paving == sl.sivia(X0, RING, sl.Interval(1, 4), 0.01, opts())


def test_progress_hook_raises():
    def stop(p):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        sl.sivia_run(X0, RING, sl.Interval(1, 4), 0.01, opts(0, True, progress=stop, progress_every=100))
    b = sl.Budget(progress=stop)
    b.progress = None
    assert b.progress is None


# ---- the loops and the temporal SLAM (loops.md, slam.md) ----

LIMACON_V = "(-sin(t) - 2*sin(2*t) + [-0.01,0.01], cos(t) + 2*cos(2*t) + [-0.01,0.01])"


def limacon():
    td = sl.TDomain(0.3, 2 * math.pi - 0.3, 0.001)
    return td, sl.TubeVector(td, LIMACON_V)


def holds_loop(tp, t1=2 * math.pi / 3, t2=4 * math.pi / 3):
    point = sl.IntervalVector([[t1, t1], [t2, t2]])
    return any(point.is_subset(b) for d in tp.detections() for b in d.boxes())


def test_detections_run_keeps_an_enclosure_of_the_loop():
    td, v = limacon()
    tp = sl.TPlane(td)
    s = tp.compute_detections_run(0.05, v)
    assert s.status == sl.Status.Converged and tp.nb_detections() == 1
    s = tp.compute_detections_run(1e-9, v, sl.Budget(max_boxes=500))
    assert s.status == sl.Status.Stopped
    assert s.reason == ("TPlane::compute_detections: budget exceeded: 501 boxes > max_boxes = 500; raise "
                        "budget.max_boxes (0: no limit) or use a larger eps")
    assert holds_loop(tp)
    token = sl.CancelToken()
    token.cancel()
    s = tp.compute_detections_run(0.05, v, sl.Budget(cancel=token))
    assert s.status == sl.Status.Cancelled and s.reason == "TPlane::compute_detections: cancelled"
    assert tp.nb_detections() == 1 and holds_loop(tp)


def test_degree_count_split_runs_have_no_value_once_stopped():
    td, v = limacon()
    tp = sl.TPlane(td)
    tp.compute_detections(0.05, v)
    boxes, f = tp.detections()[0].boxes(), sl.LoopFunction(v)
    r = sl.topological_degree_run(boxes, f)
    assert r.summary.status == sl.Status.Converged and r.value.degree == 1
    assert r.take().degree == sl.topological_degree(boxes, f).degree
    o = sl.DegreeOptions()
    o.budget = sl.Budget(max_boxes=3)
    r = sl.topological_degree_run(boxes, f, o)
    value, summary = r
    assert value is None and summary.status == sl.Status.Stopped
    assert summary.reason.startswith("topological_degree: budget exceeded: 4 boxes > max_boxes = 3")
    with pytest.raises(sl.BudgetExceeded):
        r.take()
    c = sl.count_zeros_run(boxes, 1, f)
    assert c.summary.status == sl.Status.Converged and c.value.count == 1
    o = sl.CountOptions()
    o.budget = sl.Budget(max_boxes=1)
    assert sl.count_zeros_run(boxes, 1, f, o).value is None
    s = sl.split_region_run(boxes, f)
    assert s.summary.status == sl.Status.Converged and s.value.count() == 1
    o = sl.SplitOptions()
    o.budget = sl.Budget(max_boxes=1)
    s = sl.split_region_run(boxes, f, o)
    assert s.summary.status == sl.Status.Stopped and s.value is None
    assert "SplitRun(value=None, summary=stopped" in repr(s)
    # A Python f too.
    r = sl.topological_degree_run([sl.IntervalVector([[-1, 1], [-1, 1]])], lambda b: b)
    assert r.value.degree == 1


def test_temporal_slam_run_summary_and_progress():
    from test_slam import mission
    x, v, u, z, f, h, truth = mission()
    o = sl.TemporalSlamOptions()
    o.eps = 0.01
    seen = []
    o.progress = lambda p: seen.append((p.where, p.round, p.work))
    r = sl.temporal_slam_run(x, v, u, z, f, h, o)
    rows, summary = r
    assert summary.status == sl.Status.Converged and summary.work == len(rows) == summary.rounds
    assert seen == [("temporal_slam", i, i) for i in range(1, len(rows) + 1)]
    assert x.contains(truth)
    x, v, u, z, f, h, truth = mission()
    o = sl.TemporalSlamOptions()
    o.eps, o.fast, o.max_rounds = 0.01, False, 1
    r = sl.temporal_slam_run(x, v, u, z, f, h, o)
    assert r.summary.status == sl.Status.Stopped
    assert r.summary.reason.startswith("temporal_slam: the accurate algorithm ran max_rounds = 1 rounds")
    x, v, u, z, f, h, truth = mission()
    o.cancel.cancel()
    r = sl.temporal_slam_run(x, v, u, z, f, h, o)
    assert (r.summary.status, r.summary.reason, r.rows) == (sl.Status.Cancelled, "temporal_slam: cancelled", [])
    assert x.contains(truth)
    with pytest.raises(sl.Cancelled):
        sl.temporal_slam(x, v, u, z, f, h, o)



def test_count_and_split_runs_of_python_callables():
    quadrants = [sl.IntervalVector([[a, a + 1], [b, b + 1]]) for a in (-1, 0) for b in (-1, 0)]
    f = lambda b: b  # noqa: E731  (one zero, at the origin)
    j = lambda b: sl.IntervalMatrix.identity(2)  # noqa: E731
    c = sl.count_zeros_run(quadrants, 1, f, j)
    assert c.summary.status == sl.Status.Converged and c.value.count == 1
    assert c.take().count == sl.count_zeros(quadrants, 1, f, j).count
    o = sl.CountOptions()
    o.budget = sl.Budget(max_boxes=1)
    c = sl.count_zeros_run(quadrants, 1, f, j, o)
    assert c.value is None and c.summary.status == sl.Status.Stopped
    s = sl.split_region_run(quadrants, f, j)
    assert s.summary.status == sl.Status.Converged and s.value.count() == 1
    o = sl.SplitOptions()
    o.budget = sl.Budget(max_boxes=1)
    s = sl.split_region_run(quadrants, f, j, o)
    assert s.value is None and s.summary.status == sl.Status.Stopped
    o = sl.SplitOptions()
    o.budget.cancel.cancel()
    assert sl.split_region_run(quadrants, f, j, o).summary.status == sl.Status.Cancelled
    with pytest.raises(sl.Error, match="split_region_run: a jacobian is needed to count"):
        sl.split_region_run(quadrants, f)
    o = sl.SplitOptions()
    o.count = False
    assert sl.split_region_run(quadrants, f, options=o).value.degree() == 1


POINT = ('[time]\ndomain = [0, 1]\ndelta = 0.5\n[var.x]\nkind = "interval"\nvalue = "[0, 10]"\n'
         '[[constraint]]\nkind = "expr"\nexpr = "x - {}"\n')
SLOW = ('[time]\ndomain = [0, 1]\ndelta = 0.5\n[network]\nratio = 0\n[var.x]\nkind = "interval"\n'
        'value = "[0, 1000000]"\n[var.y]\nkind = "interval"\nvalue = "[0, 1000000]"\n[[constraint]]\n'
        'kind = "expr"\nexpr = "x - y"\n[[constraint]]\nkind = "expr"\nexpr = "y - 0.99999*x"\n')


def test_problem_solve_summary(tmp_path):
    path = tmp_path / "p.toml"
    path.write_text(POINT.format(1))
    r = sl.solve(str(path))
    assert (r.summary.status, r.summary.reason) == (sl.Status.Converged, "")
    assert r.summary.work == r.schedule[-1]["stats"].contractor_calls > 0 and r.summary.finished()
    path.write_text(POINT.format(20))
    r = sl.solve(str(path))
    assert r.empty and r.summary.status == sl.Status.NoSolution and r.summary.reason == r.why_empty
    assert "p.toml" in r.summary.reason  # the constraint and its place in the file
    path.write_text(SLOW)
    r = sl.solve_problem(sl.load_problem(str(path)), budget=sl.Budget(max_boxes=1000))
    assert r.summary.status == sl.Status.Stopped and r.summary.reason == r.stopped and r.summary.work == 1000
    assert not r.summary.finished() and r.summary.seconds >= r.contract_seconds()
