// gomne_tube: range fixes to four beacons along x(t) = (cos t, sin t), known
// through its derivative, two of the ten ranges wrong. q = 2 is found, the
// wrong ranges are named, the truth stays in the tube; without a wrong range
// q = 0. Range fixes use TubeObservation's constraint on z.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/circle_mission.h"
#include "sillage/ctc/ctc_function.h"
#include "sillage/dynamics/gomne_tube.h"

using namespace sillage;

namespace {

struct RangeFixes : test::CircleMission {
  std::vector<TubeObservation> obs;

  explicit RangeFixes(const std::vector<std::size_t>& wrong) {
    const int beacons[4][2] = {{3, 0}, {0, 3}, {-3, 0}, {0, -3}};
    for (std::size_t i = 0; i < 10; ++i) {
      const double t = 0.5 + static_cast<double>(i);
      const int* b = beacons[i % 4];
      double r = std::hypot(std::cos(t) - b[0], std::sin(t) - b[1]);
      if (std::find(wrong.begin(), wrong.end(), i) != wrong.end()) r += 1.0;
      const Function d({"z1", "z2"}, "sqrt((z1 - (" + std::to_string(b[0]) + "))^2 + (z2 - (" +
                                         std::to_string(b[1]) + "))^2)");
      obs.push_back({Interval(t).inflate(0.01), IntervalVector(2),
                     std::make_shared<CtcFunction>(d, Interval(r).inflate(0.05))});
    }
  }
};

}  // namespace

TEST(GomneTube, TwoWrongRanges) {
  const RangeFixes f({2, 6});
  const TubeGomneResult r = gomne_tube(f.x, f.v, f.obs);
  EXPECT_EQ(r.q, 2);
  EXPECT_EQ(r.outliers, (std::vector<std::size_t>{2, 6}));
  EXPECT_TRUE(test::holds_circle(r.x));
  EXPECT_TRUE(r.x.is_subset(f.x));
  EXPECT_LT(r.x.max_thickness(), 0.5);
}

TEST(GomneTube, NoWrongRange) {
  const RangeFixes f({});
  const TubeGomneResult r = gomne_tube(f.x, f.v, f.obs);
  EXPECT_EQ(r.q, 0);
  EXPECT_TRUE(r.outliers.empty());
  EXPECT_TRUE(test::holds_circle(r.x));
}

TEST(GomneTube, QMaxAndErrors) {
  const RangeFixes f({2, 6});
  TubeGomneOptions o;
  o.q_max = 1;
  const TubeGomneResult r = gomne_tube(f.x, f.v, f.obs, o);
  EXPECT_EQ(r.q, 2);
  EXPECT_TRUE(r.x.is_empty());
  EXPECT_TRUE(r.outliers.empty());
  o.q_max = -1;
  EXPECT_THROW(gomne_tube(f.x, f.v, f.obs, o), Error);
  o = {};
  o.max_passes = 0;
  EXPECT_THROW(gomne_tube(f.x, f.v, f.obs, o), Error);
  EXPECT_THROW(gomne_tube(f.x, f.v, {}), Error);
  std::vector<TubeObservation> late{{Interval(20, 21), IntervalVector(2)}};
  EXPECT_THROW(gomne_tube(f.x, f.v, late), Error);
  std::vector<TubeObservation> bad_ctc{
      {Interval(1.0), IntervalVector(2), std::make_shared<CtcFunction>(Function({"a"}, "a"), Interval(0))}};
  EXPECT_THROW(gomne_tube(f.x, f.v, bad_ctc), DimensionError);
}
