// detail::Hc4Rows: the HC4 on rows the caller fills gives the boxes
// hc4_revise gives one by one, also when a second Hc4Rows (a larger tape) is
// made while the first holds the thread's rows.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "sillage/expr/hc4_rows.h"

using namespace sillage;

namespace {

// Writes `count` random boxes of f's variables into hc's rows, and returns them.
std::vector<IntervalVector> fill(const detail::Hc4Rows& hc, std::size_t n, std::size_t count, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<IntervalVector> boxes(count, IntervalVector(n));
  for (std::size_t j = 0; j < count; ++j) {
    for (std::size_t i = 0; i < n; ++i) {
      const double a = u(rng), b = u(rng);
      boxes[j][i] = Interval(std::min(a, b), std::max(a, b));
      hc.var_row(i, count)[j] = boxes[j][i];
    }
  }
  return boxes;
}

// The rows hold what hc4_revise gives box by box; ok says which boxes emptied.
void expect_box_by_box(const Function& f, const detail::Hc4Rows& hc, const std::vector<IntervalVector>& boxes,
                       const std::uint8_t* ok, const IntervalVector& y) {
  const std::size_t count = boxes.size();
  for (std::size_t j = 0; j < count; ++j) {
    IntervalVector b = boxes[j];
    const bool nonempty = f.hc4_revise(b, y);
    ASSERT_EQ(ok[j] != 0, nonempty) << j;
    if (!nonempty) continue;
    for (std::size_t i = 0; i < f.nb_vars(); ++i) EXPECT_EQ(hc.var_row(i, count)[j], b[i]) << j << " " << i;
  }
}

}  // namespace

TEST(Hc4Rows, NestedRowsEqualBoxByBox) {
  const Function small({"x", "y"}, "x*y - 1");
  const Function large({"a", "b", "c"}, "a*b + sqr(c - a) - exp(b)/(1 + sqr(c))");
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const std::size_t count = 1 + trial % detail::Hc4Rows::kMaxBoxes;
    const detail::Hc4Rows outer(small);
    const auto outer_boxes = fill(outer, 2, count, rng);
    {
      const detail::Hc4Rows inner(large);  // a larger tape, while outer holds the thread's rows
      const auto inner_boxes = fill(inner, 3, count, rng);
      std::uint8_t ok[detail::Hc4Rows::kMaxBoxes];
      inner.contract(count, IntervalVector{Interval(-0.5, 0.5)}, ok);
      expect_box_by_box(large, inner, inner_boxes, ok, IntervalVector{Interval(-0.5, 0.5)});
    }
    std::uint8_t ok[detail::Hc4Rows::kMaxBoxes];
    outer.contract(count, IntervalVector{Interval(0.0)}, ok);
    expect_box_by_box(small, outer, outer_boxes, ok, IntervalVector{Interval(0.0)});
  }
}
