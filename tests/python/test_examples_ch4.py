"""The three worked examples of thesis chapter 4 (examples/python/sin_ivp.py,
lissajous.py, kidnapped_robot.py) on coarse slicings: the truth is inside, the
printed figures hold, and the variants agree."""
import math
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples" / "python"))
sin_ivp = pytest.importorskip("sin_ivp")
lissajous = pytest.importorskip("lissajous")
kidnapped = pytest.importorskip("kidnapped_robot")
from sillage import Interval, TDomain, Trajectory  # noqa: E402


# ---- 4.3.3: x' = -sin(x) ----

def test_sin_ivp_pessimistic_but_guaranteed():
    td = TDomain(0.0, 10.0, 0.01)
    n = td.nb_slices()
    truth = Trajectory(sin_ivp.TRUTH, Interval(0, 10))
    x, stats = sin_ivp.solve_decomposition(td)
    y, _ = sin_ivp.solve_direct(td)
    assert not stats.empty
    # the truth (its ~1e-15 wide enclosure) and the validated-integration box are inside
    assert sin_ivp.truth_excess(x, truth) <= 1e-9
    assert x.gate(n).is_superset(sin_ivp.REFERENCE)
    # the printed figure: x(10) in [-4.46393, 4.46759], 5e15 times wider than the reference
    assert abs(x.gate(n).lb() + 4.46393) < 1e-4 and abs(x.gate(n).ub() - 4.46759) < 1e-4
    # both decompositions reach the same fixed point (up to rounding)
    assert abs(x.gate(n).lb() - y.gate(n).lb()) < 1e-9 and abs(x.gate(n).ub() - y.gate(n).ub()) < 1e-9
    # the tube is thin at first (the wrapping only builds up later)
    assert x.thickness(0) < 0.01 and sin_ivp.onset(x, 0.1) > 3


def test_sin_ivp_sweeps_reach_the_network_fixed_point():
    td = TDomain(0.0, 10.0, 0.1)
    snaps = sin_ivp.sweeps(td)
    x, _ = sin_ivp.solve_decomposition(td)
    assert len(snaps) > 5
    assert snaps[-1] == x
    for a, b in zip(snaps, snaps[1:]):  # each sweep contracts
        assert b.is_subset(a)


def test_sin_ivp_width_shrinks_with_delta():
    widths = []
    for dt in (0.1, 0.01, 0.001):
        td = TDomain(0.0, 10.0, dt)
        x, _ = sin_ivp.solve_decomposition(td)
        widths.append(x.gate(td.nb_slices()).diam())
    assert widths[0] > widths[1] > widths[2] > 1e14 * sin_ivp.REFERENCE.diam()


def test_sin_ivp_main(tmp_path):
    ok, results = sin_ivp.main(deltas=(0.1,), out=tmp_path)
    assert ok and (tmp_path / "sin_ivp_py.svg").exists()


# ---- 4.4.2: Lissajous ----

def test_lissajous_truth_inside_and_envelope():
    x_true, dx_true, ddx_true = lissajous.truths()
    x, dx, ddx, stats = lissajous.solve(0.01)
    assert not stats.empty
    assert x.contains(x_true) and dx.contains(dx_true) and ddx.contains(ddx_true)
    x, dx, ddx, _ = lissajous.solve(0.001)
    assert x.contains(x_true) and dx.contains(dx_true) and ddx.contains(ddx_true)
    n = x.nb_slices()
    # printed figures at delta = 0.001
    assert abs(x[0].max_thickness() - 0.6051) < 1e-3 and abs(x[1].max_thickness() - 2.1952) < 1e-3
    xf = x.gate(n)
    assert abs(xf[0].lb() - 9.6974) < 1e-3 and abs(xf[1].ub() - 1.0928) < 1e-3
    # x1 never thinner than the initial uncertainty, x2 the pessimistic one
    assert x[0].max_thickness() >= 0.4 and x[1].max_thickness() > x[0].max_thickness()


def test_lissajous_main(tmp_path):
    ok, results = lissajous.main(deltas=(0.01, 0.001), out=tmp_path)
    assert ok and (tmp_path / "lissajous_py.svg").exists()


# ---- 4.4.3: kidnapped robot ----

def test_kidnapped_robot_coarse():
    td = kidnapped.make_tdomain(0.05)
    x, stats, k37 = kidnapped.solve(td)
    assert not stats.empty and td.t(k37) == 37.0
    paths = kidnapped.reference_paths(0.05)
    # the nominal truth passes through the measurement box (4.30)
    p37 = paths[int(round(37 / 0.0125)), 0]
    assert kidnapped.M1.contains(p37[0]) and kidnapped.M2.contains(p37[1])
    assert kidnapped.max_excess(x, paths) <= 1e-9
    n = td.nb_slices()
    d0 = kidnapped.diagonal(x.gate(0).subvector(0, 1))
    d37 = kidnapped.diagonal(x.gate(k37).subvector(0, 1))
    d64 = kidnapped.diagonal(x.gate(n).subvector(0, 1))
    assert abs(d37 - 2 * math.sqrt(2)) < 1e-9  # the measurement box itself
    assert abs(d0 - 37.070) < 0.01 and abs(d64 - 81.761) < 0.01
    assert d37 < d0 < d64
    # thickness decreases towards 37 and increases after it
    th = [kidnapped.diagonal(x.gate(k).subvector(0, 1)) for k in range(n + 1)]
    assert all(a >= b - 1e-9 for a, b in zip(th[:k37], th[1:k37 + 1]))
    assert all(a <= b + 1e-9 for a, b in zip(th[k37:], th[k37 + 1:]))


def test_kidnapped_robot_eval_variant_and_no_prior():
    td = kidnapped.make_tdomain(0.05)
    x, _, _ = kidnapped.solve(td)
    xe, _, _ = kidnapped.solve(td, use_eval=True)
    assert xe == x
    xu, _, k37 = kidnapped.solve(td, heading_speed_known=False)
    assert math.isinf(xu[0].gate(0).diam()) and xu[0].gate(k37).is_subset(kidnapped.M1)


def test_kidnapped_robot_main(tmp_path):
    ok, results = kidnapped.main(deltas=(0.05,), out=tmp_path)
    assert ok


def test_kidnapped_robot_figures_of_the_example():
    td = kidnapped.make_tdomain(0.005)
    x, _, k37 = kidnapped.solve(td)
    n = td.nb_slices()
    d = [kidnapped.diagonal(x.gate(k).subvector(0, 1)) for k in (0, k37, n)]
    assert abs(d[0] - 18.709) < 0.01 and abs(d[1] - 2.828) < 0.01 and abs(d[2] - 38.868) < 0.01
