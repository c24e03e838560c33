"""ContractorNetwork.set_scheduling (include/sillage/cn/scheduling.h): FIFO
(the default) or by expected contraction over cost; the same fixed point."""
import sillage as sl


def network(scheduling):
    cn = sl.ContractorNetwork()
    x = cn.create_dom(sl.Interval(0, 10), "x")
    y = cn.create_dom(sl.Interval(), "y")
    cn.set_ratio(0)
    cn.set_scheduling(scheduling)
    cn.add(sl.CtcFunction(sl.Function(["y", "x"], "y - sqr(x)")), [y, x])
    cn.add(sl.CtcFunction(sl.Function(["x"], "x - [2, 3]")), [x])
    cn.add(sl.CtcFunction(sl.Function(["y"], "y - [5, 6]")), [y])
    return cn, x, y


def test_same_fixed_point():
    assert sl.ContractorNetwork().scheduling() == sl.Scheduling.Fifo
    fifo, fx, fy = network(sl.Scheduling.Fifo)
    prio, px, py = network(sl.Scheduling.Priority)
    assert prio.scheduling() == sl.Scheduling.Priority
    assert not fifo.contract().empty and not prio.contract().empty
    assert fx == px and fy == py
    assert fx.contains(5 ** 0.5) and fy.is_subset(sl.Interval(5, 6))
