// CtcQEval: position fixes on a tube, some of them wrong. A 2-D trajectory
// x(t) = (cos t, sin t) known through its derivative, ten fixes of which two
// are wrong: q = 0 and q = 1 prove inconsistency, q = 2 keeps the truth and a
// thin tube, and a second pass names the two wrong fixes.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dynamics/circle_mission.h"
#include "sillage/dynamics/ctc_qeval.h"

using namespace sillage;

namespace {

struct Fixes : test::CircleMission {
  std::vector<TubeObservation> obs;

  explicit Fixes(const std::vector<std::size_t>& wrong) {
    for (std::size_t i = 0; i < 10; ++i) {
      const double t = 0.5 + static_cast<double>(i);
      IntervalVector z{Interval(std::cos(t)).inflate(0.05), Interval(std::sin(t)).inflate(0.05)};
      for (std::size_t w : wrong) {
        if (w == i) z += IntervalVector{Interval(2.0), Interval(-1.0)};
      }
      obs.push_back({Interval(t).inflate(0.01), z});
    }
  }
};

}  // namespace

TEST(CtcQEval, TwoWrongFixes) {
  for (int q = 0; q <= 1; ++q) {
    Fixes f({3, 7});
    CtcQEval(q).contract(f.x, f.v, f.obs);
    EXPECT_TRUE(f.x.is_empty()) << "q " << q;
  }
  Fixes f({3, 7});
  const TubeVector before = f.x;
  EXPECT_TRUE(CtcQEval(2).contract(f.x, f.v, f.obs).empty());  // each fix alone fits the wide tube
  EXPECT_TRUE(f.x.is_subset(before));
  EXPECT_TRUE(test::holds_circle(f.x));
  EXPECT_LT(f.x.max_thickness(), 0.3);
  // On the contracted tube the two wrong fixes are violated by every trajectory.
  EXPECT_EQ(CtcQEval(2).contract(f.x, f.v, f.obs), (std::vector<std::size_t>{3, 7}));
  EXPECT_TRUE(test::holds_circle(f.x));
}

TEST(CtcQEval, NoWrongFixIsTheIntersectionAndLargeQTheIdentity) {
  Fixes f({});
  CtcQEval(0).contract(f.x, f.v, f.obs);
  EXPECT_TRUE(test::holds_circle(f.x));
  EXPECT_LT(f.x.max_thickness(), 0.3);
  Fixes g({});
  const TubeVector before = g.x;
  CtcQEval(10).contract(g.x, g.v, g.obs);
  EXPECT_EQ(g.x, before);
}

TEST(CtcQEval, Errors) {
  Fixes f({});
  EXPECT_THROW(CtcQEval(-1), Error);
  EXPECT_THROW(CtcQEval(0).contract(f.x, f.v, {}), Error);
  std::vector<TubeObservation> bad{{Interval(1.0), IntervalVector(3)}};
  EXPECT_THROW(CtcQEval(0).contract(f.x, f.v, bad), DimensionError);
  const TubeVector v3(f.td, 3);
  EXPECT_THROW(CtcQEval(0).contract(f.x, v3, f.obs), DimensionError);
}
