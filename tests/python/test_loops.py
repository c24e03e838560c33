"""Loops in the t-plane from Python (thesis ch. 6): LoopFunction on
hand-computed tubes, TPlane on a limaçon and a prolate cycloid whose crossings
are known in closed form, bad input, the SVG figures and the matplotlib
helpers (Agg). The zero tests themselves are in test_zero_tests.py."""
import gc
import xml.etree.ElementTree as ET
import math

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import sillage  # noqa: E402
from sillage import (DegreeOptions, Interval, IntervalMatrix, IntervalVector, LoopFunction, PavingTag,  # noqa: E402
                     ProofOptions, TDomain, TPlane, Tube, TubeVector, count_zeros, newton_test, self_crossings,
                     topological_degree)


def box(a, b, c, d):
    return IntervalVector([Interval(a, b), Interval(c, d)])


# ---- LoopFunction ----

def small_velocity():
    """Component 1: slices [1,2], [-1,3], [0,0.5], [2,4] on [0,4]; component 2: exactly 1."""
    td = TDomain(0, 4, 1)
    return TubeVector([Tube(td, [Interval(1, 2), Interval(-1, 3), Interval(0, 0.5), Interval(2, 4)]),
                       Tube(td, Interval(1))])


def test_loop_function_hand_computed():
    f = LoopFunction(small_velocity())  # the tube is kept alive by f
    gc.collect()
    assert not f.has_positions() and not f.is_empty()
    assert f.time_domain() == Interval(0, 4)
    t = box(0.5, 1.5, 2.5, 4)
    assert f(t) == box(-1, 8.5, 1, 3.5)
    assert f.velocity_form(t) == f(t)
    lower, upper = f.integral_bounds(t[0], t[1])
    assert lower == box(-1, 1.5, 1, 3.5)
    assert upper == box(1.75, 8.5, 1, 3.5)
    # (6.18): columns -[v]([t1]) and [v]([t2]).
    assert f.jacobian(t) == IntervalMatrix([[Interval(-3, 1), Interval(0, 4)], [Interval(-1), Interval(1)]])
    assert f.position(Interval(2.5, 4)) == box(0, 9.5, 2.5, 4)
    assert f.velocity(Interval(0, 1)) == box(1, 2, 1, 1)
    assert f(box(2, 2, 2, 2)) == box(0, 0, 0, 0)  # the diagonal


def test_loop_function_with_positions_and_bad_input():
    w = small_velocity()
    p = TubeVector(TDomain(0, 4, 0.5), "(t + [-0.25,0.25], t + [-0.25,0.25])")
    f = LoopFunction(p, w)
    assert f.has_positions()
    assert f(box(0.5, 1.5, 2.5, 4)) == box(0.5, 4, 1, 3.5)  # (7.28)
    assert f.velocity_form(box(0.5, 1.5, 2.5, 4)) == box(-1, 8.5, 1, 3.5)
    with pytest.raises(sillage.DimensionError):
        LoopFunction(TubeVector(TDomain(0, 4, 1), 3, Interval(1)))
    with pytest.raises(sillage.Error):
        LoopFunction(TubeVector(TDomain(5, 9, 1), 2, Interval(1)), w)
    with pytest.raises(sillage.Error):
        f(box(5, 6, 1, 2))  # outside the time domain
    # A modified tube invalidates the function: an Error, not a stale answer.
    g = LoopFunction(w)
    w.set(IntervalVector([Interval(0, 1), Interval(0, 1)]))
    with pytest.raises(sillage.Error):
        g(box(0, 1, 2, 3))


# ---- TPlane on closed-form trajectories ----

PI = math.pi
LIMACON_V = "(-sin(t) - 2*sin(2*t) + [-0.01,0.01], cos(t) + 2*cos(2*t) + [-0.01,0.01])"
LIMACON_P = "(cos(t) + 1 + cos(2*t) + [-0.005,0.005], sin(t) + sin(2*t) + [-0.005,0.005])"
CYCLOID_V = "(1 - 2*cos(t) + [-0.01,0.01], -2*sin(t) + [-0.01,0.01])"


def limacon_p(t):
    return np.array([np.cos(t) + 1 + np.cos(2 * t), np.sin(t) + np.sin(2 * t)])


def limacon_v(t):
    return np.array([-np.sin(t) - 2 * np.sin(2 * t), np.cos(t) + 2 * np.cos(2 * t)])


def cycloid_p(t):
    return np.array([t - 2 * np.sin(t), 2 * np.cos(t)])


def cycloid_v(t):
    return np.array([1 - 2 * np.cos(t), -2 * np.sin(t)])


def crossing_degree(v, t1, t2):
    """Sign of det(-v(t1) | v(t2)): the degree at a transversal crossing."""
    a, b = v(t1), v(t2)
    return 1 if -a[0] * b[1] + b[0] * a[1] > 0 else -1


def sampled_crossings(p, t0, tf, n):
    t = np.linspace(t0, tf, n + 1)
    xy = p(t)
    return self_crossings(t, xy[0], xy[1])


def detections_at(tp, t1, t2):
    return [i for i, l in enumerate(tp.detections()) if any(b.contains([t1, t2]) for b in l.boxes())]


def limacon():
    td = TDomain(0.3, 2 * PI - 0.3, 0.001)
    return td, TubeVector(td, LIMACON_V)


def test_tplane_limacon_one_proven_loop():
    td, v = limacon()
    tp = TPlane(td)
    assert tp.domain() == IntervalVector([td.t0_tf(), td.t0_tf()])
    assert tp.eps() == 0 and tp.nb_detections() == 0
    tp.compute_detections(0.02, v)
    assert tp.eps() == 0.02
    assert tp.nb_detections() == 1 and tp.nb_complete_detections() == 1
    l = tp.detections()[0]
    t1, t2 = 2 * PI / 3, 4 * PI / 3
    assert l.complete() and l.t_box().contains([t1, t2])
    assert l.nb_inner() > 0  # a robust crossing: its neighbourhood is proven feasible
    assert l.map_box().is_empty() and l.degree() is None and l.count() is None and not l.proven()
    assert tp.nb_proofs() == 0 and tp.proofs() == []
    arr = l.boxes_array()
    assert arr.shape == (len(l.boxes()), 2, 2)
    assert arr[0, 0, 0] == l.boxes()[0][0].lb() and arr[-1, 1, 1] == l.boxes()[-1][1].ub()
    assert tp.paving().count(PavingTag.Inner) == l.nb_inner()

    tp.compute_proofs(v)
    l = tp.detections()[0]
    assert l.degree() == crossing_degree(limacon_v, t1, t2) == 1  # det = 3√3/2 > 0
    assert l.proven() and l.proven_newton() and l.count() == 1
    assert (tp.nb_proofs(), tp.nb_newton_proofs()) == (1, 1)
    assert tp.proofs()[0].t_box() == l.t_box()
    assert "complete, degree 1, count 1" in repr(l)
    # From v, positions are relative to p(t0): the true crossing point (the
    # origin, from self_crossings of the sampled path) minus p(t0).
    cs = sampled_crossings(limacon_p, td.t0_tf().lb(), td.t0_tf().ub(), 20001)
    assert len(cs) == 1 and abs(cs[0].t1 - t1) < 1e-6 and abs(cs[0].t2 - t2) < 1e-6
    start = limacon_p(td.t0_tf().lb())
    assert l.map_box().contains([cs[0].x - start[0], cs[0].y - start[1]])
    assert l.map_box().max_diam() < 1.0


def test_tplane_prolate_cycloid_every_loop_detected_and_proven():
    loops = 5
    td = TDomain(0, 2 * PI * loops + PI, 0.01)
    v = TubeVector(td, CYCLOID_V)
    tp = TPlane(td)
    tp.compute_detections(0.05, v)
    tp.compute_proofs(v)
    # s* = 2 sin s*, the half-length of a loop in time.
    s = 2.0
    for _ in range(50):
        s -= (s - 2 * math.sin(s)) / (1 - 2 * math.cos(s))
    assert s == pytest.approx(1.895494267033981, abs=1e-12)
    assert tp.nb_complete_detections() == tp.nb_proofs() == tp.nb_newton_proofs() == loops
    truth = sampled_crossings(cycloid_p, 0, 2 * PI * loops + PI, 100001)
    assert len(truth) == loops
    start = cycloid_p(0.0)
    seen = []
    for m, c in enumerate(truth, start=1):
        assert c.t1 == pytest.approx(2 * PI * m - s, abs=1e-6) and c.t2 == pytest.approx(2 * PI * m + s, abs=1e-6)
        at = detections_at(tp, c.t1, c.t2)
        assert len(at) == 1
        l = tp.detections()[at[0]]
        assert l.complete() and l.count() == 1
        assert l.degree() == crossing_degree(cycloid_v, c.t1, c.t2)
        assert l.map_box().contains([c.x - start[0], c.y - start[1]])
        seen.append(at[0])
    assert seen == sorted(seen)  # chronological order
    lbs = [l.t_box()[0].lb() for l in tp.detections()]
    assert lbs == sorted(lbs)
    assert len(tp.proofs()) == loops


def test_tplane_from_positions_and_velocities():
    td, v = limacon()
    p = TubeVector(td, LIMACON_P)
    tv, tpw = TPlane(td), TPlane(td)
    tv.compute_detections(0.02, v)
    tpw.compute_detections(0.02, p, v)
    assert tpw.paving().count(PavingTag.Inner) == 0  # no Inner leaf with positions
    assert tpw.paving().outer_volume() < tv.paving().outer_volume()
    outer_v = tv.paving().outer()
    assert all(any(b.is_subset(a) for a in outer_v) for b in tpw.paving().outer())
    assert tpw.nb_complete_detections() == 1
    tpw.compute_proofs(p, v)
    l = tpw.detections()[0]
    assert any(b.contains([2 * PI / 3, 4 * PI / 3]) for b in l.boxes())
    assert l.degree() == 1 and l.proven_newton() and l.count() == 1
    assert l.map_box().contains([0.0, 0.0])  # absolute positions with p


def test_tplane_straight_line_and_standing_robot():
    td = TDomain(0, 100, 0.1)
    tp = TPlane(td.t0_tf())  # from an Interval
    v = TubeVector(td, "(1 + [-0.01,0.01], 0.5 + [-0.01,0.01])")
    tp.compute_detections(0.01, v)
    assert tp.nb_detections() == 0 and tp.paving().outer() == []
    assert tp.paving().nb_leaves() < 10  # the injectivity test (6.9) decides at once
    tp.compute_proofs(v)
    assert tp.nb_proofs() == 0
    # Standing still: loops on the diagonal, never complete, never proven.
    td = TDomain(0, 10, 0.1)
    still = TubeVector(td, IntervalVector([Interval(-0.01, 0.01), Interval(-0.01, 0.01)]))
    tp = TPlane(td)
    tp.compute_detections(0.5, still)
    tp.compute_proofs(still)
    assert tp.nb_detections() >= 1 and tp.nb_complete_detections() == 0 and tp.nb_proofs() == 0
    assert all(l.degree() is None and "partial" in repr(l) for l in tp.detections())


def test_proof_options_round_trip_and_switches():
    o = ProofOptions()
    assert (o.degree_edge_fraction, o.degree_max_evaluations, o.count_width_fraction, o.count_max_boxes,
            o.newton, o.newton_inflation, o.count) == (0.01, 1 << 20, 0.1, 1 << 16, True, 0.25, True)
    o.degree_edge_fraction, o.degree_max_evaluations = 0.05, 1000
    o.count_width_fraction, o.count_max_boxes = 0.2, 99
    o.newton, o.newton_inflation, o.count = False, 0.5, False
    assert (o.degree_edge_fraction, o.degree_max_evaluations, o.count_width_fraction, o.count_max_boxes,
            o.newton, o.newton_inflation, o.count) == (0.05, 1000, 0.2, 99, False, 0.5, False)
    td, v = limacon()
    tp = TPlane(td)
    tp.compute_detections(0.02, v)
    tp.compute_proofs(v, o)
    l = tp.detections()[0]
    assert l.proven() and not l.proven_newton() and l.count() is None
    tp.compute_proofs(v, options=ProofOptions())  # replaces the previous proofs
    assert tp.detections()[0].proven_newton() and tp.detections()[0].count() == 1


def test_zero_tests_on_a_loop_function_agree_with_tplane():
    td, v = limacon()
    tp = TPlane(td)
    tp.compute_detections(0.02, v)
    tp.compute_proofs(v)
    l = tp.detections()[0]
    f = LoopFunction(v)
    o = DegreeOptions()
    o.min_edge_length = 0.01 * tp.eps()
    d = topological_degree(l.boxes(), f, o)
    assert d.degree == l.degree() == 1
    assert count_zeros(l.boxes(), d.degree, f).count == 1
    # Newton on a box around the crossing, strictly above the diagonal.
    r = newton_test(box(2 * PI / 3 - 0.2, 2 * PI / 3 + 0.2, 4 * PI / 3 - 0.2, 4 * PI / 3 + 0.2), f)
    assert r.proven and r.box.contains([2 * PI / 3, 4 * PI / 3])
    # The same through Python callables wrapping the LoopFunction.
    assert topological_degree(l.boxes(), lambda t: f(t), o).degree == 1


def test_tplane_bad_input():
    for bad in (Interval(1, 1), Interval(0, math.inf), Interval.empty()):
        with pytest.raises(sillage.Error):
            TPlane(bad)
    td = TDomain(0, 5, 0.1)
    v = TubeVector(td, IntervalVector([Interval(1, 2), Interval(-1, 1)]))
    v3 = TubeVector(td, 3, Interval(1, 2))
    tp = TPlane(td)
    with pytest.raises(sillage.Error):
        tp.compute_proofs(v)  # before compute_detections
    for eps in (0.0, -1.0, math.nan):
        with pytest.raises(sillage.Error):
            tp.compute_detections(eps, v)
    with pytest.raises(sillage.DimensionError):
        tp.compute_detections(0.1, v3)
    with pytest.raises(sillage.DimensionError):
        tp.compute_detections(0.1, v, v3)
    shorter = TubeVector(TDomain(1, 5, 0.1), IntervalVector([Interval(1, 2), Interval(-1, 1)]))
    with pytest.raises(sillage.Error):
        tp.compute_detections(0.1, shorter)
    inner = TPlane(Interval(1, 4))
    inner.compute_detections(0.1, v)  # a larger tube domain is fine
    with pytest.raises(sillage.DimensionError):
        inner.compute_proofs(v3)
    bad = ProofOptions()
    bad.degree_edge_fraction = 0
    with pytest.raises(sillage.Error):
        inner.compute_proofs(v, bad)


# ---- matplotlib helpers ----

def test_plot_tplane_and_loops_map(tmp_path):
    from sillage.plot_loops import LOOP_COLOURS, loop_status, plot_loops_map, plot_tplane

    # The whole limaçon: its inner loop (complete, proven) and p(0) = p(2π), a
    # loop at the corner of the t-plane (partial).
    td = TDomain(0, 2 * PI, 0.001)
    v = TubeVector(td, LIMACON_V)
    tp = TPlane(td)
    tp.compute_detections(0.01, v)  # fine enough for Inner leaves
    tp.compute_proofs(v)
    statuses = [loop_status(l) for l in tp.detections()]
    assert statuses.count("proven") == 1 and statuses.count("partial") >= 1 and "unproven" not in statuses
    truth = sampled_crossings(limacon_p, 0, 2 * PI, 20001)
    assert len(truth) == 1

    fig, (ax1, ax2, ax3) = plt.subplots(1, 3)
    out = plot_tplane(ax1, tp, truth=truth)
    paving = tp.paving()
    assert len(out["inner"].get_paths()) == paving.count(PavingTag.Inner) > 0
    assert len(out["boundary"].get_paths()) == paving.count(PavingTag.Boundary)
    for status in ("proven", "partial"):
        n = sum(len(l.boxes()) for l in tp.detections() if loop_status(l) == status)
        assert len(out[status].get_paths()) == n
        assert tuple(out[status].get_facecolor()[0][:3]) == pytest.approx(
            matplotlib.colors.to_rgb(LOOP_COLOURS[status][0]))
    assert "unproven" not in out
    assert list(out["truth"].get_xdata()) == [truth[0].t1]
    assert list(out["diagonal"].get_xdata()) == [0, 2 * PI]
    # One collection per tag, per status, for the outlines and the markers:
    # independent of the number of boxes.
    assert "markers" in out  # the detections are far smaller than the t-plane
    assert len(ax1.collections) == 2 + 2 + 1 + 1
    assert len(ax1.patches) == 1  # the domain, in the outside colour
    assert ax1.get_xlim() == (0, 2 * PI)
    # Every Outside leaf on request; (t1, t2) pairs as truth.
    out_all = plot_tplane(ax2, tp, truth=[(c.t1, c.t2) for c in truth], show_outside=True, markers=None)
    assert len(out_all["outside"].get_paths()) == paving.count(PavingTag.Outside)
    assert "markers" not in out_all and "domain" not in out_all

    # The map: the true path (absolute) and the map boxes shifted by p(t0).
    t = np.linspace(0, 2 * PI, 4001)
    path = limacon_p(t).T
    m = plot_loops_map(ax3, tp, positions=path, times=t, crossings=truth, origin=limacon_p(0.0))
    (proven_box,) = m["proven"].get_paths()
    (x0, y0), (x1, y1) = proven_box.vertices.min(axis=0), proven_box.vertices.max(axis=0)
    assert x0 <= truth[0].x <= x1 and y0 <= truth[0].y <= y1
    assert len(m["partial"].get_paths()) == statuses.count("partial")
    # The path over [t1] and over [t2] of each detection (every [ti] holds samples).
    assert len(m["projections"].get_paths()) == 2 * tp.nb_detections()
    assert len(m["crossings"].get_xdata()) == 1
    no_partial = plot_loops_map(ax3, tp, positions=path, show_partial=False)
    assert "partial" not in no_partial and "projections" not in no_partial and "proven" in no_partial
    fig.savefig(tmp_path / "loops.png", dpi=60)
    assert (tmp_path / "loops.png").stat().st_size > 1000
    plt.close(fig)

    # A position tube instead of a path: positions relative to p(0), as the map boxes from v.
    fig, ax = plt.subplots()
    p = TubeVector(td, "(cos(t) - 1 + cos(2*t) + [-0.05,0.05], sin(t) + sin(2*t) + [-0.05,0.05])")
    m = plot_loops_map(ax, tp, positions=p)
    assert "tube" in m and len(m["proven"].get_paths()) == 1
    assert len(ax.collections) == 1 + 2 + 1 + 1  # the tube, its gates 0 and N, proven, partial
    with pytest.raises(ValueError):
        plot_loops_map(ax, tp, positions=np.zeros((4, 3)))
    with pytest.raises(ValueError):
        plot_loops_map(ax, tp, times=[0, 1])
    fig.savefig(tmp_path / "map.png", dpi=60)
    plt.close(fig)


# ---- SVG figures ----

def svg_elements(svg, tag, cls):
    root = ET.fromstring(svg.encode())
    return [e for e in root.iter("{http://www.w3.org/2000/svg}" + tag) if e.get("class") == cls]


def test_svg_tplane_and_loops_map_figures(tmp_path):
    td, v = limacon()
    tp = TPlane(td)
    tp.compute_detections(0.02, v)
    tp.compute_proofs(v)
    (loop,) = tp.detections()
    assert sillage.loop_status(loop) == sillage.LoopStatus.Proven
    t = np.linspace(0.3, 2 * PI - 0.3, 2001)
    x, y = limacon_p(t)
    crossings = self_crossings(t, x, y)

    fig = sillage.tplane_figure(tp, crossings, "limaçon")
    svg = fig.svg()
    assert len(svg_elements(svg, "polygon", "proven")) == 1
    assert len(svg_elements(svg, "polyline", "diagonal")) == 1
    assert len(svg_elements(svg, "circle", "crossing")) == 1
    zoom = sillage.tplane_figure(tp, view=loop.t_box(), options=sillage.TPlaneFigureOptions())
    paving = tp.paving()
    leaves = paving.count(PavingTag.Inner) + paving.count(PavingTag.Boundary)
    drawn = svg_elements(zoom.svg(), "rect", "inner") + svg_elements(zoom.svg(), "rect", "boundary")
    assert 0 < len(drawn) <= leaves

    path = [[a - x[0], b - y[0]] for a, b in zip(x, y)]  # map boxes from v are relative to p(t0)
    options = sillage.LoopsMapOptions()
    options.show_partial = False
    m = sillage.loops_map_figure(tp, path=path, path_times=list(t), title="map", options=options)
    svg = m.svg()
    assert len(svg_elements(svg, "rect", "proven")) == 1
    assert len(svg_elements(svg, "polyline", "path")) == 1
    assert len(svg_elements(svg, "polyline", "proven-projection")) == 2
    m.save(str(tmp_path / "map.svg"))
    assert (tmp_path / "map.svg").stat().st_size > 0
    with pytest.raises(sillage.Error):
        sillage.loops_map_figure(tp, path=path, path_times=list(t[::-1]))
