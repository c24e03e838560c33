// Decimal literals are enclosed by the two doubles around them, checked
// against MPFR's directed roundings (issue 12, item 4; random texts are in
// test_parser.cpp).
#include <gtest/gtest.h>
#include <mpfr.h>

#include <limits>
#include <string>

#include "sillage/expr/function.h"
#include "sillage/expr/literal.h"

using namespace sillage;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kTiny = std::numeric_limits<double>::denorm_min();

// Directed roundings of the decimal text to binary64 (subnormals, overflow to
// the largest double downward and to inf upward): 3000 bits hold any rounding
// step exactly enough, then mpfr_get_d rounds once more in the same direction.
Interval mpfr_enclosure(const std::string& text) {
  mpfr_t v;
  mpfr_init2(v, 3000);
  mpfr_strtofr(v, text.c_str(), nullptr, 10, MPFR_RNDD);
  const double lo = mpfr_get_d(v, MPFR_RNDD);
  mpfr_strtofr(v, text.c_str(), nullptr, 10, MPFR_RNDU);
  const double hi = mpfr_get_d(v, MPFR_RNDU);
  mpfr_clear(v);
  return Interval::from_bounds_unchecked(lo, hi);
}

}  // namespace

TEST(LiteralMpfr, ListedTextsAreEnclosedByTheirDirectedRoundings) {
  for (const std::string t : {"0.1", "9007199254740993", "9007199254740992", "1e400", "1e-400", "0.2", "0.3",
                              "1.7976931348623157e308", "1.7976931348623159e308", "4.9406564584124654e-324",
                              "2.4703282292062328e-324", "2.4703282292062327e-324", "123456789012345678901234567890",
                              "0.30000000000000004", "1e23", "5e-324", "2.2250738585072011e-308"}) {
    EXPECT_EQ(detail::decimal_enclosure(t), mpfr_enclosure(t)) << t;
  }
  EXPECT_EQ(detail::decimal_enclosure("0.1"), Interval(0x1.9999999999999p-4, 0x1.999999999999ap-4));
  EXPECT_EQ(detail::decimal_enclosure("9007199254740993"), Interval(0x1p53, 0x1p53 + 2));
  EXPECT_EQ(detail::decimal_enclosure("1e400"), Interval(kMax, kInf));
  EXPECT_EQ(detail::decimal_enclosure("1e-400"), Interval(0, kTiny));
  // The sign comes from the parser.
  const Function f({"x"}, "x - 1e-400");
  EXPECT_EQ(f.eval(IntervalVector{Interval(0.0)}), Interval(-kTiny, 0));
  const Function g({"x"}, "x + 9007199254740993");
  EXPECT_EQ(g.eval(IntervalVector{Interval(0.0)}), Interval(0x1p53, 0x1p53 + 2));
}
