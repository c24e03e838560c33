// The hulls of CtcDeriv's FWD_BWD sweep 4 slices at a time with AVX2
// (polygon_hull_x4.h) against slice_hull<SoftRounding> (slice_deriv.h) slice
// by slice, bit for bit, on adversarial bounds: infinities, zeros of both
// signs, straddling and one-signed derivatives, degenerate gates, tiny
// (subnormal) and huge magnitudes, widths from 2^-40 to 2^20.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "sillage/dynamics/polygon_hull_x4.h"
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

bool same_bits(const Interval& x, const Interval& y) {
  return std::bit_cast<std::uint64_t>(x.lb()) == std::bit_cast<std::uint64_t>(y.lb()) &&
         std::bit_cast<std::uint64_t>(x.ub()) == std::bit_cast<std::uint64_t>(y.ub());
}

}  // namespace

TEST(PolygonHullX4, SameBitsAsSliceHull) {
  if (!detail::avx2_rows_available()) GTEST_SKIP() << "no AVX2";
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 20000; ++trial) {
    const std::size_t n = 4 * std::uniform_int_distribution<std::size_t>(1, 4)(rng), first = trial % 3;
    // Steps of mixed magnitudes from a start near 0: t1 - t0 is often inexact
    // (not so between close times), so the two roundings of the width differ.
    std::uniform_int_distribution<int> e(-60, 20);
    std::vector<double> t{std::ldexp(std::uniform_real_distribution<double>(-2, 2)(rng), e(rng))};
    for (std::size_t k = 0; k < first + n; ++k) {
      const double next = t.back() + std::ldexp(std::uniform_real_distribution<double>(1, 2)(rng), e(rng));
      t.push_back(next > t.back() ? next : std::nextafter(t.back(), kInf));
    }
    std::vector<Interval> s(first + n), g(first + n + 1), v(first + n);
    for (auto* arr : {&s, &g, &v})
      for (Interval& x : *arr) x = random_interval(rng);
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
TEST(PolygonHullX4, BoundsSameBitsAsPolygonHull) {
  if (!detail::avx2_rows_available()) GTEST_SKIP() << "no AVX2";
  std::mt19937_64 rng(4);
  std::uniform_int_distribution<int> e(-60, 20);
  for (int trial = 0; trial < 20000; ++trial) {
    const std::size_t n = 4 * std::uniform_int_distribution<std::size_t>(1, 4)(rng), first = trial % 3;
    std::vector<double> t{std::ldexp(std::uniform_real_distribution<double>(-2, 2)(rng), e(rng))};
    for (std::size_t k = 0; k < first + n; ++k) {
      const double next = t.back() + std::ldexp(std::uniform_real_distribution<double>(1, 2)(rng), e(rng));
      t.push_back(next > t.back() ? next : std::nextafter(t.back(), kInf));
    }
    std::vector<Interval> g(first + n + 1), v(first + n);
    for (auto* arr : {&g, &v})
      for (Interval& x : *arr) x = random_interval(rng);
    std::vector<double> lo(n), up(n);
    detail::polygon_hull_bounds_x4(t.data(), g.data(), v.data(), first, n, lo.data(), up.data());
    for (std::size_t k = first; k < first + n; ++k) {
      double plo, phi, l, u;
      detail::scale<detail::SoftRounding>(v[k].lb(), v[k].ub(), detail::width<detail::SoftRounding>(t[k], t[k + 1]),
                                          plo, phi);
      detail::polygon_hull<detail::SoftRounding, false>(g[k].lb(), g[k].ub(), g[k + 1].lb(), g[k + 1].ub(),
                                                        v[k].lb(), v[k].ub(), plo, phi,
                                                        detail::straddles(v[k].lb(), v[k].ub()), l, u);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(lo[k - first]), std::bit_cast<std::uint64_t>(l)) << trial << " " << k;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(up[k - first]), std::bit_cast<std::uint64_t>(u)) << trial << " " << k;
    }
  }
}
