"""The zero tests of thesis ch. 6 from Python: topological_degree on analytic
maps of known degree (holes, pinches, refinement), newton_test, count_zeros,
and self_crossings on closed-form curves, with their bad input."""
import math

import numpy as np
import pytest

import sillage
from sillage import (CountOptions, DegreeOptions, Interval, IntervalMatrix, IntervalVector, NewtonOptions,
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
