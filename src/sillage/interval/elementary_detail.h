#pragma once
// Private helpers of the elementary functions (not installed API).
//
// Bounds from libm: glibc 2.36 documents, per function, its largest known
// error e (manual, "Errors in Math Functions", x86_64, double): 1 ulp for exp,
// log, sin, cos, tan, asin, acos, atan, atan2, pow; 2 for sinh, cosh, tanh.
// That error is measured against the correctly rounded result r, so the exact
// y lies within e ulp(r) + ulp(r)/2 of the libm value f. widen_down/widen_up
// step one double more than e; where r may sit in the next binade up (ulps
// twice as large) they step 2e + 1. The MPFR sweeps (tests/cpp/interval/
// test_mpfr_*.cpp) check these bounds; the one place where glibc exceeds them,
// sin/cos/tan next to a multiple of pi/2, goes through trig_reduce instead.
#include <bit>
#include <cmath>
#include <cstdint>

#include "sillage/interval/interval.h"

namespace sillage::detail {

inline constexpr int kUlpsBasic = 1;   // exp, log, sin, cos, asin, acos, atan, atan2
inline constexpr int kUlpsTanPow = 1;  // tan, pow
inline constexpr int kUlpsHyp = 2;     // sinh, cosh, tanh

inline constexpr double kInf = rounding::kInf;
inline constexpr double kMax = rounding::kMax;

// Rigorous enclosures of pi/2, pi, 2pi (consecutive doubles around them).
inline constexpr double kHalfPiLo = 0x1.921fb54442d18p+0, kHalfPiHi = 0x1.921fb54442d19p+0;
inline constexpr double kPiLo = 0x1.921fb54442d18p+1, kPiHi = 0x1.921fb54442d19p+1;
inline constexpr double kTwoPiLo = 0x1.921fb54442d18p+2, kTwoPiHi = 0x1.921fb54442d19p+2;

// Magnitude of a finite nonzero double f, e + 1 doubles further from zero, as
// raw bits; 2e + 1 if f is within 2e doubles of the next binade, where the
// correctly rounded r may lie (then r <= f + 2e ulp(f) and one ulp(r) above r
// is 2e + 1 doubles from f at most). At or past the bits of +inf means +inf.
inline std::uint64_t grow_bits(std::uint64_t mag, int e) {
  const auto e2 = 2 * static_cast<std::uint64_t>(e);
  const std::uint64_t r = ((mag + e2) >> 52) != (mag >> 52) ? mag + e2 + 1 : mag + static_cast<std::uint64_t>(e) + 1;
  return r >= 0x7ff0000000000000ULL ? 0x7ff0000000000000ULL : r;
}

// A lower bound of the exact y from a libm value v within e ulps of round(y)
// (+inf is a valid v: overflow).
inline double widen_down(double v, int e) {
  const auto u = std::bit_cast<std::uint64_t>(v);
  const std::uint64_t mag = u & 0x7fffffffffffffffULL;
  const auto k = static_cast<std::uint64_t>(e) + 1;
  if (v > 0 && mag > k) return std::bit_cast<double>(u - k);  // towards zero: e + 1 doubles
  if (v < 0) return std::bit_cast<double>(grow_bits(mag, e) | 0x8000000000000000ULL);
  if (v != v) return v;
  for (std::uint64_t i = 0; i < k; ++i) v = rounding::next_down(v);  // crosses zero
  return v;
}

inline double widen_up(double v, int e) { return -widen_down(-v, e); }

// For a double v > 0: k doubles down (0 if that passes zero) or up (at most +inf).
inline double step_down_pos(double v, std::uint64_t k) {
  const auto u = std::bit_cast<std::uint64_t>(v);
  return u > k ? std::bit_cast<double>(u - k) : 0.0;
}
inline double step_up_pos(double v, std::uint64_t k) {
  const auto u = std::bit_cast<std::uint64_t>(v);
  return u + k >= 0x7ff0000000000000ULL ? kInf : std::bit_cast<double>(u + k);
}

// Interval from bounds known to be ordered and valid.
inline Interval make(double lo, double hi) { return Interval::from_bounds_unchecked(lo + 0.0, hi + 0.0); }

}  // namespace sillage::detail
