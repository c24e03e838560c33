#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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

TEST(Interval, NumericFunctionsAndSpecialCases) {
  EXPECT_EQ(Interval(-1, 3).mid(), 1.0);
  EXPECT_EQ(Interval::all_reals().mid(), 0.0);
  EXPECT_EQ(Interval(1, INFINITY).mid(), std::numeric_limits<double>::max());
  EXPECT_EQ(Interval(-INFINITY, 1).mid(), -std::numeric_limits<double>::max());
  EXPECT_TRUE(std::isnan(Interval::empty().mid()));
  EXPECT_EQ(Interval(-1, 3).rad(), 2.0);
  EXPECT_EQ(Interval(-5, 3).mag(), 5.0);
  EXPECT_EQ(Interval(-5, 3).mig(), 0.0);
  EXPECT_EQ(Interval(2, 3).mig(), 2.0);
  EXPECT_EQ(Interval(0, INFINITY).diam(), INFINITY);
  EXPECT_EQ(Interval::empty().volume(), 0.0);
  // No -0 bound: printing and equality behave.
  EXPECT_EQ(Interval(-0.0).str(), "[0, 0]");
  EXPECT_EQ((-Interval(0, 1)).str(), "[-1, 0]");
  EXPECT_EQ(Interval(1, 2).str(), "[1, 2]");
  EXPECT_EQ(Interval::empty().str(), "[ empty ]");
}

TEST(Interval, PredicatesFollowIeee1788) {
  const Interval x(0, 2), e = Interval::empty();
  EXPECT_TRUE(e.is_subset(x));
  EXPECT_TRUE(e.is_interior_subset(e));
  EXPECT_TRUE(Interval::all_reals().is_interior_subset(Interval::all_reals()));
  EXPECT_FALSE(Interval(0, 1).is_interior_subset(x));
  EXPECT_TRUE(Interval(0.5, 1).is_interior_subset(x));
  EXPECT_TRUE(x.is_disjoint(e));
  EXPECT_TRUE(x.intersects(Interval(2, 3)));
  EXPECT_FALSE(x.contains(INFINITY));
  EXPECT_FALSE(Interval::all_reals().contains(-INFINITY));
  EXPECT_TRUE(Interval(1, 2).is_strict_subset(x));
  EXPECT_FALSE(x.is_strict_subset(x));
}

TEST(Interval, BisectAndInflate) {
  auto [a, b] = Interval(0, 4).bisect(0.25);
  EXPECT_EQ(a, Interval(0, 1));
  EXPECT_EQ(b, Interval(1, 4));
  auto [c, d] = Interval::all_reals().bisect();
  EXPECT_EQ(c, Interval(-INFINITY, 0));
  EXPECT_EQ(d, Interval(0, INFINITY));
  auto [f, g] = Interval(5, INFINITY).bisect();
  EXPECT_TRUE(f.is_bounded() && g.is_unbounded() && f.ub() == g.lb());
  EXPECT_EQ(Interval(1, 2).inflate(0.5), Interval(0.5, 2.5));
  const Interval t = Interval(0.1).inflate(0.1);  // rounded outward
  EXPECT_TRUE(t.lb() <= 0 && t.ub() >= 0.2);
}

TEST(Interval, Div2IsTheRelationalQuotient) {
  auto [lo, hi] = div2(Interval(1, 2), Interval(-1, 1));
  EXPECT_EQ(lo, Interval(-INFINITY, -1));
  EXPECT_EQ(hi, Interval(1, INFINITY));
  // 0 * z = 0 for every z: unlike operator/, the whole line.
  EXPECT_TRUE(div2(Interval(0), Interval(0, 1)).first.is_all_reals());
  EXPECT_EQ(Interval(0) / Interval(0, 1), Interval(0));
}

TEST(IntervalVector, MoreOperations) {
  IntervalVector x = IntervalVector::from_bounds({{0, 1}, {-2, 4}, {3, 3}});
  EXPECT_EQ(x.size(), 3u);
  EXPECT_EQ(x.lb(), (Vector{0, -2, 3}));
  EXPECT_EQ(x.ub(), (Vector{1, 4, 3}));
  EXPECT_EQ(x.mid(), (Vector{0.5, 1, 3}));
  EXPECT_EQ(x.diam(), (Vector{1, 6, 0}));
  EXPECT_EQ(x.mag(), (Vector{1, 4, 3}));
  EXPECT_EQ(x.mig(), (Vector{0, 0, 3}));
  EXPECT_EQ(x.extr_diam_index(), 1u);
  EXPECT_EQ(x.extr_diam_index(false), 2u);
  EXPECT_EQ(x.min_diam(), 0.0);
  EXPECT_EQ(x.volume(), 0.0);
  EXPECT_EQ(x.subvector(1, 2), (IntervalVector{{-2, 4}, 3}));
  EXPECT_THROW(x.subvector(2, 3), DimensionError);
  x.put(0, IntervalVector{5, 6});
  EXPECT_EQ(x, (IntervalVector{5, 6, 3}));
  EXPECT_THROW(x.put(2, IntervalVector{5, 6}), DimensionError);
  EXPECT_TRUE(x.is_degenerate());
  EXPECT_EQ(IntervalVector::from_point({1, 2}), (IntervalVector{1, 2}));
  const IntervalVector a{{0, 1}, {0, 1}}, b{{2, 3}, {0, 1}};
  EXPECT_EQ(hull(a, b), (IntervalVector{{0, 3}, {0, 1}}));
  EXPECT_TRUE((a & b).is_empty());
  EXPECT_TRUE((a & b)[1].is_empty());  // a box with an empty component is emptied entirely
  EXPECT_EQ(a | IntervalVector::empty(2), a);
  EXPECT_EQ(a + b, (IntervalVector{{2, 4}, {0, 2}}));
  EXPECT_EQ(b - a, (IntervalVector{{1, 3}, {-1, 1}}));
  EXPECT_EQ(Interval(2) * a, (IntervalVector{{0, 2}, {0, 2}}));
  EXPECT_EQ(dot(a, b), Interval(0, 4));
  EXPECT_EQ(norm(IntervalVector{3, 4}), Interval(5));
  EXPECT_EQ(abs(IntervalVector{{-2, 1}}), (IntervalVector{{0, 2}}));
  EXPECT_TRUE((IntervalVector{{0.2, 0.8}, {0.2, 0.8}}).is_interior_subset(a));
  EXPECT_FALSE(a.is_interior_subset(a));
  EXPECT_TRUE(a.intersects(IntervalVector{{1, 2}, {1, 2}}));
  EXPECT_EQ(a.inflate(1), (IntervalVector{{-1, 2}, {-1, 2}}));
  EXPECT_THROW(a.contains({1}), DimensionError);
  EXPECT_THROW(a.bisect(2, 0.5), DimensionError);
  EXPECT_EQ(a.str(), "([0, 1] ; [0, 1])");
}

TEST(Interval, ExactZeroBoundsArePositiveZero) {
  EXPECT_FALSE(std::signbit(Interval(1).diam()));
  EXPECT_FALSE(std::signbit((Interval(-1) + Interval(1)).ub()));
  EXPECT_FALSE(std::signbit((Interval(2) - Interval(2)).ub()));
}
