// QInterColumns (CtcQEval's accumulator): each column's hull, from its q + 1
// extreme bounds per side, equals q_inter of all the intervals added, for
// every q' <= q. Random columns with ties, empty and unbounded intervals.
#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

#include "sillage/ctc/q_inter.h"
#include "sillage/ctc/q_inter_columns.h"

using namespace sillage;
using sillage::detail::QInterColumns;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Bounds drawn from a few values, so that ties between bounds are common.
Interval random_interval(std::mt19937& rng) {
  std::uniform_int_distribution<int> kind(0, 19), v(-6, 6);
  const int k = kind(rng);
  if (k == 0) return Interval::empty();
  if (k == 1) return Interval(-kInf, v(rng));
  if (k == 2) return Interval(v(rng), kInf);
  int a = v(rng), b = v(rng);
  if (a > b) std::swap(a, b);
  return Interval(a, b);
}

}  // namespace

TEST(QInterColumns, EqualsQInterOfEveryColumn) {
  std::mt19937 rng(20261129);
  for (int q = 0; q <= 4; ++q) {
    const std::size_t nb_columns = 400;
    QInterColumns columns(nb_columns, q);
    std::vector<std::vector<Interval>> kept(nb_columns);
    std::uniform_int_distribution<int> size(0, 12);
    for (std::size_t c = 0; c < nb_columns; ++c) {
      const int m = size(rng);
      for (int i = 0; i < m; ++i) {
        const Interval x = random_interval(rng);
        kept[c].push_back(x);
        columns.add(c, x);
      }
    }
    for (std::size_t c = 0; c < nb_columns; ++c) {
      ASSERT_EQ(columns.count(c), kept[c].size());
      for (int qp = 0; qp <= q; ++qp) {
        const Interval expected = kept[c].empty() ? Interval::all_reals() : q_inter(kept[c], qp);
        ASSERT_EQ(columns.hull(c, qp), expected) << "q " << q << " q' " << qp << " column " << c;
      }
    }
  }
}

TEST(QInterColumns, HandCases) {
  QInterColumns columns(3, 1);
  // Column 0: [0, 4], [1, 5], [3, 9]: every point of [3, 4] is in all three,
  // [1, 5] in two of them.
  for (const Interval& x : {Interval(0, 4), Interval(1, 5), Interval(3, 9)}) columns.add(0, x);
  EXPECT_EQ(columns.hull(0, 0), Interval(3, 4));
  EXPECT_EQ(columns.hull(0, 1), Interval(1, 5));
  // Column 1: two disjoint intervals and an empty one: no point in two of them.
  for (const Interval& x : {Interval(0, 1), Interval(2, 3), Interval::empty()}) columns.add(1, x);
  EXPECT_TRUE(columns.hull(1, 0).is_empty());
  EXPECT_TRUE(columns.hull(1, 1).is_empty());
  // Column 2: nothing added, or fewer intervals than q' + 1: the whole line.
  EXPECT_EQ(columns.hull(2, 0), Interval::all_reals());
  columns.add(2, Interval(7));
  EXPECT_EQ(columns.hull(2, 1), Interval::all_reals());
  EXPECT_EQ(columns.hull(2, 0), Interval(7));
  EXPECT_THROW(QInterColumns(1, -1), Error);
}
