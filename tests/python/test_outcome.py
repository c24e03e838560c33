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
