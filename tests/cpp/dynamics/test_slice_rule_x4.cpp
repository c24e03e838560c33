// CtcDeriv's slice rule 4 slices at a time with AVX2 (slice_rule_x4.h):
// δ[v], the hulls of a FWD_BWD sweep and CtcEval's hull bounds against
// scale, slice_hull and polygon_hull on SoftRounding (slice_deriv.h) slice by
// slice, bit for bit, on adversarial bounds: infinities, zeros of both
// signs, straddling and one-signed derivatives, degenerate gates, tiny
// (subnormal) and huge magnitudes, times whose differences round.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "sillage/dynamics/slice_rule_x4.h"
#include "sillage/interval/arith_rows.h"
#include "sillage/tube/slice_deriv.h"

using namespace sillage;

namespace {

const double kInf = rounding::kInf;

// A bound drawn from a pool that favours the special cases.
double special(std::mt19937_64& rng) {
  static const std::vector<double> pool = {0.0, -0.0, 1.0, -1.0, 0x1p-1074, -0x1p-1074, 0x1p-1000, -0x1p-970,
                                           0x1p-968, 0x1p1000, -0x1p1001, 0x1.fffffffffffffp1023, kInf, -kInf,
                                           3.0, -0.1, 1e-300, 1e300};
  std::uniform_real_distribution<double> u(-10, 10);
  const auto pick = std::uniform_int_distribution<std::size_t>(0, 2 * pool.size())(rng);
  return pick < pool.size() ? pool[pick] : u(rng);
}

// A non-empty interval (the bounds of non-empty sets the rule requires).
Interval random_interval(std::mt19937_64& rng) {
  double a = special(rng), b = std::uniform_int_distribution<int>(0, 4)(rng) == 0 ? a : special(rng);
  if (b < a) std::swap(a, b);
  if (a == kInf) a = 0.0;
  if (b == -kInf) b = 0.0;
  return Interval(a, b);
}

// Times from a start near 0 by steps of mixed magnitudes: t[k+1] - t[k] is
// often inexact (not so between close times), so the two roundings of the
// width differ.
std::vector<double> random_times(std::mt19937_64& rng, std::size_t n) {
  std::uniform_int_distribution<int> e(-60, 20);
  std::vector<double> t{std::ldexp(std::uniform_real_distribution<double>(-2, 2)(rng), e(rng))};
  for (std::size_t k = 0; k < n; ++k) {
    const double next = t.back() + std::ldexp(std::uniform_real_distribution<double>(1, 2)(rng), e(rng));
    t.push_back(next > t.back() ? next : std::nextafter(t.back(), kInf));
  }
  return t;
}

// δ[v] of slice k by the scalar rule (scale and width of slice_deriv.h).
void scalar_scale(const std::vector<double>& t, const std::vector<Interval>& v, std::size_t k, double& plo,
                  double& phi) {
  detail::scale<detail::SoftRounding>(v[k].lb(), v[k].ub(), detail::width<detail::SoftRounding>(t[k], t[k + 1]), plo,
                                      phi);
}

bool same_bits(double x, double y) { return std::bit_cast<std::uint64_t>(x) == std::bit_cast<std::uint64_t>(y); }

bool same_bits(const Interval& x, const Interval& y) {
  return std::bit_cast<std::uint64_t>(x.lb()) == std::bit_cast<std::uint64_t>(y.lb()) &&
         std::bit_cast<std::uint64_t>(x.ub()) == std::bit_cast<std::uint64_t>(y.ub());
}

// Slices first .. first+n-1 (n a multiple of 4) of random arrays: times,
// slices, gates and derivative bounds.
struct Block {
  std::size_t first, n;
  std::vector<double> t;
  std::vector<Interval> s, g, v;
};

Block random_block(std::mt19937_64& rng, int trial) {
  const std::size_t n = 4 * std::uniform_int_distribution<std::size_t>(1, 4)(rng), first = trial % 3;
  Block b{first, n, random_times(rng, first + n), std::vector<Interval>(first + n), std::vector<Interval>(first + n + 1),
          std::vector<Interval>(first + n)};
  for (auto* arr : {&b.s, &b.g, &b.v})
    for (Interval& x : *arr) x = random_interval(rng);
  return b;
}

}  // namespace

TEST(SliceRuleX4, SameBitsAsSliceHull) {
  if (!detail::avx2_rows_available()) GTEST_SKIP() << "no AVX2";
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 20000; ++trial) {
    auto [first, n, t, s, g, v] = random_block(rng, trial);
    if (trial % 2) {  // unknown slices, where the hull alone gives the bounds
      for (Interval& x : s) x = Interval();
    }
    std::vector<Interval> wide = s, one = s;
    detail::polygon_hulls_x4(t.data(), wide.data(), g.data(), v.data(), first, n);
    bool changed = false;
    for (std::size_t k = first; k < first + n; ++k) {
      double slo = one[k].lb(), shi = one[k].ub();
      detail::slice_hull<detail::SoftRounding>(t[k], t[k + 1], g[k].lb(), g[k].ub(), g[k + 1].lb(), g[k + 1].ub(),
                                               v[k].lb(), v[k].ub(), slo, shi);
      // The slice may empty (bounds crossed): compare the raw bounds.
      const Interval r = Interval::from_bounds_unchecked(slo, shi);
      changed |= !same_bits(r, s[k]);
      ASSERT_TRUE(same_bits(wide[k], r)) << "trial " << trial << " slice " << k << ": " << wide[k].lb() << " "
                                         << wide[k].ub() << " against " << slo << " " << shi;
    }
    for (std::size_t k = 0; k < first; ++k) ASSERT_TRUE(same_bits(wide[k], s[k]));  // outside the range: untouched
    std::vector<Interval> again = s;
    ASSERT_EQ(detail::polygon_hulls_x4(t.data(), again.data(), g.data(), v.data(), first, n) != 0, changed) << trial;
  }
}

// CtcEval's hull bounds (polygon_hull<SoftRounding, false>, gates not
// consistent) against the scalar rule, on the same adversarial bounds.
TEST(SliceRuleX4, BoundsSameBitsAsPolygonHull) {
  if (!detail::avx2_rows_available()) GTEST_SKIP() << "no AVX2";
  std::mt19937_64 rng(4);
  for (int trial = 0; trial < 20000; ++trial) {
    const auto [first, n, t, s, g, v] = random_block(rng, trial);
    std::vector<double> lo(n), up(n);
    detail::polygon_hull_bounds_x4(t.data(), g.data(), v.data(), first, n, lo.data(), up.data());
    for (std::size_t k = first; k < first + n; ++k) {
      double plo, phi, l, u;
      scalar_scale(t, v, k, plo, phi);
      detail::polygon_hull<detail::SoftRounding, false>(g[k].lb(), g[k].ub(), g[k + 1].lb(), g[k + 1].ub(),
                                                        v[k].lb(), v[k].ub(), plo, phi,
                                                        detail::straddles(v[k].lb(), v[k].ub()), l, u);
      ASSERT_TRUE(same_bits(lo[k - first], l) && same_bits(up[k - first], u)) << trial << " " << k;
    }
  }
}

TEST(SliceRuleX4, ScaledDerivativesSameBitsAsScale) {
  if (!detail::avx2_rows_available()) GTEST_SKIP() << "no AVX2";
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 20000; ++trial) {
    const auto [first, n, t, s, g, v] = random_block(rng, trial);
    std::vector<double> plo(n), phi(n);
    detail::scaled_derivatives_x4(t.data(), v.data(), first, n, plo.data(), phi.data());
    for (std::size_t k = first; k < first + n; ++k) {
      double l, u;
      scalar_scale(t, v, k, l, u);
      ASSERT_TRUE(same_bits(plo[k - first], l) && same_bits(phi[k - first], u)) << trial << " " << k;
    }
  }
}
