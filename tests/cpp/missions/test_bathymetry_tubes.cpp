// The tubes of the bathymetric mission enclose the truth at every gate and
// slice (property test over seeds), and dead reckoning drifts as in Fig. 7.17.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_tubes.h"

using namespace sillage;

namespace {

struct Case {
  BathymetryMission m;
  std::shared_ptr<TDomain> td;
  TubeVector p, w;
  Tube z;
  explicit Case(std::uint64_t seed, double dt)
      : m(seed), td(m.tdomain(dt)), p(bathymetry_dead_reckoning(m, td, bathymetry_initial_box(m))),
        w(bathymetry_velocity_tube(m, td)), z(bathymetry_observation_tube(m, td)) {}
};

const Case& case7() {
  static const Case c(7, 1.0);
  return c;
}

// Every gate holds the sample at its time; every slice holds the samples inside it.
void expect_inside(const Tube& x, const std::vector<double>& times, const std::vector<double>& v, const char* name) {
  const auto& td = *x.tdomain();
  std::size_t k = 0, misses = 0;
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    if (t < td.t0() || t > td.tf()) continue;
    while (k + 1 < td.nb_slices() && td.t(k + 1) <= t) ++k;
    if (td.t(k) == t && !x.gate(k).contains(v[i])) ++misses;
    if (t == td.tf() && !x.gate(td.nb_slices()).contains(v[i])) ++misses;
    if (!x.slice(k).contains(v[i])) ++misses;
  }
  EXPECT_EQ(misses, 0u) << name;
}

}  // namespace

TEST(BathymetryTubes, TruthInsideDeadReckoningAtEveryGate) {
  const auto& c = case7();
  expect_inside(c.p[0], c.m.times(), c.m.x1(), "east");
  expect_inside(c.p[1], c.m.times(), c.m.x2(), "north");
  expect_inside(c.p[2], c.m.times(), c.m.truth().depth, "depth");
}

TEST(BathymetryTubes, TruthInsideObservationTube) {
  const auto& c = case7();
  const auto& m = c.m;
  std::size_t misses = 0;
  for (std::size_t k = 0; k <= c.td->nb_slices(); ++k) {
    const std::size_t i = static_cast<std::size_t>(m.sample_index(c.td->t(k)));
    if (!c.z.gate(k).intersects(m.dem()(m.x1()[i], m.x2()[i]))) ++misses;
  }
  EXPECT_EQ(misses, 0u);
  const Trajectory zt = bathymetry_truth_observation(m);
  expect_inside(c.z, m.times(), zt.sample_values(), "z");
}

TEST(BathymetryTubes, TruthInsideVelocityTube) {
  // The true world velocity at the samples, from the true signals and (4.32).
  const auto& c = case7();
  const auto& t = c.m.truth();
  std::vector<double> w1, w2;
  for (std::size_t i = 0; i < c.m.nb_samples(); ++i) {
    const double cp = std::cos(t.yaw[i]), sp = std::sin(t.yaw[i]), ct = std::cos(t.pitch[i]), st = std::sin(t.pitch[i]),
                 cf = std::cos(t.roll[i]), sf = std::sin(t.roll[i]);
    w1.push_back(ct * cp * t.vx[i] + (-cf * sp + st * cp * sf) * t.vy[i] + (sp * sf + st * cp * cf) * t.vz[i]);
    w2.push_back(ct * sp * t.vx[i] + (cp * cf + st * sp * sf) * t.vy[i] + (-cp * sf + st * cf * sp) * t.vz[i]);
  }
  expect_inside(c.w[0], c.m.times(), w1, "w1");
  expect_inside(c.w[1], c.m.times(), w2, "w2");
}

TEST(BathymetryTubes, PropertyOverSeedsAndSlicings) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const Case c(seed, seed == 2 ? 0.5 : 2.0);
    expect_inside(c.p[0], c.m.times(), c.m.x1(), "east");
    expect_inside(c.p[1], c.m.times(), c.m.x2(), "north");
    expect_inside(c.z, c.m.times(), bathymetry_truth_observation(c.m).sample_values(), "z");
  }
}

TEST(BathymetryTubes, DriftOfTheThesisOrder) {
  // Fig. 7.17: the dead-reckoning diagonal grows roughly linearly to tens of metres.
  const auto& c = case7();
  const std::size_t N = c.td->nb_slices();
  const double d = std::hypot(c.p[0].gate(N).diam(), c.p[1].gate(N).diam());
  const double d_half = std::hypot(c.p[0].gate(N / 2).diam(), c.p[1].gate(N / 2).diam());
  std::printf("DR diagonal: %.1f m at t_f/2, %.1f m at t_f\n", d_half, d);
  EXPECT_GT(d, 20);
  EXPECT_LT(d, 150);
  EXPECT_GT(d, 1.5 * d_half);
}

TEST(BathymetryTubes, InitialBoxAndErrors) {
  const auto& c = case7();
  EXPECT_TRUE(c.p[0].gate(0).contains(c.m.x1().front()));
  EXPECT_THROW(bathymetry_dead_reckoning(c.m, c.td, IntervalVector(2)), DimensionError);
  EXPECT_THROW(bathymetry_initial_box(c.m, -1), Error);
}
