// x^y with an integral y in expressions: the integer power, as pow(x, double)
// for intervals, even beyond the int range (issue 12, item 3).
#include <gtest/gtest.h>

#include "sillage/expr/function.h"
#include "sillage/interval/elementary.h"

using namespace sillage;

TEST(PowIntegral, ExpressionAndIntervalAgree) {
  const ExprVar x("x");
  const std::vector<Interval> boxes = {Interval(-2, -1), Interval(-1, -1), Interval(-1, 0.5), Interval(0.5, 2)};
  for (const double y : {2.0, 3.0, -2.0, -3.0}) {
    const Function f({x}, pow(x, y));
    for (const Interval& b : boxes) EXPECT_EQ(f.eval(IntervalVector{b}), pow(b, y)) << b << "^" << y;
  }
  // Beyond the int range: (x^2)^m and x * x^(2m), still defined for x < 0.
  const Function even({x}, pow(x, 0x1p40)), odd({x}, pow(x, 0x1p40 + 1));
  EXPECT_EQ(even.eval(IntervalVector{Interval(-1.0)}), Interval(1.0));
  EXPECT_EQ(odd.eval(IntervalVector{Interval(-1.0)}), Interval(-1.0));
  for (const Interval& b : boxes) {
    EXPECT_TRUE(pow(b, 0x1p40).is_subset(even.eval(IntervalVector{b}))) << b;
    EXPECT_TRUE(pow(b, 0x1p40 + 1).is_subset(odd.eval(IntervalVector{b}))) << b;
  }
}
