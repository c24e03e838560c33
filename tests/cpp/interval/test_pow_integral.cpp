// pow(x, double) with an integral exponent is the integer power, as x^2.0
// in an expression (issue 12, item 3).
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "sillage/interval/elementary.h"

using namespace sillage;

TEST(PowIntegral, IntegralDoubleIsTheIntegerPower) {
  EXPECT_EQ(pow(Interval(-2, -1), 2.0), Interval(1, 4));
  EXPECT_EQ(pow(Interval(-2, -1), 3.0), Interval(-8, -1));
  EXPECT_EQ(pow(Interval(-2, 1), -1.0), Interval::all_reals());
  EXPECT_EQ(pow(Interval(-2, -1), -2.0), Interval(0.25, 1));
  EXPECT_EQ(pow(Interval(-3, 2), 0.0), Interval(1.0));
  EXPECT_TRUE(pow(Interval(0.0), -2.0).is_empty());
  EXPECT_TRUE(pow(Interval(-2, -1), 0.5).is_empty());  // a real exponent needs x >= 0
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int k = 0; k < 2000; ++k) {
    double a = u(rng), b = u(rng);
    if (a > b) std::swap(a, b);
    const int n = static_cast<int>(rng() % 13) - 6;
    ASSERT_EQ(pow(Interval(a, b), static_cast<double>(n)), pow(Interval(a, b), n)) << a << " " << b << " " << n;
  }
}

TEST(PowIntegral, BeyondTheIntRange) {
  const double even = 0x1p40, odd = 0x1p40 + 1;
  EXPECT_EQ(pow(Interval(-1, -1), even), Interval(1.0));
  EXPECT_EQ(pow(Interval(-1, -1), odd), Interval(-1.0));
  EXPECT_EQ(pow(Interval(-1, 1), odd), Interval(-1, 1));
  EXPECT_EQ(pow(Interval(-1, 0.5), even), Interval(0, 1));
  const Interval big = pow(Interval(-2, -2), odd);  // -2^(2^40 + 1): beyond the doubles
  EXPECT_LE(big.ub(), -1e308);
  EXPECT_EQ(big.lb(), -std::numeric_limits<double>::infinity());
  const Interval huge = pow(Interval(-0.5, -0.5), -even);  // 2^(2^40)
  EXPECT_GE(huge.lb(), 1e308);
  EXPECT_EQ(huge.ub(), std::numeric_limits<double>::infinity());
}
