// Natural and centered inclusion functions, batch evaluation, thread safety.
#include <gtest/gtest.h>
#include <mpfr.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <random>

#include "sillage/expr/function.h"

#include "kit/close_bounds.h"

using namespace sillage;

namespace {

const std::vector<std::string> kExprs = {
    "sqrt((x1 + 0.5)^2 + (x2 - 4)^2)",
    "x1 * x2 - x1^3 + 0.1",
    "sin(x1) * cos(x2) + exp(-x1^2)",
    "atan2(x2, x1) + tanh(x1 * x2)",
    "abs(x1 - x2) + min(x1, x2) * max(x1, 0.3)",
    "x1 / (1 + x2^2) - log(1 + x1^2)",
    "cosh(x1) - sinh(x2) + atan(x1 - x2)",
    "(x1 - x2)^4 + root(x1, 3) - x2^-2",
    "sqrt(abs(x1)) * sign(x2) + asin(tanh(x2))",
    "pow(1 + x1^2, x2) + acos(0.5 * sin(x1))",
    "x1 * x1 - 2 * x1 * x2 + x2 * x2",
    "tan(x1 / 3) + [0.1, 0.2] * x2 - pi",
};

IntervalVector random_box(std::mt19937_64& rng, double range = 4, double width = 2) {
  std::uniform_real_distribution<double> c(-range, range), w(0, width);
  IntervalVector x(2);
  for (std::size_t i = 0; i < 2; ++i) {
    const double a = c(rng);
    x[i] = Interval(a, a + w(rng));
  }
  return x;
}

Vector random_point(std::mt19937_64& rng, const IntervalVector& x) {
  Vector p(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    std::uniform_real_distribution<double> u(x[i].lb(), x[i].ub());
    p[i] = u(rng);
  }
  return p;
}

}  // namespace

TEST(Eval, ExactValues) {
  Function f({"x1", "x2"}, "sqrt((x1-1)^2 + (x2-2)^2)");
  EXPECT_EQ(f.nb_vars(), 2u);
  EXPECT_EQ(f.image_dim(), 1u);
  EXPECT_EQ(f.eval(IntervalVector{Interval(4.0), Interval(6.0)}), Interval(5.0));
  // Each variable once: the natural inclusion is minimal (thesis 2.28).
  EXPECT_EQ(f.eval(IntervalVector{Interval(1, 4), Interval(2, 6)}), Interval(0, 5));
  EXPECT_EQ(f.eval(IntervalVector{Interval(4, 7), Interval(6, 10)}), Interval(5, 10));
  // Dependency effect (2.29) on x - x, exact with a shared node.
  Function g({"x"}, "x - x");
  EXPECT_EQ(g.eval(IntervalVector{Interval(1, 3)}), Interval(-2, 2));
  EXPECT_TRUE(f.eval(IntervalVector{Interval::empty(), Interval(1.0)}).is_empty());
  // Set-based semantics: sqrt acts on the part of its argument in its domain.
  EXPECT_EQ(Function({"x"}, "sqrt(x)").eval(IntervalVector{Interval(-4, 4)}), Interval(0, 2));
  EXPECT_TRUE(Function({"x"}, "log(x)").eval(IntervalVector{Interval(-4, -1)}).is_empty());
}

TEST(Eval, AgainstMpfrOnTheRangeFunction) {
  Function f({"x1", "x2"}, "sqrt((x1 + 0.5)^2 + (x2 - 4.1)^2)");
  std::mt19937_64 rng(3);
  mpfr_t a, b, t;
  mpfr_inits2(300, a, b, t, static_cast<mpfr_ptr>(nullptr));
  for (int k = 0; k < 2000; ++k) {
    const IntervalVector box = random_box(rng, 10, 1);
    const Vector p = random_point(rng, box);
    mpfr_set_d(a, p[0], MPFR_RNDN);
    mpfr_set_str(t, "0.5", 10, MPFR_RNDN);
    mpfr_add(a, a, t, MPFR_RNDN);
    mpfr_sqr(a, a, MPFR_RNDN);
    mpfr_set_d(b, p[1], MPFR_RNDN);
    mpfr_set_str(t, "4.1", 10, MPFR_RNDN);  // the real 4.1, not the double
    mpfr_sub(b, b, t, MPFR_RNDN);
    mpfr_sqr(b, b, MPFR_RNDN);
    mpfr_add(a, a, b, MPFR_RNDN);
    mpfr_sqrt(a, a, MPFR_RNDN);
    const Interval yp = f.eval(IntervalVector::from_point(p));
    const Interval yb = f.eval(box);
    ASSERT_GE(mpfr_cmp_d(a, yp.lb()), 0) << k;
    ASSERT_LE(mpfr_cmp_d(a, yp.ub()), 0) << k;
    ASSERT_GE(mpfr_cmp_d(a, yb.lb()), 0) << k;
    ASSERT_LE(mpfr_cmp_d(a, yb.ub()), 0) << k;
    ASSERT_LT(yp.diam(), 1e-14 * (1 + yp.mag()));  // thin on points
  }
  mpfr_clears(a, b, t, static_cast<mpfr_ptr>(nullptr));
}

TEST(Eval, InclusionIsotonicity) {
  std::mt19937_64 rng(11);
  for (const std::string& e : kExprs) {
    Function f({"x1", "x2"}, e);
    for (int k = 0; k < 200; ++k) {
      const IntervalVector box = random_box(rng);
      const Interval yb = f.eval(box);
      const IntervalVector sub = IntervalVector{box[0].bisect(0.3).second, box[1].bisect(0.6).first};
      ASSERT_TRUE(f.eval(sub).is_subset(yb)) << e << " on " << box;
      const Vector p = random_point(rng, box);
      ASSERT_TRUE(f.eval(IntervalVector::from_point(p)).is_subset(yb)) << e << " at " << p[0] << ", " << p[1];
    }
  }
}

TEST(Eval, BatchEqualsSingleEvaluation) {
  std::mt19937_64 rng(5);
  for (const std::string& e : kExprs) {
    Function f({"x1", "x2"}, std::string("(").append(e).append(", x1 - x2)"));
    std::vector<IntervalVector> xs;
    for (int k = 0; k < 600; ++k) xs.push_back(k % 7 == 0 ? IntervalVector::empty(2) : random_box(rng));
    const std::vector<IntervalVector> ys = f.eval_batch(xs);
    ASSERT_EQ(ys.size(), xs.size());
    // Equal up to rounding: the batch's sin and cos rows have bounds of their own (trig_batch.h).
    for (std::size_t k = 0; k < xs.size(); ++k) {
      const IntervalVector y = f.eval_vector(xs[k]);
      for (std::size_t i = 0; i < y.size(); ++i)
        ASSERT_TRUE(sillage::test::close_bounds(ys[k][i], y[i], 1e-12)) << e << " box " << k << ": " << ys[k] << " vs " << y;
    }
  }
  Function f({"x1", "x2"}, "x1 + x2");
  EXPECT_TRUE(f.eval_batch({}).empty());
  EXPECT_THROW(f.eval_batch({IntervalVector(3)}), DimensionError);
}

TEST(Eval, StructureOfArraysBatch) {
  Function f({"x", "y"}, "(x * y, x + 1)");
  std::vector<Interval> x(1000), y(1000), o1(1000), o2(1000);
  for (int i = 0; i < 1000; ++i) x[i] = Interval(i, i + 1), y[i] = Interval(2.0);
  const Interval* in[] = {x.data(), y.data()};
  Interval* out[] = {o1.data(), o2.data()};
  f.eval_batch(in, 1000, out);
  for (int i = 0; i < 1000; ++i) {
    ASSERT_EQ(o1[i], Interval(2 * i, 2 * i + 2));
    ASSERT_EQ(o2[i], Interval(i + 1, i + 2));
  }
  const Interval* in1[] = {x.data()};
  EXPECT_THROW(f.eval_batch(in1, 1000, out), DimensionError);
}

TEST(Eval, CenteredFormEnclosesAndIsTighterOnSmallBoxes) {
  Function f({"x1", "x2"}, "x1 * x1 - 2 * x1 * x2 + x2 * x2");  // (x1 - x2)^2 written with dependencies
  const IntervalVector box{Interval(1, 1.01), Interval(2, 2.01)};
  const Interval nat = f.eval(box), cen = f.centered_eval(box)[0];
  EXPECT_TRUE(cen.is_subset(nat));
  EXPECT_LT(cen.diam(), 0.4 * nat.diam());
  EXPECT_LT(cen.diam(), 0.0405);  // the true range [0.9801, 1.0201] is 0.0400 wide
  EXPECT_TRUE(cen.contains(1.0));  // at (1, 2)
  std::mt19937_64 rng(9);
  for (const std::string& e : kExprs) {
    Function g({"x1", "x2"}, e);
    for (int k = 0; k < 200; ++k) {
      const IntervalVector b = random_box(rng, 3, k % 2 ? 0.05 : 1.5);
      const IntervalVector c = g.centered_eval(b);
      ASSERT_TRUE(c[0].is_subset(g.eval(b))) << e;
      for (int s = 0; s < 10; ++s) {
        const Vector p = random_point(rng, b);
        const Interval yp = g.eval(IntervalVector::from_point(p));
        ASSERT_TRUE(yp.is_empty() || c[0].intersects(yp)) << e << " box " << b << " point " << p[0] << ", " << p[1];
      }
    }
  }
}

TEST(Eval, CenteredFormOutsideTheDomainFallsBack) {
  // sqrt on [-3, 1]: the midpoint -1 is outside the domain, yet the set-based
  // image [0, 1] must be kept.
  Function f({"x"}, "0 * sqrt(x) + sqrt(x)");
  EXPECT_EQ(f.centered_eval(IntervalVector{Interval(-3, 1)})[0], Interval(0, 1));
  Function s({"x"}, "sign(x) + x");
  EXPECT_TRUE(s.centered_eval(IntervalVector{Interval(-1, 1)})[0].is_superset(Interval(-2, 2)));
  Function t({"x"}, "atan2(x, -1)");  // crosses the branch cut
  const Interval r = t.centered_eval(IntervalVector{Interval(-0.1, 0.1)})[0];
  EXPECT_TRUE(r.contains(3.1) && r.contains(-3.1));
}

TEST(Eval, DimensionErrors) {
  Function f({"x1", "x2"}, "x1 + x2");
  try {
    f.eval(IntervalVector(3));
    FAIL();
  } catch (const DimensionError& e) {
    EXPECT_STREQ(e.what(), "Function::eval: expected a box of size 2, got 3");
  }
  EXPECT_THROW(f.eval_vector(IntervalVector(1)), DimensionError);
  EXPECT_THROW(f.centered_eval(IntervalVector(1)), DimensionError);
  EXPECT_THROW(f[1], DimensionError);
  EXPECT_EQ(f[0].eval(IntervalVector{Interval(1.0), Interval(2.0)}), Interval(3.0));
}

TEST(Eval, ConcurrentEvaluationGivesTheSameResults) {
  Function f({"x1", "x2"}, "(" + kExprs[2] + ", " + kExprs[0] + ")");
  std::mt19937_64 rng(1);
  std::vector<IntervalVector> boxes;
  for (int k = 0; k < 2000; ++k) boxes.push_back(random_box(rng));
  std::vector<IntervalVector> ref, batch_ref;
  for (const auto& b : boxes) ref.push_back(f.eval_vector(b));
  for (const auto& b : boxes) batch_ref.push_back(f.eval_batch({b})[0]);
  std::vector<IntervalVector> cen_ref;
  for (const auto& b : boxes) cen_ref.push_back(f.centered_eval(b));
  std::atomic<int> bad{0};
  Function g({"x1", "x2"}, "x1 + x2");  // diff built lazily, concurrently
  tbb::parallel_for(std::size_t(0), boxes.size(), [&](std::size_t k) {
    IntervalVector x = boxes[k];
    if (f.eval_vector(x) != ref[k]) ++bad;
    if (f.centered_eval(x) != cen_ref[k]) ++bad;
    if (f.eval_batch({x, x})[1] != batch_ref[k]) ++bad;
    if (g.diff().eval_vector(x) != IntervalVector(2, Interval(1.0))) ++bad;
    f.hc4_revise(x, IntervalVector(2, Interval(0, 1)));
  });
  EXPECT_EQ(bad.load(), 0);
}

TEST(Eval, BuilderApi) {
  ExprVar x1("x1"), x2("x2");
  Function f({x1, x2}, sqrt(sqr(x1 - 1) + sqr(x2 - 2)));
  EXPECT_EQ(f.expr_str(), "sqrt((x1 - 1)^2 + (x2 - 2)^2)");
  EXPECT_EQ(f.eval(IntervalVector{Interval(4.0), Interval(6.0)}), Interval(5.0));
  Function v({x1, x2}, {x1 * 2.0, Interval(1, 2) + x2, pow(x1, 3), pow(x1, 0.5), -x1 / x2});
  EXPECT_EQ(v.image_dim(), 5u);
  const IntervalVector r = v.eval_vector(IntervalVector{Interval(4.0), Interval(2.0)});
  EXPECT_EQ(r[0], Interval(8.0));
  EXPECT_EQ(r[1], Interval(3, 4));
  EXPECT_EQ(r[2], Interval(64.0));
  EXPECT_TRUE(r[3].contains(2.0));
  EXPECT_EQ(r[4], Interval(-2.0));
  EXPECT_TRUE((Expr(2.0) * 3.0).is_const());  // folded
  EXPECT_EQ((Expr(2.0) * 3.0).node().value, Interval(6.0));
  Expr e = x1;
  e += 1;
  e *= x2;
  EXPECT_EQ(e, (x1 + 1) * x2);
  EXPECT_TRUE(Function({x1}, expr_pi() * x1).eval(IntervalVector{Interval(1.0)}) == Interval::pi());
  EXPECT_THROW(ExprVar("1x"), Error);
}
