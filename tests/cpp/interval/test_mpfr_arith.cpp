// + - * / sqr sqrt against MPFR: every result must contain the exact image
// and its bounds must be the correctly rounded ones, bit for bit, on both
// rounding paths (AVX-512F when the CPU has it, and the portable one).
#include <gtest/gtest.h>

#include "mpfr_oracle.h"
#include "sillage/interval/hardware_rounding.h"
#include "sillage/interval/interval.h"

using namespace oracle;
using sillage::Interval;

namespace {

// One end point, drawn from a mix that stresses rounding, overflow,
// underflow (subnormals), cancellation and exact cases.
double point(Gen& g) {
  switch (g.integer(0, 9)) {
    case 0: case 1: return g.any_finite();
    case 2: return g.log_uniform(-30, 30);
    case 3: return static_cast<double>(g.integer(-20, 20));
    case 4: return g.log_uniform(1000, 1023);    // products overflow
    case 5: return g.log_uniform(-1074, -1000);  // products underflow
    case 6: return g.sign() * std::ldexp(static_cast<double>(g.integer(1, 1 << 20)), static_cast<int>(g.integer(-30, 30)));
    case 7: return g.uniform(-1, 1);
    case 8: return g.log_uniform(-540, -500);    // squares near the subnormal range
    default: return g.near(g.log_uniform(-3, 3), 2);
  }
}

struct Case {
  Interval x, y;
};

Interval make_interval(Gen& g, double a) {
  double b;
  switch (g.integer(0, 5)) {
    case 0: b = a; break;
    case 1: b = g.near(a, 3); break;
    default: b = point(g); break;
  }
  if (a > b) std::swap(a, b);
  a += 0.0;
  b += 0.0;
  if (g.integer(0, 19) == 0) a = -kInf;
  if (g.integer(0, 19) == 0) b = kInf;
  return Interval(a, b);
}

Case make_case(Gen& g) {
  const Interval x = make_interval(g, point(g));
  double c0;
  switch (g.integer(0, 4)) {
    case 0: c0 = g.near(x.is_bounded() ? -x.lb() : 1.0, 2); break;  // cancellation in +
    case 1: c0 = g.near(x.is_bounded() ? x.ub() : 1.0, 2); break;   // cancellation in -
    default: c0 = point(g); break;
  }
  return {x, make_interval(g, c0)};
}

std::string describe(const Case& c) { return std::string("(") + hex(c.x) + ", " + hex(c.y) + ")"; }

// Product with the interval convention 0 * inf = 0 (limits of bounded sets).
Bounds mul(double a, double b) {
  if (a == 0 || b == 0) return {0.0, 0.0};
  return eval2(mpfr_mul, a, b);
}

Expected exact_add(const Interval& x, const Interval& y) {
  return Expected::of(eval2(mpfr_add, x.lb(), y.lb()).down, eval2(mpfr_add, x.ub(), y.ub()).up);
}

Expected exact_sub(const Interval& x, const Interval& y) {
  return Expected::of(eval2(mpfr_sub, x.lb(), y.ub()).down, eval2(mpfr_sub, x.ub(), y.lb()).up);
}

Expected exact_mul(const Interval& x, const Interval& y) {
  double lo = kInf, hi = -kInf;
  for (double u : {x.lb(), x.ub()}) {
    for (double v : {y.lb(), y.ub()}) {
      const Bounds p = mul(u, v);
      lo = std::min(lo, p.down);
      hi = std::max(hi, p.up);
    }
  }
  return Expected::of(lo, hi);
}

// The hull of { u / v : u in x, v in y, v != 0 }: a zero bound of y is the
// limit from inside y (signed zero), 0 / v = 0 counts when 0 is in x.
Expected exact_div(const Interval& x, const Interval& y) {
  const double c = y.lb(), d = y.ub();
  if (c == 0 && d == 0) return Expected::none();
  const bool zero_in_x = x.lb() <= 0 && x.ub() >= 0;
  if (c < 0 && d > 0) {
    if (x.lb() == 0 && x.ub() == 0) return Expected::of(0, 0);
    return Expected::of(-kInf, kInf);
  }
  double lo = zero_in_x ? 0.0 : kInf, hi = zero_in_x ? 0.0 : -kInf;
  for (double u : {x.lb(), x.ub()}) {
    for (double v : {c == 0 ? 0.0 : c, d == 0 ? -0.0 : d}) {
      const Bounds q = eval2(mpfr_div, u, v);
      if (!q.valid()) continue;  // 0/0, inf/inf: other corners bound the set
      lo = std::min(lo, q.down);
      hi = std::max(hi, q.up);
    }
  }
  return Expected::of(lo, hi);
}

Expected exact_sqr(const Interval& x) {
  const double a = x.lb(), b = x.ub();
  const Bounds sa = eval1(mpfr_sqr, a), sb = eval1(mpfr_sqr, b);
  if (a >= 0) return Expected::of(sa.down, sb.up);
  if (b <= 0) return Expected::of(sb.down, sa.up);
  return Expected::of(0.0, std::max(sa.up, sb.up));
}

Expected exact_sqrt(const Interval& x) {
  if (x.ub() < 0) return Expected::none();
  return Expected::of(eval1(mpfr_sqrt, std::max(x.lb(), 0.0)).down, eval1(mpfr_sqrt, x.ub()).up);
}

const std::size_t kCases = scaled(1'000'000);

// The parameter: true for the hardware path, false for the portable one.
class MpfrArith : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    if (GetParam() && !sillage::detail::hardware_rounding_available()) GTEST_SKIP() << "no AVX-512F on this CPU";
    sillage::detail::set_hardware_rounding(GetParam());
  }
  void TearDown() override { sillage::detail::set_hardware_rounding(initial_); }

 private:
  bool initial_ = sillage::detail::hardware_rounding();
};

std::string path_name(const ::testing::TestParamInfo<bool>& p) { return p.param ? "hardware" : "portable"; }

}  // namespace

INSTANTIATE_TEST_SUITE_P(Paths, MpfrArith, ::testing::Bool(), path_name);

TEST_P(MpfrArith, AddSubAreOptimal) {
  DoubleRange range;
  Gen g(0x5111a9e0001);
  Checker add("+", 0), sub("-", 0);
  for (std::size_t k = 0; k < kCases; ++k) {
    const Case c = make_case(g);
    add.check(c.x + c.y, exact_add(c.x, c.y), [&] { return describe(c); });
    sub.check(c.x - c.y, exact_sub(c.x, c.y), [&] { return describe(c); });
  }
  expect_ok(add);
  expect_ok(sub);
}

TEST_P(MpfrArith, MulIsOptimal) {
  DoubleRange range;
  Gen g(0x5111a9e0002);
  Checker mul_c("*", 0);
  for (std::size_t k = 0; k < kCases; ++k) {
    const Case c = make_case(g);
    mul_c.check(c.x * c.y, exact_mul(c.x, c.y), [&] { return describe(c); });
  }
  expect_ok(mul_c);
}

TEST_P(MpfrArith, DivIsOptimal) {
  DoubleRange range;
  Gen g(0x5111a9e0003);
  Checker div_c("/", 0);
  for (std::size_t k = 0; k < kCases; ++k) {
    Case c = make_case(g);
    if (k % 16 == 0) c.y = Interval(g.coin() ? 0.0 : -std::fabs(point(g)), g.coin() ? 0.0 : std::fabs(point(g)));
    div_c.check(c.x / c.y, exact_div(c.x, c.y), [&] { return describe(c); });
  }
  expect_ok(div_c);
}

TEST_P(MpfrArith, SqrAndSqrtAreOptimal) {
  DoubleRange range;
  Gen g(0x5111a9e0004);
  Checker sqr_c("sqr", 0), sqrt_c("sqrt", 0);
  for (std::size_t k = 0; k < kCases; ++k) {
    const Interval x = make_interval(g, point(g));
    sqr_c.check(sqr(x), exact_sqr(x), [&] { return std::string("(") + hex(x) + ")"; });
    sqrt_c.check(sqrt(x), exact_sqrt(x), [&] { return std::string("(") + hex(x) + ")"; });
  }
  expect_ok(sqr_c);
  expect_ok(sqrt_c);
}
