#pragma once
// Helpers of the ctc tests: random boxes around a known point, and the
// correctly rounded enclosure of a real value computed by MPFR.
#include <mpfr.h>

#include <cmath>
#include <limits>
#include <random>

#include "sillage/interval/interval_vector.h"

namespace sillage::test {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// A random interval containing [lo, hi]: each side widened by 0, a tiny, a
// small, a large or an infinite amount.
inline Interval random_around(double lo, double hi, std::mt19937_64& rng) {
  static const double widths[] = {0.0, 1e-9, 0.25, 1.0, 10.0, kInf};
  std::uniform_int_distribution<int> pick(0, 5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto grow = [&](int k) { return widths[k] == kInf ? kInf : widths[k] * u(rng); };
  double a = lo - grow(pick(rng)), b = hi + grow(pick(rng));
  if (std::isnan(a) || a == kInf) a = lo;
  if (std::isnan(b) || b == -kInf) b = hi;
  return Interval(a, b);
}

inline Interval random_around(double x, std::mt19937_64& rng) { return random_around(x, x, rng); }

// [RD(v), RU(v)] for the exact real v = op(x) (or op(x, y)) computed by MPFR.
template <class F>
Interval mpfr_enclosure(F op) {
  mpfr_t r, a, b;
  mpfr_inits2(200, r, a, b, static_cast<mpfr_ptr>(nullptr));
  op(r, a, b, MPFR_RNDD);
  const double lo = mpfr_get_d(r, MPFR_RNDD);
  op(r, a, b, MPFR_RNDU);
  const double hi = mpfr_get_d(r, MPFR_RNDU);
  mpfr_clears(r, a, b, static_cast<mpfr_ptr>(nullptr));
  return Interval::from_bounds_unchecked(lo, hi);
}

}  // namespace sillage::test
