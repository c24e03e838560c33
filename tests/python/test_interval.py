"""The Python interval layer: Interval, IntervalVector, IntervalMatrix, functions, bwd_*."""
import copy
import math
import pickle
import random

import numpy as np
import pytest

import sillage
from sillage import Interval, IntervalMatrix, IntervalVector

INF = math.inf


# ---- Interval ---------------------------------------------------------------------


def test_constructors_and_statics():
    assert Interval().is_all_reals()
    assert Interval(2) == Interval(2, 2)
    assert Interval(1, 3).lb() == 1 and Interval(1, 3).ub() == 3
    assert Interval(Interval(1, 2)) == Interval(1, 2)
    assert Interval.empty().is_empty()
    assert Interval.all_reals() == Interval(-INF, INF)
    pi = Interval.pi()
    assert pi.lb() < math.pi + 1e-15 and pi.contains(math.pi) and pi.diam() < 1e-15


def test_numeric_functions():
    x = Interval(-1, 3)
    assert (x.lb(), x.ub(), x.mid(), x.diam(), x.width(), x.rad(), x.mag(), x.mig(), x.volume()) == (
        -1, 3, 1, 4, 4, 2, 3, 0, 4)
    assert Interval(2, 5).mig() == 2
    assert math.isnan(Interval.empty().mid())
    assert Interval.empty().volume() == 0
    assert Interval(1, INF).mid() == 1.7976931348623157e308


def test_predicates():
    x = Interval(0, 2)
    assert x.contains(1) and 1 in x and 3 not in x and not x.contains(INF)
    assert x.interior_contains(1) and not x.interior_contains(0)
    assert Interval(0.5, 1).is_subset(x) and Interval(0.5, 1).is_strict_subset(x)
    assert x.is_subset(x) and not x.is_strict_subset(x)
    assert Interval(0.5, 1).is_interior_subset(x) and not Interval(0, 1).is_interior_subset(x)
    assert x.is_superset(Interval(1, 2))
    assert x.intersects(Interval(2, 3)) and x.is_disjoint(Interval(3, 4))
    assert Interval(1).is_degenerate() and Interval(1, INF).is_unbounded() and not x.is_empty()


def test_arithmetic_is_outward_and_accepts_floats():
    x = Interval(1, 2)
    assert x + x == Interval(2, 4)
    assert x - x == Interval(-1, 1)
    assert x * x == Interval(1, 4)
    assert x / Interval(2) == Interval(0.5, 1)
    assert x + 1 == Interval(2, 3) and 1 + x == Interval(2, 3)
    assert x - 1 == Interval(0, 1) and 3 - x == Interval(1, 2)
    assert 2 * x == Interval(2, 4) and x * 2.0 == Interval(2, 4)
    assert 1 / x == Interval(0.5, 1) and x / 2 == Interval(0.5, 1)
    assert -x == Interval(-2, -1) and +x == x and abs(-x) == x
    assert x ** 2 == Interval(1, 4) and (x ** 0.5).contains(math.sqrt(2))
    tenth = Interval(1) / 10
    assert tenth.lb() < tenth.ub() and tenth.contains(0.1)
    assert np.float64(2) * x == Interval(2, 4)


def test_set_operators_with_floats():
    x = Interval(1, 3)
    assert x & Interval(2, 5) == Interval(2, 3)
    assert x & 2 == Interval(2) and 2 & x == Interval(2)
    assert (x & 5).is_empty()
    assert x | 5 == Interval(1, 5) and 0 | x == Interval(0, 3)
    assert x | Interval.empty() == x


def test_in_place_operators_modify_the_object():
    x = Interval(0, 10)
    alias = x
    x &= Interval(2, 5)
    assert alias is x and alias == Interval(2, 5)
    x |= 7
    assert alias == Interval(2, 7)
    x += 1
    x -= Interval(1)
    x *= 2
    x /= 2
    assert alias is x and alias == Interval(2, 7)
    x &= 100
    assert alias.is_empty()


def test_equality_repr_bisect_inflate_copy_pickle():
    x = Interval(1, 2)
    assert x == Interval(1, 2) and x != Interval(1, 3) and Interval(1) == 1.0
    assert Interval.empty() == Interval.empty()
    assert repr(x) == "[1, 2]" and str(Interval.empty()) == "[ empty ]"
    a, b = x.bisect()
    assert a == Interval(1, 1.5) and b == Interval(1.5, 2)
    assert x.bisect(0.25)[0] == Interval(1, 1.25)
    assert x.inflate(1) == Interval(0, 3)
    c = copy.copy(x)
    c &= 1.5
    assert x == Interval(1, 2)
    assert pickle.loads(pickle.dumps(x)) == x
    assert pickle.loads(pickle.dumps(Interval.empty())).is_empty()
    with pytest.raises(TypeError):
        hash(x)


def test_errors_are_sillage_errors():
    for bad in (lambda: Interval(2, 1), lambda: Interval(math.nan, 1), lambda: Interval(INF, INF),
                lambda: Interval(math.inf), lambda: Interval(0, 1).bisect(0), lambda: Interval(1).bisect(),
                lambda: Interval(0, 1).inflate(-1), lambda: Interval(0, 1) + math.nan,
                lambda: sillage.root(Interval(1), 0)):
        with pytest.raises(sillage.Error):
            bad()
    assert issubclass(sillage.Error, ValueError)


# ---- functions --------------------------------------------------------------------


def test_elementary_functions_enclose_the_math_library():
    rng = random.Random(1788)
    cases = [
        (sillage.sqr, lambda v: v * v, (-5, 5)), (sillage.sqrt, math.sqrt, (0, 9)),
        (sillage.exp, math.exp, (-5, 5)), (sillage.log, math.log, (0.1, 10)),
        (sillage.sin, math.sin, (-10, 10)), (sillage.cos, math.cos, (-10, 10)),
        (sillage.tan, math.tan, (-1.5, 1.5)), (sillage.asin, math.asin, (-1, 1)),
        (sillage.acos, math.acos, (-1, 1)), (sillage.atan, math.atan, (-10, 10)),
        (sillage.sinh, math.sinh, (-5, 5)), (sillage.cosh, math.cosh, (-5, 5)),
        (sillage.tanh, math.tanh, (-5, 5)), (sillage.abs, abs, (-5, 5)),
        (sillage.sign, lambda v: (v > 0) - (v < 0), (-5, 5)),
    ]
    for f, ref, (lo, hi) in cases:
        for _ in range(50):
            a, b = sorted(rng.uniform(lo, hi) for _ in range(2))
            y = f(Interval(a, b))
            for t in (a, b, rng.uniform(a, b)):
                v = ref(t)
                # libm is within a few ulps: widen the reference by a relative 1e-14
                assert y.inflate(1e-14 * (1 + abs(v))).contains(v), (f.__name__, a, b, t)
    assert sillage.pow(Interval(2), 3) == Interval(8)
    assert sillage.pow(Interval(4), 0.5).contains(2)
    assert sillage.pow(Interval(4), Interval(0.5)).contains(2)
    assert sillage.root(Interval(27), 3).contains(3)
    assert sillage.atan2(Interval(1), Interval(1)).contains(math.pi / 4)
    assert sillage.atan2(1.0, 1.0).contains(math.pi / 4)
    assert sillage.min(Interval(0, 3), Interval(1, 2)) == Interval(0, 2)
    assert sillage.max(Interval(0, 3), 1.0) == Interval(1, 3)
    assert sillage.sqr(3.0) == Interval(9)  # floats are accepted
    assert sillage.sqrt(Interval(-4, 4)) == Interval(0, 2)  # set-based


def test_div2_gives_two_pieces():
    lo, hi = sillage.div2(Interval(1, 2), Interval(-1, 1))
    assert lo == Interval(-INF, -1) and hi == Interval(1, INF)
    lo, hi = sillage.div2(Interval(1, 2), Interval(1, 2))
    assert lo == Interval(0.5, 2) and hi.is_empty()


# ---- backward projections -----------------------------------------------------------


def test_bwd_return_tuples():
    assert sillage.bwd_add(Interval(4, 5), Interval(0, 3), Interval(-2, 2)) == (Interval(2, 3), Interval(1, 2))
    x1, x2 = sillage.bwd_mul(Interval(1, 2), Interval(0.5, 10), Interval(-1, 1))
    assert x1 == Interval(1, 10)
    (x,) = sillage.bwd_sqr(Interval(1, 4), Interval(-3, 1.5))
    assert x == Interval(-2, 1.5)
    (x,) = sillage.bwd_pow(Interval(8, 27), Interval(-10, 10), 3)
    assert x == Interval(2, 3)
    x, p = sillage.bwd_pow(Interval(4), Interval(0, 10), Interval(2))
    assert x.contains(2) and x.diam() < 1e-12
    y, x = sillage.bwd_atan2(Interval.pi() / 4, Interval(1, 3), Interval(0, 2))
    assert abs(x.lb() - 1) < 1e-12 and abs(y.ub() - 2) < 1e-12
    (x,) = sillage.bwd_exp(Interval(-2, -1), Interval(0, 1))
    assert x.is_empty()
    x1, x2 = sillage.bwd_add(Interval(0, 1), Interval(5, 6), Interval(0))
    assert x1.is_empty() and x2.is_empty()
    # arguments are values: the caller's objects are untouched
    a = Interval(0, 3)
    sillage.bwd_add(Interval(4, 5), a, Interval(-2, 2))
    assert a == Interval(0, 3)


BWD1 = {
    "bwd_neg": lambda v: -v, "bwd_sqr": lambda v: v * v, "bwd_sqrt": lambda v: math.sqrt(v) if v >= 0 else None,
    "bwd_exp": math.exp, "bwd_log": lambda v: math.log(v) if v > 0 else None,
    "bwd_sin": math.sin, "bwd_cos": math.cos, "bwd_tan": math.tan, "bwd_atan": math.atan,
    "bwd_asin": lambda v: math.asin(v) if -1 <= v <= 1 else None,
    "bwd_acos": lambda v: math.acos(v) if -1 <= v <= 1 else None,
    "bwd_sinh": math.sinh, "bwd_cosh": math.cosh, "bwd_tanh": math.tanh, "bwd_abs": abs,
    "bwd_sign": lambda v: float((v > 0) - (v < 0)),
}


@pytest.mark.parametrize("name", sorted(BWD1))
def test_bwd_keeps_sampled_solutions(name):
    # A solution t (with f(t) inside a slightly inflated [y]) is never removed.
    rng = random.Random(name)
    f, bwd = BWD1[name], getattr(sillage, name)
    for _ in range(200):
        a, b = sorted(rng.uniform(-4, 4) for _ in range(2))
        t = rng.uniform(a, b)
        v = f(t)
        if v is None:
            continue
        y = Interval(v).inflate(1e-9 * (1 + abs(v)) * rng.choice([1, 1e3, 1e6]))
        (x,) = bwd(y, Interval(a, b))
        assert x.contains(t), (name, a, b, t, y, x)
        assert x.is_subset(Interval(a, b))


# ---- IntervalVector -----------------------------------------------------------------


def test_vector_constructors():
    assert IntervalVector(3).size() == 3 and IntervalVector(3)[0].is_all_reals()
    assert IntervalVector(2, Interval(0, 1)) == IntervalVector([[0, 1], [0, 1]])
    assert IntervalVector(2, [0, 1]) == IntervalVector([[0, 1], [0, 1]])
    v = IntervalVector([Interval(0, 1), 2, (3, 4)])
    assert v[0] == Interval(0, 1) and v[1] == Interval(2) and v[2] == Interval(3, 4)
    a = np.array([[0.0, 1.0], [2.0, 3.0]])
    assert IntervalVector(a) == IntervalVector([[0, 1], [2, 3]])
    assert IntervalVector(np.array([1.0, 2.0])) == IntervalVector([1, 2])
    assert IntervalVector.from_point([1, 2]) == IntervalVector([[1, 1], [2, 2]])
    assert IntervalVector.empty(2).is_empty()
    assert IntervalVector(IntervalVector([[0, 1]])) == IntervalVector([[0, 1]])


def test_vector_errors():
    with pytest.raises(sillage.Error, match="component 1"):
        IntervalVector([[0, 1], [3, 2]])
    with pytest.raises(sillage.Error):
        IntervalVector([[0, 1, 2]])
    with pytest.raises(sillage.Error):
        IntervalVector(np.zeros((2, 3)))
    with pytest.raises(sillage.Error):
        IntervalVector(["a"])
    with pytest.raises(sillage.Error):
        IntervalVector([[math.nan, 1]])
    with pytest.raises(sillage.Error):
        IntervalVector([[0, 1]]) & IntervalVector(2)
    with pytest.raises(sillage.Error):
        IntervalVector([[0, 1]]).contains([1, 2])
    with pytest.raises(IndexError, match=r"^IntervalVector index 2 out of range \(size 2\)$"):
        IntervalVector(2)[2]
    with pytest.raises(IndexError, match=r"^IntervalVector index -3 out of range \(size 2\)$"):
        IntervalVector(2)[-3] = 1


def test_vector_access_iteration_and_slices():
    v = IntervalVector([[0, 1], [2, 3], [4, 5]])
    assert len(v) == 3 and v[-1] == Interval(4, 5)
    assert [x.lb() for x in v] == [0, 2, 4]
    assert v[1:] == IntervalVector([[2, 3], [4, 5]])
    v[0] = Interval(7, 8)
    v[1] = 9
    v[2] = [10, 11]
    assert v == IntervalVector([[7, 8], [9, 9], [10, 11]])
    v[2] &= Interval(10.5, 20)  # read, intersect, written back
    assert v[2] == Interval(10.5, 11)
    copy_of_item = v[0]
    copy_of_item &= 7.5
    assert v[0] == Interval(7, 8)  # v[i] is a copy
    assert v.subvector(1, 2) == IntervalVector([[9, 9], [10.5, 11]])


def test_vector_numeric_and_set_functions():
    v = IntervalVector([[0, 1], [2, 4]])
    assert v.lb() == [0, 2] and v.ub() == [1, 4] and v.mid() == [0.5, 3]
    assert v.diam() == [1, 2] and v.rad() == [0.5, 1] and v.volume() == 2 and v.max_diam() == 2
    assert v.contains([0.5, 3]) and not v.contains([2, 3])
    assert IntervalVector([[0.2, 0.5], [2, 3]]).is_subset(v)
    assert v & IntervalVector([[0.5, 2], [3, 9]]) == IntervalVector([[0.5, 1], [3, 4]])
    assert (v & [[5, 6], [0, 9]]).is_empty()  # a list is taken as a box
    assert v | IntervalVector([[5, 6], [0, 1]]) == IntervalVector([[0, 6], [0, 4]])
    assert v + v == IntervalVector([[0, 2], [4, 8]]) and v - v == IntervalVector([[-1, 1], [-2, 2]])
    assert 2 * v == IntervalVector([[0, 2], [4, 8]]) and v * Interval(-1) == -v
    left, right = v.bisect()
    assert left == IntervalVector([[0, 1], [2, 3]]) and right == IntervalVector([[0, 1], [3, 4]])
    assert v.bisect(0, 0.5)[0] == IntervalVector([[0, 0.5], [2, 4]])
    assert abs(IntervalVector([[-2, 1]])) == IntervalVector([[0, 2]])
    assert sillage.norm(IntervalVector([[3, 3], [4, 4]])) == Interval(5)
    assert sillage.dot(v, v) == Interval(4, 17)


def test_vector_in_place_operators_modify_the_object():
    v = IntervalVector([[0, 10], [0, 10]])
    alias = v
    v &= IntervalVector([[2, 3], [4, 5]])
    v += IntervalVector([[1, 1], [1, 1]])
    v -= IntervalVector([[1, 1], [1, 1]])
    v |= IntervalVector([[2, 2], [4, 6]])
    v *= 1.0
    assert alias is v and alias == IntervalVector([[2, 3], [4, 6]])


def test_vector_numpy_round_trip_and_pickle():
    v = IntervalVector([[0, 1], [-INF, 2], [3, INF]])
    a = v.to_numpy()
    assert a.shape == (3, 2) and a.dtype == np.float64
    assert np.array_equal(np.asarray(v), a)
    assert IntervalVector(a) == v
    e = IntervalVector.empty(2)
    assert np.all(e.to_numpy()[:, 0] == INF) and IntervalVector(e.to_numpy()).is_empty()
    assert pickle.loads(pickle.dumps(v)) == v
    assert copy.deepcopy(v) == v and copy.deepcopy(v) is not v
    assert np.asarray(v, dtype=np.float32).dtype == np.float32


# ---- IntervalMatrix -----------------------------------------------------------------


def test_matrix_construction_and_access():
    m = IntervalMatrix([[[0, 1], 2], [3, Interval(4, 5)]])
    assert m.shape == (2, 2) and m.rows() == 2 and m.cols() == 2 and len(m) == 2
    assert m[0, 0] == Interval(0, 1) and m[1, 1] == Interval(4, 5) and m[-1, 0] == Interval(3)
    assert m[1] == IntervalVector([3, [4, 5]]) and m.row(0) == m[0] and m.col(1) == IntervalVector([2, [4, 5]])
    assert IntervalMatrix(2, 3).shape == (2, 3) and IntervalMatrix(2, 3)[0, 0].is_all_reals()
    assert IntervalMatrix(1, 2, Interval(0, 1))[0, 1] == Interval(0, 1)
    assert IntervalMatrix.identity(2) == IntervalMatrix([[1, 0], [0, 1]])
    assert IntervalMatrix.from_point([[1, 2], [3, 4]]) == IntervalMatrix([[1, 2], [3, 4]])
    assert IntervalMatrix([IntervalVector([1, 2]), IntervalVector([3, 4])]) == IntervalMatrix([[1, 2], [3, 4]])
    m[0, 1] = [5, 6]
    m[1] = [7, 8]
    assert m == IntervalMatrix([[[0, 1], [5, 6]], [7, 8]])
    m.set_col(0, IntervalVector([1, 1]))
    assert m.col(0) == IntervalVector([1, 1])
    assert m.transpose() == m.T and m.T[1, 0] == Interval(5, 6)


def test_matrix_errors():
    with pytest.raises(sillage.Error, match="row 1"):
        IntervalMatrix([[1, 2], [3]])
    with pytest.raises(sillage.Error):
        IntervalMatrix([[1, 2]]) * IntervalMatrix([[1, 2]])
    with pytest.raises(sillage.Error):
        IntervalMatrix([[1, 2]]) * IntervalVector([1, 2, 3])
    with pytest.raises(sillage.Error):
        IntervalMatrix(np.zeros((2, 2, 3)))
    with pytest.raises(sillage.Error):
        IntervalMatrix([[[1, 0]]])
    with pytest.raises(IndexError, match=r"^IntervalMatrix row index 2 out of range \(size 2\)$"):
        IntervalMatrix(2, 2)[2, 0]
    with pytest.raises(IndexError, match=r"^IntervalMatrix column index 3 out of range \(size 2\)$"):
        IntervalMatrix(2, 2)[0, 3]


def test_matrix_arithmetic_is_rigorous():
    a = IntervalMatrix([[1, 2], [3, 4]])
    b = IntervalMatrix([[[0, 1], 0], [0, [-1, 1]]])
    assert a * IntervalMatrix.identity(2) == a and a @ a == IntervalMatrix([[7, 10], [15, 22]])
    assert a * IntervalVector([[0, 1], [1, 1]]) == IntervalVector([[2, 3], [4, 7]])
    assert a @ IntervalVector([1, 1]) == IntervalVector([3, 7])
    assert a + b == IntervalMatrix([[[1, 2], 2], [3, [3, 5]]]) and (a - a).contains([[0, 0], [0, 0]])
    assert 2 * a == IntervalMatrix([[2, 4], [6, 8]]) and a * 2 == 2 * a and -a == a * -1
    third = IntervalMatrix([[1]]) * Interval(1 / 3)
    assert third[0, 0] == Interval(1 / 3)
    tenth = IntervalMatrix([[0.1, 0.2]]) @ IntervalVector([1, 1])  # 0.1 + 0.2 rounded outward
    assert tenth[0].lb() < tenth[0].ub() and tenth[0].contains(0.30000000000000004)
    rng = random.Random(7)
    for _ in range(20):  # a point product always lies in the interval product
        pa = [[rng.uniform(-2, 2) for _ in range(3)] for _ in range(2)]
        pb = [[rng.uniform(-2, 2) for _ in range(2)] for _ in range(3)]
        ia = IntervalMatrix([[[v - 0.1, v + 0.1] for v in row] for row in pa])
        ib = IntervalMatrix([[[v - 0.1, v + 0.1] for v in row] for row in pb])
        assert (ia @ ib).contains(np.array(pa) @ np.array(pb))


def test_matrix_set_operations_and_in_place():
    a = IntervalMatrix([[[0, 2], [0, 2]]])
    alias = a
    a &= IntervalMatrix([[[1, 3], [-1, 1]]])
    assert alias is a and a == IntervalMatrix([[[1, 2], [0, 1]]])
    a |= IntervalMatrix([[[5, 5], [0, 0]]])
    assert alias == IntervalMatrix([[[1, 5], [0, 1]]])
    a += IntervalMatrix([[1, 1]])
    a -= IntervalMatrix([[1, 1]])
    a *= 1.0
    assert alias == IntervalMatrix([[[1, 5], [0, 1]]])
    assert IntervalMatrix([[[1, 2]]]).is_subset(a[0:1] if False else IntervalMatrix([[[0, 3]]]))
    assert (a & IntervalMatrix([[[7, 8], [0, 1]]])).is_empty()
    assert a.lb() == [[1, 0]] and a.ub() == [[5, 1]] and a.mid() == [[3, 0.5]] and a.max_diam() == 4


def test_matrix_numpy_round_trip_and_pickle():
    m = IntervalMatrix([[[0, 1], [-INF, 2]], [3, [4, INF]]])
    arr = m.to_numpy()
    assert arr.shape == (2, 2, 2) and np.array_equal(np.asarray(m), arr)
    assert IntervalMatrix(arr) == m
    assert IntervalMatrix(np.array([[1.0, 2.0], [3.0, 4.0]])) == IntervalMatrix([[1, 2], [3, 4]])
    assert pickle.loads(pickle.dumps(m)) == m
    assert copy.deepcopy(m) == m


def test_star_import_keeps_the_builtins():
    namespace = {}
    exec("from sillage import *", namespace)
    assert "Interval" in namespace and "bwd_add" in namespace
    assert "min" not in namespace and "abs" not in namespace
