// The coastal seabed (sand waves at the scale of the drift, rocky outcrops) and
// the transect layout of the mission: the stated class holds on the nodes, the
// narrow-beam footprint bound holds along the mission, the transects cross
// every rail, the smoother seabed's draws are unchanged, bad options refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bathymetry_test_util.h"
#include "sillage/error.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_seabed.h"
#include "sillage/missions/bathymetry_sensors.h"

using namespace sillage;
using sillage::test::local_spread;
using sillage::test::worst_second_difference;

namespace {

BathymetryMissionOptions coastal_mission() {
  BathymetryMissionOptions o;
  o.seabed = coastal_seabed_options();
  o.transects = true;
  o.bounds.beam_angle = 0;  // a narrow-beam altimeter: 6 deg cone
  o.bounds.beam_spread = 3;
  return o;
}

}  // namespace

TEST(CoastalSeabed, ClassHoldsAndReliefAtTheDriftScale) {
  for (std::uint64_t seed : {7u, 11u}) {
    const Seabed s = generate_seabed(seed, coastal_seabed_options());
    EXPECT_LE(worst_second_difference(s.dem), s.bounds.curvature + 4 * s.bounds.roughness) << seed;
    EXPECT_GT(worst_second_difference(s.dem), 0.3 * s.bounds.curvature) << seed;  // the bound is not vacuous
    EXPECT_GT(local_spread(s.dem, 320), 3.0) << seed;  // metres of relief within 30 m in the east
    EXPECT_LT(local_spread(s.dem, 40), 0.8) << seed;   // the smooth strip stays smooth
  }
  // More relief than the smoother seabed of the same seed, whose draws are unchanged.
  const Seabed smooth = generate_seabed(7), coastal = generate_seabed(7, coastal_seabed_options());
  EXPECT_GT(coastal.bounds.curvature, smooth.bounds.curvature);
  EXPECT_GT(local_spread(coastal.dem, 320), local_spread(smooth.dem, 320));
  EXPECT_DOUBLE_EQ(smooth.dem.node(0, 0), 21.054);
}

TEST(CoastalSeabed, BadOptionsAreRefused) {
  SeabedOptions o = coastal_seabed_options();
  o.dune_height = -1;
  EXPECT_THROW(generate_seabed(1, o), Error);
  o = coastal_seabed_options();
  o.rock_height_max = o.rock_height_min - 0.1;
  EXPECT_THROW(generate_seabed(1, o), Error);
  o = coastal_seabed_options();
  o.rock_sigma_min = 0;
  EXPECT_THROW(generate_seabed(1, o), Error);
}

TEST(CoastalMission, NarrowBeamBoundHoldsAndTransectsCrossTheRails) {
  const BathymetryMission m(7, coastal_mission());
  const double worst_ratio = test::footprint_bound_worst_ratio(m);
  EXPECT_LE(worst_ratio, 1.0);
  EXPECT_GT(worst_ratio, 0.05);
  std::size_t crossings = 0;
  for (std::size_t i = 0; i < m.nb_samples(); ++i) {
    ASSERT_GT(m.x1()[i], 10);
    ASSERT_LT(m.x1()[i], 490);
    ASSERT_GT(m.x2()[i], 10);
    ASSERT_LT(m.x2()[i], 490);
    // A rail (after the overall crossing) passing the southern transect's line y = 150 m.
    if (i > 0 && m.times()[i] > 1500 && (m.x2()[i - 1] - 150) * (m.x2()[i] - 150) < 0) ++crossings;
  }
  // The first leg is the eastward transect at 0.3 of the side.
  EXPECT_NEAR(m.x2()[3000], 150, 3);
  EXPECT_GT(m.x1()[3000], m.x1()[0] + 250);
  EXPECT_GE(crossings, 8u);  // every rail crosses it
  // The narrow beam: a footprint bound well below the 30 deg Janus beams' at the same altitude.
  const BathymetrySensorBounds janus;
  const double cell = m.dem().cell_size();
  EXPECT_LT(footprint_filter_bound(m.seabed().bounds, cell, 8, m.bounds()),
            0.5 * footprint_filter_bound(m.seabed().bounds, cell, 8, janus));
}
