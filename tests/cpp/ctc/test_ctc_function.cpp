// CtcFunction: f(x) ∈ [y] by HC4-revise. Hand cases, errors, and the
// consistency law: a sampled point p with [f](p) ⊆ [y] is a true solution and
// must stay in the contracted box.
#include <gtest/gtest.h>

#include <string>

#include "ctc/ctc_test_util.h"
#include "sillage/ctc/ctc_function.h"

using namespace sillage;
using sillage::test::random_around;

TEST(CtcFunction, HandCases) {
  const Function f({"x", "y"}, "x + y");
  IntervalVector b{{0, 3}, {-2, 2}};
  CtcFunction(f, Interval(4, 5)).contract(b);  // the C+ example of (2.31)
  EXPECT_EQ(b, (IntervalVector{{2, 3}, {1, 2}}));

  IntervalVector r{{0, 10}};
  CtcFunction(Function({"x"}, "x^2 - 4")).contract(r);  // = 0
  EXPECT_TRUE(r[0].contains(2));
  EXPECT_LT(r[0].diam(), 1e-12);

  const Function g({"x", "y"}, "(x + y, x - y)");
  IntervalVector v(2, Interval(0, 10));
  CtcFunction(g, IntervalVector{{2, 2}, {0, 0}}).contract(v);
  EXPECT_TRUE(v.contains({1, 1}));
  EXPECT_LE(v.max_diam(), 2.0);

  IntervalVector none{{0, 1}, {0, 1}};
  CtcFunction(f, Interval(3, 4)).contract(none);
  EXPECT_TRUE(none.is_empty());
  EXPECT_TRUE(none[0].is_empty() && none[1].is_empty());
}

TEST(CtcFunction, Errors) {
  const Function g({"x", "y"}, "(x + y, x - y)");
  EXPECT_THROW(CtcFunction(g, Interval(0, 1)), DimensionError);
  EXPECT_THROW(CtcFunction(g, IntervalVector(3)), DimensionError);
  const CtcFunction c(g);
  EXPECT_EQ(c.nb_vars(), 2u);
  IntervalVector three(3);
  try {
    c.contract(three);
    FAIL() << "no DimensionError";
  } catch (const DimensionError& e) {
    EXPECT_NE(std::string(e.what()).find("CtcFunction"), std::string::npos) << e.what();
  }
}

TEST(CtcFunction, SampledSolutionsAreKept) {
  const Function f({"x1", "x2"}, "x1^2 + x2 * sin(x1) - exp(x2 / 4)");
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> u(-3, 3), unit(0, 1);
  int kept = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const IntervalVector x{random_around(u(rng), rng), random_around(u(rng), rng)};
    const Interval y = random_around(u(rng), rng);
    IntervalVector out(x);
    CtcFunction(f, y).contract(out);
    ASSERT_TRUE(out.is_subset(x));
    for (int s = 0; s < 30; ++s) {
      // Sample in the bounded part of x.
      std::vector<double> p(2);
      for (std::size_t i = 0; i < 2; ++i) {
        const double lo = std::max(x[i].lb(), -20.0), hi = std::min(x[i].ub(), 20.0);
        p[i] = lo + (hi - lo) * unit(rng);
        if (!x[i].contains(p[i])) p[i] = x[i].mid();
      }
      if (f.eval(IntervalVector::from_point(p)).is_subset(y)) {
        ++kept;
        ASSERT_TRUE(out.contains(p)) << "lost " << p[0] << ", " << p[1] << " from " << x << " -> " << out;
      }
    }
  }
  EXPECT_GT(kept, 100);  // the test really exercised solutions
}
