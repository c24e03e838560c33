"""The dead-reckoning example (thesis 3.4) on a coarse slicing: the network
(CtcDeriv) is no wider than plain, every resolution contains the nominal and extreme RK4
paths, taylor and linear tighten in turn, and the delta = 0.005 figure of the
plain resolution is reproduced."""
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "examples" / "python"))
dr = pytest.importorskip("dead_reckoning")
from sillage import Interval, TDomain  # noqa: E402


def test_plain_and_cn_coarse():
    td = TDomain(0.0, 64.0, 0.05)
    plain, cn = dr.solve_plain(td), dr.solve_cn(td)
    paths = dr.rk4_paths(0.05)
    for x in (plain, cn):
        misses, _, _ = dr.check(x, paths)
        assert misses == 0
    n = td.nb_slices()
    # Up to rounding: the network's pointwise cos and sin rows (batch kernel) may be a few ulps
    # wider than the scalar functions of the tube arithmetic of plain.
    for i in (0, 1):
        c, p = cn[i].gate(n), plain[i].gate(n)
        assert c.lb() >= p.lb() - 1e-12 * abs(p.lb()) and c.ub() <= p.ub() + 1e-12 * abs(p.ub())


def test_plain_figure_of_the_brief():
    td = TDomain(0.0, 64.0, 0.005)
    x = dr.solve_plain(td)
    n = td.nb_slices()
    p1, p2 = x[0].gate(n), x[1].gate(n)
    assert abs(p1.lb() - 21.23) < 0.01 and abs(p1.ub() - 55.61) < 0.01
    assert abs(p2.lb() - 31.61) < 0.01 and abs(p2.ub() - 74.23) < 0.01
    # the nominal final position (RK4)
    assert p1.contains(38.3299) and p2.contains(53.0694)


def test_taylor_and_linear_contain_the_paths_and_tighten():
    td = TDomain(0.0, 64.0, 0.05)
    paths = dr.rk4_paths(0.05)
    taylor = dr.solve_taylor(td)
    linear = dr.solve_linear(td, taylor)
    plain = dr.solve_plain(td)
    n = td.nb_slices()
    for x in (taylor[0], linear):
        misses, _, _ = dr.check(x, paths)
        assert misses == 0
    for i in (0, 1):
        assert linear[i].gate(n).diam() < taylor[0][i].gate(n).diam() < plain[i].gate(n).diam()
    # the sampled true set at t = 64 spans about [33.9, 42.9] x [50.0, 56.1]
    assert linear[0].gate(n).is_superset(Interval(33.9, 42.9))
    assert linear[1].gate(n).is_superset(Interval(50.0, 56.1))



def test_ivp_contains_the_paths_and_beats_the_network():
    """CtcIvp (validated integration) on the coarse slicing: bounded, every RK4 path inside
    (RK4's own error aside, 1e-9), and the final box far inside the CtcDeriv network's."""
    td = TDomain(0.0, 64.0, 0.05)
    ivp, cn = dr.solve_ivp(td), dr.solve_cn(td)
    assert len(ivp) == 4 and not ivp.is_empty()
    misses, _, _ = dr.check(ivp, dr.rk4_paths(0.05))
    assert misses == 0
    n = td.nb_slices()
    for i in (0, 1):
        g = ivp[i].gate(n)
        assert g.is_subset(cn[i].gate(n)) and g.diam() < 0.25 * cn[i].gate(n).diam()
        assert g.diam() < 13  # [32.66, 44.00] x [47.81, 58.32] measured


def test_map_figure_draws_the_nominal_path(tmp_path):
    """dead_reckoning_py.svg: the tube, and the nominal path over it, named in the legend."""
    import xml.etree.ElementTree as ET

    td = TDomain(0.0, 64.0, 0.05)
    name, _ = dr.map_figure(dr.solve_plain(td), dr.rk4_paths(0.05)[:, 0, :], tmp_path)
    svg = (tmp_path / name).read_text()
    root = ET.fromstring(svg.encode())
    ns = "{http://www.w3.org/2000/svg}"
    nominal = [e for e in root.iter(ns + "polyline") if e.get("class") == "nominal"]
    assert len(nominal) == 1 and len(nominal[0].get("points").split()) > 100
    assert "nominal path (RK4)" in svg
    # drawn after (over) every slice of the tube
    assert svg.index('class="nominal"') > svg.rindex('class="slice"')
