"""Tubes from Python: TDomain and sampling, Tube construction / evaluation /
inversion / arithmetic, numpy export, TubeVector live components, Trajectory,
builders and files."""
import copy
import math
import random
import struct

import numpy as np
import pytest
import sillage
from sillage import Interval, IntervalVector, TDomain, Trajectory, Tube, TubeVector


def small():
    td = TDomain([0.0, 1.0, 2.0, 3.0])
    return td, Tube(td, [Interval(0, 2), Interval(1, 3), Interval(2, 5)])


def test_tdomain():
    td = TDomain(0.0, 1.05, 0.1)
    assert td.nb_slices() == 11
    assert td.t(3) == 3 * 0.1
    assert td.t(11) == 1.05
    assert td.t0_tf() == Interval(0, 1.05)
    assert td.slice_index(0.1 * 3) == 3
    assert td.slice_width(0).contains(0.1)
    with pytest.raises(sillage.Error):
        TDomain(0.0, 1.0, 0.0)
    with pytest.raises(sillage.Error):
        TDomain([0.0, 2.0, 1.0])
    with pytest.raises(sillage.Error):
        td.t(12)
    with pytest.raises(ValueError):
        td.slice_index(float("nan"))


def test_tube_eval_and_gates():
    td, x = small()
    assert x.nb_slices() == 3
    assert x.gate(1) == Interval(1, 2)
    assert x(0.5) == Interval(0, 2)
    assert x(1.0) == Interval(1, 2)
    assert x(Interval(0.5, 1.5)) == Interval(0, 3)
    assert x(Interval(1, 2)) == Interval(1, 3)
    assert x(Interval(1, 1)) == Interval(1, 2)
    with pytest.raises(sillage.Error):
        x(3.5)
    with pytest.raises(sillage.Error):
        x(Interval(-1, 1))
    assert x.codomain() == Interval(0, 5)
    assert x.volume() == 7.0
    assert x.max_thickness() == 3.0


def test_set_and_set_gate():
    td = TDomain([0.0, 1.0, 2.0, 3.0])
    x = Tube(td, Interval(0, 10))
    x.set(Interval(1, 2), 1)
    assert x.slice(1) == Interval(1, 2) and x.gate(1) == Interval(1, 2) and x.gate(2) == Interval(1, 2)
    x.set_gate(0, Interval(3))
    assert x.gate(0) == Interval(3, 3)
    x.set(Interval(5, 6), 2)
    assert x.gate(2).is_empty() and x.is_empty()
    x.set(Interval(0, 1))
    assert x == Tube(td, Interval(0, 1))


def test_sample_splits_every_tube():
    td, x = small()
    y = Tube(td, 1.0)
    z = x.copy()
    assert td.nb_attached() == 3
    assert td.sample(1.5) == 2
    for tube in (x, y, z):
        assert tube.nb_slices() == 4
    assert x.slice(2) == Interval(1, 3) and x.gate(2) == Interval(1, 3)
    del z, tube  # the loop variable held the last one
    assert td.nb_attached() == 2


def test_inverse():
    td = TDomain([0.0, 1.0, 2.0, 3.0])
    x = Tube(td, [Interval(0, 1), Interval(2, 3), Interval(0, 1)],
             [Interval(0, 1), Interval(1, 2), Interval(1, 2), Interval(0, 1)])
    assert x.inverse(Interval(0, 0.5)) == Interval(0, 3)
    assert x.inverse_components(Interval(0, 0.5)) == [Interval(0, 1), Interval(2, 3)]
    assert x.inverse(Interval(7, 8)).is_empty()
    assert x.inverse_components(Interval(7, 8)) == []


def test_from_expression_and_function():
    td = TDomain(0.0, 10.0, 0.1)
    x = Tube(td, "-9/20*cos(t/5) + [-0.001,0.001]")
    rng = random.Random(1)
    for _ in range(500):
        t = rng.uniform(0.0, 10.0)
        v = -9 / 20 * math.cos(t / 5)
        assert x(t).contains(v - 0.0009) and x(t).contains(v + 0.0009)
    f = sillage.Function(["t"], "2*t+1")
    y = Tube(TDomain([0.0, 1.0, 2.0]), f)
    assert y.slice(1) == Interval(3, 5) and y.gate(2) == Interval(5)
    assert x.contains(Trajectory("-9/20*cos(t/5)", Interval(0, 10)))
    assert not x.contains(Trajectory("-9/20*cos(t/5) + 0.01", Interval(0, 10)))


def test_arithmetic_and_functions():
    td = TDomain([0.0, 1.0, 2.0])
    x = Tube(td, [Interval(1, 2), Interval(-1, 3)])
    y = Tube(td, Interval(2, 4))
    assert (x + y).slice(0) == Interval(3, 6)
    assert (x - 1).slice(0) == Interval(0, 1)
    assert (1 - x).slice(0) == Interval(-1, 0)
    assert (2 * x).slice(1) == Interval(-2, 6)
    assert (x * Interval(0, 1)).slice(0) == Interval(0, 2)
    assert (x / y).slice(0) == Interval(0.25, 1)
    assert (6.0 / y).slice(0) == Interval(1.5, 3)
    assert (-x).slice(1) == Interval(-3, 1)
    assert (x ** 2).slice(1) == Interval(0, 9)
    assert abs(x).slice(1) == Interval(0, 3)
    assert sillage.sqr(x).slice(1) == Interval(0, 9)
    # sin and cos of tubes go by rows: enclosures within a few ulps of the scalar functions
    row, scalar = sillage.sin(x).slice(0), sillage.sin(Interval(1, 2))
    assert scalar.is_subset(row) and row.diam() - scalar.diam() <= 2 ** -48
    assert sillage.exp(x).gate(0) == sillage.exp(Interval(1, 2))
    assert sillage.atan2(x, y).slice(0) == sillage.atan2(Interval(1, 2), Interval(2, 4))
    assert sillage.atan2(x, 1.0).slice(0) == sillage.atan2(Interval(1, 2), Interval(1))
    assert sillage.pow(x, 3).slice(0) == Interval(1, 8)
    assert sillage.sin(Interval(0)) == Interval(0)  # the Interval overloads still work
    z = x.copy()
    z += y
    assert z == x + y
    z &= Tube(td, Interval(3, 4))
    assert z.slice(0) == Interval(3, 4)
    assert (x & y).slice(1) == Interval(2, 3)
    assert (x | y).slice(0) == Interval(1, 4)
    with pytest.raises(sillage.Error):
        x + Tube(TDomain([0.0, 1.0, 2.0]), 1.0)


def test_property_arithmetic_keeps_trajectories():
    rng = random.Random(7)
    for _ in range(20):
        times = [0.0]
        for _ in range(rng.randint(1, 10)):
            times.append(times[-1] + rng.uniform(0.05, 0.5))
        td = TDomain(times)
        samples = sorted(set(times + [rng.uniform(times[0], times[-1]) for _ in range(10)]))
        a = Trajectory(samples, [rng.uniform(-2, 2) for _ in samples])
        b = Trajectory(samples, [rng.uniform(-2, 2) for _ in samples])
        x = Tube(td, [a(td.slice_domain(k)).inflate(rng.random()) for k in range(td.nb_slices())])
        y = Tube(td, [b(td.slice_domain(k)).inflate(rng.random()) for k in range(td.nb_slices())])
        assert x.contains(a) and y.contains(b)
        z = x * y + sillage.sin(x) - y
        for _ in range(100):
            t = rng.uniform(times[0], times[-1])
            assert (a(t) * b(t) + sillage.sin(a(t)) - b(t)).is_subset(z(t))


def test_numpy_export():
    td, x = small()
    s = x.slices_array()
    g = x.gates_array()
    assert s.shape == (3, 2) and g.shape == (4, 2)
    assert np.array_equal(s, np.array([[0, 2], [1, 3], [2, 5]], dtype=float))
    assert np.array_equal(g[1], np.array([1.0, 2.0]))
    e = Tube(td, Interval.empty())
    assert e.slices_array()[0, 0] == math.inf and e.slices_array()[0, 1] == -math.inf


def test_tube_vector_live_components():
    td = TDomain([0.0, 1.0, 2.0])
    v = TubeVector(td, 2, Interval(0, 10))
    assert len(v) == 2 and v.size() == 2
    v[1].set(Interval(1, 2), 0)
    assert v[1].slice(0) == Interval(1, 2)
    c = v[0]
    c &= Tube(td, Interval(3, 4))
    assert v(0.5)[0] == Interval(3, 4)
    del v  # the component keeps its vector alive
    assert c.slice(0) == Interval(3, 4)
    w = TubeVector(td, IntervalVector([Interval(0, 1), Interval(2, 3)]))
    assert w.codomain() == IntervalVector([Interval(0, 1), Interval(2, 3)])
    assert w.volume() == 2.0
    assert w.subvector(1, 1)[0].slice(0) == Interval(2, 3)
    assert [t.slice(0) for t in w] == [Interval(0, 1), Interval(2, 3)]
    with pytest.raises(IndexError):
        w[2]
    assert w[-1].slice(1) == Interval(2, 3)


def test_indices_out_of_range_are_index_errors():
    """Every slice, gate, time point or component index past the end (or negative) is an
    IndexError (sillage.OutOfRangeError, also a sillage.Error) that gives the index and the range."""
    td = TDomain(0.0, 10.0, 0.1)  # 100 slices
    x, v = Tube(td), TubeVector(td, 2)
    y, box = Interval(0, 1), IntervalVector([[0, 1], [0, 1]])
    calls = {
        "x.set_gate(500, y)": lambda: x.set_gate(500, y), "x.gate(101)": lambda: x.gate(101),
        "x.slice(100)": lambda: x.slice(100), "x.set(y, 100)": lambda: x.set(y, 100),
        "x.thickness(100)": lambda: x.thickness(100), "x.gate(-1)": lambda: x.gate(-1),
        "v.slice(100)": lambda: v.slice(100), "v.gate(101)": lambda: v.gate(101), "v.slice(-1)": lambda: v.slice(-1),
        "v.set_gate(500, box)": lambda: v.set_gate(500, box), "v.set(box, 100)": lambda: v.set(box, 100),
        "v[2]": lambda: v[2], "td.t(101)": lambda: td.t(101), "td.t(-1)": lambda: td.t(-1),
        "td.slice_domain(100)": lambda: td.slice_domain(100), "td.slice_width(100)": lambda: td.slice_width(100),
    }
    for name, call in calls.items():
        with pytest.raises(IndexError) as e:
            call()
        assert isinstance(e.value, sillage.Error) or name == "v[2]", name
        assert "out of range" in str(e.value) or "negative" in str(e.value), (name, str(e.value))
    with pytest.raises(sillage.OutOfRangeError, match=r"^Tube::set_gate\(k, y\): gate 500 out of range \[0, 100\]$"):
        x.set_gate(500, y)


def test_tube_vector_from_expression():
    td = TDomain(0.0, 6.0, 0.1)
    v = TubeVector(td, "(cos(t), sin(t))")
    assert v.size() == 2
    assert v.contains([Trajectory("cos(t)", Interval(0, 6)), Trajectory("sin(t)", Interval(0, 6))])
    box = v(Interval(0, 6))
    assert box[0].contains(1.0) and box[1].contains(-1.0)
    td.sample(0.05)
    assert v[0].nb_slices() == 61 and v[1].nb_slices() == 61


def test_trajectory():
    x = Trajectory([0.0, 1.0, 3.0], [0.0, 2.0, -2.0])
    assert x.is_sampled()
    assert x(0.5) == Interval(1)
    assert x(Interval(0.5, 2.5)) == Interval(-1, 2)
    y = Trajectory({0.0: 1.0, 2.0: 3.0})
    assert y(1.0) == Interval(2)
    z = Trajectory("t^2", Interval(0, 2))
    assert not z.is_sampled()
    assert z(Interval(0, 2)) == Interval(0, 4)
    with pytest.raises(sillage.Error):
        x(4.0)


def test_builders_and_files(tmp_path):
    td = TDomain([0.0, 1.0, 2.0, 3.0])
    d = Trajectory([0.0, 2.0], [0.0, 0.0])
    x = sillage.tube_from_data(td, d, 0.0, Interval(-1, 1))
    assert x.gate(1) == Interval(-1, 1) and x.gate(2) == Interval(0)
    y = sillage.tube_from_data(td, Trajectory([0.0, 3.0], [0.0, 3.0]), 0.5)
    assert y.slice(0) == Interval(-0.5, 1.5)
    b = sillage.tube_from_bounds(td, Trajectory("t", Interval(0, 3)), Trajectory("t+1", Interval(0, 3)))
    assert b.slice(2) == Interval(2, 4)
    path = str(tmp_path / "x.tube")
    sillage.save_tube(y, path)
    assert sillage.load_tube(path, td) == y
    assert sillage.load_tube(path).slice(0) == y.slice(0)
    v = TubeVector(td, 2, Interval(0, 1))
    sillage.save_tube(v, path)
    assert sillage.load_tube_vector(path, td) == v
    bad = tmp_path / "bad.tube"
    bad.write_bytes(b"not a tube")
    with pytest.raises(sillage.Error):
        sillage.load_tube(str(bad))


def test_copy_semantics():
    td, x = small()
    y = copy.copy(x)
    y.set(Interval(9), 0)
    assert x.slice(0) == Interval(0, 2)
    assert copy.deepcopy(x) == x


def test_undefined_expression_gates_are_unknown_not_empty():
    td = TDomain(0, 10, 0.1)
    for e in ("sin(t)/t", "log(t)", "1/t", "t*log(t)", "atan2(t, t)"):
        v = Tube(td, e)
        assert not v.is_empty(), e
        assert v.gate(0).is_all_reals() and not v(5.0).is_empty(), e
        assert not v.integral(10.0).is_empty(), e
        x, y = Tube(td), Tube(td)
        consistent = sillage.CtcDeriv().contract(x, v)
        cn = sillage.ContractorNetwork()
        cn.add(sillage.CtcDeriv(), [y, v])
        assert consistent and not cn.contract().empty and x == y, e


def test_load_tube_rejects_trailing_bytes_and_directories(tmp_path):
    td = TDomain([0.0, 1.0, 2.0])
    x = Tube(td, [Interval(0, 1), Interval(1, 2)], [Interval(0), Interval(1), Interval(2)])
    path = tmp_path / "x.tube"
    sillage.save_tube(x, str(path))
    size = path.stat().st_size
    path.write_bytes(path.read_bytes() + b"\0")
    with pytest.raises(sillage.Error, match=f"trailing bytes after the Tube, from byte {size}"):
        sillage.load_tube(str(path))
    with pytest.raises(sillage.Error, match="is a directory"):
        sillage.load_tube(str(tmp_path))


def test_a_gate_off_its_slice_is_kept_and_loads_as_saved(tmp_path):
    """No continuous trajectory goes through gate 1: a tube that holds none, not an error."""
    td = TDomain([0.0, 1.0, 2.0])
    x = Tube(td, [Interval(0, 1), Interval(1, 2)], [Interval(0), Interval(5), Interval(2)])
    assert x.gate(1) == Interval(5) and not x.is_empty()
    path = tmp_path / "x.tube"
    sillage.save_tube(x, str(path))
    assert sillage.load_tube(str(path), td) == x


def test_load_tube_names_the_file_and_the_bad_time_point(tmp_path):
    """A time point NaN or not after the one before: the file, the point, its byte and its value."""
    path = tmp_path / "x.tube"
    sillage.save_tube(Tube(TDomain([0.0, 1.0, 2.0]), Interval(0, 1)), str(path))
    good = path.read_bytes()
    at = 8 + 4 + 4 + 8  # time point 0
    for k, t, why in [(1, math.nan, "is nan, not a finite time"), (2, 0.5, "is 0.5, not after time point 1 = 1")]:
        path.write_bytes(good[:at + 8 * k] + struct.pack("<d", t) + good[at + 8 * k + 8:])
        with pytest.raises(sillage.Error) as e:
            sillage.load_tube(str(path))
        assert str(e.value) == f"load tube: '{path}': time point {k} (byte {at + 8 * k}) {why}"
