// The bathymetric observation (7.29)-(7.30): exact tide values, sums with
// the sensor errors, errors on bad input; a tide reference that is not
// known (a constant offset on z) changes no contraction (7.4.3).
#include <gtest/gtest.h>

#include <cmath>

#include "small_slam.h"
#include "sillage/error.h"
#include "sillage/slam/ctc_p_implies_z.h"
#include "sillage/slam/observation.h"

using namespace sillage;

TEST(Observation, TideIsZeroAtTheReferenceAndFullRangeAfterOneDuration) {
  TideModel tide;
  tide.range = 4.0;
  tide.duration = 21600.0;
  tide.t_low = 0.0;
  EXPECT_EQ(tide(Interval(0.0)), Interval(0.0));
  const Interval full = tide(Interval(21600.0));
  EXPECT_TRUE(full.contains(4.0));
  EXPECT_LT(full.diam(), 1e-12);
  const Interval half = tide(Interval(10800.0));  // sin²(π/4) = 1/2
  EXPECT_TRUE(half.contains(2.0));
  tide.error = Interval(-0.1, 0.1);
  EXPECT_EQ(tide(Interval(0.0)), Interval(-0.1, 0.1));
  // Over a time interval: the range of the model.
  tide.error = Interval(0.0);
  EXPECT_TRUE(tide(Interval(0.0, 21600.0)).is_superset(Interval(0.0, 4.0)));
}

TEST(Observation, SumOfTheThreeTerms) {
  const auto td = TDomain::create(0.0, 10.0, 1.0);
  const Tube alt(td, Interval(10, 11)), depth(td, Interval(5, 5.5));
  TideModel tide;
  tide.range = 2.0;
  tide.duration = 10.0;
  tide.t_low = 0.0;
  const Tube z = bathymetric_observation(alt, depth, tide);
  EXPECT_EQ(z.gate(0), Interval(15, 16.5));
  EXPECT_TRUE(z.gate(10).contains(17.0) && z.gate(10).contains(18.5));
  EXPECT_LT(z.gate(10).diam(), 1.5 + 1e-12);
  for (std::size_t k = 0; k < 10; ++k) EXPECT_EQ(z.slice(k), Interval(15, 16.5) + tide(td->slice_domain(k))) << k;
}

TEST(Observation, BadInputSaysWhatAndWhere) {
  const auto td = TDomain::create(0.0, 10.0, 1.0), other = TDomain::create(0.0, 10.0, 0.5);
  TideModel tide;
  EXPECT_THROW(bathymetric_observation(Tube(td), Tube(other), tide), DimensionError);
  tide.duration = -1.0;
  EXPECT_THROW(bathymetric_observation(Tube(td), Tube(td), tide), Error);
  tide.duration = 1.0;
  tide.error = Interval(0.1, 0.2);
  EXPECT_THROW(tide_tube(td, tide), Error);
}

// The figure eight sensed as a bathymetric mission: the seabed height g(p)
// below the tide reference is seen as altitude + depth + tide, each with its
// error; with the reference z_0 unknown (an offset) nothing changes.
TEST(Observation, SlamFromAltitudeDepthAndTideKeepsTheTruthAndIgnoresTheReference) {
  slam_test::SmallSlam a, b;
  const auto td = a.td;
  TideModel tide;
  tide.range = 3.0;
  tide.duration = 40.0;
  tide.t_low = 0.0;  // fast on purpose: the model must be taken off
  tide.error = Interval(-0.002, 0.002);
  const Tube depth(td, "5 + 0.3*sin(t) + [-0.002,0.002]");
  // altitude = g(p) + z_0 - depth - tide (the true tide), sensed to ±0.005.
  const auto altitude = [&](double z0) {
    Tube t = a.z[0];
    t += Interval(z0);
    t -= depth;
    t -= tide_tube(td, TideModel{tide.range, tide.duration, tide.t_low, Interval(0.0)});
    t += Interval(-0.005, 0.005);
    return t;
  };
  const TubeVector za(std::vector<Tube>{bathymetric_observation(altitude(0.0), depth, tide)});
  const TubeVector zb(std::vector<Tube>{bathymetric_observation(altitude(12.5), depth, tide)});
  const auto ra = CtcPImpliesZ(0.01).contract(a.p, a.w, za);
  CtcPImpliesZ(0.01).contract(b.p, b.w, zb);
  EXPECT_TRUE(a.p.contains(a.truth));
  EXPECT_GT(ra.back().contraction_tf, 0.05);
  EXPECT_TRUE(slam_test::same_values(a.p, b.p));
}
