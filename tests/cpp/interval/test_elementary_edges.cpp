// Explicit edge cases of the elementary functions: set-based semantics
// (IEEE 1788), exact values, overflow, huge arguments, empty in -> empty out.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "sillage/interval/elementary.h"
#include "sillage/interval/interval.h"

using namespace sillage;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMax = std::numeric_limits<double>::max();
const Interval kPi = Interval::pi(), kHalfPi = Interval::half_pi();

Interval I(double a, double b) { return Interval(a, b); }
// [-hi, hi] of an enclosure, e.g. pm(pi) = [-pi_hi, pi_hi].
Interval pm(const Interval& x) { return I(-x.ub(), x.ub()); }

}  // namespace

TEST(ElementaryEdges, EmptyInEmptyOut) {
  const Interval e = Interval::empty(), x(1, 2);
  const std::vector<std::function<Interval(const Interval&)>> unary = {
      [](const Interval& v) { return exp(v); },   [](const Interval& v) { return log(v); },
      [](const Interval& v) { return sin(v); },   [](const Interval& v) { return cos(v); },
      [](const Interval& v) { return tan(v); },   [](const Interval& v) { return asin(v); },
      [](const Interval& v) { return acos(v); },  [](const Interval& v) { return atan(v); },
      [](const Interval& v) { return sinh(v); },  [](const Interval& v) { return cosh(v); },
      [](const Interval& v) { return tanh(v); },  [](const Interval& v) { return sqrt(v); },
      [](const Interval& v) { return sqr(v); },   [](const Interval& v) { return pow(v, 3); },
      [](const Interval& v) { return pow(v, -2); }, [](const Interval& v) { return pow(v, 0); },
      [](const Interval& v) { return pow(v, 2.5); }, [](const Interval& v) { return root(v, 3); },
      [](const Interval& v) { return root(v, 4); }, [](const Interval& v) { return root(v, -3); },
      [](const Interval& v) { return -v; }};
  for (std::size_t i = 0; i < unary.size(); ++i) EXPECT_TRUE(unary[i](e).is_empty()) << "function #" << i;
  EXPECT_TRUE(pow(e, x).is_empty());
  EXPECT_TRUE(pow(x, e).is_empty());
  EXPECT_TRUE(atan2(e, x).is_empty());
  EXPECT_TRUE(atan2(x, e).is_empty());
  EXPECT_TRUE((e + x).is_empty());
  EXPECT_TRUE((x * e).is_empty());
  EXPECT_TRUE((e / x).is_empty());
}

TEST(ElementaryEdges, SetBasedDomains) {
  EXPECT_EQ(log(I(-1, 1)), I(-kInf, 0));
  EXPECT_EQ(log(I(0, 1)), I(-kInf, 0));
  EXPECT_TRUE(log(I(-3, 0)).is_empty());
  EXPECT_TRUE(log(I(0, 0)).is_empty());
  EXPECT_EQ(log(I(0, kInf)), Interval::all_reals());
  EXPECT_EQ(sqrt(I(-4, 4)), I(0, 2));
  EXPECT_TRUE(sqrt(I(-4, -1)).is_empty());
  EXPECT_EQ(asin(Interval::all_reals()), pm(kHalfPi));
  EXPECT_EQ(asin(I(-1, 1)), pm(kHalfPi));
  EXPECT_TRUE(asin(I(1.5, 2)).is_empty());
  EXPECT_EQ(acos(Interval::all_reals()), I(0, kPi.ub()));
  EXPECT_EQ(acos(I(1, 5)), I(0, 0));
  EXPECT_TRUE(acos(I(-3, -1.0000001)).is_empty());
  EXPECT_EQ(asin(I(1, 7)), I(kHalfPi.lb(), kHalfPi.ub()));
  EXPECT_EQ(atan(Interval::all_reals()), pm(kHalfPi));
}

TEST(ElementaryEdges, Powers) {
  EXPECT_TRUE(pow(I(0, 0), I(-2.5, -1)).is_empty());
  EXPECT_EQ(pow(I(0, 0), I(-2.5, 1)), I(0, 0));
  EXPECT_EQ(pow(I(-3, 7), 0), I(1, 1));
  EXPECT_EQ(pow(I(-3, 7), I(0, 0)), I(1, 1));
  EXPECT_TRUE(pow(I(-3, -1), I(2, 2)).is_empty());  // pow is defined for x >= 0 only
  EXPECT_EQ(pow(I(-3, 2), I(2, 2)), I(0, 4));
  EXPECT_EQ(pow(I(0, 2), I(-2, -1)), I(0.25, kInf));
  EXPECT_EQ(pow(I(0.5, 2), Interval::all_reals()), I(0, kInf));
  EXPECT_EQ(pow(I(1, 1), Interval::all_reals()), I(1, 1));
  EXPECT_EQ(pow(I(4, 9), 0.5), I(2, 3));
  EXPECT_EQ(pow(I(2, 3), 3), I(8, 27));
  EXPECT_EQ(pow(I(-2, 3), 3), I(-8, 27));
  EXPECT_EQ(pow(I(-2, 3), 4), I(0, 81));
  EXPECT_EQ(pow(I(-3, -2), 4), I(16, 81));
  EXPECT_EQ(pow(I(2, 4), -2), I(0.0625, 0.25));
  EXPECT_EQ(pow(I(-4, -2), -3), I(-0.125, -0.015625));
  EXPECT_EQ(pow(I(-4, 2), -2), I(0.0625, kInf));
  EXPECT_EQ(pow(I(-4, 2), -3), Interval::all_reals());
  EXPECT_EQ(pow(I(0, 2), -3), I(0.125, kInf));
  EXPECT_EQ(pow(I(-2, 0), -3), I(-kInf, -0.125));
  EXPECT_TRUE(pow(I(0, 0), -2).is_empty());
  EXPECT_EQ(pow(I(0, 0), 5), I(0, 0));
  EXPECT_EQ(pow(I(10, 10), 400), I(kMax, kInf));  // overflow: lower bound MAX
  EXPECT_EQ(root(I(8, 27), 3), I(2, 3));
  EXPECT_EQ(root(I(-27, -8), 3), I(-3, -2));
  EXPECT_EQ(root(I(-16, 81), 4), I(0, 3));
  EXPECT_TRUE(root(I(-16, -1), 4).is_empty());
  EXPECT_EQ(root(I(0, 32), 5), I(0, 2));
  EXPECT_EQ(root(I(0, 8), -3), I(0.5, kInf));
  EXPECT_THROW(root(I(1, 2), 0), Error);
  // Huge n: the root of any positive double is within a few ulps of 1.
  const Interval r = root(I(1e-300, 1e300), 1000001);
  EXPECT_TRUE(r.contains(std::pow(1e-300, 1.0 / 1000001)) && r.contains(std::pow(1e300, 1.0 / 1000001)));
  EXPECT_NEAR(r.lb(), std::pow(1e-300, 1.0 / 1000001), 1e-14);
  EXPECT_NEAR(r.ub(), std::pow(1e300, 1.0 / 1000001), 1e-14);
  EXPECT_EQ(pow(I(-1, 1), std::numeric_limits<int>::min()), I(1, kInf));
  EXPECT_THROW(pow(I(1, 2), std::nan("")), Error);
  EXPECT_THROW(pow(I(1, 2), kInf), Error);
}

TEST(ElementaryEdges, Atan2BranchCut) {
  EXPECT_EQ(atan2(I(-2, 0), I(-3, -1)), pm(kPi));
  const Interval r = atan2(I(0, 2), I(-3, -1));
  EXPECT_TRUE(r.contains(2.0344439357957027));
  EXPECT_LE(r.lb(), 2.0344439357957027);
  EXPECT_GE(r.lb(), std::nextafter(std::nextafter(std::nextafter(2.0344439357957027, 0), 0), 0));
  EXPECT_EQ(r.ub(), kPi.ub());
  EXPECT_EQ(atan2(I(0, 0), I(-2, 1)), I(0, kPi.ub()));
  EXPECT_TRUE(atan2(I(0, 0), I(0, 0)).is_empty());
  EXPECT_EQ(atan2(I(0, 0), I(1, 2)), I(0, 0));
  EXPECT_EQ(atan2(I(0, 0), I(-2, -1)), kPi);
  EXPECT_EQ(atan2(I(1, 2), I(0, 0)), kHalfPi);
  EXPECT_EQ(atan2(I(-2, -1), I(0, 0)), -kHalfPi);
  EXPECT_EQ(atan2(I(-1, 1), I(-1, 1)), pm(kPi));
  EXPECT_EQ(atan2(I(-1, 1), I(0, 1)), pm(kHalfPi));
  EXPECT_EQ(atan2(I(-1, 0), I(0, 1)), I(-kHalfPi.ub(), 0));
  EXPECT_EQ(atan2(I(0, 1), I(0, 1)), I(0, kHalfPi.ub()));
  EXPECT_EQ(atan2(Interval::all_reals(), Interval::all_reals()), pm(kPi));
}

TEST(ElementaryEdges, ExactValues) {
  EXPECT_EQ(exp(I(0, 0)), I(1, 1));
  EXPECT_EQ(exp(I(-kInf, 0)), I(0, 1));
  EXPECT_EQ(exp(I(0, kInf)), I(1, kInf));
  EXPECT_EQ(log(I(1, 1)), I(0, 0));
  EXPECT_EQ(sin(I(0, 0)), I(0, 0));
  EXPECT_EQ(cos(I(0, 0)), I(1, 1));
  EXPECT_EQ(tan(I(0, 0)), I(0, 0));
  EXPECT_EQ(asin(I(0, 0)), I(0, 0));
  EXPECT_EQ(acos(I(1, 1)), I(0, 0));
  EXPECT_EQ(atan(I(0, 0)), I(0, 0));
  EXPECT_EQ(sinh(I(0, 0)), I(0, 0));
  EXPECT_EQ(cosh(I(0, 0)), I(1, 1));
  EXPECT_EQ(cosh(I(-1, 2)).lb(), 1.0);
  EXPECT_EQ(tanh(I(0, 0)), I(0, 0));
  EXPECT_EQ(tanh(Interval::all_reals()), I(-1, 1));
  EXPECT_EQ(sinh(Interval::all_reals()), Interval::all_reals());
  EXPECT_EQ(cosh(Interval::all_reals()), I(1, kInf));
  EXPECT_EQ(sin(I(0, 1e-300)), I(0, 1e-300));
  EXPECT_EQ(sin(Interval::all_reals()), I(-1, 1));
  EXPECT_EQ(cos(I(-kInf, 0)), I(-1, 1));
  EXPECT_EQ(tan(Interval::all_reals()), Interval::all_reals());
}

TEST(ElementaryEdges, OverflowRoundsOutward) {
  EXPECT_EQ(exp(I(709.78271289338409, 709.78271289338409)), I(kMax, kInf));
  const Interval below = exp(I(709.78271289338397, 709.78271289338397));  // exp < MAX
  EXPECT_LT(below.lb(), kMax);
  EXPECT_EQ(exp(I(1000, 2000)), I(kMax, kInf));
  EXPECT_EQ(exp(I(-2000, -1000)).lb(), 0.0);
  EXPECT_GT(exp(I(-2000, -1000)).ub(), 0.0);
  EXPECT_EQ(sinh(I(711, 712)), I(kMax, kInf));
  EXPECT_EQ(sinh(I(-712, -711)), I(-kInf, -kMax));
  EXPECT_EQ(cosh(I(711, 712)), I(kMax, kInf));
  EXPECT_EQ(cosh(I(-712, -711)), I(kMax, kInf));
}

TEST(ElementaryEdges, TrigAroundPolesAndExtrema) {
  EXPECT_EQ(tan(I(1.5, 1.6)), Interval::all_reals());   // pole at pi/2
  EXPECT_EQ(tan(I(-1.6, -1.5)), Interval::all_reals());
  EXPECT_FALSE(tan(I(1.5, 1.57)).is_unbounded());       // pi/2 = 1.5707963...
  EXPECT_EQ(tan(I(3.1, 3.2)).is_unbounded(), false);     // crosses pi, no pole
  EXPECT_EQ(sin(I(1.5, 1.6)).ub(), 1.0);
  EXPECT_LT(sin(I(1.5, 1.57)).ub(), 1.0);
  EXPECT_EQ(sin(I(4.7, 4.8)).lb(), -1.0);                // 3pi/2 = 4.712...
  EXPECT_EQ(cos(I(3.1, 3.2)).lb(), -1.0);
  EXPECT_EQ(cos(I(-0.1, 0.1)).ub(), 1.0);
  EXPECT_EQ(sin(I(0, 6.3)), I(-1, 1));
  EXPECT_EQ(cos(I(1, 7.3)), I(-1, 1));                   // contains pi and 2pi
  const Interval s = sin(I(0.5, 1.0));                   // monotone piece
  EXPECT_TRUE(s.contains(std::sin(0.5)) && s.contains(std::sin(1.0)));
  EXPECT_LT(s.diam(), std::sin(1.0) - std::sin(0.5) + 1e-15);
  // pi/2 lies strictly between these doubles.
  EXPECT_EQ(sin(I(1.5707963267948966, 1.5707963267948968)).ub(), 1.0);
  EXPECT_EQ(cos(I(1.5707963267948966, 1.5707963267948968)).lb() < 0, true);
  EXPECT_EQ(cos(I(1.5707963267948966, 1.5707963267948968)).ub() > 0, true);
}

TEST(ElementaryEdges, HugeArguments) {
  const double h = 1e308;
  const Interval s = sin(I(h, h));
  EXPECT_TRUE(s.contains(std::sin(h)));
  EXPECT_LT(s.diam(), 1e-15);
  EXPECT_EQ(sin(I(h, std::nextafter(h, kInf))), I(-1, 1));  // ulp(1e308) >> 2 pi
  EXPECT_EQ(cos(I(-kMax, kMax)), I(-1, 1));
  EXPECT_EQ(tan(I(h, std::nextafter(h, kInf))), Interval::all_reals());
  // 2^60 has ulp 256 > 2 pi, so two neighbours span every extremum.
  EXPECT_EQ(sin(I(0x1p60, std::nextafter(0x1p60, kInf))), I(-1, 1));
  // Near 2^40 the ulp is 2^-12: neighbouring doubles rarely span an extremum,
  // and then the result is a tight monotone image.
  const double x = 0x1p40;
  const Interval t = sin(I(x, std::nextafter(x, kInf)));
  EXPECT_LT(t.diam(), 1e-3);
  EXPECT_TRUE(t.contains(std::sin(x)));
  const Interval c = cos(I(-1e22, -1e22));
  EXPECT_TRUE(c.contains(std::cos(-1e22)));
  // 6381956970095103 * 2^797 is the double closest to a multiple of pi/2;
  // cos there is -0x1.14ae72e6ba22e...p-61 (MPFR), on which glibc is 7 ulps off.
  const Interval w = cos(I(0x1.6ac5b262ca1ffp+849, 0x1.6ac5b262ca1ffp+849));
  EXPECT_LE(w.lb(), -0x1.14ae72e6ba22fp-61);
  EXPECT_GE(w.ub(), -0x1.14ae72e6ba22ep-61);
  EXPECT_LE(w.diam(), 0x1p-110);
  const Interval tw = tan(I(0x1.6ac5b262ca1ffp+849, 0x1.6ac5b262ca1ffp+849));
  EXPECT_LE(tw.lb(), -0x1.d9ba9a7975636p+60);
  EXPECT_GE(tw.ub(), -0x1.d9ba9a7975635p+60);
  EXPECT_LE(tw.diam(), 0x1p+10);
}

TEST(ElementaryEdges, ZeroTimesUnbounded) {
  EXPECT_EQ(Interval(0) * Interval::all_reals(), I(0, 0));
  EXPECT_EQ(Interval::all_reals() * Interval(0), I(0, 0));
  EXPECT_EQ(I(0, 0) * I(-kInf, 5), I(0, 0));
  EXPECT_EQ(I(0, 1) * I(1, kInf), I(0, kInf));
}
