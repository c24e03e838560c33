"""ContractorNetwork on tubes from Python: pointwise constraints over tubes and
tube vectors (components live), constants over time, errors."""
import pytest
import sillage
from sillage import Interval, Function, TDomain, Tube, TubeVector


def ctc(vars_, text):
    return sillage.CtcFunction(Function(vars_, text))


def test_pointwise_constraint_on_tubes_in_place():
    td = TDomain(0.0, 10.0, 0.1)
    x3 = Tube(td, "t/5 + [-0.05, 0.05]")
    x4 = Tube(td, Interval(9.9, 10.1))
    v = TubeVector(td, 2)
    cn = sillage.ContractorNetwork()
    cn.add(ctc(["v1", "x3", "x4"], "v1 - x4*cos(x3)"), [v[0], x3, x4])
    cn.add(ctc(["v2", "x3", "x4"], "v2 - x4*sin(x3)"), [sillage.DomainRef.component(v, 1), x3, x4])
    assert cn.nb_dom() == 4
    s = cn.contract()
    assert not s.empty
    # the vector's own components were contracted (v[0] is a live reference)
    assert v[0].slice(0).is_subset(Interval(9.8, 10.2))
    assert v.max_thickness() < 1.5
    truth = [sillage.Trajectory("10*cos(t/5)", Interval(0, 10)), sillage.Trajectory("10*sin(t/5)", Interval(0, 10))]
    assert v.contains(truth)


def test_whole_tube_vector_and_constant():
    td = TDomain(0.0, 10.0, 0.5)
    p = TubeVector(td, "(t, 2*t + [-0.1, 0.1])")
    a = Interval(-10, 10)
    cn = sillage.ContractorNetwork()
    cn.add(ctc(["t", "x", "a"], "x - a*t"), [p, a])  # a tube vector: one variable per component
    assert not cn.contract().empty
    assert a.contains(2.0) and a.diam() < 0.2


def test_component_outlives_its_vector():
    td = TDomain(0.0, 1.0, 0.25)
    x = TubeVector(td, 2, Interval(0, 1))[1]
    del td
    assert x.nb_slices() == 4  # the vector is kept alive by its component


def test_errors():
    td, other = TDomain(0.0, 1.0, 0.1), TDomain(0.0, 1.0, 0.2)
    cn = sillage.ContractorNetwork()
    with pytest.raises(sillage.DimensionError, match="one TDomain"):
        cn.add(ctc(["a", "b"], "a - b"), [Tube(td), Tube(other)])
    with pytest.raises(sillage.DimensionError, match="a tube counts as one variable"):
        cn.add(ctc(["a", "b"], "a - b"), [Tube(td)])
    with pytest.raises(sillage.Error, match="expected Interval, IntervalVector, Tube"):
        cn.add(ctc(["a"], "a"), [3.0])
    assert cn.nb_dom() == 0


def test_inconsistency():
    td = TDomain(0.0, 1.0, 0.1)
    x = Tube(td, Interval(0, 1))
    cn = sillage.ContractorNetwork()
    cn.add(ctc(["a"], "a - 5"), [x])
    s = cn.contract()
    assert s.empty and "Tube" in s.empty_domain
    assert x.slice(0).is_empty()
