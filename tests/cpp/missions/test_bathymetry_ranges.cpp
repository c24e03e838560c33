// Range observation tubes for a range-only temporal SLAM without the beacon
// positions: a hand case, bad input, and on plaza1 (../shared/data) the true
// ranges (ground truth and surveyed beacons) inside every tube.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "sillage/error.h"
#include "sillage/io/csv.h"
#include "sillage/missions/bathymetry_range_observation.h"

using namespace sillage;

TEST(RangeObservation, HandCase) {
  // One beacon, two measurements 10 s apart: at t = 0 the gate is [r - long, r + short]
  // widened by speed * time_err; in between both cones intersect.
  auto td = TDomain::create(0.0, 10.0, 1.0);
  const RangeBounds b{1.0, 2.0, 0.5, 1.0};
  const TubeVector z = range_observation_tubes(td, {0.0, 10.0}, {3, 3}, {20.0, 24.0}, {3}, b);
  ASSERT_EQ(z.size(), 1u);
  EXPECT_EQ(z[0].gate(0), Interval(20 - 2 - 0.5, 20 + 1 + 0.5));
  EXPECT_EQ(z[0].gate(10), Interval(24 - 2 - 0.5, 24 + 1 + 0.5));
  // Gate 5: from both: [17.5, 21.5] + [-5, 5] and [21.5, 25.5] + [-5, 5] -> [16.5, 26.5].
  EXPECT_EQ(z[0].gate(5), Interval(16.5, 26.5));
  // Slice 0 = [0, 1]: the first cone over one second, cut by the second.
  EXPECT_EQ(z[0].slice(0), Interval(16.5, 22.5));
  // Never negative.
  const TubeVector near = range_observation_tubes(td, {0.0}, {1}, {0.5}, {1}, b);
  EXPECT_GE(near[0].gate(3).lb(), 0.0);
}

TEST(RangeObservation, BadInput) {
  auto td = TDomain::create(0.0, 10.0, 1.0);
  EXPECT_THROW(range_observation_tubes(td, {0.0}, {1, 2}, {3.0}, {1}), DimensionError);
  EXPECT_THROW(range_observation_tubes(td, {0.0}, {1}, {3.0}, {2}), Error);  // no measurement of 2
  EXPECT_THROW(range_observation_tubes(td, {5.0, 1.0}, {1, 1}, {3.0, 3.0}, {1}), Error);
  EXPECT_THROW(range_observation_tubes(td, {0.0}, {1}, {NAN}, {1}), Error);
  EXPECT_THROW(range_observation_tubes(td, {0.0}, {1}, {3.0}, {1}, RangeBounds{-1, 1, 1, 1}), Error);
  // Contradictory measurements (100 m apart in 1 s at 2 m/s): said, not an empty success.
  EXPECT_THROW(range_observation_tubes(td, {0.0, 1.0}, {1, 1}, {10.0, 110.0}, {1}), Error);
}

TEST(RangeObservation, Plaza1TruthInside) {
  const std::filesystem::path dir = std::filesystem::path(SILLAGE_SHARED_DIR) / "data" / "plaza1";
  if (!std::filesystem::exists(dir / "ranges.csv")) GTEST_SKIP() << "no plaza1 data";
  const CsvTable gt = CsvTable::read((dir / "ground_truth.csv").string());
  const CsvTable rg = CsvTable::read((dir / "ranges.csv").string());
  const CsvTable bc = CsvTable::read((dir / "beacons.csv").string());
  const auto t = gt.values("t_s"), x = gt.values("x_m"), y = gt.values("y_m");
  const auto rt = rg.values("t_s"), rid = rg.values("beacon_id"), r = rg.values("range_m");
  const auto bid = bc.values("beacon_id"), bx = bc.values("x_m"), by = bc.values("y_m");
  std::vector<int> ids, beacon;
  for (double v : bid) ids.push_back(static_cast<int>(v));
  for (double v : rid) beacon.push_back(static_cast<int>(v));
  auto td = TDomain::create(t.front(), t.back(), 1.0);
  const TubeVector z = range_observation_tubes(td, rt, beacon, r, ids);  // the plaza1 bounds (plaza1_bounds.h)
  ASSERT_EQ(z.size(), ids.size());
  std::size_t misses = 0, checked = 0;
  double width = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double truth = std::hypot(x[k] - bx[i], y[k] - by[i]);
      if (!z[i](t[k]).contains(truth)) ++misses;
      ++checked;
    }
    for (std::size_t k = 0; k < td->nb_slices(); ++k) width += z[i].slice(k).diam();
  }
  width /= static_cast<double>(ids.size() * td->nb_slices());
  std::printf("plaza1 range tubes: %zu truth checks, %zu misses, mean slice width %.1f m\n", checked, misses, width);
  EXPECT_EQ(misses, 0u);
  EXPECT_LT(width, 40);  // informative: the ranges go up to ~70 m
}
