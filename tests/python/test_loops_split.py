"""split_region and the pieces of TPlane detections (component_split.h): the
twins of tests/cpp/loops/test_component_split.cpp."""
import math
import random

import pytest

import sillage as sl


def grid(x0, x1, y0, y1, n, m):
    return [sl.IntervalVector([[x0 + (x1 - x0) * i / n, x0 + (x1 - x0) * (i + 1) / n],
                               [y0 + (y1 - y0) * j / m, y0 + (y1 - y0) * (j + 1) / m]])
            for i in range(n) for j in range(m)]


def holds(boxes, x, y):
    return any(b[0].contains(x) and b[1].contains(y) for b in boxes)


def two_zeros(a):
    return lambda b: [sl.sqr(b[0]) - a * a, b[1]]


def two_zeros_jacobian(b):
    return [[2 * b[0], sl.Interval(0)], [sl.Interval(0), sl.Interval(1)]]


def three_zeros(a):
    return lambda b: [b[0] * (sl.sqr(b[0]) - a * a), b[1]]


def three_zeros_jacobian(a):
    return lambda b: [[3 * sl.sqr(b[0]) - a * a, sl.Interval(0)], [sl.Interval(0), sl.Interval(1)]]


def test_two_zeros_of_opposite_orientations():
    cells = grid(-1, 1, -0.5, 0.5, 4, 2)
    assert sl.topological_degree(cells, two_zeros(0.3)).degree == 0
    r = sl.split_region(cells, two_zeros(0.3), two_zeros_jacobian)
    assert [p.degree for p in r.pieces] == [-1, 1]
    assert [p.count for p in r.pieces] == [1, 1]
    assert holds(r.pieces[0].boxes, -0.3, 0) and holds(r.pieces[1].boxes, 0.3, 0)
    assert r.degree() == 0 and r.count() == 2 and r.nb_proven() == 2
    assert "SplitResult" in repr(r) and "SplitPiece" in repr(r.pieces[0])


def test_three_zeros_and_a_zero_on_a_cut():
    for a, cells in ((0.4, grid(-1, 1, -0.25, 0.25, 8, 2)), (0.25, grid(-1, 1, -0.5, 0.5, 8, 4))):
        r = sl.split_region(cells, three_zeros(a), three_zeros_jacobian(a))
        assert r.degree() == 1 and r.count() == 3
        for x in (-a, 0.0, a):
            assert sum(holds(p.boxes, x, 0) for p in r.pieces) == 1


def test_no_zero_counts_zero():
    r = sl.split_region(grid(-1, 1, -0.5, 0.5, 4, 2), lambda b: [sl.sqr(b[0]) + 0.01, b[1]], two_zeros_jacobian)
    assert r.pieces == [] and r.count() == 0


def test_random_maps_pieces_hold_their_zeros():
    rng = random.Random(17)
    for trial in range(12):
        zeros = [(rng.uniform(-0.9, 0.9), rng.uniform(-0.9, 0.9), rng.random() < 0.5) for _ in range(1 + trial % 3)]

        def f(b, zeros=zeros):
            re, im = sl.Interval(1), sl.Interval(0)
            for zx, zy, conj in zeros:
                u, w = b[0] - zx, (b[1] - zy) * (-1 if conj else 1)
                re, im = re * u - im * w, re * w + im * u
            return [re, im]

        cells = grid(-1, 1, -1, 1, 4, 4)
        o = sl.SplitOptions()
        o.count = False
        o.max_levels = 5
        r = sl.split_region(cells, f, None, o)
        whole = sl.topological_degree(cells, f).degree
        if whole is not None and r.degree() is not None:
            assert whole == r.degree()  # a split never changes the total degree
        for p in r.pieces:
            if p.degree is not None:
                assert p.degree == sum((-1 if c else 1) for x, y, c in zeros if holds(p.boxes, x, y))


def test_bad_input():
    cells = grid(-1, 1, -0.5, 0.5, 4, 2)
    with pytest.raises(sl.Error):
        sl.split_region([], two_zeros(0.3), two_zeros_jacobian)
    with pytest.raises(sl.Error):
        sl.split_region(cells, two_zeros(0.3))  # counting needs a jacobian
    o = sl.SplitOptions()
    o.max_levels = 0
    with pytest.raises(sl.Error):
        sl.split_region(cells, two_zeros(0.3), two_zeros_jacobian, o)
    o = sl.ProofOptions()
    o.split_max_levels = 0
    td = sl.TDomain(0.0, 10.0, 0.1)
    tp = sl.TPlane(td)
    v = sl.TubeVector(td, "(1 + [-0.01,0.01], [-0.01,0.01])")
    tp.compute_detections(0.5, v)
    with pytest.raises(sl.Error):
        tp.compute_proofs(v, o)


def test_tplane_pieces_on_a_survey():
    """Every proven piece holds a true crossing; degrees of pieces add up; proofs() lists the pieces."""
    T = 3600.0
    td = sl.TDomain(0.0, T, 0.5)
    w1, w2 = "(2*pi*7/3600)", "(2*pi*8.3/3600)"
    v = sl.TubeVector(td, f"(120*{w1}*cos({w1}*t) + [-0.01,0.01], 120*{w2}*cos({w2}*t + 0.4) + [-0.01,0.01])")
    tp = sl.TPlane(td)
    tp.compute_detections(T / 1000, v)
    tp.compute_proofs(v)
    W1, W2 = 2 * math.pi * 7 / 3600, 2 * math.pi * 8.3 / 3600
    ts = [k * 0.05 for k in range(int(T / 0.05) + 1)]
    crossings = sl.self_crossings(ts, [120 * math.sin(W1 * t) for t in ts], [120 * math.sin(W2 * t + 0.4) for t in ts])
    for loop in tp.detections():
        degrees = [p.degree() for p in loop.pieces()]
        if degrees and None not in degrees and loop.degree() is not None:
            assert sum(degrees) == loop.degree()
        for p in loop.pieces():
            assert p.complete() and p.pieces() == []
            if p.proven():
                assert any(holds(p.boxes(), c.t1, c.t2) for c in crossings)
    # Here one detection of degree 0 holds two crossings of opposite orientations: split, both proven.
    split = [l for l in tp.detections() if l.nb_proven_pieces() >= 2 and l.degree() == 0]
    assert split and split[0].count() == 2 and split[0].proven_split() and not split[0].proven()
    assert all(p.proven() for p in tp.proofs())
    assert len(tp.proofs()) >= tp.nb_proofs()
