"""CtcEvalList: the fixes of a tube as one network node (the C++ tests are
tests/cpp/dynamics/test_ctc_eval_list.cpp). Position fixes on the circle
x(t) = (cos t, sin t): the truth stays inside, the tube is the one of a CtcEval
node per fix, and a wrong fix is an emptiness naming it."""
import math

import pytest
import sillage
from sillage import Interval, IntervalVector

from test_qinter import fixes


def network(obs, listed):
    x, v, _ = fixes([])
    cn = sillage.ContractorNetwork()
    cn.add(sillage.CtcDeriv(), [x, v])
    if listed:
        cn.add(sillage.CtcEvalList(obs), [x, v])
    else:
        for o in obs:
            cn.add(sillage.CtcEval(), [Interval(o.t), IntervalVector(o.z), x, v])
    return x, cn.contract()


def volume(x):
    return sum(x[j].gate(k).diam() for j in range(2) for k in range(x[j].nb_slices() + 1))


def test_ctc_eval_list_is_the_network_of_its_fixes():
    _, _, obs = fixes([])
    x, s = network(obs, True)
    y, r = network(obs, False)
    assert not s.empty and not r.empty
    assert all(x(k / 10).contains([math.cos(k / 10), math.sin(k / 10)]) for k in range(101))
    assert x.max_thickness() < 0.3
    assert volume(x) == pytest.approx(volume(y), rel=0.02)
    assert s.contractor_calls < r.contractor_calls
    c = sillage.CtcEvalList(obs)
    assert len(c.observations()) == 10 and repr(c) == "CtcEvalList(10 observations)"


def test_ctc_eval_list_names_the_wrong_fix():
    _, _, obs = fixes([])
    obs[3].z = IntervalVector([Interval(20, 20.1), Interval(0, 0.1)])  # outside the tube's [-10, 10]^2
    for i, o in enumerate(obs):
        o.name = f"fix at {0.5 + i} s"
    assert obs[3].name == "fix at 3.5 s" and "name='fix at 3.5 s'" in repr(obs[3])
    x, s = network(obs, True)
    assert s.empty and x.is_empty()
    assert s.empty_contractor == "CtcEvalList (fix at 3.5 s)" and " emptied " in s.emptiness
    assert sillage.TubeObservation(Interval(1), IntervalVector(2), None, "a fix").name == "a fix"


def test_ctc_eval_list_errors():
    with pytest.raises(sillage.Error, match="at least one observation"):
        sillage.CtcEvalList([])
    x, v, _ = fixes([])
    cn = sillage.ContractorNetwork()
    with pytest.raises(sillage.DimensionError, match="observation 0 has 3 components"):
        cn.add(sillage.CtcEvalList([sillage.TubeObservation(Interval(1), IntervalVector(3))]), [x, v])
    with pytest.raises(sillage.Error, match="does not meet the time domain"):
        cn.add(sillage.CtcEvalList([sillage.TubeObservation(Interval(20, 30), IntervalVector(2))]), [x, v])
