"""Issue 12 §4: tubes that feel native in Python: numpy both ways, TubeVector
arithmetic and integrals, pickling, reprs, set(y, t=), sillage.__version__."""
import copy
import pickle
import re
from pathlib import Path

import numpy as np
import pytest

import sillage as s
from sillage import Interval, IntervalVector, TDomain, Trajectory, Tube, TubeVector

ROOT = Path(__file__).resolve().parents[2]

A = np.array([[0.0, 1.0], [0.5, 2.0], [1.0, 3.0]])


def td3():
    return TDomain(0.0, 3.0, 1.0)


# ---- numpy in -------------------------------------------------------------

def test_tube_from_array_default_gates():
    x = Tube(td3(), A)
    assert x.slices_array().tolist() == A.tolist()
    # inner gates: intersection of the two slices around t_k; end gates: the end slices
    assert x.gates_array().tolist() == [[0.0, 1.0], [0.5, 1.0], [1.0, 2.0], [1.0, 3.0]]


def test_tube_from_arrays_with_gates():
    g = np.array([[0.0, 0.0], [0.75, 1.0], [1.5, 2.0], [3.0, 3.0]])
    x = Tube(td3(), A, g)
    assert x.gates_array().tolist() == g.tolist()
    assert x.slices_array().tolist() == A.tolist()


def test_tube_from_array_round_trip_with_empty_slice():
    td = td3()
    x = Tube(td, A)
    x.set(Interval.empty(), 1)
    y = Tube(td, x.slices_array(), x.gates_array())
    assert y == x
    assert y.slices_array()[1].tolist() == [np.inf, -np.inf]


def test_tube_from_array_errors():
    td = td3()
    with pytest.raises(s.DimensionError, match=r"shape \(3, 2\), got \(2, 2\)"):
        Tube(td, A[:2])
    with pytest.raises(s.DimensionError, match=r"shape \(4, 2\), got \(3, 2\)"):
        Tube(td, A, A)
    with pytest.raises(s.DimensionError, match="6 slices given, the TDomain has 3"):
        Tube(td, A.ravel())  # (6,): six points
    with pytest.raises(s.DimensionError, match=r"got \(3, 2, 1\)"):
        Tube(td, A[:, :, None])
    bad = A.copy()
    bad[2, 0] = np.nan
    with pytest.raises(s.Error, match="slices row 2 has a NaN bound"):
        Tube(td, bad)
    bad = A.copy()
    bad[0] = [2.0, 1.0]
    with pytest.raises(s.Error, match="slices row 0: lb > ub"):
        Tube(td, bad)
    g = np.array([[0.0, 0.0], [0.5, 1.0], [1.0, 2.0], [3.0, 3.0]])
    bad = g.copy()
    bad[1, 1] = np.nan
    with pytest.raises(s.Error, match="gates row 1 has a NaN bound"):
        Tube(td, A, bad)
    bad = g.copy()
    bad[3] = [4.0, 3.0]
    with pytest.raises(s.Error, match="gates row 3: lb > ub"):
        Tube(td, A, bad)


def test_tube_from_arrays_keeps_a_gate_off_its_slice():
    """Not malformed: a tube with no continuous trajectory, kept as given (a
    network reports it as empty, test_cn_emptiness.py), and pickled as such."""
    g = np.array([[0.0, 0.0], [5.0, 6.0], [1.0, 2.0], [3.0, 3.0]])  # gate 1 disjoint from slice 0
    x = Tube(td3(), A, g)
    assert x.gates_array().tolist() == g.tolist() and not x.is_empty()
    assert pickle.loads(pickle.dumps(x)).gates_array().tolist() == g.tolist()
    v = TubeVector(td3(), [A, A], [g, g])
    assert v[1].gate(1) == Interval(5, 6)


def test_tube_list_forms_still_work():
    td = td3()
    assert Tube(td, [Interval(0, 1), Interval(0.5, 2), Interval(1, 3)]) == Tube(td, A)
    assert Tube(td, Interval(-1, 1)).codomain() == Interval(-1, 1)


def test_tube_vector_from_arrays():
    td = td3()
    b = np.stack([A, A + 10.0])
    v = TubeVector(td, b)
    assert len(v) == 2
    assert v.slices_array().tolist() == b.tolist()
    assert v.slices_array().shape == (2, 3, 2) and v.gates_array().shape == (2, 4, 2)
    assert v[1].gates_array().tolist() == (Tube(td, A + 10.0)).gates_array().tolist()
    # a list of (N, 2) arrays is the same
    assert TubeVector(td, [A, A + 10.0]) == v
    # with gates
    g = v.gates_array()
    assert TubeVector(td, b, g) == v
    assert TubeVector(td, [A, A + 10.0], [g[0], g[1]]) == v


def test_tube_vector_box_forms_still_work():
    td = td3()
    v = TubeVector(td, [[0, 1], [2, 3]])
    assert v.codomain() == IntervalVector([[0, 1], [2, 3]])
    w = TubeVector(td, np.array([[0.0, 1.0], [2.0, 3.0]]))  # a 2-D array is a box
    assert w == v


def test_tube_vector_from_arrays_errors():
    td = td3()
    with pytest.raises(s.DimensionError, match=r"shape \(dim, 3, 2\)"):
        TubeVector(td, np.zeros((2, 4, 2)))
    with pytest.raises(s.DimensionError, match="dimension mismatch"):
        TubeVector(td, np.stack([A, A]), np.zeros((1, 4, 2)))
    with pytest.raises(s.DimensionError, match=r"slices\[1\] must have shape \(3, 2\)"):
        TubeVector(td, [A, A[:2]])


# ---- numpy out ------------------------------------------------------------

def test_lb_ub_diam():
    td = td3()
    x = Tube(td, A)
    assert isinstance(x.lb(), np.ndarray)
    assert x.lb().tolist() == [0.0, 0.5, 1.0]
    assert x.ub().tolist() == [1.0, 2.0, 3.0]
    assert x.diam().tolist() == [1.0, 1.5, 2.0]
    x.set(Interval.empty(), 0)
    assert x.lb()[0] == np.inf and x.ub()[0] == -np.inf and np.isnan(x.diam()[0])
    v = TubeVector(td, [A, A * 2.0])
    assert v.lb().tolist() == [[0.0, 0.5, 1.0], [0.0, 1.0, 2.0]]
    assert v.ub().shape == (2, 3)
    assert v.diam().tolist() == [[1.0, 1.5, 2.0], [2.0, 3.0, 4.0]]


def test_inflate():
    td = td3()
    x = Tube(td, A)
    y = x.inflate(0.5)
    assert y.slices_array().tolist() == [[-0.5, 1.5], [0.0, 2.5], [0.5, 3.5]]
    assert y.gates_array().tolist() == [[-0.5, 1.5], [0.0, 1.5], [0.5, 2.5], [0.5, 3.5]]
    assert x.slices_array().tolist() == A.tolist()  # unchanged
    r = Tube(td, np.array([[0.0, 1.0], [0.0, 0.0], [2.0, 2.0]]))
    z = x.inflate(r)
    assert z.slices_array().tolist() == [[-1.0, 2.0], [0.5, 2.0], [-1.0, 5.0]]
    with pytest.raises(s.Error, match="radius"):
        x.inflate(-1.0)
    with pytest.raises(s.Error, match="negative"):
        x.inflate(Tube(td, Interval(-1, 1)))
    v = TubeVector(td, [A, A])
    assert v.inflate(1.0).lb().tolist() == [[-1.0, -0.5, 0.0]] * 2
    assert v.inflate(IntervalVector([1.0, 2.0])).ub().tolist() == [[2.0, 3.0, 4.0], [3.0, 4.0, 5.0]]
    assert v.inflate(TubeVector([r, r])).slices_array()[0].tolist() == z.slices_array().tolist()


# ---- TubeVector arithmetic, integrals, inverse ------------------------------

def test_tube_vector_arithmetic():
    td = td3()
    v = TubeVector(td, [A, A + 1.0])
    x = Tube(td, A)
    assert (v + v).slices_array().tolist() == (2.0 * v).slices_array().tolist()
    assert (v + v).lb().tolist() == [[0.0, 1.0, 2.0], [2.0, 3.0, 4.0]]
    assert (v - v).slices_array()[0].tolist() == [[-1.0, 1.0], [-1.5, 1.5], [-2.0, 2.0]]
    assert (v * 2).slices_array().tolist() == (2 * v).slices_array().tolist()
    assert (v + 1).lb().tolist() == [[1.0, 1.5, 2.0], [2.0, 2.5, 3.0]]
    assert (1 - v).ub().tolist() == [[1.0, 0.5, 0.0], [0.0, -0.5, -1.0]]
    assert (v * x)[0] == x * x and (x * v)[1] == x * (x + 1.0)
    assert (v / Interval(2.0)).ub().tolist() == [[0.5, 1.0, 1.5], [1.0, 1.5, 2.0]]
    box = IntervalVector([[0, 1], [10, 10]])
    assert (v + box).lb().tolist() == [[0.0, 0.5, 1.0], [11.0, 11.5, 12.0]]
    assert (box - v)[1] == Interval(10.0) - v[1]
    assert (-v)[0] == -x
    with pytest.raises(s.DimensionError, match="dimension mismatch"):
        v + TubeVector(td, 3)
    with pytest.raises(s.DimensionError, match="dimension mismatch"):
        v + IntervalVector(3)


def test_tube_vector_in_place_keeps_components():
    td = td3()
    v = TubeVector(td, [A, A])
    c0 = v[0]
    v += 1.0
    assert c0.lb().tolist() == [1.0, 1.5, 2.0]  # the live reference sees the change
    v *= Tube(td, Interval(2.0))
    assert c0.lb().tolist() == [2.0, 3.0, 4.0]
    v -= v
    assert v[1].slices_array()[0].tolist() == [-2.0, 2.0]
    w = v & TubeVector(td, 2, Interval(0, 1))
    assert w.codomain() == IntervalVector([[0, 1], [0, 1]])


def test_tube_vector_integral_primitive():
    td = td3()
    v = TubeVector(td, [A, A + 1.0])
    assert v.integral(3.0) == IntervalVector([[1.5, 6.0], [4.5, 9.0]])
    assert v.integral(1.0, 2.0) == IntervalVector([[0.5, 2.0], [1.5, 3.0]])
    assert v.integral(Interval(1.0, 2.0))[0] == v[0].integral(Interval(1.0, 2.0))
    p = v.primitive()
    assert p.gates_array()[:, -1].tolist() == [[1.5, 6.0], [4.5, 9.0]]
    q = v.primitive([1.0, [0, 1]])
    assert q.gate(0) == IntervalVector([[1, 1], [0, 1]])
    assert q[0] == v[0].primitive(Interval(1.0))
    with pytest.raises(s.DimensionError):
        v.primitive([1.0])


def test_tube_vector_eval_and_inverse():
    td = td3()
    v = TubeVector(td, [A, A + 1.0])
    assert v(0.5) == IntervalVector([[0, 1], [1, 2]])
    assert v(Interval(0.5, 1.5)) == IntervalVector([[0, 2], [1, 3]])
    # both components must meet y at once: slices 0 and 1 (not 2: [1, 3] misses [0.2, 0.4])
    assert v.inverse(IntervalVector([[0.2, 0.4], [1.2, 1.4]])) == Interval(0.0, 1.0)
    assert v.inverse(IntervalVector([[0.6, 0.7], [1.6, 1.7]])) == Interval(0.0, 2.0)
    assert v.inverse(IntervalVector([[5, 6], [0, 9]])).is_empty()


# ---- pickling ---------------------------------------------------------------

def _bits(a):
    return np.asarray(a, dtype=float).tobytes()


def test_pickle_interval_and_box():
    x = Interval(0.1, 1.0 / 3.0)
    y = pickle.loads(pickle.dumps(x))
    assert y == x and y.lb() == 0.1 and y.ub() == 1.0 / 3.0
    assert pickle.loads(pickle.dumps(Interval.empty())).is_empty()
    b = IntervalVector([[0.1, 0.2], [-np.inf, 1.0 / 7.0]])
    assert pickle.loads(pickle.dumps(b)) == b


def test_pickle_tdomain():
    td = TDomain([0.0, 0.1, 0.3, 1.0 / 3.0])
    u = pickle.loads(pickle.dumps(td))
    assert u.times() == td.times()
    assert _bits(u.times()) == _bits(td.times())


def test_pickle_tube_bit_exact():
    td = TDomain(0.0, 1.0, 0.1)
    x = Tube(td, "sin(t)/3 + [-0.01, 0.01]")
    x.set_gate(4, Interval(0.1, 0.1 + 1e-17))
    x.set(Interval.empty(), 9)
    y = pickle.loads(pickle.dumps(x))
    assert _bits(y.slices_array()) == _bits(x.slices_array())
    assert _bits(y.gates_array()) == _bits(x.gates_array())
    assert y.tdomain().times() == td.times()
    assert y.tdomain() is not td  # a new TDomain ...
    assert y != x  # ... so not the same tube in the C++ sense (== needs one TDomain)


def test_pickle_tubes_together_share_their_tdomain():
    td = td3()
    x, v = Tube(td, A), TubeVector(td, [A, A + 1.0])
    x2, v2 = pickle.loads(pickle.dumps((x, v)))
    assert x2.tdomain() is v2.tdomain()
    assert x2 * v2[1] == (x2 * (x2 + 1.0))
    assert _bits(v2.gates_array()) == _bits(v.gates_array())
    v2.tdomain().sample(0.5)  # both follow the refinement
    assert x2.nb_slices() == 4 and v2.nb_slices() == 4


def test_pickle_trajectory():
    t = Trajectory([0.0, 0.1, 1.0 / 3.0], [1.0, 1.0 / 7.0, -2.0])
    u = pickle.loads(pickle.dumps(t))
    assert u.sample_times() == t.sample_times() and u.sample_values() == t.sample_values()
    with pytest.raises(s.Error, match="analytic"):
        pickle.dumps(Trajectory("t^2", Interval(0, 1)))


def test_copy_and_deepcopy_still_attach_to_the_same_tdomain():
    td = td3()
    x = Tube(td, A)
    assert copy.deepcopy(x) == x and copy.copy(x).tdomain() is td


# ---- set(y, t=) ---------------------------------------------------------------

def test_set_at_a_time_point_sets_the_gate():
    td = td3()
    x = Tube(td, A)
    x.set(Interval(0.75), t=1.0)
    assert x.gate(1) == Interval(0.75)
    assert x.slices_array().tolist() == A.tolist()  # slices unchanged
    assert td.nb_slices() == 3


def test_set_between_time_points_samples_the_tdomain():
    td = td3()
    x, other = Tube(td, A), Tube(td, Interval(5, 6))
    x.set(Interval(1.5), t=1.5)
    assert td.times() == [0.0, 1.0, 1.5, 2.0, 3.0]
    assert x.gate(2) == Interval(1.5)
    assert x.slice(1) == Interval(0.5, 2) and x.slice(2) == Interval(0.5, 2)
    assert other.nb_slices() == 4 and other.codomain() == Interval(5, 6)


def test_set_index_and_errors():
    td = td3()
    x = Tube(td, A)
    x.set(Interval(0, 9), 0)  # positional index: slice 0
    assert x.slice(0) == Interval(0, 9)
    x.set(Interval(2, 3), k=2)
    assert x.slice(2) == Interval(2, 3)
    x.set(Interval(-1, 1))
    assert x.codomain() == Interval(-1, 1)
    with pytest.raises(s.Error, match="not both"):
        x.set(Interval(0), 1, t=1.0)
    with pytest.raises(s.Error):
        x.set(Interval(0), t=4.0)
    with pytest.raises(s.OutOfRangeError):
        x.set(Interval(0), -1)
    v = TubeVector(td, [A, A])
    v.set(IntervalVector([1.0, 2.0]), t=2.5)
    assert v.gate(td.time_index(2.5)) == IntervalVector([1.0, 2.0])


# ---- reprs and version ------------------------------------------------------

def test_reprs():
    td = TDomain(0.0, 10.0, 0.1)
    assert repr(td) == "TDomain(t=[0, 10], 100 slices)"
    x = Tube(td, Interval(-1, 1))
    assert repr(x) == "Tube(t=[0, 10], 100 slices, codomain=[-1, 1])"
    v = TubeVector(td, IntervalVector([[0, 1], [2, 3]]))
    assert repr(v) == "TubeVector(t=[0, 10], 100 slices, dim 2, codomain=([0, 1], [2, 3]))"
    assert repr(Trajectory([0, 1, 4], [0, 1, 0])) == "Trajectory(sampled, 3 points, t=[0, 4])"
    assert repr(Trajectory("sin(t)", Interval(0, 10))) == "Trajectory(analytic, t=[0, 10])"
    assert repr(s.ContractorNetwork()) == "ContractorNetwork(0 contractors, 0 domains)"
    tp = s.TPlane(Interval(0, 10))
    assert repr(tp) == "TPlane(t1=[0, 10], t2=[0, 10], eps=0, 0 detections, 0 proofs)"
    assert repr(s.TubeStyle()) == "TubeStyle(show_gates=False, merge_px=1)"
    assert repr(s.TubeAnalysis(x)) == "TubeAnalysis(Tube(t=[0, 10], 100 slices, codomain=[-1, 1]))"


def test_version_is_the_cmake_project_version():
    m = re.search(r"project\(sillage VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text())
    assert s.__version__ == m.group(1)
    assert s._sillage.__version__ == s.__version__


# ---- figure units and the t-plane legend ------------------------------------

def test_svg_tube_figures_have_time_in_seconds():
    td = TDomain(0.0, 10.0, 0.5)
    x = Tube(td, "sin(t) + [-0.1, 0.1]")
    assert ">t (s)<" in s.tube_figure(x).svg()
    assert ">t (s)<" in s.thickness_figure(x).svg()


def test_matplotlib_axes_units_and_tplane_legend():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from sillage import plot_loops, plot_tube

    td = TDomain(0.0, 10.0, 0.5)
    x = Tube(td, "sin(t) + [-0.1, 0.1]")
    fig, ax = plt.subplots()
    plot_tube.plot_tube(ax, x)
    assert ax.get_xlabel() == "t (s)"
    ax.clear()
    plot_tube.plot_thickness(ax, x)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("t (s)", "d(t)")
    plt.close(fig)

    td = TDomain(0.0, 2 * np.pi, 0.01)
    v = TubeVector(td, "(cos(t) + [-0.01, 0.01], -sin(t) + [-0.01, 0.01])")
    tp = s.TPlane(td)
    tp.compute_detections(0.05, v)
    fig, ax = plt.subplots()
    out = plot_loops.plot_tplane(ax, tp, truth=[(1.0, 2.0)])
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("t1 (s)", "t2 (s)")
    texts = [t.get_text() for t in out["legend"].get_texts()]
    assert texts[0] == "outside (no loop)" and "t1 = t2" in texts and texts[-1] == "true crossings"
    assert all(t in plot_loops.TPLANE_LEGEND.values() for t in texts)
    ax.clear()
    assert "legend" not in plot_loops.plot_tplane(ax, tp, legend=False)
    ax.clear()
    positions = v.primitive()
    plot_loops.plot_loops_map(ax, tp, positions)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("x (m)", "y (m)")
    plt.close(fig)


# ---- Trajectory arithmetic and TrajectoryVector ------------------------------

def test_trajectory_arithmetic():
    x = Trajectory([0.0, 1.0, 3.0], [0.0, 2.0, -2.0])
    y = Trajectory("2*t", Interval(0, 2))
    z = x + y
    assert not z.is_sampled() and not z.is_analytic() and y.is_analytic()
    assert repr(z) == "Trajectory(composite, t=[0, 2])"
    assert z.domain() == Interval(0, 2)
    assert z(1.0) == Interval(4)
    assert (x - y)(1.0) == Interval(0) and (x * y)(1.0) == Interval(4) and (x / y)(1.0) == Interval(1)
    assert (x + 1)(1.0) == Interval(3) and (1 - x)(1.0) == Interval(-1) and (3 * x)(1.0) == Interval(6)
    assert (x / 4)(1.0) == Interval(0.5) and (8 / x)(1.0) == Interval(4) and (-x)(1.0) == Interval(-2)
    assert s.sqr(x)(1.0) == Interval(4) and abs(-x)(1.0) == Interval(2) and s.abs(-x)(1.0) == Interval(2)
    assert s.cos(x)(0.0).contains(1.0) and s.exp(x)(0.0).contains(1.0)
    assert (x - x)(Interval(0, 1)) == Interval(-2, 2)  # operands evaluated independently
    td = TDomain(0.0, 3.0, 0.5)
    assert s.tube_from_data(td, x + 1.0).gate(2) == Interval(3)
    with pytest.raises(s.Error, match="do not overlap"):
        x + Trajectory("t", Interval(5, 6))
    with pytest.raises(s.Error, match="only a sampled"):
        pickle.dumps(z)


def test_trajectory_vector():
    v = s.TrajectoryVector([0.0, 1.0, 2.0], np.array([[0.0, 10.0], [1.0, 11.0], [4.0, 12.0]]))
    assert len(v) == 2 and v.domain() == Interval(0, 2)
    assert repr(v) == "TrajectoryVector(dim 2, t=[0, 2])"
    assert v(1.0) == IntervalVector([1, 11])
    assert v(Interval(0, 2)) == IntervalVector([[0, 4], [10, 12]])
    assert v[-1].sample_values() == [10.0, 11.0, 12.0]
    w = s.TrajectoryVector("(t, 2*t)", Interval(0, 4))
    assert (v + w)(1.0) == IntervalVector([2, 13]) and (v - w)(2.0) == IntervalVector([2, 8])
    assert (2 * v)(1.0) == IntervalVector([2, 22]) and (v * w[0])(2.0) == IntervalVector([8, 24])
    assert (v / 2)(2.0) == IntervalVector([2, 6]) and (-v)(0.0) == IntervalVector([0, -10])
    u = pickle.loads(pickle.dumps(v))
    assert u(0.5) == v(0.5)
    td = TDomain(0.0, 2.0, 0.5)
    assert TubeVector(td, "(t + [-0.1, 0.1], 2*t + [-0.1, 0.1])").contains(s.TrajectoryVector("(t, 2*t)", Interval(0, 2)))
    assert s.TrajectoryVector([Trajectory("t", Interval(0, 1))]).size() == 1
    with pytest.raises(s.DimensionError):
        v + s.TrajectoryVector("t", Interval(0, 1))
    with pytest.raises(s.DimensionError):
        s.TrajectoryVector([0.0, 1.0], np.array([[0.0, 1.0]]))


def test_tube_from_points_array():
    td = td3()
    x = Tube(td, np.array([1.0, 2.0, 3.0]))  # (N,) points, as IntervalVector takes them
    assert x.slices_array().tolist() == [[1.0, 1.0], [2.0, 2.0], [3.0, 3.0]]
    with pytest.raises(s.DimensionError):
        Tube(td, np.array([1.0, 2.0]))
