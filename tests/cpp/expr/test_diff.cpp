// Symbolic differentiation: exact derivatives, simplifications, Jacobians,
// and a check against divided differences.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sillage/expr/diff.h"
#include "sillage/expr/function.h"
#include "sillage/expr/parser.h"
#include "sillage/interval/interval_matrix.h"

using namespace sillage;

namespace {

std::string d(const std::string& e, const std::string& v = "x") {
  return detail::diff(detail::parse_expr({"x", "y"}, e), ExprVar(v)).str();
}

}  // namespace

TEST(Diff, SimplifiedExpressions) {
  EXPECT_EQ(d("x"), "1");
  EXPECT_EQ(d("y"), "0");
  EXPECT_EQ(d("3"), "0");
  EXPECT_EQ(d("x + y"), "1");
  EXPECT_EQ(d("x * y"), "y");
  EXPECT_EQ(d("x * y", "y"), "x");
  EXPECT_EQ(d("x^2"), "2 * x");
  EXPECT_EQ(d("x^3"), "3 * x^2");
  EXPECT_EQ(d("sin(x)"), "cos(x)");
  EXPECT_EQ(d("cos(x)"), "-sin(x)");
  EXPECT_EQ(d("exp(x)"), "exp(x)");
  EXPECT_EQ(d("log(x)"), "1 / x");
  EXPECT_EQ(d("-x"), "-1");
  EXPECT_EQ(d("x - y", "y"), "-1");
  EXPECT_EQ(d("sin(y) * x"), "sin(y)");
  EXPECT_EQ(d("exp(2 * x)"), "exp(2 * x) * 2");
  EXPECT_EQ(d("sqrt(x)"), "1 / (2 * sqrt(x))");
  EXPECT_EQ(d("abs(x)"), "sign(x)");
  EXPECT_EQ(d("sign(x)"), "0");
}

TEST(Diff, SharesNodesWithTheFunction) {
  ExprVar x("x");
  const Expr f = exp(sin(x));
  const Expr df = detail::diff(f, x);  // exp(sin(x)) * cos(x)
  EXPECT_EQ(df, f * cos(x));
}

TEST(Diff, GradientAndJacobian) {
  Function f({"x1", "x2"}, "sqrt((x1-1)^2 + (x2-2)^2)");
  Function g = f.diff();
  EXPECT_EQ(g.image_dim(), 2u);
  EXPECT_EQ(g.nb_vars(), 2u);
  const IntervalVector r = g.eval_vector(IntervalVector{Interval(4.0), Interval(6.0)});
  EXPECT_TRUE(r[0].contains(0.6) && r[0].diam() < 1e-15);
  EXPECT_TRUE(r[1].contains(0.8) && r[1].diam() < 1e-15);
  Function v({"x", "y"}, "(x * y, x + y^2, sin(x))");
  Function j = v.diff();
  EXPECT_EQ(j.image_dim(), 6u);  // 3 x 2, row-major
  EXPECT_EQ(j.expr_str(), "(y, x, 1, 2 * y, cos(x), 0)");
  const IntervalVector jv = v.jacobian_vector(IntervalVector{Interval(0.0), Interval(3.0)});
  EXPECT_EQ(jv, (IntervalVector{Interval(3.0), Interval(0.0), Interval(1.0), Interval(6.0), Interval(1.0), Interval(0.0)}));
  // Second derivative: Hessian of x^2 y.
  Function h = Function({"x", "y"}, "x^2 * y").diff().diff();
  EXPECT_EQ(h.expr_str(), "(2 * y, 2 * x, 2 * x, 0)");
}

// The derivative enclosure over a box contains every divided difference of
// two points of the box, per variable (mean-value theorem, 1-D slices).
TEST(Diff, EnclosesDividedDifferences) {
  const std::vector<std::string> exprs = {
      "sqrt((x + 0.5)^2 + (y - 4)^2)", "x * y - x^3", "sin(x) * cos(y) + exp(-x^2)",
      "atan2(y + 5, x) + tanh(x * y)", "x / (3 + y^2) - log(1 + x^2)", "cosh(x) - sinh(y) + atan(x - y)",
      "(x - y)^4 + root(x + 5, 3) - (y + 5)^-2", "pow(1 + x^2, y)", "asin(tanh(x)) + acos(0.5 * sin(y))",
      "tan(x / 3) * y", "abs(x - y) + min(x, y) * max(x, 0.3)"};
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> c(-2, 2), w(0.01, 1), u(0, 1);
  for (const std::string& e : exprs) {
    Function f({"x", "y"}, e);
    Function g = f.diff();
    for (int k = 0; k < 300; ++k) {
      const double a = c(rng), b = c(rng);
      const IntervalVector box{Interval(a, a + w(rng)), Interval(b, b + w(rng))};
      const IntervalVector grad = g.eval_vector(box);
      for (int var = 0; var < 2; ++var) {
        IntervalVector p = IntervalVector::from_point(box.mid()), q = p;
        const double t1 = box[var].lb() + u(rng) * box[var].diam(), t2 = box[var].lb() + u(rng) * box[var].diam();
        if (t1 == t2) continue;
        p[var] = Interval(t1);
        q[var] = Interval(t2);
        // Rigorous divided difference: (f(q) - f(p)) / (t2 - t1) in intervals.
        const Interval dd = (f.eval(q) - f.eval(p)) / (Interval(t2) - Interval(t1));
        ASSERT_TRUE(dd.intersects(grad[var])) << e << " d/d" << (var ? "y" : "x") << " on " << box << ": " << dd
                                              << " vs " << grad[var];
      }
    }
  }
}

TEST(Diff, JacobianMatrix) {
  Function v({"x", "y"}, "(x * y, x + y^2, sin(x))");
  const IntervalMatrix j = v.jacobian(IntervalVector{Interval(0.0), Interval(3.0)});
  ASSERT_EQ(j.rows(), 3u);
  ASSERT_EQ(j.cols(), 2u);
  EXPECT_EQ(j(0, 0), Interval(3.0));
  EXPECT_EQ(j(1, 1), Interval(6.0));
  EXPECT_EQ(j(2, 0), Interval(1.0));
  EXPECT_EQ(j(2, 1), Interval(0.0));
  EXPECT_THROW(v.jacobian(IntervalVector(3)), DimensionError);
}
