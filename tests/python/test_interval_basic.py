import math

import pytest
import sillage


def test_interval_arithmetic():
    x = sillage.Interval(1, 2)
    assert (x * x) == sillage.Interval(1, 4)
    third = sillage.Interval(1) / sillage.Interval(3)
    assert third.lb() < 1 / 3 < third.ub() or third.contains(1 / 3)


def test_bad_bounds_raise_value_error():
    with pytest.raises(ValueError, match="inverted"):
        sillage.Interval(2, 1)
    with pytest.raises(sillage.Error):
        sillage.Interval(math.nan, 1)
