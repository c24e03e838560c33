// CtcAngleEquation: a bearing b from a heading ψ known modulo 2π,
// atan2(ly - py, lx - px) - ψ - b ≡ 0: ψ narrowed from a wide unwrapped
// interval, the truth kept modulo 2π, the position contracted back.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sillage/ctc/ctc_angle_equation.h"
#include "sillage/error.h"
#include "sillage/interval/angle.h"

using namespace sillage;

namespace {

// Box (ψ, px, py, lx, ly, b); f = atan2(ly - py, lx - px) - b + [-e, e].
CtcAngleEquation bearing(double e) {
  return CtcAngleEquation({-1}, Function({"px", "py", "lx", "ly", "b"},
                                         "atan2(ly - py, lx - px) - b + [-" + std::to_string(e) + ", " + std::to_string(e) + "]"));
}

TEST(CtcAngleEquation, ABearingNarrowsAWideHeadingAndKeepsTheTruth) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-5, 5), a(-M_PI, M_PI);
  for (int trial = 0; trial < 500; ++trial) {
    const double px = u(rng), py = u(rng), lx = u(rng), ly = u(rng), psi = a(rng) + 14 * M_PI;
    if (std::hypot(lx - px, ly - py) < 0.5) continue;
    const double b = std::remainder(std::atan2(ly - py, lx - px) - psi, 2 * M_PI);
    IntervalVector box{Interval(-46, 46), Interval(px).inflate(0.01), Interval(py).inflate(0.01),
                       Interval(lx), Interval(ly), Interval(b)};
    bearing(0.02).contract(box);
    ASSERT_FALSE(box.is_empty());
    ASSERT_TRUE(angle_contains(box[0], psi)) << box[0] << " " << psi;
    ASSERT_LT(box[0].diam(), 0.5) << trial;
    ASSERT_TRUE(box[1].contains(px) && box[2].contains(py));
  }
}

TEST(CtcAngleEquation, TheHeadingContractsThePosition) {
  // Landmark at (1, 0), heading 0 exactly, bearing 0 ± 0.01: py stays near 0.
  IntervalVector box{Interval(2 * M_PI), Interval(-1, 0), Interval(-1, 1), Interval(1), Interval(0), Interval(0)};
  bearing(0.01).contract(box);
  ASSERT_FALSE(box.is_empty());
  EXPECT_LT(box[2].diam(), 0.05);
  EXPECT_TRUE(box[2].contains(0));
}

TEST(CtcAngleEquation, AnImpossibleBearingEmptiesTheBox) {
  IntervalVector box{Interval(0, 0.1), Interval(0), Interval(0), Interval(1), Interval(0), Interval(2.0)};
  bearing(0.01).contract(box);
  EXPECT_TRUE(box.is_empty());
}

TEST(CtcAngleEquation, SeveralAnglesAndBadArguments) {
  // a1 - a2 - 0.5 ≡ 0: a1 ≡ [1.5, 1.6] from a2.
  CtcAngleEquation c({1, -1}, Function({"u"}, "u"));
  IntervalVector box{Interval(-20, 20), Interval(1, 1.1) + Interval(6 * M_PI), Interval(-0.5)};
  c.contract(box);
  EXPECT_TRUE(angle_contains(box[0], 1.55));
  EXPECT_LT(box[0].diam(), 0.11);
  EXPECT_THROW(CtcAngleEquation({}, Function({"u"}, "u")), Error);
  EXPECT_THROW(CtcAngleEquation({2}, Function({"u"}, "u")), Error);
  EXPECT_THROW(CtcAngleEquation({1}, Function({"u"}, "(u, u)")), DimensionError);
}

}  // namespace
