// split_region (component_split.h): pieces of a region with zero-free
// boundaries, checked against analytic maps with known zeros and against a
// brute-force winding number.
#include <gtest/gtest.h>

#include <random>

#include "plane_maps.h"
#include "sillage/error.h"
#include "sillage/loops/component_split.h"
#include "sillage/loops/topological_degree.h"

using namespace sillage;
using namespace sillage::test;

namespace {

// Cells of an n x m grid over [x0, x1] x [y0, y1].
std::vector<IntervalVector> grid(double x0, double x1, double y0, double y1, int n, int m) {
  std::vector<IntervalVector> r;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      r.push_back(box(x0 + (x1 - x0) * i / n, x0 + (x1 - x0) * (i + 1) / n, y0 + (y1 - y0) * j / m,
                      y0 + (y1 - y0) * (j + 1) / m));
    }
  }
  return r;
}

bool holds(const std::vector<IntervalVector>& boxes, double x, double y) {
  for (const IntervalVector& b : boxes) {
    if (b[0].contains(x) && b[1].contains(y)) return true;
  }
  return false;
}

// f = (x^2 - a^2, y): zeros (-a, 0) of degree -1 and (a, 0) of degree +1.
PlaneFunction two_zeros(double a) {
  return interval_map([a](auto x, auto y) { return std::pair{sq(x) - a * a, y}; });
}
PlaneJacobian two_zeros_jacobian() {
  return [](const IntervalVector& t) {
    IntervalMatrix j(2, 2, Interval(0));
    j(0, 0) = 2 * t[0];
    j(1, 1) = Interval(1);
    return j;
  };
}

// f = (x (x^2 - a^2), y): zeros at x = -a, 0, a of degrees +1, -1, +1.
PlaneFunction three_zeros(double a) {
  return interval_map([a](auto x, auto y) { return std::pair{x * (sq(x) - a * a), y}; });
}
PlaneJacobian three_zeros_jacobian(double a) {
  return [a](const IntervalVector& t) {
    IntervalMatrix j(2, 2, Interval(0));
    j(0, 0) = 3 * sqr(t[0]) - a * a;
    j(1, 1) = Interval(1);
    return j;
  };
}

}  // namespace

TEST(SplitRegion, TwoZerosOfOppositeOrientations) {
  const auto cells = grid(-1, 1, -0.5, 0.5, 4, 2);
  const PlaneFunction f = two_zeros(0.3);
  ASSERT_EQ(topological_degree(cells, f).degree, 0);  // the whole proves nothing
  const SplitResult r = split_region(cells, f, two_zeros_jacobian());
  ASSERT_EQ(r.pieces.size(), 2u);
  EXPECT_EQ(r.pieces[0].degree, -1);  // ordered by lower corner: x = -0.3 first
  EXPECT_EQ(r.pieces[1].degree, 1);
  EXPECT_TRUE(holds(r.pieces[0].boxes, -0.3, 0));
  EXPECT_TRUE(holds(r.pieces[1].boxes, 0.3, 0));
  EXPECT_EQ(r.degree(), 0);
  EXPECT_EQ(r.count(), 2u);
  EXPECT_EQ(r.nb_proven(), 2u);
  for (const SplitPiece& p : r.pieces) {
    EXPECT_EQ(p.count, 1u);
    for (const IntervalVector& b : p.boxes) EXPECT_TRUE(b.is_subset(p.t_box));
  }
}

TEST(SplitRegion, ThreeZeros) {
  const double a = 0.4;
  const auto cells = grid(-1, 1, -0.25, 0.25, 8, 2);
  const PlaneFunction f = three_zeros(a);
  ASSERT_EQ(topological_degree(cells, f).degree, 1);
  const SplitResult r = split_region(cells, f, three_zeros_jacobian(a));
  ASSERT_EQ(r.pieces.size(), 3u);
  const double xs[] = {-a, 0, a};
  const int degrees[] = {1, -1, 1};
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(r.pieces[k].degree, degrees[k]);
    EXPECT_EQ(r.pieces[k].count, 1u);
    EXPECT_TRUE(holds(r.pieces[k].boxes, xs[k], 0));
  }
  EXPECT_EQ(r.degree(), 1);
  EXPECT_EQ(r.count(), 3u);
}

// The zeros at x = ±0.25 lie on edges of the grid (cells of width 0.25), and
// the middle one on a corner: each still lies in a piece of its degree.
TEST(SplitRegion, ZeroOnACandidateCut) {
  const double a = 0.25;
  const auto cells = grid(-1, 1, -0.5, 0.5, 8, 4);
  const SplitResult r = split_region(cells, three_zeros(a), three_zeros_jacobian(a));
  EXPECT_EQ(r.degree(), 1);
  EXPECT_EQ(r.count(), 3u);
  for (double x : {-a, 0.0, a}) {
    std::size_t in = 0;
    for (const SplitPiece& p : r.pieces) in += holds(p.boxes, x, 0) ? 1 : 0;
    EXPECT_EQ(in, 1u) << x;
  }
}

// A region without zero vanishes: the count 0 proves it.
TEST(SplitRegion, NoZeroAtAll) {
  const auto cells = grid(-1, 1, -0.5, 0.5, 4, 2);
  const PlaneFunction f = interval_map([](auto x, auto y) { return std::pair{sq(x) + 0.01, y}; });
  const SplitResult r = split_region(cells, f, two_zeros_jacobian());
  EXPECT_TRUE(r.pieces.empty());
  EXPECT_EQ(r.count(), 0u);
  EXPECT_EQ(r.degree(), 0);
}

// Random products of (z - z_k) and conj(z - z_k): zeros z_k of degree +1 or
// -1. On random unions of cells, every piece of determined degree has the
// brute-force winding number of its boundary, a proven piece holds a zero,
// and the pieces add up to the degree of the region.
TEST(SplitRegion, RandomMapsAgreeWithBruteForceWindingNumbers) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> at(-0.9, 0.9);
  std::bernoulli_distribution flip(0.5);
  int determined = 0;
  for (int trial = 0; trial < 40; ++trial) {
    struct Zero {
      double x, y;
      bool conj;
    };
    std::vector<Zero> zeros;
    const int nz = 1 + trial % 4;
    for (int k = 0; k < nz; ++k) zeros.push_back({at(rng), at(rng), flip(rng)});
    auto map = [zeros](auto x, auto y) {
      using T = decltype(x);
      T re = T(1.0), im = T(0.0);
      for (const Zero& z : zeros) {
        const T u = x - z.x, w = z.conj ? -(y - z.y) : y - z.y;
        const T r2 = re * u - im * w, i2 = re * w + im * u;
        re = r2;
        im = i2;
      }
      return std::pair{re, im};
    };
    const PlaneFunction f = interval_map(map);
    const PointMap g = point_map(map);
    const auto cells = random_cells(rng, 6, -1, 1, 0.7);
    SplitOptions o;
    o.count = false;  // no Jacobian here
    o.max_levels = 6;
    const SplitResult r = split_region(cells, f, PlaneJacobian{}, o);
    const DegreeResult whole = topological_degree(cells, f);
    if (whole.degree && r.degree()) { EXPECT_EQ(*whole.degree, *r.degree()); }
    for (const SplitPiece& p : r.pieces) {
      for (const IntervalVector& b : p.boxes) EXPECT_TRUE(holds(cells, b[0].mid(), b[1].mid()));
      if (!p.degree) continue;
      ++determined;
      EXPECT_NEAR(sampled_winding(contour(p.boxes), g), *p.degree, 1e-6);
      int inside = 0;
      for (const Zero& z : zeros) inside += holds(p.boxes, z.x, z.y) ? (z.conj ? -1 : 1) : 0;
      EXPECT_EQ(inside, *p.degree);  // zeros on a shared edge are not drawn (probability 0)
      if (p.proves_zero()) {
        bool any = false;
        for (const Zero& z : zeros) any = any || holds(p.boxes, z.x, z.y);
        EXPECT_TRUE(any);
      }
    }
  }
  EXPECT_GE(determined, 40);
}

TEST(SplitRegion, BadInputAndBudget) {
  const auto cells = grid(-1, 1, -0.5, 0.5, 4, 2);
  const PlaneFunction f = two_zeros(0.3);
  EXPECT_THROW(split_region({}, f, two_zeros_jacobian()), Error);
  SplitOptions o;
  o.max_levels = 0;
  EXPECT_THROW(split_region(cells, f, two_zeros_jacobian(), o), Error);
  o.max_levels = 4;
  o.budget.max_boxes = 10;
  EXPECT_THROW(split_region(cells, f, two_zeros_jacobian(), o), BudgetExceeded);
  EXPECT_THROW(split_region({IntervalVector{Interval(0, 1)}}, f, two_zeros_jacobian()), DimensionError);
}
