#pragma once
// Operands for bit-for-bit tests of the interval arithmetic: every interval
// over a list of special bounds (zeros, subnormals, the 2^-968 limit of the
// portable path, huge, max, infinities) and the empty set; random intervals
// over the whole binary64 range.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "sillage/interval/interval.h"

namespace sillage::test {

inline std::vector<Interval> adversarial_intervals() {
  const double inf = rounding::kInf, max = rounding::kMax, tiny = std::numeric_limits<double>::denorm_min();
  const std::vector<double> v = {
      -inf, -max, -1e308, -0x1p1000, -3.0, -1.0, -0.1, -0x1.8p-968, -0x1p-968, -0x1p-1000,
      -std::numeric_limits<double>::min(), -tiny, 0.0, tiny, 3 * tiny, std::numeric_limits<double>::min(),
      0x1p-1000, 0x1p-969, 0x1p-968, 0x1p-484, 0x1p-500, 0.1, 1.0, 1.0 + 0x1p-52, 3.0, 0x1p512, 0x1p1000,
      1e308, max, inf,
      // ∓max plus these rounds to nearest by half an ulp of 2^1023 toward ∓max, so that the
      // 2Sum's s - a overflows while the sum does not.
      0x1.0000000000003p+1022, -0x1.0000000000003p+1022};
  std::vector<Interval> r = {Interval::empty()};
  for (double a : v)
    for (double b : v)
      if (a <= b && a < inf && b > -inf) r.push_back(Interval(a, b));
  return r;
}

// Random bounds: any binade, both signs, some zeros and infinities; about
// one interval in 20 empty.
inline std::vector<Interval> random_intervals(std::size_t n, std::uint64_t seed = 20261124) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> kind(0, 19), expo(-1074, 1023);
  std::uniform_real_distribution<double> m(1.0, 2.0);
  auto bound = [&]() -> double {
    const int k = kind(rng);
    if (k == 0) return 0.0;
    if (k == 1) return (rng() & 1) ? rounding::kInf : -rounding::kInf;
    const double x = std::ldexp(m(rng), k < 10 ? expo(rng) : expo(rng) / 30);
    return (rng() & 1) ? -x : x;
  };
  std::vector<Interval> r;
  while (r.size() < n) {
    double a = bound(), b = bound();
    if (a > b) std::swap(a, b);
    if (kind(rng) == 0) r.push_back(Interval::empty());
    else if (a < rounding::kInf && b > -rounding::kInf) r.push_back(Interval(a, b));
  }
  return r;
}

}  // namespace sillage::test
