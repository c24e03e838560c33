"""The slam/ layer from Python (thesis ch. 7): CtcT1T2 (Alg. 11) on hand cases
and a drifting tube with a known loop, CtcOmega (Alg. 12) on a two-box paving,
errors and reprs."""
import math

import pytest
import sillage
from sillage import CtcOmega, CtcPImpliesZ, CtcT1T2, Interval, IntervalVector, TDomain, Tube, TubeVector


def drifting_loop():
    """p*(t) = cos(t) on [0, 2π]: thin early, drifting late; w thin."""
    td = TDomain(0.0, 2 * math.pi, 0.01)
    p = TubeVector([Tube(td, "cos(t) + [-1,1]*(0.02 + 0.1*t)")])
    w = TubeVector([Tube(td, "-sin(t) + [-0.01,0.01]")])
    return td, p, w, sillage.Trajectory("cos(t)", Interval(0, 2 * math.pi))


def two_gates(g2, g7):
    """p in [-10, 10] on [0, 10], w unknown, gates 2 and 7 given."""
    td = TDomain(0.0, 10.0, 1.0)
    p, w = Tube(td, Interval(-10, 10)), Tube(td, Interval())
    p.set_gate(2, g2)
    p.set_gate(7, g7)
    return td, p, w


def test_known_times_intersect_the_two_gates():
    td, p, w = two_gates(Interval(0, 1), Interval(0.5, 2))
    t1, t2 = Interval(2.0), Interval(7.0)
    assert CtcT1T2().contract(t1, t2, p, w)
    assert p.gate(2) == Interval(0.5, 1) and p.gate(7) == Interval(0.5, 1)


def test_times_contracted_in_place():
    td = TDomain(0.0, 10.0, 0.5)
    p = TubeVector([Tube(td, "t")])
    w = TubeVector([Tube(td, Interval(1.0))])
    t1, t2 = Interval(1, 4), Interval(3, 8)
    assert CtcT1T2().contract(t1, t2, p, w)
    assert t1 == Interval(3, 4) and t2 == Interval(3, 4)


def test_drifting_tube_pulled_back_truth_kept():
    td, p, w, truth = drifting_loop()
    before = p.copy()
    t1, t2 = Interval(1.1, 1.3), Interval(4.9, 5.3)
    assert CtcT1T2().contract(t1, t2, p, w)
    assert p.is_subset(before) and p.volume() < before.volume()
    assert p[0].contains(truth)
    assert t1.contains(1.2) and t2.contains(2 * math.pi - 1.2)
    k = td.slice_index(5.1)
    assert before[0].thickness(k) > 1.0 and p[0].thickness(k) < 0.6


def test_inconsistent_and_bad_input():
    td, p, w = two_gates(Interval(0, 1), Interval(2, 3))
    t1, t2 = Interval(2.0), Interval(7.0)
    assert not CtcT1T2().contract(t1, t2, p, w)
    assert t1.is_empty() and t2.is_empty() and p.is_empty()
    with pytest.raises(sillage.DimensionError):
        CtcT1T2().contract(Interval(1, 2), Interval(3, 4), TubeVector(td, 2), TubeVector(td, 3))
    with pytest.raises(sillage.Error, match="t1"):
        CtcT1T2().contract(Interval(20, 30), Interval(3, 4), TubeVector(td, 2), TubeVector(td, 2))
    with pytest.raises(sillage.Error):
        CtcT1T2(ratio=1.0)


def test_omega_two_box_paving_is_the_hull_of_each_box():
    td, p, w, truth = drifting_loop()
    boxes = [IntervalVector([Interval(1.1, 1.3), Interval(4.9, 5.3)]),
             IntervalVector([Interval(1.0, 1.1), Interval(5.2, 5.4)])]
    expected = TubeVector(td, 1, Interval.empty())
    for b in boxes:
        q = p.copy()
        t1, t2 = b[0], b[1]
        assert CtcT1T2().contract(t1, t2, q, w)
        expected |= q
    before = p.copy()
    assert CtcOmega().contract(boxes, p, w)
    assert p == expected and p.is_subset(before) and p[0].contains(truth)
    # an inconsistent box is left out; no consistent box: p emptied
    q = before.copy()
    assert CtcOmega().contract(boxes + [IntervalVector([Interval(1.1, 1.3), Interval(2.9, 3.3)])], q, w)
    assert q == expected
    assert not CtcOmega().contract([IntervalVector([Interval(1.1, 1.3), Interval(2.9, 3.3)])], q, w)
    assert q.is_empty()


def test_reprs():
    assert repr(CtcT1T2()) == "CtcT1T2(ratio=0.001, max_passes=100)"
    assert repr(CtcOmega()) == "<CtcOmega>"


def small_slam(bias="0"):
    """The figure eight of tests/cpp/slam/small_slam.h: one self-crossing at
    t1 = 1/2, t2 = 1/2 + π; dead reckoning from a start known to ±0.05 with
    velocities to ±0.2; z = g(p) to ±0.01 (g never given)."""
    td = TDomain(0.0, 5.0, 0.01)
    w = TubeVector([Tube(td, "10*cos(t - 0.5) + [-0.2,0.2]"), Tube(td, "10*cos(2*t - 1) + [-0.2,0.2]")])
    z = Tube(td, "sin(10*sin(t - 0.5)/3) + cos(5*sin(2*t - 1)/4) + sin(t - 0.5) + [-0.01,0.01] + " + bias)
    p = TubeVector(td, 2)
    p.set_gate(0, IntervalVector([Interval(-4.85, -4.75), Interval(-4.26, -4.16)]))
    sillage.CtcDeriv().contract(p, w)
    truth = [sillage.Trajectory("10*sin(t - 0.5)", Interval(0, 5)), sillage.Trajectory("5*sin(2*t - 1)", Interval(0, 5))]
    return td, p, w, z, truth


def test_p_implies_z_accurate_pulls_the_end_back_and_keeps_the_truth():
    td, p, w, z, truth = small_slam()
    dr = p.copy()
    rows = CtcPImpliesZ(0.01).contract(p, w, z)
    assert rows and rows[0].nb_proofs == 1 and not rows[0].fast
    assert rows[-1].contraction_tf > 0.1
    assert [r.iteration for r in rows] == list(range(1, len(rows) + 1))
    assert p.is_subset(dr) and p.contains(truth)


def test_p_implies_z_fast_then_accurate_never_wider():
    td, p, w, z, truth = small_slam()
    fast_rows = CtcPImpliesZ(0.01, fast=True).contract(p, w, z)
    assert fast_rows[0].fast and p.contains(truth)
    after_fast = p.copy()
    CtcPImpliesZ(0.01).contract(p, w, z)
    assert p.is_subset(after_fast) and p.contains(truth)


def test_constant_bias_changes_nothing():
    td, p, w, z, _ = small_slam()
    _, q, wq, zq, _ = small_slam("3.25")
    CtcPImpliesZ(0.01).contract(p, w, z)
    CtcPImpliesZ(0.01).contract(q, wq, zq)
    n = td.nb_slices()
    assert all(p[i].slice(k) == q[i].slice(k) and p[i].gate(k) == q[i].gate(k) for i in range(2) for k in range(n))


def test_p_implies_z_in_a_network():
    td, p, w, z, truth = small_slam()
    dr = p.copy()
    cn = sillage.ContractorNetwork()
    cn.add(CtcPImpliesZ(0.01), [p, w, TubeVector([z])])
    assert not cn.contract().empty
    assert p.is_subset(dr) and p.volume() < dr.volume() and p.contains(truth)


def test_p_implies_z_bad_input_and_repr():
    td, p, w, z, truth = small_slam()
    with pytest.raises(sillage.Error):
        CtcPImpliesZ(0.0)
    with pytest.raises(sillage.DimensionError):
        CtcPImpliesZ(0.01).contract(TubeVector(td, 3), w, z)
    assert repr(CtcPImpliesZ(0.01, fast=True)) == "CtcPImpliesZ(eps=0.01, fast=True)"
    assert repr(sillage.SlamRow()).startswith("SlamRow(iteration=0, fast=False")


def mission():
    """The figure eight as a 3-D state (x1, x2, depth), f(x, u) = u, h(x) = (x1, x2)."""
    td, p, w, z, truth = small_slam()
    x, v = TubeVector(td, 3), TubeVector(td, 3)
    x.set_gate(0, IntervalVector([p.gate(0)[0], p.gate(0)[1], Interval(-5.05, -4.95)]))
    u = TubeVector([w[0], w[1], Tube(td, Interval(-0.01, 0.01))])
    f = sillage.Function(["x1", "x2", "x3", "u1", "u2", "u3"], "(u1, u2, u3)")
    h = sillage.Function(["x1", "x2", "x3"], "(x1, x2)")
    truth = truth + [sillage.Trajectory("-5", Interval(0, 5))]
    return x, v, u, TubeVector([z]), f, h, truth


def test_temporal_slam_fast_then_accurate():
    x, v, u, z, f, h, truth = mission()
    o = sillage.TemporalSlamOptions()
    o.eps = 0.01
    rows = sillage.temporal_slam(x, v, u, z, f, h, o)
    assert rows[0].fast and not rows[-1].fast
    assert [r.iteration for r in rows] == list(range(1, len(rows) + 1))
    assert rows[-1].contraction_tf > 0.1
    assert x.contains(truth)
    assert "eps=0.01" in repr(o)


def test_tide_and_observation():
    tide = sillage.TideModel(range=4.0, duration=21600.0, t_low=0.0)
    assert tide(Interval(0.0)) == Interval(0.0)
    assert tide(Interval(21600.0)).contains(4.0)
    td = TDomain(0.0, 10.0, 1.0)
    z = sillage.bathymetric_observation(Tube(td, Interval(10, 11)), Tube(td, Interval(5, 5.5)),
                                        sillage.TideModel(range=2.0, duration=10.0, t_low=0.0))
    assert z.gate(0) == Interval(15, 16.5)
    assert sillage.tide_tube(td, tide).gate(0) == Interval(0.0)
    with pytest.raises(sillage.Error, match="duration"):
        sillage.tide_tube(td, sillage.TideModel(duration=-1.0))
    assert repr(tide).startswith("TideModel(")


def test_temporal_slam_on_iteration_sees_every_row():
    """The observer gets each row and p (2-D): the truth inside at every iteration,
    accurate never wider than the last fast p; an exception in it stops the run."""
    x, v, u, z, f, h, truth = mission()
    o = sillage.TemporalSlamOptions()
    o.eps = 0.01
    seen = []

    def watch(row, p):
        seen.append((row.iteration, row.fast, p))
        assert p.contains(truth[:2])

    o.on_iteration = watch
    rows = sillage.temporal_slam(x, v, u, z, f, h, o)
    assert [s[0] for s in seen] == [r.iteration for r in rows]
    last_fast = [p for _, fast, p in seen if fast][-1]
    assert all(p.is_subset(last_fast) for _, fast, p in seen if not fast)

    def stop(row, p):
        raise ValueError("stop here")

    x, v, u, z, f, h, truth = mission()
    o.on_iteration = stop
    with pytest.raises(ValueError, match="stop here"):
        sillage.temporal_slam(x, v, u, z, f, h, o)


def test_slam_figures():
    td = TDomain(0.0, 10.0, 1.0)
    a = TubeVector(td, IntervalVector([Interval(0, 4), Interval(0, 3)]))
    b = TubeVector(td, IntervalVector([Interval(1, 2), Interval(1, 2)]))
    svg = sillage.slam_thickness_figure([sillage.ThicknessCurve(a, "dead reckoning", "#777777"),
                                         sillage.ThicknessCurve(b, "slam", "#d62728")]).svg()
    assert "dead reckoning" in svg and "#d62728" in svg
    assert repr(sillage.ThicknessCurve(a, "x", "red")) == "ThicknessCurve(label='x', colour='red')"
    with pytest.raises(sillage.Error):
        sillage.slam_thickness_figure([])
    opts = sillage.BathymetryMissionOptions()
    opts.duration = 300.0
    m = sillage.BathymetryMission(seed=3, options=opts)
    tdm = m.tdomain(1.0)
    p = sillage.bathymetry_dead_reckoning(m, tdm, sillage.bathymetry_initial_box(m))
    fig = sillage.slam_map_figure(m, p, p, [p.gate(tdm.nb_slices())])
    assert "p-tf" in fig.svg()


def test_ctc_omega_hull_is_contract_without_doing_it():
    td, p, w, truth = drifting_loop()
    boxes = [IntervalVector([Interval(1.1, 1.3), Interval(4.9, 5.3)]),
             IntervalVector([Interval(1.0, 1.1), Interval(5.2, 5.4)])]
    before = p.copy()
    h = CtcOmega().hull(boxes, p, w)
    assert p == before and not h.empty and len(h.atoms) > 0
    assert h.nb_boxes == 2 and h.nb_consistent == 2 and h.nb_touched >= len(h.atoms)
    q = p.copy()
    assert h.apply_to(q)
    r = p.copy()
    assert CtcOmega().contract(boxes, r, w)
    assert q == r and q.contains([truth])
    a = h.atoms[0]
    assert a.component == 0 and a.value.is_subset(p[0].gate(a.atom // 2) if a.atom % 2 == 0 else p[0].slice(a.atom // 2))
    assert repr(h).startswith("OmegaHull(empty=False") and repr(a).startswith("OmegaHullAtom(component=0")
