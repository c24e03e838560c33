// Angles modulo 2π (interval/angle.h): angle_meet keeps every common angle
// inside its first argument (brute force over sampled angles), picks one
// copy when one fits, and angle_contains never reports a true angle outside.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <random>

#include "sillage/interval/angle.h"

using namespace sillage;

namespace {

const double kTwoPi = 2 * M_PI;

TEST(Angle, MeetPicksTheCopyThatFits) {
  const Interval r = angle_meet(Interval(0, 1), Interval(kTwoPi + 0.5, kTwoPi + 0.7));
  EXPECT_LE(r.lb(), 0.5);
  EXPECT_GE(r.ub(), 0.7);
  EXPECT_LT(r.diam(), 0.2 + 1e-12);
  // A wide (unwrapped) heading narrowed to one turn, the copy nearest its middle.
  const Interval w = angle_meet(Interval(-46, 46), Interval(1, 1.1) + Interval(40 * M_PI));
  EXPECT_TRUE(w.is_subset(Interval(-46, 46)));
  EXPECT_TRUE(angle_contains(w, 1.0) && angle_contains(w, 1.1));
  EXPECT_LT(std::abs(w.mid()), M_PI + 1.1);  // the copy nearest the middle of [-46, 46]
  EXPECT_LT(w.diam(), 0.1 + 1e-10);
  const Interval h = angle_meet(Interval(0, INFINITY), Interval(-0.2, 0.2));
  EXPECT_TRUE(h.is_subset(Interval(0, INFINITY)));
  EXPECT_LT(h.diam(), 0.4 + 1e-10);
}

TEST(Angle, MeetHullsThePiecesWhenNoCopyFits) {
  // [5.5, 6.5] meets [0, 6] at both ends (6.5 - 2π ≈ 0.217): the hull is [0, 6].
  EXPECT_EQ(angle_meet(Interval(0, 6), Interval(5.5, 6.5)), Interval(0, 6));
  // One end only: [5.5, 6].
  const Interval r = angle_meet(Interval(3, 6), Interval(5.5, 6.5));
  EXPECT_EQ(r.ub(), 6);
  EXPECT_LE(r.lb(), 5.5);
  EXPECT_GT(r.lb(), 5.49);
}

TEST(Angle, MeetOfDisjointArcsIsEmptyAndOfTheCircleIsTheFirst) {
  EXPECT_TRUE(angle_meet(Interval(0, 1), Interval(2, 3)).is_empty());
  EXPECT_TRUE(angle_meet(Interval(0, 1), Interval(2, 3) + Interval(8 * M_PI)).is_empty());
  EXPECT_EQ(angle_meet(Interval(0.3, 0.4), Interval(-4, 4)), Interval(0.3, 0.4));
  EXPECT_EQ(angle_meet(Interval(0.3, 0.4), Interval()), Interval(0.3, 0.4));
  EXPECT_TRUE(angle_meet(Interval::empty(), Interval(0, 1)).is_empty());
}

// Every angle of both arcs, sampled, stays; the result is inside x.
TEST(Angle, MeetKeepsEveryCommonAngleBruteForce) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-30, 30), w(0, 8);
  for (int trial = 0; trial < 3000; ++trial) {
    const double xl = u(rng), yl = u(rng);
    const Interval x(xl, xl + w(rng)), y(yl, yl + w(rng) * (trial % 3 == 0 ? 0.1 : 1));
    const Interval r = angle_meet(x, y);
    ASSERT_TRUE(r.is_subset(x)) << x << " " << y << " -> " << r;
    for (int s = 0; s < 40; ++s) {
      const double a = std::min(x.ub(), x.lb() + (x.ub() - x.lb()) * s / 39.0);  // an angle of x
      // Is a on y's arc (with a margin off the rounding)? Then it must be on r's.
      const double off = std::remainder(a - y.mid(), kTwoPi);
      if (std::abs(off) > y.rad() - 1e-9) continue;
      ASSERT_TRUE(angle_contains(r, a)) << std::setprecision(17) << x << " " << y << " -> " << r << " loses " << a;
    }
  }
}

TEST(Angle, ContainsModuloTwoPi) {
  EXPECT_TRUE(angle_contains(Interval(0.1, 0.2), 0.15 + 6 * M_PI));
  EXPECT_TRUE(angle_contains(Interval(0.1, 0.2) + Interval(-4 * M_PI), 0.15));
  EXPECT_FALSE(angle_contains(Interval(0.1, 0.2), 0.3));
  EXPECT_FALSE(angle_contains(Interval(0.1, 0.2), NAN));
  EXPECT_TRUE(angle_contains(Interval(-10, 10), 123.0));  // the whole circle
  EXPECT_TRUE(angle_is_circle(Interval(-4, 4)));
  EXPECT_FALSE(angle_is_circle(Interval(-3, 3)));
  EXPECT_TRUE(angle_is_circle(Interval()));
}

}  // namespace

namespace {

// angle_lift keeps every copy inside a real interval (a lifted heading),
// where angle_meet may keep one: brute force over the copies.
TEST(Angle, LiftKeepsEveryCopy) {
  // [3, 3.1] inside [-4, 4]: the copies [3, 3.1] and [3 - 2π, 3.1 - 2π] both.
  const Interval l = angle_lift(Interval(3, 3.1), Interval(-4, 4));
  EXPECT_LE(l.lb(), 3 - 2 * M_PI);
  EXPECT_GE(l.ub(), 3.1);
  EXPECT_EQ(angle_lift(Interval(3, 3.1), Interval(0, 1)), Interval::empty());
  EXPECT_EQ(angle_lift(Interval(-4, 4), Interval(0, 1)), Interval(0, 1));
  EXPECT_EQ(angle_lift(Interval(0, 0.1), Interval(0, INFINITY)), Interval(0, INFINITY));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-60, 60), w(0, 30);
  for (int trial = 0; trial < 2000; ++trial) {
    const double wl = u(rng), yl = u(rng);
    const Interval within(wl, wl + w(rng)), y(yl, yl + w(rng) / 10);
    const Interval l = angle_lift(y, within);
    ASSERT_TRUE(l.is_subset(within));
    for (int k = -30; k <= 30; ++k) {
      const Interval piece = Interval(y.lb() + 2 * M_PI * k, y.ub() + 2 * M_PI * k) & within;
      if (piece.is_empty() || angle_is_circle(y)) continue;
      ASSERT_TRUE(piece.is_subset(l.inflate(1e-9))) << within << " " << y << " -> " << l << " loses copy " << k;
    }
  }
}

}  // namespace
