#include <gtest/gtest.h>

#include "sillage/interval/interval.h"
#include "sillage/interval/interval_vector.h"

using namespace sillage;

TEST(Interval, SetOperationsFollowTheThesis) {
  const Interval x(1, 3), e = Interval::empty(), all = Interval::all_reals();
  EXPECT_EQ(x | e, x);                 // (2.9)
  EXPECT_TRUE((x & e).is_empty());     // (2.10)
  EXPECT_EQ(x | all, all);             // (2.11)
  EXPECT_EQ(x & all, x);               // (2.12)
  EXPECT_EQ(x & Interval(2, 5), Interval(2, 3));
  EXPECT_TRUE((x & Interval(4, 5)).is_empty());
}

TEST(Interval, ContractorPlusExampleOfTheThesis) {
  // C+([4,5],[0,3],[-2,2]) = ([4,5],[2,3],[1,2]) (2.31)
  Interval a(4, 5), x(0, 3), y(-2, 2);
  a &= x + y;
  x &= a - y;
  y &= a - x;
  EXPECT_EQ(a, Interval(4, 5));
  EXPECT_EQ(x, Interval(2, 3));
  EXPECT_EQ(y, Interval(1, 2));
}

TEST(Interval, DivisionByIntervalsContainingZero) {  // (2.19)
  EXPECT_TRUE((Interval(1) / Interval(0, 0)).is_empty());
  EXPECT_EQ(Interval(1) / Interval(0, 2), Interval(0.5, INFINITY));
  EXPECT_EQ(Interval(1) / Interval(-2, 0), Interval(-INFINITY, -0.5));
  EXPECT_EQ(Interval(1) / Interval(-1, 1), Interval::all_reals());
  EXPECT_EQ(Interval(-30, 0) / Interval(-3, 0), Interval(0, INFINITY));
}

TEST(Interval, ZeroTimesUnboundedIsZero) {
  EXPECT_EQ(Interval(0) * Interval::all_reals(), Interval(0));
  EXPECT_EQ(Interval(0) * Interval(1, INFINITY), Interval(0));
}

TEST(Interval, SqrtIsSetBased) {
  EXPECT_EQ(sqrt(Interval(-4, 4)), Interval(0, 2));
  EXPECT_TRUE(sqrt(Interval(-5, -1)).is_empty());
}

TEST(Interval, OutwardRounding) {
  const Interval tenth = Interval(1) / Interval(10);
  EXPECT_LT(tenth.lb(), tenth.ub());
  EXPECT_TRUE(tenth.contains(0.1));
  EXPECT_EQ(tenth.ub(), rounding::next_up(tenth.lb()));
}

TEST(Interval, BadInputIsAnError) {
  EXPECT_THROW(Interval(2, 1), Error);
  EXPECT_THROW(Interval(NAN, 1), Error);
  EXPECT_THROW(Interval(INFINITY, INFINITY), Error);
  EXPECT_THROW(Interval(0, 1).bisect(0), Error);
  EXPECT_THROW(Interval(0, 1).inflate(-1), Error);
}

TEST(IntervalVector, BasicsAndErrors) {
  IntervalVector x{{0, 1}, {2, 4}};
  EXPECT_EQ(x.size(), 2u);
  EXPECT_DOUBLE_EQ(x.max_diam(), 2.0);
  auto [l, r] = x.bisect();
  EXPECT_EQ(l[1], Interval(2, 3));
  EXPECT_EQ(r[1], Interval(3, 4));
  EXPECT_THROW(x & IntervalVector(3), DimensionError);
  EXPECT_TRUE(x.contains({0.5, 3}));
}
