// self_crossings (the true loops λ* of a sampled path): curves whose
// crossings are known in closed form (lemniscate of Gerono, limaçon), a
// square spiral with an exit line of known count, non-crossing paths
// (straight line, back-tracking, touching), random polylines against an
// O(n^2) brute force with exact integer arithmetic (degenerate cases on a
// small grid, near-collinear cases on large integers), and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "sillage/error.h"
#include "sillage/loops/orientation.h"
#include "sillage/loops/path_crossings.h"

using namespace sillage;

namespace {

using std::numbers::pi;

struct Path {
  std::vector<double> t, x, y;
  void add(double tk, double xk, double yk) {
    t.push_back(tk);
    x.push_back(xk);
    y.push_back(yk);
  }
};

template <class F>
Path sample(F&& curve, double ta, double tb, std::size_t n) {
  Path p;
  for (std::size_t k = 0; k <= n; ++k) {
    const double tk = ta + (tb - ta) * double(k) / double(n);
    const auto [xk, yk] = curve(tk);
    p.add(tk, xk, yk);
  }
  return p;
}

// Brute force with exact integer orientations (coordinates must be integers
// with |c| < 2^40 so that the products fit in 128 bits).
int int_orientation(const Path& p, std::size_t a, std::size_t b, std::size_t c) {
  __extension__ typedef __int128 I;
  auto x = [&](std::size_t k) { return I(std::int64_t(p.x[k])); };
  auto y = [&](std::size_t k) { return I(std::int64_t(p.y[k])); };
  const I abx = x(b) - x(a), aby = y(b) - y(a), acx = x(c) - x(a), acy = y(c) - y(a);
  const I d = abx * acy - aby * acx;
  return (d > 0) - (d < 0);
}

std::vector<std::pair<std::size_t, std::size_t>> brute_force_integer(const Path& p) {
  std::vector<std::pair<std::size_t, std::size_t>> r;
  for (std::size_t i = 0; i + 1 < p.t.size(); ++i) {
    for (std::size_t j = i + 2; j + 1 < p.t.size(); ++j) {
      const int c = int_orientation(p, i, i + 1, j), d = int_orientation(p, i, i + 1, j + 1);
      const int a = int_orientation(p, j, j + 1, i), b = int_orientation(p, j, j + 1, i + 1);
      if (c * d < 0 && a * b < 0) r.emplace_back(i, j);
    }
  }
  return r;
}

std::vector<std::pair<std::size_t, std::size_t>> segment_pairs(const std::vector<PathCrossing>& cs) {
  std::vector<std::pair<std::size_t, std::size_t>> r;
  for (const auto& c : cs) r.emplace_back(c.segment1, c.segment2);
  std::sort(r.begin(), r.end());
  return r;
}

// ---- closed-form curves ----

TEST(PathCrossings, LemniscateOfGeronoCrossesAtPiAndTwoPi) {
  // (sin t, sin t cos t) passes through the origin at t = π and t = 2π
  // (transversally); no other double point on [0.5, 2π + 0.5].
  const Path p = sample([](double t) { return std::pair{std::sin(t), std::sin(t) * std::cos(t)}; }, 0.5,
                        2 * pi + 0.5, 20000);
  const auto cs = self_crossings(p.t, p.x, p.y);
  ASSERT_EQ(cs.size(), 1u);
  EXPECT_NEAR(cs[0].t1, pi, 1e-6);
  EXPECT_NEAR(cs[0].t2, 2 * pi, 1e-6);
  EXPECT_NEAR(cs[0].x, 0.0, 1e-9);
  EXPECT_NEAR(cs[0].y, 0.0, 1e-9);
  EXPECT_LT(cs[0].segment1 + 1, cs[0].segment2);
  EXPECT_LE(p.t[cs[0].segment1], cs[0].t1);
  EXPECT_LE(cs[0].t1, p.t[cs[0].segment1 + 1]);
}

TEST(PathCrossings, LimaconInnerLoopCrossesAtTwoThirdsPi) {
  // r = 1/2 + cos θ vanishes at θ = 2π/3 and 4π/3: the inner loop closes there.
  auto limacon = [](double th) {
    const double r = 0.5 + std::cos(th);
    return std::pair{r * std::cos(th), r * std::sin(th)};
  };
  for (std::size_t n : {999u, 10000u, 100001u}) {  // odd counts: no sample exactly at the crossing
    const Path p = sample(limacon, 0.0, 2 * pi, n);
    const auto cs = self_crossings(p.t, p.x, p.y);
    ASSERT_EQ(cs.size(), 1u) << n;
    const double h = 2 * pi / double(n);
    EXPECT_NEAR(cs[0].t1, 2 * pi / 3, 2 * h * h) << n;
    EXPECT_NEAR(cs[0].t2, 4 * pi / 3, 2 * h * h) << n;
    EXPECT_LT(std::hypot(cs[0].x, cs[0].y), h * h) << n;
  }
}

TEST(PathCrossings, TwoTurnsOfACircleOverlapButNeverCross) {
  // A circle run twice through the very same samples: collinear overlaps
  // (every segment of the second turn lies on one of the first), no proper
  // crossing. (Recomputing the second turn's samples would move them by
  // ulps, and then exact predicates do see tiny crossings.)
  Path p = sample([](double t) { return std::pair{std::cos(2 * pi * t / 100), std::sin(2 * pi * t / 100)}; }, 0, 99,
                  99);
  for (std::size_t k = 0; k < 101; ++k) p.add(100.0 + double(k), p.x[k % 100], p.y[k % 100]);
  EXPECT_TRUE(self_crossings(p.t, p.x, p.y).empty());
}

TEST(PathCrossings, ProlateCycloidCrossesOncePerArch) {
  // (s - 2 sin s, 1 - 2 cos s): one crossing per period, at 2πm ± s*,
  // s* = 2 sin s* (s* ≈ 1.895494267).
  double s = 1.9;
  for (int k = 0; k < 50; ++k) s -= (s - 2 * std::sin(s)) / (1 - 2 * std::cos(s));
  const Path p = sample([](double u) { return std::pair{u - 2 * std::sin(u), 1 - 2 * std::cos(u)}; }, 0.0, 8 * pi,
                        80001);
  const auto cs = self_crossings(p.t, p.x, p.y);
  ASSERT_EQ(cs.size(), 3u);  // the loops around 2π, 4π, 6π (0 and 8π are the ends)
  for (std::size_t m = 0; m < 3; ++m) {
    EXPECT_NEAR(cs[m].t1, 2 * pi * double(m + 1) - s, 1e-6);
    EXPECT_NEAR(cs[m].t2, 2 * pi * double(m + 1) + s, 1e-6);
    EXPECT_NEAR(cs[m].x, 2 * pi * double(m + 1), 1e-6);
  }
}

// ---- constructed paths with known counts ----

// Outward square spiral on integer points: steps 1, 1, 2, 2, 3, 3, ...
// heading E, N, W, S; `sides` segments. Never crosses itself.
Path square_spiral(std::size_t sides) {
  Path p;
  double x = 0, y = 0, t = 0;
  p.add(t, x, y);
  const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
  for (std::size_t k = 0; k < sides; ++k) {
    const double len = double(k / 2 + 1);
    x += dx[k % 4] * len;
    y += dy[k % 4] * len;
    t += len;
    p.add(t, x, y);
  }
  return p;
}

TEST(PathCrossings, SquareSpiralWithExitLineCrossesEveryUpperSide) {
  for (std::size_t sides : {4u, 9u, 40u, 401u}) {
    Path s = square_spiral(sides);
    EXPECT_TRUE(self_crossings(s.t, s.x, s.y).empty()) << sides;
    // Run it inward (reversed), then leave the centre along x = y/(2 ymax):
    // the exit crosses every side above the centre (at integer y > 0, away
    // from the integer vertices), and nothing else.
    Path p;
    const std::size_t n = s.t.size();
    for (std::size_t k = 0; k < n; ++k) p.add(s.t[n - 1] - s.t[n - 1 - k], s.x[n - 1 - k], s.y[n - 1 - k]);
    const double ymax = *std::max_element(s.y.begin(), s.y.end()) + 0.5;
    p.add(p.t.back() + ymax, 0.5, ymax);
    std::size_t upper = 0;
    for (std::size_t k = 0; k + 1 < n; ++k) upper += (s.y[k] == s.y[k + 1] && s.y[k] > 0) ? 1 : 0;
    const auto cs = self_crossings(p.t, p.x, p.y);
    ASSERT_EQ(cs.size(), upper) << sides;
    const double t_exit = p.t[p.t.size() - 2];
    for (const auto& c : cs) {
      EXPECT_EQ(c.segment2, p.t.size() - 2);
      EXPECT_NEAR(c.x, 0.5 * c.y / ymax, 1e-12);
      EXPECT_NEAR(c.t2, t_exit + c.y, 1e-9);  // unit speed along y on the exit line
      EXPECT_EQ(c.y, std::round(c.y));
    }
  }
}

TEST(PathCrossings, StraightLinesAndTouchingPathsHaveNoCrossing) {
  Path line = sample([](double t) { return std::pair{3 * t - 1, 0.5 * t}; }, 0, 1, 100000);
  EXPECT_TRUE(self_crossings(line.t, line.x, line.y).empty());
  Path back;  // out and back on the same line: collinear overlap only
  for (int k = 0; k <= 10; ++k) back.add(k, k, 2 * k);
  for (int k = 9; k >= 0; --k) back.add(20 - k, k + 0.5, 2 * k + 1);
  EXPECT_TRUE(self_crossings(back.t, back.x, back.y).empty());
  Path touch;  // a vertex lands on an earlier segment and turns back: a touch
  for (auto [x, y] : {std::pair{0.0, 0.0}, {4.0, 0.0}, {4.0, 2.0}, {2.0, 2.0}, {2.0, 0.0}, {1.0, 2.0}}) {
    touch.add(double(touch.t.size()), x, y);
  }
  EXPECT_TRUE(self_crossings(touch.t, touch.x, touch.y).empty());
  Path stay;  // a standing point repeated: zero-length segments
  for (int k = 0; k < 1000; ++k) stay.add(k, 1.0, 1.0);
  EXPECT_TRUE(self_crossings(stay.t, stay.x, stay.y).empty());
  Path few;
  few.add(0, 0, 0), few.add(1, 1, 1), few.add(2, 0, 1);
  EXPECT_TRUE(self_crossings(few.t, few.x, few.y).empty());
  EXPECT_TRUE(self_crossings({}, {}, {}).empty());
}

TEST(PathCrossings, CrossingExactlyAtADoubleVertexIsNotProper) {
  // Two segments meeting at a shared vertex of both (an X through a sample):
  // the crossing is between a vertex and segments: touching, not proper.
  Path p;
  for (auto [x, y] : {std::pair{-1.0, -1.0}, {0.0, 0.0}, {1.0, 1.0}, {1.0, -1.0}, {0.0, 0.0}, {-1.0, 1.0}}) {
    p.add(double(p.t.size()), x, y);
  }
  EXPECT_TRUE(self_crossings(p.t, p.x, p.y).empty());
  // Shift the second pass by a hair to the right of y = x: segment 4 now
  // crosses segment 1 properly (at x = y = 5e-101), segment 3 stays below.
  p.x[4] = 1e-100;
  const auto cs = self_crossings(p.t, p.x, p.y);
  ASSERT_EQ(cs.size(), 1u);
  EXPECT_EQ(cs[0].segment1, 1u);
  EXPECT_EQ(cs[0].segment2, 4u);
}

// ---- random polylines against the brute force ----

TEST(PathCrossings, RandomIntegerPolylinesMatchExactBruteForce) {
  // Coordinates on a 9 x 9 grid: many collinear, overlapping and touching cases.
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = 2 + rng() % 60;
    Path p;
    for (std::size_t k = 0; k < n; ++k) p.add(double(k), double(rng() % 9), double(rng() % 9));
    const auto cs = self_crossings(p.t, p.x, p.y);
    ASSERT_EQ(segment_pairs(cs), brute_force_integer(p)) << "trial " << trial;
    for (const auto& c : cs) {
      EXPECT_LT(c.t1, c.t2);
      EXPECT_LE(p.t[c.segment1], c.t1);
      EXPECT_LE(c.t2, p.t[c.segment2 + 1]);
    }
  }
}

TEST(PathCrossings, NearCollinearLargeIntegersMatchExactBruteForce) {
  // Points on a line y = 3x + 1 at about 2^38, nudged by a unit: the double
  // evaluation of the orientation rounds (products near 2^77), the exact
  // predicate must not.
  std::mt19937_64 rng(7);
  const std::int64_t big = std::int64_t(1) << 38;
  std::size_t total = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = 4 + rng() % 12;
    Path p;
    for (std::size_t k = 0; k < n; ++k) {
      const std::int64_t u = std::int64_t(rng() % (1u << 20)) - (1 << 19);
      const std::int64_t x = big / 4 + u, y = 3 * x + 1 + std::int64_t(rng() % 3) - 1;
      p.add(double(k), double(x), double(y));
    }
    const auto expected = brute_force_integer(p);
    total += expected.size();
    ASSERT_EQ(segment_pairs(self_crossings(p.t, p.x, p.y)), expected) << "trial " << trial;
  }
  EXPECT_GT(total, 0u);  // the test does exercise crossings
}

TEST(PathCrossings, RandomWalksMatchBruteForce) {
  // Random walks with steps of very different scales and real coordinates
  // (degenerate configurations have probability zero): the grid finds
  // exactly the pairs of an all-pairs scan with the same predicate.
  std::mt19937_64 rng(2024);
  auto uniform = [&] { return double(rng() >> 11) * 0x1p-53; };
  for (int trial = 0; trial < 30; ++trial) {
    const std::size_t n = 50 + rng() % 1500;
    const double step = trial % 3 == 0 ? 1e-3 : trial % 3 == 1 ? 1.0 : 1e4;
    Path p;
    double x = 1000 * uniform(), y = -500 * uniform();
    for (std::size_t k = 0; k < n; ++k) {
      p.add(0.1 * double(k), x, y);
      const double a = 2 * pi * uniform(), r = step * (trial % 2 ? uniform() : std::pow(uniform(), 4));
      x += r * std::cos(a);
      y += r * std::sin(a);
    }
    std::vector<std::pair<std::size_t, std::size_t>> expected;
    for (std::size_t i = 0; i + 1 < n; ++i) {
      for (std::size_t j = i + 2; j + 1 < n; ++j) {
        auto o = [&](std::size_t a, std::size_t b, std::size_t c) {
          return detail::orientation_sign(p.x[a], p.y[a], p.x[b], p.y[b], p.x[c], p.y[c]);
        };
        if (o(i, i + 1, j) * o(i, i + 1, j + 1) < 0 && o(j, j + 1, i) * o(j, j + 1, i + 1) < 0) {
          expected.emplace_back(i, j);
        }
      }
    }
    const auto cs = self_crossings(p.t, p.x, p.y);
    ASSERT_EQ(segment_pairs(cs), expected) << "trial " << trial;
    for (const auto& c : cs) {  // the reported point lies on both segments
      for (std::size_t s : {c.segment1, c.segment2}) {
        const double len = std::hypot(p.x[s + 1] - p.x[s], p.y[s + 1] - p.y[s]);
        const double cross = (p.x[s + 1] - p.x[s]) * (c.y - p.y[s]) - (p.y[s + 1] - p.y[s]) * (c.x - p.x[s]);
        EXPECT_LE(std::fabs(cross) / len, 1e-9 * (1 + std::fabs(c.x) + std::fabs(c.y))) << trial;
      }
    }
  }
}

TEST(PathCrossings, OrientationSignIsExactWhereDoublesFail) {
  // Shewchuk's example: points near (0.5, 0.5) on the line y = x, offset by
  // ulps; the sign is that of the exact determinant.
  const double u = std::numeric_limits<double>::epsilon() / 2;
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      const double px = 0.5 + i * u, py = 0.5 + j * u;
      // orient((12, 12), (24, 24), p) = 12 (py - px): exact sign of j - i.
      EXPECT_EQ(detail::orientation_sign(12, 12, 24, 24, px, py), (j > i) - (j < i)) << i << " " << j;
    }
  }
  EXPECT_EQ(detail::orientation_sign(0, 0, 1, 0, 0, 1), 1);
  EXPECT_EQ(detail::orientation_sign(0, 0, 1, 0, 0, -1), -1);
  EXPECT_EQ(detail::orientation_sign(0, 0, 1, 1, 3, 3), 0);
}

TEST(PathCrossings, MillionPointSurveyMatchesCoarseSampling) {
  // A lawn-mower path (10 legs along x, then 10 along y, 100 crossings),
  // sampled with 10^6 points: the same crossings as with 2 * 10^4 points
  // (neither sampling puts a point on a crossing).
  auto survey = [](double s) {
    // 20 legs of length 100 joined by straight 10 m hops; s in [0, 20 * 110).
    const int leg = std::min(19, int(s / 110));
    const double u = s - 110 * leg;
    const double along = u < 100 ? u : 100, across = u < 100 ? 0 : u - 100;
    const double a = leg % 2 == 0 ? along : 100 - along;
    const double off = 5 + 10 * (leg % 10) + across;
    return leg < 10 ? std::pair{a, off} : std::pair{off, 100 - a};
  };
  const double end = 20 * 110 - 10;
  const Path fine = sample(survey, 0, end, 1000000), coarse = sample(survey, 0, end, 21937);
  const auto cf = self_crossings(fine.t, fine.x, fine.y), cc = self_crossings(coarse.t, coarse.x, coarse.y);
  ASSERT_EQ(cf.size(), 100u);
  ASSERT_EQ(cc.size(), 100u);
  for (std::size_t k = 0; k < cf.size(); ++k) {
    EXPECT_NEAR(cf[k].t1, cc[k].t1, 1e-6);
    EXPECT_NEAR(cf[k].t2, cc[k].t2, 1e-6);
  }
}

// ---- bad input ----

TEST(PathCrossings, BadInputIsAnError) {
  EXPECT_THROW(self_crossings({0, 1}, {0, 1}, {0}), DimensionError);
  EXPECT_THROW(self_crossings({0, 1, 1}, {0, 1, 2}, {0, 1, 2}), Error);
  EXPECT_THROW(self_crossings({0, 2, 1}, {0, 1, 2}, {0, 1, 2}), Error);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(self_crossings({0, 1, 2}, {0, nan, 2}, {0, 1, 2}), Error);
  EXPECT_THROW(self_crossings({0, 1, 2}, {0, 1, 2}, {0, 1, inf}), Error);
  EXPECT_THROW(self_crossings({0, nan, 2}, {0, 1, 2}, {0, 1, 2}), Error);
  EXPECT_THROW(self_crossings({0, 1, 2}, {0, 1e200, 2}, {0, 1, 2}), Error);
  try {
    self_crossings({0, 1, 2, 2.5, 2.5}, {0, 1, 2, 3, 4}, {0, 1, 2, 3, 4});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("t[4]"), std::string::npos) << e.what();
  }
}

}  // namespace
