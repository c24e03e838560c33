// The rounding paths of Interval's + - * / sqr sqrt against each other, bit
// for bit: hardware (AVX-512F, when the CPU has it), portable (branch-free
// error-free transformations) and rounding.h's scalar functions (branches on
// the rounding error; themselves checked against MPFR in test_mpfr_arith).
// Operands: kit/arith_samples.h.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "sillage/interval/arith_kernels.h"
#include "sillage/interval/hardware_rounding.h"
#include "sillage/interval/interval.h"

#include "kit/arith_samples.h"

using namespace sillage;
using detail::BoundPair;

namespace {

const double kInf = rounding::kInf;
const double kMax = rounding::kMax;
const double kTiny = std::numeric_limits<double>::denorm_min();

std::string bits(const BoundPair& p) {
  char s[80];
  std::snprintf(s, sizeof s, "[%a, %a]", p.lo, p.hi);
  return s;
}

// Same bounds bit for bit (both paths return +0, never -0).
bool same(const BoundPair& p, const BoundPair& q) {
  return std::bit_cast<std::uint64_t>(p.lo) == std::bit_cast<std::uint64_t>(q.lo) &&
         std::bit_cast<std::uint64_t>(p.hi) == std::bit_cast<std::uint64_t>(q.hi);
}

// Runs every kernel on (x, y) with policies R and S and compares.
template <class R, class S>
void compare(const Interval& x, const Interval& y, const char* what, int& failures) {
  using namespace detail;
  const double a = x.lb(), b = x.ub(), c = y.lb(), d = y.ub();
  const std::pair<const char*, std::pair<BoundPair, BoundPair>> results[] = {
      {"+", {add_bounds<R>(a, b, c, d), add_bounds<S>(a, b, c, d)}},
      {"-", {sub_bounds<R>(a, b, c, d), sub_bounds<S>(a, b, c, d)}},
      {"*", {mul_bounds<R>(a, b, c, d), mul_bounds<S>(a, b, c, d)}},
      {"/", {div_bounds<R>(a, b, c, d), div_bounds<S>(a, b, c, d)}},
      {"sqr", {sqr_bounds<R>(a, b), sqr_bounds<S>(a, b)}},
      {"sqrt", {sqrt_bounds<R>(a, b), sqrt_bounds<S>(a, b)}},
  };
  for (const auto& [op, r] : results) {
    if (!same(r.first, r.second) && ++failures <= 20) {
      ADD_FAILURE() << what << ": " << op << " of " << x << ", " << y << ": " << bits(r.first) << " vs "
                    << bits(r.second);
    }
  }
}

template <class R, class S>
void compare_all(const char* what) {
  int failures = 0;
  const auto adv = test::adversarial_intervals();
  for (const Interval& x : adv)
    for (const Interval& y : adv) compare<R, S>(x, y, what, failures);
  const auto rnd = test::random_intervals(200'000);
  for (std::size_t i = 0; i + 1 < rnd.size(); ++i) compare<R, S>(rnd[i], rnd[i + 1], what, failures);
  EXPECT_EQ(failures, 0) << what;
}

}  // namespace

TEST(RoundingPaths, PortableEqualsScalarBitForBit) {
  compare_all<detail::BranchFreeRounding, detail::ScalarRounding>("portable vs scalar");
}

#if SILLAGE_HARD_ROUNDING
TEST(RoundingPaths, HardwareEqualsPortableBitForBit) {
  if (!detail::hardware_rounding_available()) GTEST_SKIP() << "no AVX-512F on this CPU";
  compare_all<detail::HardRounding, detail::BranchFreeRounding>("hardware vs portable");
}
#endif

// The operators follow the switch, and give the same bounds either way.
TEST(RoundingPaths, OperatorsFollowTheSwitch) {
  const bool initial = detail::hardware_rounding();
  const Interval x(0.1, 0.3), y(-0.7, 0.2);
  detail::set_hardware_rounding(false);
  EXPECT_FALSE(detail::use_hardware_rounding());
  const Interval p[] = {x + y, x - y, x * y, x / y, y / x, sqr(y), sqrt(x)};
  detail::set_hardware_rounding(true);
  EXPECT_EQ(detail::use_hardware_rounding(), detail::hardware_rounding_available());
  const Interval h[] = {x + y, x - y, x * y, x / y, y / x, sqr(y), sqrt(x)};
  detail::set_hardware_rounding(initial);
  for (std::size_t i = 0; i < std::size(p); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(p[i].lb()), std::bit_cast<std::uint64_t>(h[i].lb())) << i;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(p[i].ub()), std::bit_cast<std::uint64_t>(h[i].ub())) << i;
  }
}

// IEEE 1788 cases that no sign analysis may lose, on whichever path is on.
TEST(RoundingPaths, SetSemanticsEdges) {
  const Interval e = Interval::empty(), all = Interval::all_reals(), z(0.0);
  EXPECT_TRUE((e + all).is_empty());
  EXPECT_TRUE((all * e).is_empty());
  EXPECT_TRUE((Interval(1.0) / z).is_empty());
  EXPECT_TRUE(sqrt(Interval(-4.0, -1.0)).is_empty());
  EXPECT_EQ(z * all, z);
  EXPECT_EQ(z / Interval(-1.0, 1.0), z);
  EXPECT_EQ(Interval(1.0, 2.0) / Interval(0.0, 4.0), Interval(0.25, kInf));
  EXPECT_EQ(Interval(-2.0, -1.0) / Interval(0.0, 4.0), Interval(-kInf, -0.25));
  EXPECT_EQ(Interval(1.0, 2.0) / Interval(-4.0, 0.0), Interval(-kInf, -0.25));
  EXPECT_EQ(Interval(-2.0, 0.0) / Interval(-4.0, 0.0), Interval(0.0, kInf));
  EXPECT_EQ(Interval(-1.0, 2.0) / Interval(-4.0, 0.0), all);
  EXPECT_EQ(Interval(0.0, 1.0) * Interval(2.0, kInf), Interval(0.0, kInf));
  EXPECT_EQ(Interval(kMax) + Interval(kMax), Interval(kMax, kInf));
  EXPECT_EQ(Interval(-kMax) * Interval(2.0), Interval(-kInf, -kMax));
  EXPECT_EQ(sqr(Interval(-3.0, 2.0)), Interval(0.0, 9.0));
  EXPECT_EQ(Interval(kTiny) * Interval(0.5), Interval(0.0, kTiny));
  const Interval c = Interval(1.0) - Interval(1.0);  // exact zero: +0 bounds on both paths
  EXPECT_FALSE(std::signbit(c.lb()));
  EXPECT_FALSE(std::signbit(c.ub()));
}

// 2Sum's first difference bv = s - a overflows, the sum not: a + (-max) with
// a = 0x1.0000000000003p+1022 is a tie at 2^1023 broken toward -max. The
// upper bound is the double above s on every path (the exact sum lies
// strictly between them; rounding.h's ordered Fast2Sum never overflows).
TEST(RoundingPaths, TwoSumOverflowOfTheDifference) {
  const double a = 0x1.0000000000003p+1022;
  const double s = a - kMax;  // round to nearest: below a - max
  const double up = std::nextafter(s, kInf);
  EXPECT_EQ(rounding::add_up(a, -kMax), up);
  EXPECT_EQ(rounding::add_down(a, -kMax), s);
  const bool initial = detail::hardware_rounding();
  for (const bool hardware : {false, true}) {
    detail::set_hardware_rounding(hardware);
    EXPECT_EQ((Interval(a) + Interval(-kMax)).ub(), up) << hardware;
    EXPECT_EQ((Interval(a) - Interval(kMax)).ub(), up) << hardware;
    EXPECT_EQ((Interval(-a) + Interval(kMax)).lb(), -up) << hardware;
    EXPECT_EQ((Interval(-a) - Interval(-kMax)).lb(), -up) << hardware;
  }
  detail::set_hardware_rounding(initial);
}
