"""An empty network is an answer: stats.emptiness names the contractor and the
domain (and the slice or gate of a tube, with its time)."""
import pytest
import sillage
from sillage import CtcDeriv, CtcEval, CtcFunction, Function, Interval, IntervalVector, TDomain, Tube, TubeVector


def test_interval_network():
    cn = sillage.ContractorNetwork()
    x = cn.create_dom(Interval(0, 1), "x")
    y = cn.create_dom(Interval(2, 3), name="y")
    cn.add(CtcFunction(Function(["a", "b"], "a - b")), [x, y])
    s = cn.contract()
    assert s.empty
    assert s.emptiness == "CtcFunction(a - b) emptied interval 'x'"
    assert s.empty_contractor == "CtcFunction(a - b)"
    assert (s.empty_domain_index, s.empty_domain_name, s.empty_atom) == (0, "x", "")
    assert "emptiness='CtcFunction(a - b) emptied interval 'x''" in repr(s)


def test_python_contractor_and_empty_on_input():
    class Impossible(sillage.Ctc):
        def __init__(self):
            super().__init__(1)

        def contract(self, box):
            box.set_empty()

    cn = sillage.ContractorNetwork()
    rho = Interval(1, 2)
    cn.add(Impossible(), [rho])
    cn.set_name(rho, "rho")
    assert cn.domain_name(0) == "rho"
    assert cn.contract().emptiness == "Impossible emptied interval 'rho'"
    s = cn.contract()
    assert s.emptiness == "interval 'rho' was empty on input"
    assert s.empty_contractor == ""


def test_tube_with_ctc_deriv():
    td = TDomain(0.0, 6.0, 1.0)
    x, v = Tube(td), Tube(td, Interval(1))
    x.set_gate(0, Interval(0))
    x.set_gate(3, Interval(0, 0.5))  # x(3) = 3 if x' = 1
    cn = sillage.ContractorNetwork()
    cn.add(CtcDeriv(), [x, v])
    cn.set_name(x, "x")
    s = cn.contract()
    assert s.emptiness == "CtcDeriv emptied tube 'x' at gate 3 (t = 3)"
    assert (s.empty_atom, s.empty_atom_index, s.empty_time) == ("gate", 3, Interval(3))


def test_ctc_eval_with_an_impossible_observation():
    td = TDomain(0.0, 10.0, 1.0)
    p = TubeVector(td, "(t, 2*t)")
    t, z = Interval(4.25, 4.75), IntervalVector([[4, 5], [100, 101]])
    cn = sillage.ContractorNetwork()
    cn.add(CtcEval(), [t, z, p])
    cn.set_name(p, "p")
    s = cn.contract()
    assert s.empty
    assert s.emptiness == "CtcEval emptied tube 'p[0]' at slice 4 [4, 5] for t in [4.25, 4.75]"
    assert s.empty_contractor == "CtcEval"


def test_a_gate_off_its_slice_is_inconsistent_input():
    """A tube with no continuous trajectory (gate 3 misses slice 2): no
    solution before any contractor runs, the pair named, the tube left as given."""
    td = TDomain(0.0, 2.0, 0.5)
    slices, gates = [Interval()] * 4, [Interval()] * 5
    slices[2], gates[3] = Interval(0, 1), Interval(5, 6)
    x, v = Tube(td, slices, gates), Tube(td, Interval(-1, 1))
    given = x.copy()
    cn = sillage.ContractorNetwork()
    cn.add(CtcDeriv(), [x, v])
    cn.add(CtcEval(), [Interval(0.1, 0.2), Interval(-10, 10), x, v])
    cn.set_name(x, "x")
    for _ in range(2):  # never a success, however often asked
        s = cn.contract()
        assert s.empty and s.contractor_calls == 0 and s.empty_contractor == ""
        assert s.emptiness == ("tube 'x': gate 3 [5, 6] at t = 1.5 does not meet slice 2 [0, 1] ([1, 1.5]): "
                               "no continuous trajectory through it (inconsistent input)")
        assert (s.empty_domain_name, s.empty_atom, s.empty_atom_index) == ("x", "gate", 3)
        assert (s.empty_time, s.empty_atom_value) == (Interval(1.5), Interval(5, 6))
        assert (s.disjoint_atom, s.disjoint_atom_index) == ("slice", 2)
        assert (s.disjoint_time, s.disjoint_value) == (Interval(1, 1.5), Interval(0, 1))
    assert x == given
    assert not CtcDeriv().contract(x.copy(), v)  # alone: no solution too
    assert not CtcEval().contract(Interval(0.1, 0.2), Interval(-10, 10), x.copy(), v)


def test_set_name_errors():
    cn = sillage.ContractorNetwork()
    with pytest.raises(sillage.Error, match="empty name"):
        cn.set_name(Interval(0, 1), "")
