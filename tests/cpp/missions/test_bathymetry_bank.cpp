// The channel flanks of the seabed (ChannelBank, bank_seabed_options) and the
// bank mission (bank_mission_options): the flanks' stated class holds on the
// DEM nodes (differences of the flanks alone and of the whole seabed), the
// other features are the same with or without them, the narrow-beam footprint
// bound holds along the mission, bad flanks are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "bathymetry_test_util.h"
#include "sillage/error.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_seabed.h"

using namespace sillage;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The flanks as documented: height (1 + tanh(s / width)) / 2.
double flanks(const std::vector<ChannelBank>& banks, double x, double y) {
  double d = 0;
  for (const ChannelBank& b : banks) {
    const double th = b.direction * kPi / 180, s = std::cos(th) * (x - b.x) + std::sin(th) * (y - b.y);
    d += b.height * (1 + std::tanh(s / b.width)) / 2;
  }
  return d;
}

// Worst second difference of step h along x and y, every third row / column.
double worst_second_difference(const BathymetryDem& d, std::size_t h) {
  double worst = 0;
  for (std::size_t j = 0; j < d.ny(); j += 3)
    for (std::size_t i = h; i + h < d.nx(); ++i)
      worst = std::max(worst, std::abs(d.node(i + h, j) - 2 * d.node(i, j) + d.node(i - h, j)));
  for (std::size_t i = 0; i < d.nx(); i += 3)
    for (std::size_t j = h; j + h < d.ny(); ++j)
      worst = std::max(worst, std::abs(d.node(i, j + h) - 2 * d.node(i, j) + d.node(i, j - h)));
  return worst;
}

}  // namespace

TEST(ChannelBank, ClassHoldsOnTheNodes) {
  const SeabedOptions o = bank_seabed_options();
  ASSERT_EQ(o.channel_banks.size(), 2u);
  double kappa = 0, slope = 0, steepest = 0;  // stated from the parameters
  for (const ChannelBank& b : o.channel_banks) {
    kappa += 0.385 * std::abs(b.height) / (b.width * b.width);
    slope += std::abs(b.height) / (2 * b.width);
    steepest = std::max(steepest, std::abs(b.height) / (2 * b.width));
  }
  SeabedOptions none = o;
  none.channel_banks.clear();
  for (std::uint64_t seed : {7u, 11u}) {
    const Seabed s = generate_seabed(seed, o), f = generate_seabed(seed, none);
    // The class of the whole seabed is the other features' plus the flanks' terms.
    EXPECT_NEAR(s.bounds.curvature, f.bounds.curvature + 1.01 * kappa, 1e-12) << seed;
    EXPECT_NEAR(s.bounds.slope, f.bounds.slope + 1.01 * slope, 1e-12) << seed;
    EXPECT_LE(test::worst_second_difference(s.dem), s.bounds.curvature + 4 * s.bounds.roughness) << seed;
    EXPECT_LE(test::worst_first_difference(s.dem), s.bounds.slope + 2 * s.bounds.roughness) << seed;
    // The flanks alone: the difference of the two DEMs, each quantized to the millimetre.
    const std::size_t n = s.dem.nx();
    std::vector<double> diff(n * n);
    double worst = 0;
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t i = 0; i < n; ++i) {
        diff[j * n + i] = s.dem.node(i, j) - f.dem.node(i, j);
        worst = std::max(worst, std::abs(diff[j * n + i] - flanks(o.channel_banks, static_cast<double>(i), static_cast<double>(j))));
      }
    EXPECT_LE(worst, 0.001 + 1e-9) << seed;  // two roundings to the millimetre: nothing else moved
    const BathymetryDem d(0, 0, 1, n, n, std::move(diff));
    const double q = 0.001;  // node error of the difference
    EXPECT_LE(test::worst_first_difference(d), slope + 2 * q) << seed;
    EXPECT_GT(test::worst_first_difference(d), 0.97 * steepest) << seed;  // the slope bound is reached
    EXPECT_LE(worst_second_difference(d, 1), kappa + 4 * q) << seed;
    EXPECT_LE(worst_second_difference(d, 10), kappa * 100 + 4 * q) << seed;
    EXPECT_GT(worst_second_difference(d, 10), 0.3 * kappa * 100) << seed;  // not vacuous
  }
  // Without flanks the bank seabed is the default one, node for node.
  const Seabed a = generate_seabed(7, none), b = generate_seabed(7);
  for (std::size_t k = 0; k < a.dem.nx(); k += 7) EXPECT_EQ(a.dem.node(k, k), b.dem.node(k, k));
}

TEST(ChannelBank, BadFlanksAreRefused) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (const ChannelBank& bad : {ChannelBank{15, 0, 0, 250, 250}, ChannelBank{15, -3, 0, 250, 250},
                                 ChannelBank{15, inf, 0, 250, 250}, ChannelBank{nan, 30, 0, 250, 250},
                                 ChannelBank{15, 30, inf, 250, 250}, ChannelBank{15, 30, 0, nan, 250}}) {
    SeabedOptions o;
    o.channel_banks = {bad};
    EXPECT_THROW(generate_seabed(1, o), Error);
  }
}

TEST(BankMission, TransectsOverTheFlanksAndTheFootprintBoundHolds) {
  const BathymetryMission m(7, bank_mission_options());
  EXPECT_TRUE(m.options().transects);
  EXPECT_EQ(m.bounds().beam_angle, 0.0);
  const double worst_ratio = test::footprint_bound_worst_ratio(m);
  EXPECT_LE(worst_ratio, 1.0);
  // The southern transect runs up the western flank: 15 m shallower from x = 40 to 200 m.
  const auto depth_at = [&](double x) {
    std::size_t i = 0;
    while (m.x1()[i] < x) ++i;
    EXPECT_NEAR(m.x2()[i], 150, 3);
    return m.dem()(m.x1()[i], m.x2()[i]).mid();
  };
  EXPECT_GT(depth_at(45) - depth_at(200), 12.0);
  // The channel puts the seabed far below the vehicle, never above it.
  const auto [lo, hi] = std::minmax_element(m.truth().altitude.begin(), m.truth().altitude.end());
  EXPECT_GT(*lo, 3.0);
  EXPECT_GT(*hi, 25.0);
  EXPECT_LT(*hi, 40.0);
}
