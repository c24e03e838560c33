"""Loops in the t-plane from Python (thesis ch. 6): the zero tests on analytic
maps of known degree, self_crossings on closed-form curves, LoopFunction on
hand-computed tubes, TPlane on a limaçon and a prolate cycloid whose crossings
are known in closed form, bad input, and the matplotlib helpers (Agg)."""
import gc
import math

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import sillage  # noqa: E402
from sillage import (CountOptions, DegreeOptions, Interval, IntervalMatrix, IntervalVector,  # noqa: E402
                     LoopFunction, NewtonOptions, PavingTag, ProofOptions, TDomain, TPlane, Tube, TubeVector,
                     count_zeros, newton_test, self_crossings, sqr, topological_degree)


def box(a, b, c, d):
    return IntervalVector([Interval(a, b), Interval(c, d)])


def shifted_identity(cx, cy):
    """(x - cx, y - cy): one zero at (cx, cy), Jacobian the identity."""
    return lambda t: IntervalVector([t[0] - cx, t[1] - cy])


def z2(t):  # z^2, a zero of multiplicity 2 at 0
    x, y = t[0], t[1]
    return [sqr(x) - sqr(y), 2 * x * y]


def z3(t):  # z^3, multiplicity 3
    x, y = t[0], t[1]
    return [x * (sqr(x) - 3 * sqr(y)), y * (3 * sqr(x) - sqr(y))]


def conj_z2(t):  # conj(z)^2: orientation reversed, degree -2
    x, y = t[0], t[1]
    return [sqr(x) - sqr(y), -2 * x * y]


def identity_jacobian(t):
    return IntervalMatrix.identity(2)


def degree(boxes, f, options=None):
    return (topological_degree(boxes, f) if options is None else topological_degree(boxes, f, options)).degree


# ---- topological_degree ----

def test_identity_degree_is_one_without_refinement():
    r = topological_degree([box(-1, 1, -1, 1)], lambda t: t)
    assert isinstance(r, sillage.DegreeResult)
    assert r.degree == 1 and r.proves_zero()
    # Every whole edge excludes 0: four evaluations, four pieces.
    assert (r.nb_pieces, r.nb_evaluations, r.nb_unresolved) == (4, 4, 0)
    assert "degree 1" in repr(r)


def test_degrees_of_analytic_maps():
    assert degree([box(-1, 1, -2, 0.5)], lambda t: [t[0], -t[1]]) == -1  # a reflection
    assert degree([box(-1, 1, -1, 1)], z2) == 2
    assert degree([box(-1, 2, -0.5, 1)], z3) == 3
    assert degree([box(-1, 1, -1, 1)], conj_z2) == -2
    # The callable may return a list, a tuple, an (n, 2) array or an IntervalVector.
    assert degree([box(-1, 1, -1, 1)], lambda t: (t[0], t[1])) == 1
    assert degree([box(-1, 1, -1, 1)], lambda t: t.to_numpy()) == 1
    # Boxes as lists of pairs.
    assert degree([[[-1, 1], [-1, 1]]], z2) == 2


def test_region_without_the_zero_has_degree_zero():
    r = topological_degree([box(1, 2, -1, 1)], lambda t: t)
    assert r.degree == 0 and not r.proves_zero()
    assert degree([box(-1, 1, -1, 1)], shifted_identity(5, -3)) == 0
    assert degree([box(0.5, 2, -1, 1)], z2) == 0
    assert degree([box(0.5, 2, -1, 1)], z3) == 0


def test_union_with_a_hole_and_its_contours():
    ring = [box(2 * i - 1, 2 * i + 1, 2 * j - 1, 2 * j + 1) for i in (-1, 0, 1) for j in (-1, 0, 1) if (i, j) != (0, 0)]
    f = shifted_identity(0, 0)  # the zero is in the hole
    assert degree(ring, f) == 0
    assert degree(ring, shifted_identity(2, 0.5)) == 1  # in the body of the ring
    loops = sillage.contour(ring)
    assert [l.is_hole for l in loops] == [False, True]
    assert topological_degree([loops[0]], f).degree == 1   # the outer loop, counter-clockwise
    assert topological_degree([loops[1]], f).degree == -1  # the hole, clockwise
    assert topological_degree(loops, f).degree == 0
    assert topological_degree([loops[1]], shifted_identity(2, 0.5)).degree == 0


def test_l_shape_and_pinched_unions():
    l_shape = [box(0, 2, 0, 1), box(0, 1, 1, 2)]
    assert degree(l_shape, shifted_identity(0.5, 1.5)) == 1
    assert degree(l_shape, shifted_identity(1.5, 0.25)) == 1
    assert degree(l_shape, shifted_identity(1.5, 1.5)) == 0  # in the notch
    pinch = [box(-1, 0, -1, 0), box(0, 1, 0, 1)]
    # Zeros (±1/2, ±1/2): two inside, det J = 4xy > 0 at both.
    assert degree(pinch, lambda t: [(t[0] - 0.5) * (t[0] + 0.5), (t[1] - 0.5) * (t[1] + 0.5)]) == 2


def test_refinement_and_its_limits():
    # (x + y, y - x): each whole edge contains 0 in one component, each half excludes it.
    rot = lambda t: [t[0] + t[1], t[1] - t[0]]  # noqa: E731
    r = topological_degree([box(-1, 1, -1, 1)], rot)
    assert (r.degree, r.nb_pieces, r.nb_evaluations) == (1, 8, 12)
    o = DegreeOptions()
    o.min_edge_length = 3  # no room to bisect edges of length 2
    coarse = topological_degree([box(-1, 1, -1, 1)], rot, o)
    assert coarse.degree is None and not coarse.proves_zero()
    assert (coarse.nb_unresolved, coarse.nb_evaluations) == (4, 4)
    # A zero on the boundary: undetermined, a logarithmic number of evaluations.
    o = DegreeOptions()
    o.min_edge_length = 1e-6
    on_edge = topological_degree([box(0, 1, -1, 1)], lambda t: t, o)
    assert on_edge.degree is None and on_edge.nb_unresolved >= 1
    assert 20 < on_edge.nb_evaluations < 200
    # The evaluation budget is respected.
    o = DegreeOptions()
    o.max_evaluations = 10
    capped = topological_degree([box(0, 1, -1, 1)], lambda t: t, o)
    assert capped.degree is None and capped.nb_evaluations == 10
    o.max_evaluations = 12
    assert topological_degree([box(-1, 1, -1, 1)], rot, o).degree == 1
    o.max_evaluations = 11
    assert topological_degree([box(-1, 1, -1, 1)], rot, o).degree is None


def test_degree_options_round_trip():
    o = DegreeOptions()
    assert o.min_edge_length == 1e-9 and o.max_evaluations == 1 << 20
    o.min_edge_length, o.max_evaluations = 0.5, 77
    assert (o.min_edge_length, o.max_evaluations) == (0.5, 77)


def test_degree_bad_input():
    with pytest.raises(sillage.Error):
        topological_degree([], lambda t: t)
    o = DegreeOptions()
    o.min_edge_length = 0
    with pytest.raises(sillage.Error):
        topological_degree([box(-1, 1, -1, 1)], lambda t: t, o)
    # A wrong value from the callable is an Error, its own exceptions pass through.
    with pytest.raises(sillage.DimensionError):
        topological_degree([box(-1, 1, -1, 1)], lambda t: [t[0], t[1], t[0]])
    with pytest.raises(sillage.Error):
        topological_degree([box(-1, 1, -1, 1)], lambda t: "abc")
    with pytest.raises(ZeroDivisionError):
        topological_degree([box(-1, 1, -1, 1)], lambda t: 1 / 0)
    assert issubclass(sillage.DimensionError, sillage.Error)


# ---- newton_test and count_zeros ----

def test_newton_proves_a_simple_zero():
    # (x^2 + y^2 - 1, x - y): the zero (1/√2, 1/√2).
    f = lambda t: [sqr(t[0]) + sqr(t[1]) - 1, t[0] - t[1]]  # noqa: E731
    j = lambda t: IntervalMatrix([[2 * t[0], 2 * t[1]], [1, -1]])  # noqa: E731
    r = newton_test(box(0.6, 0.8, 0.6, 0.8), f, j)
    assert isinstance(r, sillage.NewtonResult)
    assert r.proven and "proven" in repr(r)
    z = math.sqrt(0.5)
    assert r.box.contains([z, z])
    assert r.box.is_subset(box(0.6, 0.8, 0.6, 0.8))
    assert r.box.max_diam() < 1e-6
    assert r.nb_iterations >= 1
    # The Jacobian may also be a list of rows.
    assert newton_test(box(0.6, 0.8, 0.6, 0.8), f, lambda t: [[2 * t[0], 2 * t[1]], [1, -1]]).proven


def test_newton_contracts_then_proves():
    # (x + y^2/2 - 0.3, y + x^2/2 - 0.2), det J = 1 - xy > 0 on [-0.9, 0.9]^2.
    f = lambda t: [t[0] + 0.5 * sqr(t[1]) - 0.3, t[1] + 0.5 * sqr(t[0]) - 0.2]  # noqa: E731
    j = lambda t: [[1, t[1]], [t[0], 1]]  # noqa: E731
    r = newton_test(box(-0.9, 0.9, -0.9, 0.9), f, j)
    assert r.proven and r.nb_iterations > 1
    x = y = 0.0
    for _ in range(50):  # point Newton
        f1, f2, det = x + 0.5 * y * y - 0.3, y + 0.5 * x * x - 0.2, 1 - x * y
        x, y = x - (f1 - y * f2) / det, y - (f2 - x * f1) / det
    assert r.box.contains([x, y]) and r.box.max_diam() < 1e-3
    o = NewtonOptions()
    assert o.max_iterations == 20
    o.max_iterations = 1
    assert newton_test(box(-0.9, 0.9, -0.9, 0.9), f, j, o).nb_iterations <= 1


def test_newton_fails_on_a_double_zero_and_empties_without_zero():
    # (x^2, y): det J = 2x vanishes at the double zero.
    r = newton_test(box(-1, 1, -1, 1), lambda t: [sqr(t[0]), t[1]], lambda t: [[2 * t[0], 0], [0, 1]])
    assert not r.proven
    assert not r.box.is_empty() and r.box.contains([0, 0])
    far = newton_test(box(-1, 1, -1, 1), shifted_identity(5, 0), identity_jacobian)
    assert not far.proven and far.box.is_empty()
    with pytest.raises(sillage.Error):
        newton_test(box(-1, 1, -1, 1), lambda t: t, lambda t: 5)
    with pytest.raises(sillage.DimensionError):
        newton_test(IntervalVector([[0, 1], [0, 1], [0, 1]]), lambda t: t, identity_jacobian)


def test_count_zeros():
    one = count_zeros([box(-1, 1, -1, 1)], 1, lambda t: t, identity_jacobian)
    assert isinstance(one, sillage.CountResult)
    assert (one.count, one.nb_boxes) == (1, 1)
    # z^2 - 1: zeros ±1, det J = 4|z|^2 > 0 where f may vanish.
    f = lambda t: [sqr(t[0]) - sqr(t[1]) - 1, 2 * t[0] * t[1]]  # noqa: E731
    j = lambda t: [[2 * t[0], -2 * t[1]], [2 * t[1], 2 * t[0]]]  # noqa: E731
    omega = [box(-2, 2, -1, 1)]
    assert degree(omega, f) == 2
    two = count_zeros(omega, 2, f, j)
    assert two.count == 2 and two.nb_boxes > 1
    # (x^2 - 1, y): degree 0 from zeros of opposite orientations, not countable; each half is.
    g = lambda t: [sqr(t[0]) - 1, t[1]]  # noqa: E731
    jg = lambda t: [[2 * t[0], 0], [0, 1]]  # noqa: E731
    assert degree(omega, g) == 0
    assert count_zeros(omega, 0, g, jg).count is None
    assert count_zeros([box(0, 2, -1, 1)], 1, g, jg).count == 1
    assert count_zeros([box(-2, 0, -1, 1)], -1, g, jg).count == 1
    # No zero: a count of 0; a contradicting degree: no count.
    assert count_zeros([box(1, 2, 1, 2)], 0, lambda t: t, identity_jacobian).count == 0
    assert count_zeros([box(-1, 1, -1, 1)], -1, lambda t: t, identity_jacobian).count is None


def test_count_zeros_options_and_bad_input():
    jz2 = lambda t: [[2 * t[0], -2 * t[1]], [2 * t[1], 2 * t[0]]]  # noqa: E731
    o = CountOptions()
    assert o.min_width == 1e-9 and o.max_boxes == 1 << 16
    o.min_width = 1e-3  # z^2 is singular at its zero: no count
    assert count_zeros([box(-1, 1, -1, 1)], 2, z2, jz2, o).count is None
    o.min_width, o.max_boxes = 1e-12, 16
    capped = count_zeros([box(-1, 1, -1, 1)], 2, z2, jz2, o)
    assert capped.count is None and capped.nb_boxes <= 16
    with pytest.raises(sillage.Error):
        count_zeros([], 0, lambda t: t, identity_jacobian)
    o.min_width = 0
    with pytest.raises(sillage.Error):
        count_zeros([box(-1, 1, -1, 1)], 1, lambda t: t, identity_jacobian, o)


# ---- self_crossings ----

def test_self_crossings_of_a_polyline():
    # (0,0) -> (2,2) -> (2,0) -> (0,2): segments 0 and 2 cross at (1, 1), halfway along both.
    cs = self_crossings([0, 1, 2, 3], [0, 2, 2, 0], [0, 2, 0, 2])
    assert len(cs) == 1
    c = cs[0]
    assert (c.t1, c.t2, c.x, c.y, c.segment1, c.segment2) == (0.5, 2.5, 1.0, 1.0, 0, 2)
    assert "t1=0.5" in repr(c)
    # A vertex on a segment is a touch, not a crossing; a straight line has none.
    assert self_crossings([0, 1, 2, 3, 4, 5], [0, 4, 4, 2, 2, 1], [0, 0, 2, 2, 0, 2]) == []
    assert self_crossings(list(range(100)), list(range(100)), [0.5 * k for k in range(100)]) == []
    assert self_crossings([], [], []) == []


def test_self_crossings_of_the_limacon_inner_loop():
    # r = 1/2 + cos θ vanishes at θ = 2π/3 and 4π/3: the inner loop closes at the origin.
    n = 999  # odd: no sample exactly at the crossing
    th = np.linspace(0, 2 * math.pi, n + 1)
    r = 0.5 + np.cos(th)
    cs = self_crossings(th, r * np.cos(th), r * np.sin(th))  # numpy arrays are accepted
    assert len(cs) == 1
    h = 2 * math.pi / n
    assert abs(cs[0].t1 - 2 * math.pi / 3) < 2 * h * h
    assert abs(cs[0].t2 - 4 * math.pi / 3) < 2 * h * h
    assert math.hypot(cs[0].x, cs[0].y) < h * h


def test_self_crossings_bad_input():
    with pytest.raises(sillage.DimensionError):
        self_crossings([0, 1], [0, 1], [0])
    with pytest.raises(sillage.Error):
        self_crossings([0, 2, 1], [0, 1, 2], [0, 1, 2])  # times not increasing
    with pytest.raises(sillage.Error):
        self_crossings([0, 1, 2], [0, math.nan, 2], [0, 1, 2])
    with pytest.raises(sillage.Error, match=r"t\[4\]"):
        self_crossings([0, 1, 2, 2.5, 2.5], [0, 1, 2, 3, 4], [0, 1, 2, 3, 4])


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
