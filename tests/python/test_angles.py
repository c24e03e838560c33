"""Angles known modulo 2 pi in Python, same names as C++: angle_meet / angle_contains, the angle
tube contractors CtcDerivAngle and CtcEvalAngle (alone and in a network), CtcAngleEquation (a
bearing from a heading wider than a turn), and `angle = true` in a problem file."""
import math

import pytest
import sillage
from sillage import (ContractorNetwork, CtcAngleEquation, CtcDerivAngle, CtcEvalAngle, Function, Interval,
                     IntervalVector, TDomain, Tube, angle_contains, angle_is_circle, angle_meet)


def test_angle_meet_and_contains():
    r = angle_meet(Interval(-46, 46), Interval(1, 1.1) + Interval(40 * math.pi))
    assert r.is_subset(Interval(-46, 46)) and r.diam() < 0.1 + 1e-10
    assert angle_contains(r, 1.05) and angle_contains(r, 1.05 + 2 * math.pi)
    assert angle_meet(Interval(0, 1), Interval(2, 3)).is_empty()
    assert angle_meet(Interval(0, 6), Interval(5.5, 6.5)) == Interval(0, 6)
    assert angle_is_circle(Interval(-4, 4)) and not angle_is_circle(Interval(-3, 3))


def test_ctc_deriv_angle_narrows_the_past_from_a_late_arc():
    td = TDomain(0, 20, 0.5)
    x, v = Tube(td), Tube(td, Interval(0.5, 1.5))
    x.set_gate(0, Interval(0, 0.1))
    assert CtcDerivAngle().contract(x, v)
    assert angle_is_circle(x.gate(40))
    x.set_gate(40, angle_meet(x.gate(40), Interval(20.0, 20.1) - Interval(6 * math.pi)))
    assert CtcDerivAngle().contract(x, v)
    assert angle_contains(x.gate(39), 19.25) and angle_contains(x.gate(39), 19.85)
    assert x.gate(39).diam() == pytest.approx(0.6)
    ok, changed = CtcDerivAngle().contract_local(x, v, 0, 39)
    assert ok and changed == []  # already a fixed point there


def test_ctc_eval_angle_alone_and_in_a_network():
    td = TDomain(0, 10, 0.5)
    x, v = Tube(td), Tube(td, Interval(0.9, 1.1))
    z = Interval(5.23, 5.27) - Interval(2 * math.pi)
    assert CtcEvalAngle().contract(Interval(5.1, 5.3), z, x, v)
    assert angle_contains(x.gate(10), 5.05) and x.gate(10).diam() < 1
    y = Tube(td)
    y.set_angle(True)
    assert y.is_angle() and y.copy().is_angle()
    t, z2 = Interval(5.1, 5.3), Interval(5.23, 5.27)
    cn = ContractorNetwork()
    cn.add(CtcEvalAngle(), [t, z2, y, v])
    cn.add(CtcDerivAngle(), [y, v])
    cn.contract()
    assert angle_contains(y.gate(0), 0.05) and y.gate(0).diam() < 3


def test_ctc_angle_equation_bearing():
    # Robot at (0, 0), landmark at (3, 4), heading 1 + 7 turns: bearing atan2(4, 3) - 1.
    c = CtcAngleEquation([-1], Function(["px", "py", "b"], "atan2(4 - py, 3 - px) - b + [-0.01, 0.01]"))
    box = IntervalVector([Interval(-46, 46), Interval(-0.01, 0.01), Interval(-0.01, 0.01),
                          Interval(math.atan2(4, 3) - 1)])
    c.contract(box)
    assert angle_contains(box[0], 1 + 14 * math.pi) and box[0].diam() < 0.05
    assert c.signs() == [-1]
    with pytest.raises(sillage.Error):
        CtcAngleEquation([2], Function(["u"], "u"))


def test_problem_file_angle(tmp_path):
    (tmp_path / "b.csv").write_text("t,b\n" + "".join(
        f"{2 * i},{math.remainder(math.atan2(4, 3) - (i + 1), 2 * math.pi)}\n" for i in range(1, 30)))
    (tmp_path / "p.toml").write_text(
        '[time]\ndomain = [0, 60]\ndelta = 0.1\n[data.b]\nfile = "b.csv"\n'
        '[var.psi]\nkind = "tube"\nangle = true\n[var.omega]\nkind = "tube"\nvalue = "[0.45, 0.55]"\n'
        '[[constraint]]\nkind = "deriv"\nx = "psi"\nv = "omega"\n'
        '[[constraint]]\nkind = "eval"\ndata = "b"\ny = "psi"\nv = "omega"\ntime = "t"\ntime_error = 0.01\n'
        'expr = "atan2(4, 3) - psi - b + [-0.02, 0.02]"\n')
    r = sillage.solve(str(tmp_path / "p.toml"))
    assert not r.empty
    psi = r.domains["psi"]
    assert angle_contains(psi.gate(300), 0.5 * 30 + 1) and psi.gate(300).diam() < 0.2
    (tmp_path / "bad.toml").write_text((tmp_path / "p.toml").read_text().replace(
        'expr = "atan2', 'expr = "2*psi + atan2'))
    with pytest.raises(sillage.ParseError, match="outside sin, cos, tan"):
        sillage.load_problem(str(tmp_path / "bad.toml"))
