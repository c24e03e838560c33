#include <gtest/gtest.h>

#include <random>

#include "sillage/interval/interval_matrix.h"

using namespace sillage;

TEST(IntervalMatrix, ConstructionAndAccess) {
  const IntervalMatrix a{{{0, 1}, 2}, {3, {4, 5}}};
  EXPECT_EQ(a.rows(), 2u);
  EXPECT_EQ(a.cols(), 2u);
  EXPECT_EQ(a(0, 0), Interval(0, 1));
  EXPECT_EQ(a(1, 1), Interval(4, 5));
  EXPECT_EQ(a.at(1, 0), Interval(3));
  EXPECT_THROW(a.at(2, 0), DimensionError);
  EXPECT_EQ(a.row(1), (IntervalVector{3, {4, 5}}));
  EXPECT_EQ(a.col(1), (IntervalVector{2, {4, 5}}));
  EXPECT_THROW(a.row(2), DimensionError);
  EXPECT_TRUE(IntervalMatrix(2, 3)(1, 2).is_all_reals());
  EXPECT_EQ(IntervalMatrix::identity(2), (IntervalMatrix{{1, 0}, {0, 1}}));
  EXPECT_EQ(IntervalMatrix::from_point({{1, 2}, {3, 4}}), (IntervalMatrix{{1, 2}, {3, 4}}));
  EXPECT_EQ(IntervalMatrix::from_bounds({{0, 1}}, {{2, 3}}), (IntervalMatrix{{{0, 2}, {1, 3}}}));
  EXPECT_EQ(IntervalMatrix({IntervalVector{1, 2}, IntervalVector{3, 4}}), (IntervalMatrix{{1, 2}, {3, 4}}));
  EXPECT_THROW((IntervalMatrix{{1, 2}, {3}}), DimensionError);
  EXPECT_THROW(IntervalMatrix::from_bounds({{0, 1}}, {{2}}), DimensionError);
  EXPECT_THROW(IntervalMatrix::from_bounds({{1}}, {{0}}), Error);  // inverted bounds
}

TEST(IntervalMatrix, RowsColumnsTranspose) {
  IntervalMatrix a(2, 3, Interval(0));
  a.set_row(0, IntervalVector{1, 2, 3});
  a.set_col(2, IntervalVector{7, 8});
  EXPECT_EQ(a, (IntervalMatrix{{1, 2, 7}, {0, 0, 8}}));
  EXPECT_THROW(a.set_row(0, IntervalVector{1, 2}), DimensionError);
  EXPECT_THROW(a.set_col(3, IntervalVector{1, 2}), DimensionError);
  const IntervalMatrix t = a.transpose();
  EXPECT_EQ(t.rows(), 3u);
  EXPECT_EQ(t(2, 1), Interval(8));
  EXPECT_EQ(t.transpose(), a);
}

TEST(IntervalMatrix, Arithmetic) {
  const IntervalMatrix a{{1, 2}, {3, 4}};
  const IntervalMatrix b{{{0, 1}, 0}, {0, {-1, 1}}};
  EXPECT_EQ(a * IntervalMatrix::identity(2), a);
  EXPECT_EQ(a * a, (IntervalMatrix{{7, 10}, {15, 22}}));
  EXPECT_EQ(a * b, (IntervalMatrix{{{0, 1}, {-2, 2}}, {{0, 3}, {-4, 4}}}));
  EXPECT_EQ(a * (IntervalVector{{0, 1}, 1}), (IntervalVector{{2, 3}, {4, 7}}));
  EXPECT_EQ(a + b, (IntervalMatrix{{{1, 2}, 2}, {3, {3, 5}}}));
  EXPECT_EQ(a - a, (IntervalMatrix{{0, 0}, {0, 0}}));
  EXPECT_EQ(Interval(2) * a, (IntervalMatrix{{2, 4}, {6, 8}}));
  EXPECT_EQ(a * Interval(-1), -a);
  EXPECT_THROW(a * IntervalMatrix(3, 1), DimensionError);
  EXPECT_THROW(a * IntervalVector(3), DimensionError);
  EXPECT_THROW(a + IntervalMatrix(2, 3), DimensionError);
  // Outward rounding: 0.1 + 0.2 is not a double.
  const IntervalVector s = IntervalMatrix{{0.1, 0.2}} * IntervalVector{1, 1};
  EXPECT_LT(s[0].lb(), s[0].ub());
}

TEST(IntervalMatrix, ProductsEncloseEveryPointProduct) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-3, 3), w(0, 0.5), t(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    IntervalMatrix a(3, 4), b(4, 2);
    Matrix pa(3, Vector(4)), pb(4, Vector(2));
    for (std::size_t i = 0; i < 3; ++i)
      for (std::size_t j = 0; j < 4; ++j) {
        const double lo = u(rng), hi = lo + w(rng);
        a(i, j) = Interval(lo, hi);
        pa[i][j] = lo + (hi - lo) * t(rng);
      }
    for (std::size_t i = 0; i < 4; ++i)
      for (std::size_t j = 0; j < 2; ++j) {
        const double lo = u(rng), hi = lo + w(rng);
        b(i, j) = Interval(lo, hi);
        pb[i][j] = lo + (hi - lo) * t(rng);
      }
    // The exact product of the point matrices, entry by entry, lies in a * b:
    // checked with degenerate intervals (rigorous) against the interval product.
    const IntervalMatrix prod = a * b, exact = IntervalMatrix::from_point(pa) * IntervalMatrix::from_point(pb);
    EXPECT_TRUE(exact.is_subset(prod));
    EXPECT_EQ((a * b).transpose(), b.transpose() * a.transpose());
  }
}

TEST(IntervalMatrix, SetOperationsAndPredicates) {
  IntervalMatrix a{{{0, 2}, {0, 2}}};
  const IntervalMatrix b{{{1, 3}, {-1, 1}}};
  EXPECT_EQ(a & b, (IntervalMatrix{{{1, 2}, {0, 1}}}));
  EXPECT_EQ(a | b, (IntervalMatrix{{{0, 3}, {-1, 2}}}));
  EXPECT_EQ(hull(a, b), a | b);
  const IntervalMatrix disjoint{{{5, 6}, {0, 1}}};
  EXPECT_TRUE((a & disjoint).is_empty());
  EXPECT_TRUE((a & disjoint)(0, 1).is_empty());  // every entry emptied, like boxes
  EXPECT_EQ(a | IntervalMatrix::empty(1, 2), a);
  EXPECT_TRUE((a & b).is_subset(a));
  EXPECT_FALSE(a.is_subset(b));
  EXPECT_TRUE(IntervalMatrix::empty(1, 2).is_subset(b));
  EXPECT_TRUE((IntervalMatrix{{{0.5, 1}, {0.5, 1}}}).is_interior_subset(a));
  EXPECT_TRUE(a.intersects(b));
  EXPECT_FALSE(a.intersects(disjoint));
  EXPECT_TRUE(a.contains({{1, 1}}));
  EXPECT_FALSE(a.contains({{1, 3}}));
  EXPECT_THROW(a.contains({{1, 1, 1}}), DimensionError);
  EXPECT_THROW(a & IntervalMatrix(2, 2), DimensionError);
  EXPECT_EQ(a.lb(), (Matrix{{0, 0}}));
  EXPECT_EQ(a.ub(), (Matrix{{2, 2}}));
  EXPECT_EQ(a.mid(), (Matrix{{1, 1}}));
  EXPECT_EQ(a.max_diam(), 2);
  EXPECT_TRUE(IntervalMatrix{{1}}.is_degenerate());
  EXPECT_TRUE(IntervalMatrix(1, 1).is_unbounded());
  EXPECT_EQ(abs(IntervalMatrix{{{-2, 1}}}), (IntervalMatrix{{{0, 2}}}));
  EXPECT_EQ(a.inflate(1), (IntervalMatrix{{{-1, 3}, {-1, 3}}}));
  a &= b;
  EXPECT_EQ(a, (IntervalMatrix{{{1, 2}, {0, 1}}}));
}

TEST(IntervalMatrix, Str) {
  EXPECT_EQ((IntervalMatrix{{1, {2, 3}}, {4, 5}}).str(), "(([1, 1] ; [2, 3]) ; ([4, 4] ; [5, 5]))");
}
