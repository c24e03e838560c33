// The temporal SLAM on the synthetic bathymetric mission (thesis 7.3.2, 7.3.3),
// shortened to 1800 s: the truth inside [p] at every gate and slice of every
// iteration, accurate never wider than fast, in both scenarios (start known;
// start unknown with one fix at mid-mission); a short mission whose rail
// crosses the southern transect on a channel flank, which contracts [p](t_f);
// the SLAM figures.
#include <gtest/gtest.h>

#include <string>

#include "sillage/error.h"
#include "sillage/expr/function.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_tubes.h"
#include "sillage/missions/slam_figures.h"
#include "sillage/slam/temporal_slam.h"

using namespace sillage;

namespace {

// Samples of the true path (east, north) outside p, at its gates and slices.
std::size_t misses(const BathymetryMission& m, const TubeVector& p) {
  const auto& td = *p.tdomain();
  std::size_t n = 0, k = 0;
  for (std::size_t i = 0; i < m.nb_samples(); ++i) {
    const double t = m.times()[i];
    while (k + 1 < td.nb_slices() && td.t(k + 1) <= t) ++k;
    const Interval a(m.x1()[i]), b(m.x2()[i]);
    if (!p[0].slice(k).is_superset(a) || !p[1].slice(k).is_superset(b)) ++n;
    for (std::size_t g : {k, k + 1})
      if (td.t(g) == t && (!p[0].gate(g).is_superset(a) || !p[1].gate(g).is_superset(b))) ++n;
  }
  return n;
}

struct SlamRun {
  std::vector<SlamRow> rows;
  std::size_t lost = 0, wider = 0;
  TubeVector dr, x;
};

SlamRun run(int scenario, const BathymetryMission& m, bool accurate = true) {
  const auto td = m.tdomain(1.0);
  const std::size_t N = td->nb_slices();
  const TubeVector w = bathymetry_velocity_tube(m, td);
  const TubeVector z(std::vector<Tube>{bathymetry_observation_tube(m, td)});
  SlamRun r{{}, 0, 0, TubeVector(td, 2), bathymetry_dead_reckoning(m, td, bathymetry_initial_box(m))};
  if (scenario == 2) {
    const std::ptrdiff_t i = m.sample_index(td->t(N / 2));
    r.x[0].set(Interval());
    r.x[1].set(Interval());
    r.x[0].set_gate(N / 2, Interval(m.x1()[i]) + Interval(-1, 1));
    r.x[1].set_gate(N / 2, Interval(m.x2()[i]) + Interval(-1, 1));
  }
  TubeVector v = w, last_fast(td, 2);
  TemporalSlamOptions o;
  o.eps = 1.0;
  o.accurate = accurate;
  o.on_iteration = [&](const SlamRow& row, const TubeVector& p) {
    r.lost += misses(m, p);
    if (row.fast) last_fast = p;
    else if (!p.is_subset(last_fast)) ++r.wider;
  };
  r.rows = temporal_slam(r.x, v, w, z, Function({"x1", "x2", "x3", "u1", "u2", "u3"}, "(u1, u2, u3)"),
                         Function({"x1", "x2", "x3"}, "(x1, x2)"), o);
  r.lost += misses(m, r.x.subvector(0, 1));
  return r;
}

const BathymetryMission& default_mission() {
  static const BathymetryMission m(7, [] {
    BathymetryMissionOptions mo;
    mo.duration = 1800;
    return mo;
  }());
  return m;
}

// The bank mission shortened to 2100 s, with one flank (12 m over 24 m: 25 %)
// dropping eastward across x = 385 m: the rail there crosses the southern
// transect on it near the end (t ~ 2060 s), the transect running up the slope.
BathymetryMissionOptions short_bank_mission(bool flank) {
  BathymetryMissionOptions mo = bank_mission_options();
  mo.duration = 2100;
  mo.seabed.channel_banks.clear();
  if (flank) mo.seabed.channel_banks.push_back(ChannelBank{12, 24, 0, 385, 250});
  return mo;
}

}  // namespace

TEST(BathymetrySlam, KnownStartKeepsTheTruthAtEveryIteration) {
  const SlamRun r = run(1, default_mission());
  ASSERT_GE(r.rows.size(), 2u);  // fast then accurate
  EXPECT_TRUE(r.rows.front().fast);
  EXPECT_FALSE(r.rows.back().fast);
  EXPECT_GE(r.rows.back().nb_detections, 1u);
  EXPECT_EQ(r.lost, 0u);
  EXPECT_EQ(r.wider, 0u);
  for (const SlamRow& row : r.rows) {
    EXPECT_GE(row.contraction_tf, 0.0);
    EXPECT_LE(row.contraction_tf, 1.0);
  }
  EXPECT_FALSE(r.x.codomain().is_unbounded());
}

TEST(BathymetrySlam, UnknownStartWithAMidFixKeepsTheTruth) {
  const SlamRun r = run(2, default_mission());
  ASSERT_GE(r.rows.size(), 2u);
  EXPECT_EQ(r.lost, 0u);
  EXPECT_EQ(r.wider, 0u);
  EXPECT_FALSE(r.x.codomain().is_unbounded());  // propagated backward to t_0 and forward to t_f
  EXPECT_LT(r.x.gate(0)[0].diam(), 50.0);
}

TEST(BathymetrySlam, AChannelFlankContractsTheEnd) {
  // Measured 16.4 % (x at t_f 20.5 -> 13.8 m): the transect's depth along the
  // flank pins the loop time on it to seconds, hence the rail's east.
  const BathymetryMission m(7, short_bank_mission(true));
  const SlamRun r = run(1, m);
  ASSERT_GE(r.rows.size(), 2u);
  EXPECT_FALSE(r.rows.back().fast);
  EXPECT_EQ(r.lost, 0u);
  EXPECT_EQ(r.wider, 0u);
  EXPECT_GT(r.rows.back().contraction_tf, 0.10);
  // The same mission without the flank: nothing.
  const SlamRun flat = run(1, BathymetryMission(7, short_bank_mission(false)), false);
  EXPECT_EQ(flat.lost, 0u);
  EXPECT_LT(flat.rows.back().contraction_tf, 0.01);
}

TEST(SlamFigures, ThicknessAndMap) {
  const auto td = TDomain::create(0.0, 10.0, 1.0);
  const TubeVector a(td, IntervalVector{Interval(0, 4), Interval(0, 3)});
  const TubeVector b(td, IntervalVector{Interval(1, 2), Interval(1, 2)});
  const std::string svg =
      slam_thickness_figure({{a, "dead reckoning", "#777777"}, {b, "slam", "#d62728"}}).svg();
  EXPECT_NE(svg.find("dead reckoning"), std::string::npos);
  EXPECT_NE(svg.find("#d62728"), std::string::npos);
  // Two names for one curve: the figure says that the curves coincide.
  const std::string same = slam_thickness_figure({{a, "dead reckoning", "#777777"}, {a, "slam", "#d62728"}}).svg();
  EXPECT_NE(same.find("dead reckoning = slam (the curves coincide)"), std::string::npos);
  const TubeVector other(TDomain::create(0.0, 10.0, 0.5), 2);
  EXPECT_THROW(slam_thickness_figure({{a, "a", "red"}, {other, "b", "blue"}}), DimensionError);
  EXPECT_THROW(slam_thickness_figure({}), Error);
  BathymetryMissionOptions mo;
  mo.duration = 300;
  const BathymetryMission m(3, mo);
  const auto tdm = m.tdomain(1.0);
  const TubeVector p = bathymetry_dead_reckoning(m, tdm, bathymetry_initial_box(m));
  const Figure f = slam_map_figure(m, p, p, {p.gate(tdm->nb_slices())});
  EXPECT_NE(f.svg().find("p-tf"), std::string::npos);
  EXPECT_THROW(slam_map_figure(m, TubeVector(tdm, 1), p, {}), DimensionError);
}
