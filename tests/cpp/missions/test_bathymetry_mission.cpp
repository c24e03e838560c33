// The synthetic bathymetric mission (thesis 7.3.2): determinism, the stated
// bounds hold for every draw, the truth lies in every tube at every gate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_rng.h"
#include "sillage/missions/bathymetry_tubes.h"

using namespace sillage;

namespace {

const BathymetryMission& mission() {
  static const BathymetryMission m(7);
  return m;
}

constexpr double kDeg = 3.14159265358979323846 / 180;

}  // namespace

TEST(BathymetryMission, SummaryLooksLikeTheThesis) {
  const auto& m = mission();
  EXPECT_EQ(m.nb_samples(), 57601u);
  EXPECT_EQ(m.times().back(), 5760.0);
  const double len = m.path_length();
  EXPECT_GT(len, 5500);  // ~1.03 m/s for 5760 s
  EXPECT_LT(len, 6300);
  // The path stays inside the area and the vehicle at a survey altitude.
  for (std::size_t i = 0; i < m.nb_samples(); ++i) {
    ASSERT_GT(m.x1()[i], 10);
    ASSERT_LT(m.x1()[i], 490);
    ASSERT_GT(m.x2()[i], 10);
    ASSERT_LT(m.x2()[i], 490);
    ASSERT_GT(m.truth().altitude[i], 1);
    ASSERT_LT(m.truth().altitude[i], 25);
  }
}

TEST(BathymetryMission, DeterministicFromTheSeed) {
  const BathymetryMission a(7), b(8);
  const auto& m = mission();
  EXPECT_EQ(a.x1(), m.x1());
  EXPECT_EQ(a.measured().altitude, m.measured().altitude);
  EXPECT_EQ(a.dem().depths(), m.dem().depths());
  EXPECT_NE(b.dem().depths(), m.dem().depths());
  EXPECT_NE(b.measured().vx, m.measured().vx);
}

TEST(BathymetryMission, GeneratorIsPlatformIndependent) {
  // xoshiro256** with splitmix64 seeding: integer arithmetic only, so fixed reference values.
  detail::BathymetryRng r(1);
  EXPECT_EQ(r.next(), 12966619160104079557ULL);
  EXPECT_EQ(r.next(), 9600361134598540522ULL);
  // The DEM is quantized to the millimetre: libm's last-bit differences do not show.
  const auto& d = mission().dem();
  EXPECT_DOUBLE_EQ(d.node(250, 250), 19.369);
  EXPECT_DOUBLE_EQ(d.node(0, 0), 21.054);
  EXPECT_DOUBLE_EQ(d.node(500, 123), 23.565);
  detail::BathymetryRng u(42);
  for (int k = 0; k < 1000; ++k) {
    const double x = u.uniform(-2, 3);
    ASSERT_GE(x, -2);
    ASSERT_LT(x, 3);
  }
}

TEST(BathymetryMission, MeasurementsWithinTheStatedBounds) {
  const auto& m = mission();
  const auto& b = m.bounds();
  const auto& t = m.truth();
  const auto& me = m.measured();
  for (std::size_t i = 0; i < m.nb_samples(); ++i) {
    ASSERT_LE(std::abs(me.yaw[i] - t.yaw[i]), b.heading * kDeg);
    ASSERT_LE(std::abs(me.pitch[i] - t.pitch[i]), b.attitude * kDeg);
    ASSERT_LE(std::abs(me.roll[i] - t.roll[i]), b.attitude * kDeg);
    const double speed = std::sqrt(me.vx[i] * me.vx[i] + me.vy[i] * me.vy[i] + me.vz[i] * me.vz[i]);
    const double ev = b.dvl_scale * speed + b.dvl_offset;
    ASSERT_LE(std::abs(me.vx[i] - t.vx[i]), ev);
    ASSERT_LE(std::abs(me.vy[i] - t.vy[i]), ev);
    ASSERT_LE(std::abs(me.vz[i] - t.vz[i]), ev);
    ASSERT_LE(std::abs(me.depth[i] - t.depth[i]), b.depth);
    ASSERT_LE(std::abs(me.altitude[i] - m.filtered_altitude()[i]), b.altitude_scale * me.altitude[i] + b.altitude_offset);
    ASSERT_LE(std::abs(m.tide_truth()[i] - m.tide().height_value(m.times()[i])), b.tide);
    ASSERT_LT(std::hypot(me.vx[i], me.vy[i]), b.speed_max);
  }
}

TEST(BathymetryMission, DynamicsClassHolds) {
  // Second differences of the true signals: |x''| <= stated bound (+ slack for
  // the finite difference itself).
  const auto& m = mission();
  const auto& b = m.bounds();
  const auto& t = m.truth();
  const double h = m.options().step;
  auto check = [&](const std::vector<double>& x, double bound, const char* name) {
    double worst = 0;
    for (std::size_t i = 1; i + 1 < x.size(); ++i) worst = std::max(worst, std::abs(x[i + 1] - 2 * x[i] + x[i - 1]) / (h * h));
    EXPECT_LE(worst, bound) << name;
  };
  check(t.yaw, b.angle_accel * kDeg, "yaw");
  check(t.pitch, b.angle_accel * kDeg, "pitch");
  check(t.roll, b.angle_accel * kDeg, "roll");
  check(t.vx, b.velocity_accel2, "vx");
  check(t.vy, b.velocity_accel2, "vy");
  check(t.vz, b.velocity_accel2, "vz");
}

TEST(BathymetryMission, TDomainOfSampleTimes) {
  const auto td = mission().tdomain(1.0);
  EXPECT_EQ(td->nb_slices(), 5760u);
  EXPECT_THROW(mission().tdomain(0.25), Error);
  EXPECT_THROW(mission().tdomain(-1), Error);
  EXPECT_THROW(bathymetry_velocity_tube(mission(), TDomain::create(0.0, 5760.0, 0.7)), Error);
}

TEST(BathymetryMission, BadOptionsAreRefused) {
  BathymetryMissionOptions o;
  o.rail_spacing = 60;  // >= 2 R: no keyhole turn
  EXPECT_THROW(BathymetryMission(1, o), Error);
  o = {};
  o.duration = -1;
  EXPECT_THROW(BathymetryMission(1, o), Error);
}

// SeabedOptions.relief scales the relief and its class bounds; a seabed that
// rises above the vehicle is a clear error, not a crash.
TEST(BathymetryMission, ReliefScalesTheSeabedAndACollisionIsAnError) {
  SeabedOptions o;
  const Seabed one = generate_seabed(5, o);
  o.relief = 2;
  const Seabed two = generate_seabed(5, o);
  EXPECT_NEAR(two.bounds.curvature, 2 * one.bounds.curvature, 1e-12);
  EXPECT_NEAR(two.bounds.slope, 2 * one.bounds.slope, 1e-12);
  EXPECT_GT(two.dem.max_depth() - two.dem.min_depth(), 1.5 * (one.dem.max_depth() - one.dem.min_depth()));
  o.relief = -1;
  EXPECT_THROW(generate_seabed(5, o), Error);
  BathymetryMissionOptions mo;
  mo.duration = 600;
  mo.seabed.relief = 4;
  try {
    const BathymetryMission m(7, mo);
    FAIL() << "a seabed above the vehicle must be an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("rises above the vehicle"), std::string::npos) << e.what();
  }
}
