// TaylorOde: Taylor coefficients of ODE solutions by automatic
// differentiation, against the coefficients known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sillage/error.h"
#include "sillage/expr/taylor.h"
#include "sillage/interval/elementary.h"

using namespace sillage;

namespace {

std::vector<Interval> coeffs(const Function& f, const std::vector<Interval>& x0, int order, double sign = 1.0,
                             const std::vector<Interval>& u = {}) {
  detail::TaylorOde ode(f);
  std::vector<Interval> x = x0;
  EXPECT_TRUE(ode.coefficients(x, u.data(), order, sign));
  return x;
}

}  // namespace

TEST(TaylorOde, ExponentialHasInverseFactorials) {
  // x' = x, x(0) = 1: x_k = 1/k!
  const auto x = coeffs(Function({"x"}, "x"), {Interval(1.0)}, 12);
  double fact = 1.0;
  for (int k = 0; k <= 12; ++k) {
    if (k > 0) fact *= k;
    EXPECT_TRUE(x[k].contains(1.0 / fact)) << k << " " << x[k];
    EXPECT_LT(x[k].diam(), 1e-15) << k;
  }
}

TEST(TaylorOde, BackwardFlipsTheOddOrders) {
  const auto x = coeffs(Function({"x"}, "x"), {Interval(1.0)}, 5, -1.0);
  EXPECT_TRUE(x[1].contains(-1.0));
  EXPECT_TRUE(x[2].contains(0.5));
  EXPECT_TRUE(x[3].contains(-1.0 / 6));
}

TEST(TaylorOde, RotationGivesSinAndCos) {
  // x1' = x2, x2' = -x1 from (0, 1): x1 = sin t, x2 = cos t.
  const auto x = coeffs(Function({"x1", "x2"}, "(x2, -x1)"), {Interval(0.0), Interval(1.0)}, 9);
  const double s[] = {0, 1, 0, -1.0 / 6, 0, 1.0 / 120, 0, -1.0 / 5040, 0, 1.0 / 362880};
  const double c[] = {1, 0, -0.5, 0, 1.0 / 24, 0, -1.0 / 720, 0, 1.0 / 40320, 0};
  for (int k = 0; k <= 9; ++k) {
    EXPECT_TRUE(x[2 * k].contains(s[k])) << k;
    EXPECT_TRUE(x[2 * k + 1].contains(c[k])) << k;
  }
}

TEST(TaylorOde, ElementaryRulesMatchClosedForms) {
  // Each ODE has the solution x(t) = g(t) with g's Taylor coefficients known
  // at t = 0: compare through the third order.
  struct Row {
    const char* f;
    double x0;
    double c1, c2, c3;
  };
  const Row rows[] = {
      {"-sin(x)", 0.0, 0, 0, 0},  // the equilibrium
      {"x^2", 1.0, 1, 1, 1},      // x = 1/(1-t)
      {"sqr(x)", 1.0, 1, 1, 1},
      {"1/x", 1.0, 1, -0.5, 0.5},           // x = sqrt(1+2t)
      {"1/(2*sqrt(x))", 1.0, 0.5, -0.125, 1.0 / 16},  // x = sqrt(1+t)... x=(1+3t/2)^(2/3)? no: see below
      {"exp(-x)", 0.0, 1, -0.5, 1.0 / 3},   // x = log(1+t)
      {"cos(x)^2", 0.0, 1, 0, -1.0 / 3},    // x = atan(t)
      {"1 + tan(x)^2 - tan(x)^2 + 1 + x^2 - 1", 0.0, 1, 0, 1.0 / 3},  // x' = 1 + x^2: x = tan t
      {"1 + sinh(x)*0 + cosh(x)*0", 0.0, 1, 0, 0},
      {"log(exp(x))", 1.0, 1, 0.5, 1.0 / 6},  // x = e^t
      {"x^(-1)", 1.0, 1, -0.5, 0.5},
      {"x^3", 1.0, 1, 1.5, 2.5},  // x = (1-2t)^(-1/2)
  };
  for (const Row& r : rows) {
    const auto x = coeffs(Function({"x"}, r.f), {Interval(r.x0)}, 3);
    if (std::string(r.f) == "1/(2*sqrt(x))") {
      // x' = 1/(2 sqrt x), x(0) = 1: x = (1 + 3t/4)^(2/3): c1 = 1/2, c2 = -1/16, c3 = 1/48
      EXPECT_TRUE(x[1].contains(0.5));
      EXPECT_TRUE(x[2].contains(-1.0 / 16)) << x[2];
      EXPECT_TRUE(x[3].contains(1.0 / 48)) << x[3];
      continue;
    }
    EXPECT_TRUE(x[1].contains(r.c1)) << r.f << " " << x[1];
    EXPECT_TRUE(x[2].contains(r.c2)) << r.f << " " << x[2];
    EXPECT_TRUE(x[3].contains(r.c3)) << r.f << " " << x[3];
  }
}

TEST(TaylorOde, ElementaryFunctionsOfTime) {
  // s' = 1, s(0) = 0 (s = t) and x' = g(s), x(0) = 0: x = ∫ g, whose
  // coefficients of orders 1..4 are known.
  struct Row {
    const char* g;
    double c[4];
  };
  const Row rows[] = {
      {"sin(s)", {0, 0.5, 0, -1.0 / 24}},       {"cos(s)", {1, 0, -1.0 / 6, 0}},
      {"sinh(s)", {0, 0.5, 0, 1.0 / 24}},       {"cosh(s)", {1, 0, 1.0 / 6, 0}},
      {"tan(s)", {0, 0.5, 0, 1.0 / 12}},        {"atan(s)", {0, 0.5, 0, -1.0 / 12}},
      {"exp(s)", {1, 0.5, 1.0 / 6, 1.0 / 24}},  {"log(1+s)", {0, 0.5, -1.0 / 6, 1.0 / 12}},
      {"sqrt(1+s)", {1, 0.25, -1.0 / 24, 1.0 / 64}},
  };
  for (const Row& r : rows) {
    const auto x = coeffs(Function({"s", "x"}, std::string("(1, ") + r.g + ")"), {Interval(0.0), Interval(0.0)}, 4);
    for (int k = 1; k <= 4; ++k) EXPECT_TRUE(x[2 * k + 1].contains(r.c[k - 1])) << r.g << " order " << k << " " << x[2 * k + 1];
  }
}

TEST(TaylorOde, VariationalCoefficientsAreDerivatives) {
  // x' = -x^2: x(t) = x0/(1 + x0 t), x_k = (-1)^k x0^(k+1), d x_k/dx0 = (-1)^k (k+1) x0^k.
  detail::TaylorOde ode(Function({"x"}, "-x^2"));
  std::vector<Interval> x{Interval(0.5)}, v;
  ASSERT_TRUE(ode.coefficients(x, v, nullptr, 6, 1.0));
  for (int k = 0; k <= 6; ++k) {
    const double s = (k % 2 == 0) ? 1.0 : -1.0;
    EXPECT_TRUE(x[k].contains(s * std::pow(0.5, k + 1))) << k;
    EXPECT_TRUE(v[k].contains(s * (k + 1) * std::pow(0.5, k))) << k << " " << v[k];
  }
}

TEST(TaylorOde, InputsAreHeldConstant) {
  // x' = u: x = x0 + u t.
  const auto x = coeffs(Function({"x", "u"}, "u"), {Interval(1.0)}, 3, 1.0, {Interval(2.0)});
  EXPECT_TRUE(x[1].contains(2.0));
  EXPECT_EQ(x[2], Interval(0.0));
}

TEST(TaylorOde, OutsideTheDomainIsRefused) {
  detail::TaylorOde ode(Function({"x"}, "sqrt(x)"));
  std::vector<Interval> x{Interval(-1.0, 1.0)};
  EXPECT_FALSE(ode.coefficients(x, nullptr, 4, 1.0));
}

TEST(TaylorOde, ErrorsNameTheProblem) {
  EXPECT_THROW(detail::TaylorOde(Function({"x"}, "(x, x)")), DimensionError);
}

TEST(TaylorOde, RulesOfTheOtherOperationsMatchIdentities) {
  // s' = 1 from s0 = 0.3 and x' = g(s), y' = h(s) with g = h as functions:
  // the coefficients of x and y (orders 1..6) must intersect, and be tight.
  struct Row {
    const char* g;
    const char* h;
  };
  const Row rows[] = {
      {"tanh(s)", "sinh(s)/cosh(s)"},
      {"asin(s/2)", "atan((s/2)/sqrt(1 - (s/2)^2))"},
      {"acos(s/2) + asin(s/2)", "1.5707963267948966"},
      {"atan2(sin(s) + 0.5, 2 + s)", "atan((sin(s) + 0.5)/(2 + s))"},
      {"atan2(-1 - s, -2 + s)", "atan((-1 - s)/(-2 + s)) - 3.141592653589793"},
      {"(1 + s)^2.5", "sqrt(1 + s)^5"},
      {"(1 + s)^(s)", "exp(s*log(1 + s))"},
      {"root(1 + s, 3)", "exp(log(1 + s)/3)"},
      {"root(s - 2, 3)", "-exp(log(2 - s)/3)"},
      {"abs(s - 2)", "2 - s"},
      {"abs(s + 2)", "s + 2"},
      {"sign(s - 2)*s", "-s"},
      {"min(s, s + 1)", "s"},
      {"max(cos(s), 2 + s)", "2 + s"},
  };
  for (const Row& r : rows) {
    const auto x = coeffs(Function({"s", "x", "y"}, std::string("(1, ") + r.g + ", " + r.h + ")"),
                          {Interval(0.3), Interval(0.0), Interval(0.0)}, 6);
    for (int k = 1; k <= 6; ++k) {
      const Interval& a = x[3 * k + 1];
      const Interval& b = x[3 * k + 2];
      EXPECT_TRUE(a.intersects(b.inflate(1e-15))) << r.g << " order " << k << " " << a << " " << b;
      EXPECT_LT(a.diam(), 1e-12) << r.g << " order " << k;
    }
  }
}

TEST(TaylorOde, NonSmoothPointsAreRefused) {
  // abs, sign, min, max at their kinks, atan2 on its cut, asin at |a| = 1,
  // pow of a non-positive, an even root of a negative: no series.
  const char* gs[] = {"abs(s)", "sign(s)", "min(s, -s)", "max(s, 0)", "atan2(s, -1)",
                      "asin(s + 1)", "acos(s - 1)", "(s)^1.5", "root(s - 1, 2)"};
  for (const char* g : gs) {
    detail::TaylorOde ode(Function({"s", "x"}, std::string("(1, ") + g + ")"));
    std::vector<Interval> x{Interval(0.0), Interval(0.0)};
    EXPECT_FALSE(ode.coefficients(x, nullptr, 3, 1.0)) << g;
  }
}
