// The DEM as an inclusion function: point and box enclosures, exact box range
// against a brute-force reference, and the seabed class bounds the generator
// states (curvature, roughness) used by the altitude footprint filter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bathymetry_test_util.h"
#include "sillage/error.h"
#include "sillage/missions/bathymetry_mission.h"
#include "sillage/missions/bathymetry_rng.h"
#include "sillage/missions/bathymetry_seabed.h"
#include "sillage/missions/bathymetry_sensors.h"
#include "sillage/slam/bathymetry_tide.h"

using namespace sillage;

namespace {

const Seabed& seabed() {
  static const Seabed s = generate_seabed(11);
  return s;
}

// Bilinear value in long double (a reference independent of the Interval code).
long double bilinear_ref(const BathymetryDem& d, double x, double y) {
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(std::floor(x)), d.nx() - 2);
  const std::size_t j = std::min<std::size_t>(static_cast<std::size_t>(std::floor(y)), d.ny() - 2);
  const long double u = static_cast<long double>(x) - i, v = static_cast<long double>(y) - j;
  return (1 - u) * (1 - v) * d.node(i, j) + u * (1 - v) * d.node(i + 1, j) + (1 - u) * v * d.node(i, j + 1) +
         u * v * d.node(i + 1, j + 1);
}

}  // namespace

TEST(BathymetryDem, ExactOnAHandGrid) {
  // 3 x 2 nodes, cell 2: depths 0 1 2 / 3 4 5.
  const BathymetryDem d(0, 0, 2, 3, 2, {0, 1, 2, 3, 4, 5});
  EXPECT_EQ(d(0, 0), Interval(0));
  EXPECT_EQ(d(4, 2), Interval(5));
  EXPECT_TRUE(d(1, 1).contains(2.0));  // (0+1+3+4)/4
  EXPECT_LT(d(1, 1).diam(), 1e-14);
  EXPECT_EQ(d.eval(IntervalVector{Interval(0, 4), Interval(0, 2)}), Interval(0, 5));
  const Interval r = d.eval(IntervalVector{Interval(1, 3), Interval(0.5, 1.5)});
  EXPECT_TRUE(r.contains(1.5 * 0.5 + 0.5));  // f = x/2 + 3y/2: min at (1, 0.5) = 1.25
  EXPECT_NEAR(r.lb(), 1.25, 1e-12);
  EXPECT_NEAR(r.ub(), 3.75, 1e-12);
  EXPECT_EQ(d.eval_cells(IntervalVector{Interval(1, 3), Interval(0.5, 1.5)}), Interval(0, 5));
  // Outside the map: unknown; empty: empty.
  EXPECT_EQ(d.eval(IntervalVector{Interval(-1, 1), Interval(0, 1)}), Interval());
  EXPECT_TRUE(d(5, 0).is_unbounded());
  EXPECT_TRUE(d.eval(IntervalVector{Interval::empty(), Interval(0, 1)}).is_empty());
}

TEST(BathymetryDem, BadInputIsRefused) {
  EXPECT_THROW(BathymetryDem(0, 0, 1, 1, 2, {0, 1}), Error);
  EXPECT_THROW(BathymetryDem(0, 0, 1, 2, 2, {0, 1, 2}), DimensionError);
  EXPECT_THROW(BathymetryDem(0, 0, 0.1, 4, 2, {0, 1, 2, 3, 4, 5, 6, 7}), Error);  // 3 * 0.1 not exact
  EXPECT_THROW(BathymetryDem(0, 0, 1, 2, 2, {0, NAN, 2, 3}), Error);
  const BathymetryDem d(0, 0, 1, 2, 2, {0, 1, 2, 3});
  EXPECT_THROW(d.eval(IntervalVector{Interval(0, 1)}), DimensionError);
  EXPECT_THROW(d.node(2, 0), OutOfRangeError);
  EXPECT_THROW(d(NAN, 0), Error);
}

TEST(BathymetryDem, PointEnclosuresContainTheBilinearValue) {
  const auto& d = seabed().dem;
  detail::BathymetryRng r(3);
  for (int k = 0; k < 20000; ++k) {
    const double x = r.uniform(0, 500), y = r.uniform(0, 500);
    const Interval v = d(x, y);
    const long double ref = bilinear_ref(d, x, y);
    ASSERT_LE(static_cast<long double>(v.lb()), ref + 1e-12L) << x << " " << y;
    ASSERT_GE(static_cast<long double>(v.ub()), ref - 1e-12L) << x << " " << y;
    ASSERT_LT(v.diam(), 1e-10);
  }
}

TEST(BathymetryDem, BoxRangeIsExactAgainstBruteForce) {
  const auto& d = seabed().dem;
  detail::BathymetryRng r(5);
  for (int k = 0; k < 300; ++k) {
    const double w = r.uniform(0, k % 3 == 0 ? 2.5 : 25), hgt = r.uniform(0, 25);
    const double x = r.uniform(0, 500 - w), y = r.uniform(0, 500 - hgt);
    const IntervalVector box{Interval(x, x + w), Interval(y, y + hgt)};
    const Interval e = d.eval(box), c = d.eval_cells(box);
    ASSERT_TRUE(e.is_subset(c));
    // Brute force: a fine sampling (every point lies inside), plus the box corners
    // and the grid nodes inside (where the extremes are): hull == eval up to rounding.
    double lo = INFINITY, hi = -INFINITY;
    const int n = 60;
    for (int a = 0; a <= n; ++a)
      for (int b = 0; b <= n; ++b) {
        const double px = x + w * a / n, py = y + hgt * b / n;
        const long double v = bilinear_ref(d, std::min(px, x + w), std::min(py, y + hgt));
        ASSERT_TRUE(e.lb() <= v + 1e-9L && v - 1e-9L <= e.ub());
        lo = std::min(lo, static_cast<double>(v)), hi = std::max(hi, static_cast<double>(v));
      }
    for (double gx = std::ceil(x); gx <= x + w; ++gx)
      for (double gy = std::ceil(y); gy <= y + hgt; ++gy) {
        const double v = d.node(static_cast<std::size_t>(gx), static_cast<std::size_t>(gy));
        lo = std::min(lo, v), hi = std::max(hi, v);
      }
    for (double gx = std::ceil(x); gx <= x + w; ++gx)
      for (double py : {y, y + hgt}) {
        const double v = static_cast<double>(bilinear_ref(d, gx, py));
        lo = std::min(lo, v), hi = std::max(hi, v);
      }
    for (double gy = std::ceil(y); gy <= y + hgt; ++gy)
      for (double px : {x, x + w}) {
        const double v = static_cast<double>(bilinear_ref(d, px, gy));
        lo = std::min(lo, v), hi = std::max(hi, v);
      }
    ASSERT_NEAR(e.lb(), lo, 1e-9);
    ASSERT_NEAR(e.ub(), hi, 1e-9);
  }
}

TEST(BathymetryDem, ReliefLikeFig720) {
  const Seabed& s = seabed();
  const double relief = s.dem.max_depth() - s.dem.min_depth();
  EXPECT_GT(relief, 4);  // several metres
  EXPECT_LT(relief, 15);
  // The smooth strip varies much less, at the metre scale, than the rough part.
  EXPECT_LT(test::local_spread(s.dem, 40), 0.8);
  EXPECT_GT(test::local_spread(s.dem, 320), 1.0);
}

TEST(BathymetryDem, SeabedClassHolds) {
  // Second differences of the node depths minus the roughness: |D2| h^2 bounded by
  // curvature h^2 + 4 roughness (each node carries at most `roughness` of noise).
  const Seabed& s = seabed();
  EXPECT_LE(test::worst_second_difference(s.dem), s.bounds.curvature + 4 * s.bounds.roughness);
}

TEST(BathymetryFootprint, FilterBoundHoldsAlongTheMission) {
  static const BathymetryMission m(7);
  const double worst_ratio = test::footprint_bound_worst_ratio(m);
  EXPECT_LE(worst_ratio, 1.0);
  EXPECT_GT(worst_ratio, 0.05);  // the bound is not vacuous
}

TEST(BathymetryFootprint, WiderWhenHigherAndBoundAtRandomPoints) {
  const Seabed& s = seabed();
  const BathymetrySensorBounds b;
  const auto low = dvl_footprint(250, 250, 0.3, 5, b), high = dvl_footprint(250, 250, 0.3, 15, b);
  ASSERT_EQ(low.size(), 20u);
  double rl = 0, rh = 0, sx = 0, sy = 0;
  for (std::size_t k = 0; k < low.size(); ++k) {
    rl = std::max(rl, std::hypot(low[k][0] - 250, low[k][1] - 250));
    rh = std::max(rh, std::hypot(high[k][0] - 250, high[k][1] - 250));
    sx += high[k][0] - 250, sy += high[k][1] - 250;
  }
  EXPECT_NEAR(rh / rl, 3, 1e-9);  // proportional to the altitude
  EXPECT_NEAR(sx, 0, 1e-9);       // symmetric about the nadir
  EXPECT_NEAR(sy, 0, 1e-9);
  detail::BathymetryRng r(9);
  for (int k = 0; k < 5000; ++k) {
    const double a = r.uniform(1, 20), x = r.uniform(20, 480), y = r.uniform(20, 480), yaw = r.uniform(-4, 4);
    const double e = std::abs(footprint_depth(s.dem, x, y, yaw, a, b) - s.dem(x, y).mid());
    ASSERT_LE(e, footprint_filter_bound(s.bounds, s.dem.cell_size(), a, b));
  }
  EXPECT_THROW(nadir_altitude_max(1e4, s.bounds, 1, b), Error);
}

TEST(BathymetryTide, SinusoidalModel) {
  const TideModel t;
  EXPECT_TRUE(t.height(Interval(t.t_low)).contains(0));
  EXPECT_TRUE(t.height(Interval(t.t_low + t.duration)).contains(t.range));
  EXPECT_TRUE(t.height(Interval(t.t_low + t.duration / 2)).contains(t.range / 2));
  for (double x = -100; x < 6000; x += 37.5) EXPECT_TRUE(t.height(Interval(x)).contains(t.height_value(x)));
  const Interval h = t.height(Interval(0, 5760));
  EXPECT_LE(h.lb(), t.height_value(0));
  EXPECT_GE(h.ub(), t.height_value(5760));
}
