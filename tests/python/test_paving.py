"""Set inversion from Python: sivia with callables, Functions, separators and
contractors, kernel_sivia, and the Paving queries (components, contours)."""
import math
import random

import pytest
import sillage
from sillage import Interval, IntervalVector, PavingTag


def box(a, b, c, d):
    return IntervalVector([Interval(a, b), Interval(c, d)])


def disk(x):
    """Inclusion function of x0^2 + x1^2 as a Python callable (returns an Interval)."""
    return x[0] * x[0] + x[1] * x[1]


def test_sivia_with_a_python_callable():
    p = sillage.sivia(box(-2, 2, -2, 2), disk, Interval(0, 1), 0.05)
    assert p.dim() == 2
    assert p.nb_leaves() == p.count(PavingTag.Inner) + p.count(PavingTag.Boundary) + p.count(PavingTag.Outside)
    assert len(p.inner()) == p.count(PavingTag.Inner) > 0
    assert len(p.outer()) == len(p.inner()) + len(p.boundary())
    assert p.volume(PavingTag.Inner) < math.pi < p.outer_volume()
    assert p.tag_at([0.0, 0.0]) == PavingTag.Inner
    assert p.tag_at([1.9, 1.9]) == PavingTag.Outside
    assert p.tag_at([5.0, 0.0]) is None
    for b in p.boundary():
        assert max(b[0].diam(), b[1].diam()) < 0.05
    rng = random.Random(1)
    for _ in range(2000):
        x, y = rng.uniform(-2, 2), rng.uniform(-2, 2)
        t = p.tag_at([x, y])
        if x * x + y * y < 0.999:
            assert t != PavingTag.Outside
        if x * x + y * y > 1.001:
            assert t != PavingTag.Inner


def test_exact_1d_tree_and_node_access():
    p = sillage.sivia(IntervalVector([Interval(0, 1)]), lambda x: x, IntervalVector([Interval(0.25, 0.75)]), 0.25)
    leaves = [(p.node_box(i)[0].lb(), p.node_box(i)[0].ub(), p.tag(i)) for i in range(p.nb_nodes()) if p.is_leaf(i)]
    assert leaves == [(0, 0.125, PavingTag.Outside), (0.125, 0.25, PavingTag.Boundary), (0.25, 0.5, PavingTag.Inner),
                      (0.5, 0.75, PavingTag.Inner), (0.75, 0.875, PavingTag.Boundary), (0.875, 1, PavingTag.Outside)]
    assert p.node_box(p.left(0))[0].ub() == 0.5
    assert p.hull()[0].lb() == 0.125 and p.hull()[0].ub() == 0.875
    arr = p.boxes_array(PavingTag.Inner)
    assert arr.shape == (2, 1, 2)
    assert arr[0, 0, 0] == 0.25 and arr[1, 0, 1] == 0.75
    with pytest.raises(sillage.Error):
        p.tag(0)  # internal node


def test_components_and_contours():
    ring = sillage.sivia(box(-2, 2, -2, 2), disk, Interval(0.5, 2.0), 0.05)
    comps = ring.components()
    assert len(comps) == 1
    c = comps[0]
    assert len(c) == len(ring.outer())
    assert c.count(PavingTag.Inner) + c.count(PavingTag.Boundary) == len(c)
    loops = c.contour()
    assert [loop.is_hole for loop in loops] == [False, True]
    for loop in loops:
        v = loop.vertices()
        for k, e in enumerate(loop.edges):
            assert e.a == v[k] and e.b == v[(k + 1) % len(v)]
    # Hand-made contours: two boxes touching at a corner are one component, one loop.
    boxes = [box(0, 1, 0, 1), box(1, 2, 1, 2)]
    assert len(sillage.connected_components(boxes)) == 1
    (loop,) = sillage.contour(boxes)
    assert loop.vertices() == [(0, 0), (1, 0), (1, 1), (2, 1), (2, 2), (1, 2), (1, 1), (0, 1)]
    assert loop.edges[0].box()[1].diam() == 0


def two_beacons():
    f = sillage.Function(["x1", "x2"], "(sqrt((x1 - 8)^2 + (x2 - 5)^2), sqrt((x1 - 7)^2 + (x2 - 2.2)^2))")
    return f, box(9.03, 9.83, 6.94, 7.74), box(-10, 10, -10, 10)


def test_sivia_with_a_function_is_deterministic():
    f, y, x0 = two_beacons()
    p = sillage.sivia(x0, f, y, 0.05)
    q = sillage.sivia(x0, f, y, 0.05)
    assert p == q
    assert p.tag_at([0.0, 0.0]) != PavingTag.Outside
    assert len(p.components()) >= 2
    # The same inclusion function through Python gives the same paving.
    r = sillage.sivia(x0, lambda x: f.eval_vector(x), y, 0.05)
    assert r == p


def test_sivia_with_separators_and_contractors():
    f, y, x0 = two_beacons()
    sep = sillage.SepFunction(f, y)
    p = sillage.sivia(x0, sep, 0.05)
    assert p.count(PavingTag.Inner) > 0 and p.count(PavingTag.Outside) > 0
    assert p.tag_at([0.0, 0.0]) != PavingTag.Outside
    plain = sillage.sivia(x0, f, y, 0.05)
    tc = sillage.sivia(x0, f, y, sillage.CtcFunction(f, y), 0.05)  # thesis Fig. 2.13
    assert tc.nb_leaves() < plain.nb_leaves()
    assert tc.outer_volume() < plain.outer_volume()
    assert tc.tag_at([0.0, 0.0]) != PavingTag.Outside
    c = sillage.sivia(x0, sillage.CtcFunction(f, y), 0.05)
    assert c.count(PavingTag.Inner) == 0
    assert c.tag_at([0.0, 0.0]) == PavingTag.Boundary


def test_sivia_with_a_python_contractor():
    class HalfPlane(sillage.Ctc):  # x0 <= 0.5
        def __init__(self):
            sillage.Ctc.__init__(self, 2)

        def contract(self, x):
            return IntervalVector([x[0] & Interval(-1e300, 0.5), x[1]])

    p = sillage.sivia(box(0, 1, 0, 1), HalfPlane(), 0.1)
    out = p.outside()
    assert len(out) == 1 and out[0][0].lb() == 0.5
    assert p.hull()[0].ub() == 0.5


def test_kernel_sivia():
    def f(x):  # [f](x) = x^2 - 1 + [-0.1, 0.1]
        s = x[0] * x[0]
        return s - Interval(1.1), s - Interval(0.9)

    p = sillage.kernel_sivia(IntervalVector([Interval(0, 2)]), f, 0.001)
    kernel = math.sqrt(1.1) - math.sqrt(0.9)
    assert p.volume(PavingTag.Inner) < kernel < p.outer_volume()
    assert p.tag_at([1.0]) == PavingTag.Inner
    lo = sillage.Function(["x"], "x^2 - 1.1")
    hi = sillage.Function(["x"], "x^2 - 0.9")
    q = sillage.kernel_sivia(IntervalVector([Interval(-2, 2)]), lo, hi, 0.001)
    assert len(q.components()) == 2
    assert q.volume(PavingTag.Inner) < 2 * kernel < q.outer_volume()


def test_invalid_input_raises():
    with pytest.raises(sillage.Error, match="eps"):
        sillage.sivia(box(0, 1, 0, 1), disk, Interval(0, 1), 0.0)
    with pytest.raises(ValueError):
        sillage.sivia(box(0, 1, 0, 1), disk, Interval(0, 1), math.nan)
    with pytest.raises(sillage.Error, match="dimension"):
        sillage.sivia(box(0, 1, 0, 1), disk, box(0, 1, 0, 1), 0.1)
    f, y, _ = two_beacons()
    with pytest.raises(sillage.Error):
        sillage.sivia(IntervalVector([Interval(0, 1)]), f, y, 0.1)
    with pytest.raises(sillage.Error, match="bounded"):
        sillage.sivia(IntervalVector([Interval(0, 1), Interval(0, math.inf)]), disk, Interval(0, 1), 0.1)
    with pytest.raises(ZeroDivisionError):
        sillage.sivia(box(0, 1, 0, 1), lambda x: 1 / 0, Interval(0, 1), 0.1)
    with pytest.raises(sillage.Error):
        sillage.kernel_sivia(box(0, 1, 0, 1), lambda x: (x,), 0.1)


def test_sivia_options_sequential_gives_the_same_paving():
    opts = sillage.SiviaOptions()
    assert opts.parallel is True and repr(opts).startswith("SiviaOptions(parallel=True, budget=Budget(")
    seq = sillage.SiviaOptions(parallel=False)
    assert seq.parallel is False
    opts.parallel = False
    assert not opts.parallel
    f, y, x0 = two_beacons()
    p = sillage.sivia(x0, f, y, 0.05)
    assert sillage.sivia(x0, f, y, 0.05, seq) == p
    assert sillage.sivia(x0, f, y, 0.05, options=seq) == p
    assert sillage.sivia(x0, f, y, 0.05, sillage.SiviaOptions(True)) == p
    ctc = sillage.CtcFunction(f, y)
    assert sillage.sivia(x0, f, y, ctc, 0.05, options=seq) == sillage.sivia(x0, f, y, ctc, 0.05)
    sep = sillage.SepFunction(f, y)
    assert sillage.sivia(x0, sep, 0.05, options=seq) == sillage.sivia(x0, sep, 0.05)
    assert sillage.sivia(x0, ctc, 0.05, options=seq) == sillage.sivia(x0, ctc, 0.05)
    g = sillage.Function(["x"], "x^2 - 2")
    x1 = IntervalVector([Interval(-3, 3)])
    assert sillage.sivia(x1, g, Interval(0, 1), 0.01, seq) == sillage.sivia(x1, g, Interval(0, 1), 0.01)
    lo, hi = sillage.Function(["x"], "x^2 - 1.1"), sillage.Function(["x"], "x^2 - 0.9")
    assert sillage.kernel_sivia(x1, lo, hi, 0.001, seq) == sillage.kernel_sivia(x1, lo, hi, 0.001)
    # Python callables always run sequentially; the options are accepted for uniformity.
    assert sillage.sivia(x0, lambda b: f.eval_vector(b), y, 0.05, options=sillage.SiviaOptions(True)) == p
    q = sillage.kernel_sivia(x1, lambda b: (lo.eval_vector(b), hi.eval_vector(b)), 0.001, seq)
    assert q == sillage.kernel_sivia(x1, lo, hi, 0.001)
