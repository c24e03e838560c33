"""sillage.TubeCtc: a contractor on whole tubes written in Python, run by a
ContractorNetwork to the fixed point; ContractorNetwork.contract releases the
GIL; CtcEval.contract refuses a list or a float where it contracts in place."""
import threading

import pytest
import sillage
from sillage import Interval, TDomain, Tube


class PyIncrement(sillage.TubeCtc):
    """x(t_{k+1}) - x(t_k) in [i](k): CtcIncrement, in Python."""

    def contract(self, domains):
        x, i = domains
        n = x.nb_slices()
        for k in range(n):
            x.set_gate(k + 1, x.gate(k + 1) & (x.gate(k) + i.slice(k)))
        for k in reversed(range(n)):
            x.set_gate(k, x.gate(k) & (x.gate(k + 1) - i.slice(k)))
        return not x.gate(0).is_empty()


def gates(x):
    return [x.gate(k) for k in range(x.nb_slices() + 1)]


def test_python_tube_ctc_matches_the_cpp_one_in_a_network():
    td = TDomain(0.0, 1.0, 0.1)
    results = []
    for ctc in (PyIncrement(), sillage.CtcIncrement()):
        x, i = Tube(td, Interval(-10, 10)), Tube(td, Interval(0.9, 1.1))
        x.set_gate(0, Interval(0))
        cn = sillage.ContractorNetwork()
        cn.add(ctc, [x, i])
        s = cn.contract()
        assert not s.empty
        results.append(gates(x))
    assert results[0] == results[1]
    assert results[0][10].is_subset(Interval(8.9, 11.1))


def test_python_tube_ctc_wakes_the_pointwise_contractors():
    td = TDomain(0.0, 1.0, 0.1)
    x, y, i = Tube(td, Interval(-10, 10)), Tube(td, Interval(-100, 100)), Tube(td, Interval(1))
    x.set_gate(0, Interval(0))
    cn = sillage.ContractorNetwork()
    cn.add(PyIncrement(), [x, i])
    cn.add(sillage.CtcFunction(sillage.Function(["x", "y"], "y - 2*x")), [x, y])
    assert not cn.contract().empty
    assert y.gate(10).is_subset(Interval(19.99, 20.01))


def test_python_tube_ctc_cannot_enlarge_and_reports_emptiness():
    td = TDomain(0.0, 1.0, 0.5)

    class Widen(sillage.TubeCtc):
        def contract(self, domains):
            domains[0].set(Interval(-100, 100))

    x = Tube(td, Interval(0, 1))
    cn = sillage.ContractorNetwork()
    cn.add(Widen(), [x])
    assert not cn.contract().empty
    assert x.gate(1) == Interval(0, 1)

    class Never(sillage.TubeCtc):
        def name(self):
            return "Never"

        def contract(self, domains):
            return False

    cn = sillage.ContractorNetwork()
    cn.add(Never(), [x, Interval(0, 1)])
    s = cn.contract()
    assert s.empty and s.empty_contractor == "Never"
    assert x.is_empty()


def test_python_tube_ctc_errors():
    td = TDomain(0.0, 1.0, 0.5)

    class Bad(sillage.TubeCtc):
        def contract(self, domains):
            return 3

    cn = sillage.ContractorNetwork()
    cn.add(Bad(), [Tube(td)])
    with pytest.raises(TypeError, match="must return None, True or False"):
        cn.contract()

    class Missing(sillage.TubeCtc):
        pass

    cn = sillage.ContractorNetwork()
    cn.add(Missing(), [Tube(td)])
    with pytest.raises(RuntimeError, match="contract"):
        cn.contract()


def test_contract_releases_the_gil():
    td = TDomain(0.0, 100.0, 0.001)
    x, v = Tube(td, Interval(-1e6, 1e6)), Tube(td, Interval(-1, 1))
    x.set_gate(0, Interval(0))
    cn = sillage.ContractorNetwork()
    cn.add(sillage.CtcDeriv(), [x, v])
    cn.add(sillage.CtcFunction(sillage.Function(["x"], "x")), [x])
    ticks = []
    worker = threading.Thread(target=cn.contract)
    worker.start()
    while worker.is_alive():
        ticks.append(1)
    worker.join()
    assert len(ticks) > 1
    assert x.gate(100000).is_subset(Interval(-100.1, 100.1))


def test_contract_with_python_contractors_after_gil_release():
    class Half(sillage.Ctc):
        def __init__(self):
            super().__init__(1)

        def contract(self, x):
            x[0] &= Interval(-5, 5)

    td = TDomain(0.0, 1.0, 0.1)
    x = Tube(td, Interval(-10, 10))
    cn = sillage.ContractorNetwork()
    cn.add(Half(), [x])
    assert not cn.contract().empty
    assert x.gate(3) == Interval(-5, 5)


def test_ctc_eval_refuses_a_conversion_of_what_it_contracts():
    td = TDomain(0.0, 1.0, 0.1)
    y, w = Tube(td, Interval(-1, 1)), Tube(td, Interval(-1, 1))
    with pytest.raises(TypeError):
        sillage.CtcEval().contract(0.5, Interval(0), y, w)
    with pytest.raises(TypeError):
        sillage.CtcEval().contract(Interval(0.5), 0.0, y, w)
    t, z = Interval(0.5), Interval(0)
    assert sillage.CtcEval().contract(t, z, y, w)
