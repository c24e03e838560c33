"""sillage.ThreadLimit: the limit holds inside the with block only, the results
do not depend on it, and a limit below 1 is an error."""
import pytest

import sillage as sl


def test_limit_inside_the_block_only():
    everything = sl.ThreadLimit.current()
    assert everything >= 1
    with sl.ThreadLimit(1) as limit:
        assert limit.threads == 1 and repr(limit) == "ThreadLimit(1)"
        assert sl.ThreadLimit.current() == 1
        with sl.ThreadLimit(4):
            assert sl.ThreadLimit.current() == 1  # the smallest limit holds
    assert sl.ThreadLimit.current() == everything


def test_same_tube_and_paving_under_any_limit():
    td = sl.TDomain(0, 20, 0.001)
    expr = "cos(t)^2 - atan(t/5) + [-0.01, 0.01]"
    a = sl.Tube(td, expr)
    f = sl.Function(["x", "y"], "x^2 + y^2")
    p = sl.sivia(sl.IntervalVector([[-2, 2], [-2, 2]]), f, sl.Interval(1, 2), 0.05)
    with sl.ThreadLimit(1):
        b = sl.Tube(td, expr)
        q = sl.sivia(sl.IntervalVector([[-2, 2], [-2, 2]]), f, sl.Interval(1, 2), 0.05)
    assert all(a.slice(k) == b.slice(k) for k in range(a.nb_slices()))
    assert all(a.gate(k) == b.gate(k) for k in range(a.nb_slices() + 1))
    assert q == p


@pytest.mark.parametrize("n", [0, -3])
def test_below_one_is_an_error(n):
    with pytest.raises(sl.Error, match=rf"^ThreadLimit: the number of threads must be at least 1, got {n}$"):
        sl.ThreadLimit(n)
