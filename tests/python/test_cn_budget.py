"""The network's budget and Ctrl-C: contract() runs without the GIL on a
worker and stops on a budget, a cancelled token or a KeyboardInterrupt."""
import os
import signal
import threading
import time

import pytest

import sillage as s


def halving():
    cn = s.ContractorNetwork()
    x, y = s.Interval(-1, 1), s.Interval(-1, 1)
    cn.add(s.CtcFunction(s.Function(["x", "y"], "x - y/2")), [x, y])
    cn.add(s.CtcFunction(s.Function(["x", "y"], "y - x/2")), [x, y])
    cn.set_ratio(0)
    return cn, x, y


def test_budget_exceeded_names_the_calls():
    cn, x, _ = halving()
    b = s.Budget()
    b.max_boxes = 5
    cn.set_budget(b)
    with pytest.raises(s.BudgetExceeded, match="6 contractor calls > max_boxes = 5"):
        cn.contract()
    assert x.contains(0.0) and x.is_subset(s.Interval(-1, 1))


def test_cancelled_token():
    cn, _, _ = halving()
    b = s.Budget()
    b.cancel.cancel()
    cn.set_budget(b)
    with pytest.raises(s.Cancelled):
        cn.contract()


class Slow(s.TubeCtc):
    """Shrinks the first gate by 1 % per call, slowly: with two of them the
    network runs for minutes unless interrupted."""

    def contract(self, domains):
        x = domains[0]
        g = x.gate(0)
        x.set_gate(0, s.Interval(g.lb(), g.ub() - 0.01 * g.diam()))
        time.sleep(0.005)
        return True


def test_ctrl_c_interrupts_contract(sigint_raises):
    td = s.TDomain(0.0, 1.0, 0.5)
    x = s.Tube(td, s.Interval(0, 1))
    cn = s.ContractorNetwork()
    cn.add(Slow(), [x])
    cn.add(Slow(), [x])
    cn.set_ratio(0)
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        cn.contract()
    timer.join()
    assert time.monotonic() - start < 3.0
    assert repr(cn.budget()).startswith("Budget(")  # the caller's budget is back


def test_contract_run_is_an_answer_with_its_summary_and_progress():
    cn, x, _ = halving()
    seen = []
    cn.set_budget(s.Budget(progress=lambda p: seen.append(p.round)))
    st = cn.contract_run()
    assert st.summary.status == s.Status.Converged and st.summary.work == st.contractor_calls
    assert seen == list(range(1, st.iterations + 1))  # the hook once per round
    cn, x, _ = halving()
    cn.set_budget(s.Budget(max_boxes=5))
    st = cn.contract_run()
    assert st.summary.status == s.Status.Stopped and st.contractor_calls == 5
    assert st.summary.reason.startswith("ContractorNetwork::contract: budget exceeded: 6 contractor calls")
    assert x.contains(0.0) and x.is_subset(s.Interval(-1, 1))
    with pytest.raises(s.BudgetExceeded):
        cn.contract()  # the throwing form: the same stop
