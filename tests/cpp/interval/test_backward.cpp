// Hand-computed cases of the backward projections (exact where mathematics
// gives exact doubles, else enclosure of the true value and a width bound).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <cmath>

#include "sillage/interval/backward.h"
#include "sillage/interval/elementary.h"

using namespace sillage;

namespace {

constexpr double kInf = INFINITY;
constexpr double kPi = 3.14159265358979323846;

// [x] contains the real `v` (given as a double near it) up to `tol`, and is at most `width` wide.
::testing::AssertionResult Near(const Interval& x, double lo, double hi, double tol = 1e-12) {
  if (x.is_empty()) return ::testing::AssertionFailure() << "empty, expected near [" << lo << ", " << hi << "]";
  if (std::fabs(x.lb() - lo) > tol || std::fabs(x.ub() - hi) > tol) {
    return ::testing::AssertionFailure() << x << " is not near [" << lo << ", " << hi << "]";
  }
  return ::testing::AssertionSuccess();
}

}  // namespace

TEST(Backward, ThesisContractorPlus) {
  // C+([4,5],[0,3],[-2,2]) = ([4,5],[2,3],[1,2]) (2.31)
  Interval a(4, 5), x(0, 3), y(-2, 2);
  EXPECT_TRUE(bwd_add(a, x, y));
  EXPECT_EQ(x, Interval(2, 3));
  EXPECT_EQ(y, Interval(1, 2));
}

TEST(Backward, ThesisContractorExp) {
  // C_exp (2.32): [b] ∩= log([a]), with a = exp(b).
  Interval b = Interval::all_reals();
  EXPECT_TRUE(bwd_exp(Interval(-1, 1), b));
  EXPECT_EQ(b, Interval(-kInf, 0));
  b = Interval(-1, 1);
  EXPECT_TRUE(bwd_exp(Interval(1, 10), b));
  EXPECT_EQ(b.lb(), 0.0);
  EXPECT_EQ(b.ub(), 1.0);
  b = Interval(-1, 1);
  EXPECT_FALSE(bwd_exp(Interval(-2, -1), b));
  EXPECT_TRUE(b.is_empty());
}

TEST(Backward, SubAndNeg) {
  Interval x1(0, 10), x2(0, 10);
  EXPECT_TRUE(bwd_sub(Interval(8, 9), x1, x2));  // x1 - x2 in [8, 9]
  EXPECT_EQ(x1, Interval(8, 10));
  EXPECT_EQ(x2, Interval(0, 2));
  Interval x(-5, 0.5);
  EXPECT_TRUE(bwd_neg(Interval(-1, 3), x));
  EXPECT_EQ(x, Interval(-3, 0.5));
}

TEST(Backward, MulUsesTheTwoPieceQuotient) {
  Interval x1(0.5, 10), x2(-1, 1);
  EXPECT_TRUE(bwd_mul(Interval(1, 2), x1, x2));
  EXPECT_EQ(x1, Interval(1, 10));
  EXPECT_EQ(x2.ub(), 1.0);  // x2 in [1, 2] / [1, 10] = [0.1, 2]
  EXPECT_TRUE(x2.contains(0.1));
  EXPECT_LT(x2.lb(), 0.1000000001);
  // 0 in y and in x2: x1 unconstrained.
  x1 = Interval(-3, 7);
  x2 = Interval(-1, 1);
  EXPECT_TRUE(bwd_mul(Interval(-1, 1), x1, x2));
  EXPECT_EQ(x1, Interval(-3, 7));
  // No solution: x1 * x2 >= 1 with x1 in [-3, -1] and x2 in [0, 5].
  x1 = Interval(-3, -1);
  x2 = Interval(0, 5);
  EXPECT_FALSE(bwd_mul(Interval(1, 2), x1, x2));
  EXPECT_TRUE(x1.is_empty() && x2.is_empty());
}

TEST(Backward, Div) {
  Interval x1(-10, 10), x2(1, 2);
  EXPECT_TRUE(bwd_div(Interval(1, 2), x1, x2));
  EXPECT_EQ(x1, Interval(1, 4));
  EXPECT_EQ(x2, Interval(1, 2));
  // x2 = 0 is never a solution of y = x1 / x2.
  x1 = Interval(0, 0);
  x2 = Interval(0, 0);
  EXPECT_FALSE(bwd_div(Interval(-1, 1), x1, x2));
  EXPECT_TRUE(x1.is_empty());
  // y >= 1, x1 in [0, 1]: x2 must be positive, so x2 in [-1, 0] leaves only x2 = 0: empty.
  x1 = Interval(0, 1);
  x2 = Interval(-1, 0);
  EXPECT_FALSE(bwd_div(Interval(1, kInf), x1, x2));
}

TEST(Backward, SqrKeepsBothBranchesSeparately) {
  Interval x(-3, 1.5);
  EXPECT_TRUE(bwd_sqr(Interval(1, 4), x));
  EXPECT_EQ(x, Interval(-2, 1.5));
  x = Interval(-0.5, 3);
  EXPECT_TRUE(bwd_sqr(Interval(1, 4), x));
  EXPECT_EQ(x, Interval(1, 2));
  x = Interval(-0.5, 0.5);
  EXPECT_FALSE(bwd_sqr(Interval(1, 4), x));
  x = Interval(-5, 5);
  EXPECT_FALSE(bwd_sqr(Interval(-2, -1), x));
}

TEST(Backward, SqrtAbsSign) {
  Interval x(-5, 10);
  EXPECT_TRUE(bwd_sqrt(Interval(1, 2), x));
  EXPECT_EQ(x, Interval(1, 4));
  x = Interval(-5, 10);
  EXPECT_FALSE(bwd_sqrt(Interval(-2, -1), x));
  x = Interval(-3, 1.5);
  EXPECT_TRUE(bwd_abs(Interval(1, 2), x));
  EXPECT_EQ(x, Interval(-2, 1.5));
  x = Interval(-2, 3);
  EXPECT_TRUE(bwd_sign(Interval(1, 1), x));
  EXPECT_EQ(x, Interval(0, 3));
  x = Interval(-2, 3);
  EXPECT_TRUE(bwd_sign(Interval(-1, 0), x));
  EXPECT_EQ(x, Interval(-2, 0));
  x = Interval(1, 3);
  EXPECT_FALSE(bwd_sign(Interval(-1, -0.5), x));
}

TEST(Backward, MinMax) {
  Interval x1(0, 5), x2(3, 4);
  EXPECT_TRUE(bwd_min(Interval(1, 2), x1, x2));  // x2 > 2: x1 is the minimum
  EXPECT_EQ(x1, Interval(1, 2));
  EXPECT_EQ(x2, Interval(3, 4));
  x1 = Interval(0, 5);
  x2 = Interval(-1, 0);
  EXPECT_TRUE(bwd_max(Interval(1, 2), x1, x2));
  EXPECT_EQ(x1, Interval(1, 2));
  EXPECT_EQ(x2, Interval(-1, 0));
  x1 = Interval(3, 5);
  x2 = Interval(4, 6);
  EXPECT_FALSE(bwd_min(Interval(1, 2), x1, x2));
  EXPECT_TRUE(x1.is_empty() && x2.is_empty());
}

TEST(Backward, IntegerPowers) {
  Interval x(-10, 10);
  EXPECT_TRUE(bwd_pow(Interval(8, 27), x, 3));
  EXPECT_EQ(x, Interval(2, 3));
  x = Interval(-10, 2);
  EXPECT_TRUE(bwd_pow(Interval(4, 9), x, 2));
  EXPECT_EQ(x, Interval(-3, 2));
  x = Interval(-10, 10);
  EXPECT_TRUE(bwd_pow(Interval(16, 81), x, 4));
  EXPECT_EQ(x, Interval(-3, 3));
  x = Interval(-10, 10);
  EXPECT_TRUE(bwd_pow(Interval(1, 2), x, -1));
  EXPECT_EQ(x, Interval(0.5, 1));
  x = Interval(0.5, 10);
  EXPECT_TRUE(bwd_pow(Interval(0.25, 1), x, -2));
  EXPECT_EQ(x, Interval(1, 2));
  x = Interval(-3, 7);
  EXPECT_TRUE(bwd_pow(Interval(0, 2), x, 0));
  EXPECT_EQ(x, Interval(-3, 7));
  EXPECT_FALSE(bwd_pow(Interval(2, 3), x, 0));
  x = Interval(0, 0);
  EXPECT_FALSE(bwd_pow(Interval::all_reals(), x, -2));  // 0^-2 is undefined
}

TEST(Backward, RealPowerAndRoot) {
  Interval x(0, 10), p(2, 2);
  EXPECT_TRUE(bwd_pow(Interval(4, 4), x, p));
  EXPECT_TRUE(Near(x, 2, 2));
  EXPECT_TRUE(x.contains(2));
  x = Interval(2, 2);
  p = Interval(0, 10);
  EXPECT_TRUE(bwd_pow(Interval(8, 8), x, p));
  EXPECT_TRUE(p.contains(3));
  EXPECT_TRUE(Near(p, 3, 3));
  x = Interval(-1, 1);  // 0^p = 0 for p > 0
  p = Interval(1, 2);
  EXPECT_TRUE(bwd_pow(Interval(0, 0), x, p));
  EXPECT_EQ(x, Interval(0, 0));
  x = Interval::all_reals();
  EXPECT_TRUE(bwd_root(Interval(2, 3), x, 2));
  EXPECT_EQ(x, Interval(4, 9));
  x = Interval::all_reals();
  EXPECT_TRUE(bwd_root(Interval(-2, 3), x, 3));
  EXPECT_EQ(x, Interval(-8, 27));
  EXPECT_THROW(bwd_root(Interval(1), x, 0), Error);
}

TEST(Backward, LogAndHyperbolic) {
  Interval x(-5, 5);
  EXPECT_TRUE(bwd_log(Interval(0, 1), x));
  EXPECT_TRUE(Near(x, 1, std::exp(1.0)));
  EXPECT_TRUE(x.contains(1) && x.contains(2.718281828459045));
  x = Interval(-5, 5);
  EXPECT_TRUE(bwd_sinh(Interval(0, 0), x));
  EXPECT_EQ(x, Interval(0, 0));
  x = Interval(-1, 1);
  EXPECT_TRUE(bwd_cosh(Interval(1, 1), x));
  EXPECT_EQ(x, Interval(0, 0));
  x = Interval(-10, 10);
  EXPECT_TRUE(bwd_cosh(Interval(1, std::cosh(2.0)), x));
  EXPECT_TRUE(Near(x, -2, 2, 1e-9));
  x = Interval::all_reals();
  EXPECT_TRUE(bwd_tanh(Interval(-1, 0), x));
  EXPECT_EQ(x, Interval(-kInf, 0));
  x = Interval::all_reals();
  EXPECT_FALSE(bwd_tanh(Interval(1, 2), x));
}

TEST(Backward, InverseTrig) {
  Interval x = Interval::all_reals();
  EXPECT_TRUE(bwd_asin(Interval(0, 10), x));
  EXPECT_EQ(x, Interval(0, 1));
  x = Interval::all_reals();
  EXPECT_FALSE(bwd_asin(Interval(2, 3), x));
  x = Interval::all_reals();
  EXPECT_TRUE(bwd_acos(Interval(-1, 4), x));
  EXPECT_EQ(x, Interval(-1, 1));
  x = Interval::all_reals();
  EXPECT_TRUE(bwd_atan(Interval(0, 10), x));
  EXPECT_EQ(x, Interval(0, kInf));
  x = Interval::all_reals();
  EXPECT_TRUE(bwd_atan(Interval(kPi / 4), x));
  EXPECT_TRUE(Near(x, 1, 1));
}

TEST(Backward, SinIsTightOnTheEndBranches) {
  Interval x(0, 10);
  EXPECT_TRUE(bwd_sin(Interval(0.5, 1), x));  // [pi/6, 5pi/6 + 2pi]
  EXPECT_TRUE(Near(x, kPi / 6, 5 * kPi / 6 + 2 * kPi));
  EXPECT_TRUE(x.contains(0.52359877559829893) && x.contains(8.9011791851710811));
  x = Interval(2, 2.5);
  EXPECT_FALSE(bwd_sin(Interval(0, 0), x));
  x = Interval(3, 3.5);
  EXPECT_TRUE(bwd_sin(Interval(0, 0), x));
  EXPECT_TRUE(x.contains(3.141592653589793) && x.diam() < 1e-15);
  x = Interval(-1.2, 12.1);
  EXPECT_TRUE(bwd_sin(Interval(-1, 1), x));
  EXPECT_EQ(x, Interval(-1.2, 12.1));
  x = Interval(-5, 5);
  EXPECT_FALSE(bwd_sin(Interval(1.1, 2), x));
  // Unbounded on one side: only the finite bound moves.
  x = Interval(1, kInf);
  EXPECT_TRUE(bwd_sin(Interval(-1, -0.5), x));
  EXPECT_TRUE(Near(x, 7 * kPi / 6, kInf));
  // Far from 0 (k about 1.6e5).
  x = Interval(1e6, 1e6 + 1);
  EXPECT_TRUE(bwd_sin(Interval(0, 0), x));
  const double root = std::round(1e6 / kPi) * kPi;  // the one multiple of pi in x
  EXPECT_TRUE(Near(x, root, root, 1e-9));
}

TEST(Backward, CosAndTan) {
  Interval x(-0.1, 0.1);
  EXPECT_TRUE(bwd_cos(Interval(1, 1), x));
  EXPECT_TRUE(x.contains(0) && x.diam() < 1e-14);
  x = Interval(0, 2.1);
  EXPECT_TRUE(bwd_cos(Interval(-0.41614683654714241, 0.54030230586813977), x));  // cos(2), cos(1)
  EXPECT_TRUE(Near(x, 1, 2, 1e-14));
  x = Interval(0, 4);
  EXPECT_TRUE(bwd_tan(Interval(1, 1), x));  // pi/4 and 5pi/4
  EXPECT_TRUE(Near(x, kPi / 4, 5 * kPi / 4));
  x = Interval(-1.5708, 1.5708);
  EXPECT_TRUE(bwd_tan(Interval::all_reals(), x));
  EXPECT_EQ(x, Interval(-1.5708, 1.5708));
}

TEST(Backward, Atan2UsesTheQuadrants) {
  const Interval quarter = Interval::pi() / Interval(4);
  Interval y(1, 3), x(0, 2);
  EXPECT_TRUE(bwd_atan2(quarter, y, x));  // on the diagonal y = x
  EXPECT_TRUE(Near(x, 1, 2));
  EXPECT_TRUE(Near(y, 1, 2));
  y = Interval(-1, 1);
  x = Interval(-1, 2);
  EXPECT_TRUE(bwd_atan2(Interval(0, 0), y, x));  // the positive x axis
  EXPECT_EQ(y, Interval(0, 0));
  EXPECT_EQ(x, Interval(0, 2));
  y = Interval(-1, 1);
  x = Interval(-1, 2);
  EXPECT_TRUE(bwd_atan2(Interval::half_pi(), y, x));  // the positive y axis
  EXPECT_EQ(y.lb(), 0);
  EXPECT_EQ(y.ub(), 1);
  EXPECT_TRUE(x.contains(0) && x.diam() < 1e-15);
  y = Interval(1, 2);
  x = Interval(1, 2);
  EXPECT_FALSE(bwd_atan2(Interval(-3, -2), y, x));  // third quadrant only
  EXPECT_TRUE(x.is_empty() && y.is_empty());
  y = Interval(0, 0);
  x = Interval(0, 0);
  EXPECT_FALSE(bwd_atan2(Interval(-4, 4), y, x));  // atan2(0, 0) is undefined
}

TEST(Backward, EmptyEverywhere) {
  Interval x1(5, 6), x2(0, 0);
  EXPECT_FALSE(bwd_add(Interval(0, 1), x1, x2));
  EXPECT_TRUE(x1.is_empty() && x2.is_empty());
  x1 = Interval(0, 1);
  x2 = Interval::empty();
  EXPECT_FALSE(bwd_mul(Interval(0, 1), x1, x2));
  EXPECT_TRUE(x1.is_empty());
  Interval x(0, 1);
  EXPECT_FALSE(bwd_sin(Interval::empty(), x));
  EXPECT_TRUE(x.is_empty());
}

TEST(Backward, Div2RoundsOutward) {
  // Each bound of the two pieces encloses the exact quotient (checked with MPFR).
  auto check = [](double c, double b, double bound, bool is_upper) {
    mpfr_t q;
    mpfr_init2(q, 256);
    mpfr_set_d(q, c, MPFR_RNDN);
    mpfr_div_d(q, q, b, MPFR_RNDN);  // 256 bits: exact enough to compare with doubles
    const int cmp = mpfr_cmp_d(q, bound);
    mpfr_clear(q);
    return is_upper ? cmp <= 0 : cmp >= 0;
  };
  for (double c : {1.0, 0.1, 3.0, 7.0, 1e-300}) {
    for (double b : {3.0, 0.3, 10.0, 1e300}) {
      const auto [lo, hi] = div2(Interval(c, 2 * c), Interval(-b, b));
      EXPECT_EQ(lo.lb(), -kInf);
      EXPECT_EQ(hi.ub(), kInf);
      EXPECT_TRUE(check(c, -b, lo.ub(), true)) << c << " / " << -b;
      EXPECT_TRUE(check(c, b, hi.lb(), false)) << c << " / " << b;
      EXPECT_LE(hi.lb(), c / b);  // and tight: at most one rounding away
      EXPECT_GE(rounding::next_up(hi.lb()), c / b);
      const auto [nlo, nhi] = div2(Interval(-2 * c, -c), Interval(-b, b));
      EXPECT_TRUE(check(-c, b, nlo.ub(), true));
      EXPECT_TRUE(check(-c, -b, nhi.lb(), false));
    }
  }
  const auto [e1, e2] = div2(Interval(1, 2), Interval(0, 0));
  EXPECT_TRUE(e1.is_empty() && e2.is_empty());
  EXPECT_TRUE(div2(Interval(0, 2), Interval(0, 0)).first.is_all_reals());
  EXPECT_EQ(div2(Interval(1, 2), Interval(0, 4)).first, Interval(0.25, kInf));
  EXPECT_EQ(div2(Interval(1, 2), Interval(-4, 0)).first, Interval(-kInf, -0.25));
  EXPECT_EQ(div2(Interval(-2, -1), Interval(0, 4)).first, Interval(-kInf, -0.25));
  EXPECT_EQ(div2(Interval(1, 2), Interval(1, 4)).first, Interval(0.25, 2));
}
