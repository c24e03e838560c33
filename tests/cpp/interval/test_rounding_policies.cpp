// The rounding policies of the slice rule against rounding.h (itself checked
// against MPFR in the interval tests): bit-identical on random and edge-case
// operands within their documented preconditions, never below (above) the
// rounding.h result where they are allowed to be one ulp looser.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include "sillage/interval/rounding_policies.h"
#include "sillage/interval/rounding.h"

using namespace sillage;

namespace {

const double kInf = rounding::kInf;
const double kMax = rounding::kMax;

// Random doubles: uniform in magnitude over many binades, both signs, plus
// neighbours of powers of two and a few specials.
std::vector<double> operands() {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> m(0.5, 1.0);
  std::uniform_int_distribution<int> e(-40, 40), big(-1070, 1023);
  std::vector<double> r = {0.0, -0.0, 1.0, -1.0, 0.1, -0.1, 3.0, kMax, -kMax, 1e308, -1e308,
                           std::numeric_limits<double>::denorm_min(), -std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::min(), 0x1p-968, 0x1p-969, 0x1p1000, kInf, -kInf};
  for (int i = 0; i < 300; ++i) {
    const double x = std::ldexp(m(rng), i % 10 == 0 ? big(rng) : e(rng));
    r.push_back(i % 2 ? -x : x);
    r.push_back(rounding::next_up(std::ldexp(1.0, e(rng))));
  }
  return r;
}

bool same(double a, double b) { return a == b || (a != a && b != b); }

template <class R>
void check_policy(const char* name) {
  const auto xs = operands();
  for (double a : xs) {
    for (double b : xs) {
      // add_up: operands > -inf; add_down: operands < +inf.
      if (a > -kInf && b > -kInf && !(a == kInf && b == -kInf)) {
        ASSERT_TRUE(same(R::add_up(a, b) + 0.0, rounding::add_up(a, b) + 0.0)) << name << " add_up " << a << " " << b;
        ASSERT_TRUE(same(R::sub_up(a, -b) + 0.0, rounding::sub_up(a, -b) + 0.0)) << name << " sub_up " << a << " " << b;
      }
      if (a < kInf && b < kInf) {
        ASSERT_TRUE(same(R::add_down(a, b) + 0.0, rounding::add_down(a, b) + 0.0))
            << name << " add_down " << a << " " << b;
        ASSERT_TRUE(same(R::sub_down(a, -b) + 0.0, rounding::sub_down(a, -b) + 0.0))
            << name << " sub_down " << a << " " << b;
      }
      // mul: exact except tiny products (one ulp above allowed); 0·inf = 0.
      const double ref_up = rounding::mul_up(a, b), ref_dn = rounding::mul_down(a, b);
      const double up = R::mul_up(a, b), dn = R::mul_down(a, b);
      if (std::fabs(ref_up) >= 0x1p-960 || a == 0 || b == 0) {
        ASSERT_TRUE(same(up + 0.0, ref_up + 0.0)) << name << " mul_up " << a << " " << b;
      } else {
        ASSERT_GE(up, ref_up) << name << " mul_up " << a << " " << b;
        ASSERT_LE(up, rounding::next_up(ref_up)) << name << " mul_up " << a << " " << b;
      }
      if (std::fabs(ref_dn) >= 0x1p-960 || a == 0 || b == 0) {
        ASSERT_TRUE(same(dn + 0.0, ref_dn + 0.0)) << name << " mul_down " << a << " " << b;
      } else {
        ASSERT_LE(dn, ref_dn) << name << " mul_down " << a << " " << b;
        ASSERT_GE(dn, rounding::next_down(ref_dn)) << name << " mul_down " << a << " " << b;
      }
      // div_up for a >= 0 finite, b > 0 finite.
      if (a >= 0 && b > 0 && a < kInf && b < kInf) {
        const double ref = rounding::div_up(a, b), q = R::div_up(a, b);
        ASSERT_GE(q, ref) << name << " div_up " << a << " " << b;
        ASSERT_LE(q, rounding::next_up(ref)) << name << " div_up " << a << " " << b;
        if (a >= 0x1p-900 && b >= 0x1p-900 && b <= 0x1p900 && std::fabs(ref) >= 0x1p-900 && ref <= 0x1p900) {
          ASSERT_EQ(q, ref) << name << " div_up " << a << " " << b;
        }
      }
    }
  }
}

}  // namespace

TEST(RoundingPolicies, SoftwareMatchesRounding) { check_policy<detail::SoftRounding>("soft"); }

TEST(RoundingPolicies, HardwareMatchesRounding) {
#if SILLAGE_HARD_ROUNDING
  if (!detail::hardware_rounding_available()) GTEST_SKIP() << "no AVX-512F";
  check_policy<detail::HardRounding>("hard");
#else
  GTEST_SKIP() << "not compiled in";
#endif
}

TEST(RoundingPolicies, Switch) {
  const bool saved = detail::hardware_rounding();
  detail::set_hardware_rounding(false);
  EXPECT_FALSE(detail::hardware_rounding());
  detail::set_hardware_rounding(true);
  EXPECT_EQ(detail::hardware_rounding(), detail::hardware_rounding_available());
  detail::set_hardware_rounding(saved);
}

TEST(RoundingPolicies, NextUpIf) {
  EXPECT_EQ(detail::next_up_if(1.0, false), 1.0);
  EXPECT_EQ(detail::next_up_if(1.0, true), rounding::next_up(1.0));
  EXPECT_EQ(detail::next_up_if(-1.0, true), rounding::next_up(-1.0));
  EXPECT_EQ(detail::next_up_if(0.0, true), std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(detail::next_up_if(-kInf, true), -kMax);
  EXPECT_EQ(detail::next_up_if(kMax, true), kInf);
}
