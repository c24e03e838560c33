// The centered form on boxes touching the boundary of a partial function:
// f is defined there but its derivative formula is not (issue 12, item 1).
#include <gtest/gtest.h>

#include <random>

#include "sillage/expr/function.h"

using namespace sillage;

namespace {

Interval centered(const Function& f, const IntervalVector& x) { return f.centered_eval(x)[0]; }

}  // namespace

TEST(Centered, DefinedWhereTheDerivativeIsNot) {
  const Function s({"y"}, "sqrt(y)");
  EXPECT_EQ(centered(s, IntervalVector{Interval(0, 0)}), Interval(0.0));
  EXPECT_EQ(centered(s, IntervalVector{Interval(0, 4)}), Interval(0, 2));
  const Function d({"x1", "x2"}, "sqrt((x1-1)^2+(x2-2)^2)");
  EXPECT_EQ(centered(d, IntervalVector{Interval(1.0), Interval(2.0)}), Interval(0.0));
  EXPECT_TRUE(centered(d, IntervalVector{Interval(1.0), Interval(1, 3)}).is_superset(Interval(0, 1)));
  EXPECT_TRUE(centered(d, IntervalVector{Interval(0.5, 1), Interval(2, 2.5)}).contains(0.0));
  EXPECT_EQ(centered(Function({"y"}, "acos(y)"), IntervalVector{Interval(1.0)}), Interval(0.0));
  EXPECT_TRUE(centered(Function({"y"}, "asin(y)"), IntervalVector{Interval(1.0)}).is_superset(Interval::half_pi()));
  EXPECT_EQ(centered(Function({"y"}, "root(y, 4)"), IntervalVector{Interval(0.0)}), Interval(0.0));
  EXPECT_EQ(centered(Function({"y"}, "log(1 + sqrt(y))"), IntervalVector{Interval(0.0)}), Interval(0.0));
  EXPECT_EQ(centered(Function({"y"}, "root(y, 4)"), IntervalVector{Interval(0, 16)}), Interval(0, 2));
}

TEST(Centered, PropertyEnclosesPointValuesAndIsNeverEmptyWhereNaturalIsNot) {
  const std::vector<std::string> exprs = {
      "sqrt(x1) + x2",         "sqrt((x1-1)^2+(x2-2)^2)", "acos(x1) * x2",  "asin(x1) - x2^2",
      "root(x1, 4) * (1 + x2)", "log(1 + sqrt(x1)) + x2",   "sqrt(x1 * x2)", "x1 * sqrt(1 - x2)",
      "atan2(x2, x1)",         "sqrt(x1) / (1 + x2^2)",
  };
  // Bounds drawn among the domain boundaries -1, 0, 1, 2 and random values;
  // one box in three has a degenerate component.
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1.5, 3);
  const double special[] = {-1, 0, 1, 2};
  auto bound = [&] { return rng() % 2 ? special[rng() % 4] : u(rng); };
  auto component = [&] {
    double a = bound(), b = rng() % 3 == 0 ? a : bound();
    if (a > b) std::swap(a, b);
    return Interval(a, b);
  };
  for (const std::string& e : exprs) {
    const Function f({"x1", "x2"}, e);
    for (int k = 0; k < 2000; ++k) {
      const IntervalVector b{component(), component()};
      const Interval nat = f.eval(b), cen = centered(f, b);
      ASSERT_TRUE(cen.is_subset(nat)) << e << " on " << b;
      ASSERT_EQ(nat.is_empty(), cen.is_empty()) << e << " on " << b;
      for (int s = 0; s < 8; ++s) {
        // Corners (where the boundaries are) and random points.
        Vector p(2);
        for (std::size_t i = 0; i < 2; ++i) {
          const double t = s < 4 ? ((s >> i) & 1) : std::uniform_real_distribution<double>(0, 1)(rng);
          p[i] = std::clamp(b[i].lb() + t * (b[i].ub() - b[i].lb()), b[i].lb(), b[i].ub());
        }
        const Interval yp = f.eval(IntervalVector::from_point(p));
        // f(p) lies in both (a degenerate yp is f(p) itself); empty: p outside the domain.
        ASSERT_TRUE(yp.is_empty() || (yp.is_degenerate() ? yp.is_subset(cen) : yp.intersects(cen))) << e << " on " << b << " at " << p[0] << ", " << p[1];
      }
    }
  }
}
