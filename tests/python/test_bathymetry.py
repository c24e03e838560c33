"""The synthetic bathymetric mission from Python: same names as C++, determinism
from the seed, the DEM as an inclusion function, the truth inside the dead
reckoning and the observation tubes, bad input refused."""
import math

import numpy as np
import pytest

import sillage
from sillage import BathymetryDem, BathymetryMission, Interval, IntervalVector


@pytest.fixture(scope="module")
def mission():
    return BathymetryMission(seed=7)


def test_summary_and_determinism(mission):
    assert mission.nb_samples == 57601
    assert 5500 < mission.path_length() < 6300
    again = BathymetryMission(seed=7)
    assert np.array_equal(again.x1, mission.x1)
    assert np.array_equal(again.measured.altitude, mission.measured.altitude)
    other = BathymetryMission(seed=8)
    assert not np.array_equal(other.dem.depths(), mission.dem.depths())
    assert "BathymetryMission(seed=7" in repr(mission)


def test_measurements_within_stated_bounds(mission):
    b, t, m = mission.bounds, mission.truth, mission.measured
    deg = np.pi / 180
    assert np.all(np.abs(m.yaw - t.yaw) <= b.heading * deg)
    assert np.all(np.abs(m.depth - t.depth) <= b.depth)
    speed = np.sqrt(m.vx ** 2 + m.vy ** 2 + m.vz ** 2)
    assert np.all(np.abs(m.vx - t.vx) <= b.dvl_scale * speed + b.dvl_offset)
    assert np.all(np.abs(m.altitude - mission.filtered_altitude) <= b.altitude_scale * m.altitude + b.altitude_offset)


def test_dem_encloses_random_points_and_boxes(mission):
    dem = mission.dem
    rng = np.random.default_rng(1)
    for x, y in rng.uniform(0, 500, size=(300, 2)):
        i, j = min(int(x), 499), min(int(y), 499)
        u, v = x - i, y - j
        ref = ((1 - u) * (1 - v) * dem.node(i, j) + u * (1 - v) * dem.node(i + 1, j)
               + (1 - u) * v * dem.node(i, j + 1) + u * v * dem.node(i + 1, j + 1))
        assert dem(x, y).inflate(1e-9).contains(ref)
        box = IntervalVector([[max(0, x - 3), min(500, x + 3)], [max(0, y - 2), min(500, y + 2)]])
        r = dem.eval(box)
        assert r.contains(dem(x, y).mid())
        assert r.is_subset(dem.eval_cells(box))
    assert dem.eval(IntervalVector([[-5, 5], [0, 1]])).is_unbounded()  # outside the map: unknown


def test_dem_by_hand_and_errors():
    dem = BathymetryDem(0, 0, 2, np.array([[0.0, 1, 2], [3, 4, 5]]))
    assert dem.eval(IntervalVector([[0, 4], [0, 2]])) == Interval(0, 5)
    assert abs(dem.eval(IntervalVector([[1, 3], [0.5, 1.5]])).lb() - 1.25) < 1e-12
    with pytest.raises(sillage.Error):
        BathymetryDem(0, 0, 0.1, np.zeros((2, 4)))  # 3 * 0.1 is not exact
    with pytest.raises(sillage.Error):
        BathymetryDem(0, 0, 1, np.zeros(4))


def inside(tube, times, values):
    tp = np.asarray(tube.tdomain().times())
    s = np.asarray(tube.slices_array())
    g = np.asarray(tube.gates_array())
    k = np.clip(np.searchsorted(tp, times, side="right") - 1, 0, len(s) - 1)
    ok_s = (values >= s[k, 0]) & (values <= s[k, 1])
    on = np.isin(times, tp)
    kg = np.searchsorted(tp, times[on])
    ok_g = (values[on] >= g[kg, 0]) & (values[on] <= g[kg, 1])
    return ok_s.all() and ok_g.all()


def test_truth_inside_the_tubes(mission):
    td = mission.tdomain(2.0)
    p = sillage.bathymetry_dead_reckoning(mission, td, sillage.bathymetry_initial_box(mission))
    z = sillage.bathymetry_observation_tube(mission, td)
    w = sillage.bathymetry_velocity_tube(mission, td)
    assert len(p) == 3 and len(w) == 3
    t = mission.times
    assert inside(p[0], t, mission.x1) and inside(p[1], t, mission.x2) and inside(p[2], t, mission.truth.depth)
    zt = sillage.bathymetry_truth_observation(mission)
    assert inside(z, t, np.asarray(zt.sample_values()))
    # Fig. 7.17: tens of metres of drift at the end.
    pf = p.gate(td.nb_slices())
    assert 20 < np.hypot(pf[0].diam(), pf[1].diam()) < 150


def test_footprint_and_tide(mission):
    pts = sillage.dvl_footprint(250, 250, 0.2, 10)
    assert len(pts) == 20
    c = mission.seabed.bounds
    e = sillage.footprint_filter_bound(c, 1.0, 10)
    assert abs(sillage.footprint_depth(mission.dem, 250, 250, 0.2, 10) - mission.dem(250, 250).mid()) <= e
    assert sillage.footprint_filter_bound(c, 1.0, 20) > e  # wider when higher
    tide = sillage.TideModel()
    assert tide.height(Interval(tide.t_low)).contains(0)
    assert tide.height(Interval(0)).contains(tide.height_value(0))


def test_bad_input(mission):
    with pytest.raises(sillage.Error):
        mission.tdomain(0.25)
    with pytest.raises(sillage.Error):
        sillage.bathymetry_observation_tube(mission, sillage.TDomain(0, 5760, 0.7))
    o = sillage.BathymetryMissionOptions()
    o.rail_spacing = 60
    with pytest.raises(sillage.Error):
        BathymetryMission(seed=1, options=o)


def test_figures(mission, tmp_path):
    td = mission.tdomain(4.0)
    p = sillage.bathymetry_dead_reckoning(mission, td, sillage.bathymetry_initial_box(mission))
    f = sillage.bathymetry_dem_figure(mission.dem, list(mission.x1), list(mission.x2))
    f.save(str(tmp_path / "dem.svg"))
    assert (tmp_path / "dem.svg").stat().st_size > 10000
    assert "<svg" in sillage.bathymetry_map_figure(mission, p).svg()
    assert sillage.depth_colour(0, 0, 1) != sillage.depth_colour(1, 0, 1)


def test_range_observation_tubes():
    """Range-only temporal SLAM without beacon positions: z = the ranges, one tube each."""
    td = sillage.TDomain(0, 10, 1)
    z = sillage.range_observation_tubes(td, [0.0, 10.0], [3, 3], [20.0, 24.0], [3],
                                        sillage.RangeBounds(1.0, 2.0, 0.5, 1.0))
    assert len(z) == 1
    assert z[0].gate(5) == Interval(16.5, 26.5)
    with pytest.raises(sillage.Error):
        sillage.range_observation_tubes(td, [0.0], [1], [3.0], [2])


def test_range_observation_plaza1():
    import csv
    from pathlib import Path
    d = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "plaza1"
    if not (d / "ranges.csv").exists():
        pytest.skip("no plaza1 data")

    def cols(name):
        with open(d / name) as f:
            rows = list(csv.DictReader(f))
        return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}
    gt, rg, bc = cols("ground_truth.csv"), cols("ranges.csv"), cols("beacons.csv")
    ids = [int(i) for i in bc["beacon_id"]]
    td = sillage.TDomain(gt["t_s"][0], gt["t_s"][-1], 2.0)
    z = sillage.range_observation_tubes(td, list(rg["t_s"]), [int(i) for i in rg["beacon_id"]], list(rg["range_m"]),
                                        ids)
    for i in range(len(ids)):
        truth = np.hypot(gt["x_m"] - bc["x_m"][i], gt["y_m"] - bc["y_m"][i])
        for t, r in list(zip(gt["t_s"], truth))[::7]:
            assert z[i](float(t)).contains(float(r))


def test_relief_scales_the_seabed_class():
    o = sillage.SeabedOptions()
    one = sillage.generate_seabed(5, o)
    o.relief = 2.0
    two = sillage.generate_seabed(5, o)
    assert abs(two.bounds.curvature - 2 * one.bounds.curvature) < 1e-12
    assert abs(two.bounds.slope - 2 * one.bounds.slope) < 1e-12
    o.relief = -1.0
    with pytest.raises(sillage.Error, match="relief"):
        sillage.generate_seabed(5, o)


def test_coastal_seabed_and_transects():
    smooth = sillage.generate_seabed(7)
    coastal = sillage.generate_seabed(7, sillage.coastal_seabed_options())
    assert coastal.bounds.curvature > smooth.bounds.curvature
    box = sillage.IntervalVector([[320, 350], [200, 230]])
    assert coastal.dem.eval(box).diam() > smooth.dem.eval(box).diam()
    o = sillage.coastal_seabed_options()
    assert o.dune_height > 0 and o.rock_height_min >= 1.5
    o.rock_height_max = o.rock_height_min - 1
    with pytest.raises(sillage.Error, match="rock_height"):
        sillage.generate_seabed(7, o)
    mo = sillage.BathymetryMissionOptions()
    mo.duration, mo.transects = 600.0, True
    m = sillage.BathymetryMission(seed=7, options=mo)
    # The first leg is the eastward transect at 0.3 of the side.
    assert abs(m.x2[3000] - 150) < 3 and m.x1[3000] > m.x1[0] + 250


def test_tie_line_layout():
    """Tie lines at 17 deg to the rails first, from the south-east; bad angles refused."""
    mo = sillage.BathymetryMissionOptions()
    mo.duration, mo.tie_line_angle = 600.0, 17.0
    m = sillage.BathymetryMission(seed=7, options=mo)
    assert m.options.tie_line_angle == 17.0
    assert m.x1[0] > 400 and abs(m.x2[0] - 100) < 1
    dx, dy = m.x1[2500] - m.x1[300], m.x2[2500] - m.x2[300]
    assert abs(math.degrees(math.atan2(-dx, dy)) - 17) < 1.5  # north-west, 17 deg from north
    for bad in (-1.0, 50.0):
        mo.tie_line_angle = bad
        with pytest.raises(sillage.Error, match="tie_line_angle"):
            sillage.BathymetryMission(seed=7, options=mo)


def test_channel_banks_class_on_the_nodes():
    """The bank seabed: two flanks whose stated class holds on the nodes (the flanks alone,
    as the difference of the DEMs with and without them); ChannelBank from Python."""
    o = sillage.bank_seabed_options()
    banks = o.channel_banks
    assert len(banks) == 2 and banks[0].direction == 180.0 and banks[1].direction == 90.0
    none = sillage.bank_seabed_options()
    none.channel_banks = []
    s, f = sillage.generate_seabed(7, o), sillage.generate_seabed(7, none)
    kappa = sum(0.385 * abs(b.height) / b.width ** 2 for b in banks)
    slope = sum(abs(b.height) / (2 * b.width) for b in banks)
    assert math.isclose(s.bounds.curvature, f.bounds.curvature + 1.01 * kappa, abs_tol=1e-12)
    assert math.isclose(s.bounds.slope, f.bounds.slope + 1.01 * slope, abs_tol=1e-12)
    d, q = np.asarray(s.dem.depths()) - np.asarray(f.dem.depths()), 0.001  # two millimetre roundings
    for axis in (0, 1):
        assert np.abs(np.diff(d, axis=axis)).max() <= slope + 2 * q
        assert np.abs(np.diff(d, 2, axis=axis)).max() <= kappa + 4 * q
    d10 = d[::10, ::10]  # step 10 m: the curvature shows above the rounding
    worst = max(np.abs(np.diff(d10, 2, axis=a)).max() for a in (0, 1))
    assert 0.3 * kappa * 100 < worst <= kappa * 100 + 4 * q
    c = sillage.ChannelBank(height=10.0, width=20.0, direction=90.0, x=0.0, y=100.0)
    assert "ChannelBank(" in repr(c) and "width=20" in repr(c)
    o.channel_banks = [c]
    assert o.channel_banks[0].width == 20.0
    o.channel_banks = [sillage.ChannelBank(width=0.0)]
    with pytest.raises(sillage.Error, match="channel bank"):
        sillage.generate_seabed(7, o)
    mo = sillage.bank_mission_options()
    assert mo.transects and mo.bounds.beam_angle == 0.0 and len(mo.seabed.channel_banks) == 2


def test_a_channel_flank_contracts_the_end():
    """The twin of the C++ test (fast algorithm): a rail crossing the southern transect on a
    flank near the end of a 2100 s mission; the truth at every gate of every iteration."""
    mo = sillage.bank_mission_options()
    mo.duration = 2100.0
    mo.seabed.channel_banks = [sillage.ChannelBank(12.0, 24.0, 0.0, 385.0, 250.0)]
    m = BathymetryMission(seed=7, options=mo)
    td = m.tdomain(1.0)
    w = sillage.bathymetry_velocity_tube(m, td)
    z = sillage.TubeVector([sillage.bathymetry_observation_tube(m, td)])
    x = sillage.bathymetry_dead_reckoning(m, td, sillage.bathymetry_initial_box(m))
    gates = np.asarray(td.times())
    idx = np.searchsorted(np.asarray(m.times), gates)
    lost = []

    def on_iteration(row, p):
        for c, truth in ((0, np.asarray(m.x1)[idx]), (1, np.asarray(m.x2)[idx])):
            g = np.asarray(p[c].gates_array())
            lost.append(int(((truth < g[:, 0]) | (truth > g[:, 1])).sum()))

    o = sillage.TemporalSlamOptions()
    o.eps, o.accurate, o.on_iteration = 1.0, False, on_iteration
    f = sillage.Function(["x1", "x2", "x3", "u1", "u2", "u3"], "(u1, u2, u3)")
    h = sillage.Function(["x1", "x2", "x3"], "(x1, x2)")
    rows = sillage.temporal_slam(x, w.copy(), w, z, f, h, o)
    assert lost and sum(lost) == 0
    assert rows[-1].contraction_tf > 0.10  # measured 16.4 %
