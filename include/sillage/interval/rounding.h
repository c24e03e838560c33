#pragma once
// Directed rounding without touching the FPU mode.
//
// Every function here computes in round-to-nearest and recovers the exactly
// rounded downward (_down) or upward (_up) result from the sign of the exact
// rounding error, obtained by error-free transformations: Fast2Sum for + and -,
// an fma residual for *, / and sqrt. Where the residual could underflow (tiny
// results) the operands are rescaled by powers of two, which is exact, so the
// results stay optimal in the whole binary64 range, subnormals included.
//
// Every public header reaches this one. Fast-math is refused: reassociation
// and dropped error terms defeat the error-free transformations (a consumer
// would get Interval(0.1) + Interval(0.2) excluding the exact sum), and
// finite-math-only drops the infinite bounds of unbounded and empty sets.
#if defined(__FAST_MATH__)
#error "sillage: -ffast-math breaks guaranteed enclosures; build code that includes sillage with -fno-fast-math"
#endif
#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error "sillage: -ffinite-math-only breaks guaranteed enclosures (infinite bounds); use -fno-finite-math-only"
#endif

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace sillage::rounding {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kMax = std::numeric_limits<double>::max();

// Next double towards +inf / -inf (identity on +inf / -inf; NaN stays NaN).
inline double next_up(double x) {
  if (x != x || x == kInf) return x;
  if (x == 0.0) return std::numeric_limits<double>::denorm_min();
  auto u = std::bit_cast<std::uint64_t>(x);
  u = x > 0 ? u + 1 : u - 1;
  return std::bit_cast<double>(u);
}

inline double next_down(double x) { return -next_up(-x); }

}  // namespace sillage::rounding

namespace sillage::detail {

// Sign (-1, 0, +1) of the exact value a*b - p, for the round-to-nearest p of a*b.
inline int mul_error_sign(double a, double b, double p) {
  if (std::fabs(p) >= 0x1p-968) {
    const double e = std::fma(a, b, -p);  // nonzero iff the product was inexact
    return (e > 0) - (e < 0);
  }
  // Tiny product: rescale so that the residual cannot underflow.
  int ea = 0, eb = 0;
  const double ma = std::frexp(a, &ea), mb = std::frexp(b, &eb);
  const double q = std::ldexp(p, -(ea + eb));  // exact: lands near [1/4, 1)
  const double e = std::fma(ma, mb, -q);
  return (e > 0) - (e < 0);
}

// Sign of the exact value a/b - q, for the round-to-nearest q of a/b (b != 0).
inline int div_error_sign(double a, double b, double q) {
  const int sb = b > 0 ? 1 : -1;
  // The remainder a - q*b is a multiple of ulp(q) ulp(b) >= 2^-1073 when
  // |a| >= 2^-968, so the fma cannot round a nonzero remainder to zero. (A
  // tiny a with a normal q, e.g. subnormal / 2^-500, needs the rescaling.)
  if (std::fabs(a) >= 0x1p-968 && std::fabs(q) >= 0x1p-968 && std::fabs(b) >= 0x1p-968 &&
      std::fabs(q) <= 0x1p1000 && std::fabs(b) <= 0x1p1000) {
    const double r = std::fma(-q, b, a);  // a - q*b, exact sign
    return ((r > 0) - (r < 0)) * sb;
  }
  int ea = 0, eb = 0;
  const double ma = std::frexp(a, &ea), mb = std::frexp(b, &eb);
  const double qs = std::ldexp(q, eb - ea);  // exact: lands near [1/2, 2]
  const double r = std::fma(-qs, mb, ma);
  return ((r > 0) - (r < 0)) * sb;
}

}  // namespace sillage::detail

namespace sillage::rounding {

// ---- addition and subtraction -------------------------------------------------

// Sign of the exact error a + b - s (s = round-to-nearest of a + b, both finite).
inline int add_error_sign(double a, double b, double s) {
  if (std::fabs(a) < std::fabs(b)) std::swap(a, b);
  const double z = s - a;  // Fast2Sum: exact since |a| >= |b|
  const double e = b - z;
  return (e > 0) - (e < 0);
}

inline double add_down(double a, double b) {
  const double s = a + b;
  if (std::isinf(s)) {
    // Overflow of two finite numbers rounds down to the largest finite double.
    return (s > 0 && std::isfinite(a) && std::isfinite(b)) ? kMax : s;
  }
  if (s != s) return s;
  return add_error_sign(a, b, s) < 0 ? next_down(s) : s;
}

// "+ 0.0" turns an exact zero into +0 (-(+0) would be -0).
inline double add_up(double a, double b) { return -add_down(-a, -b) + 0.0; }
inline double sub_down(double a, double b) { return add_down(a, -b); }
inline double sub_up(double a, double b) { return -add_down(-a, b) + 0.0; }

// ---- multiplication -------------------------------------------------------------
// A zero factor gives 0 even against an infinity: bounds of intervals are
// limits, and 0 times an unbounded set of reals is {0} (IEEE 1788).

inline double mul_down(double a, double b) {
  if (a == 0 || b == 0) return 0.0;
  const double p = a * b;
  if (std::isinf(p)) return (p > 0 && std::isfinite(a) && std::isfinite(b)) ? kMax : p;
  return detail::mul_error_sign(a, b, p) < 0 ? next_down(p) : p;
}

inline double mul_up(double a, double b) {
  if (a == 0 || b == 0) return 0.0;
  const double p = a * b;
  if (std::isinf(p)) return (p < 0 && std::isfinite(a) && std::isfinite(b)) ? -kMax : p;
  return detail::mul_error_sign(a, b, p) > 0 ? next_up(p) : p;
}

// ---- division (b != 0; a zero numerator gives 0, an infinite divisor 0) ---------

inline double div_down(double a, double b) {
  if (a == 0) return 0.0;
  const double q = a / b;
  if (std::isinf(q)) return (q > 0 && std::isfinite(a)) ? kMax : q;
  if (std::isinf(b) || std::isinf(a)) return q;
  return detail::div_error_sign(a, b, q) < 0 ? next_down(q) : q;
}

inline double div_up(double a, double b) {
  if (a == 0) return 0.0;
  const double q = a / b;
  if (std::isinf(q)) return (q < 0 && std::isfinite(a)) ? -kMax : q;
  if (std::isinf(b) || std::isinf(a)) return q;
  return detail::div_error_sign(a, b, q) > 0 ? next_up(q) : q;
}

// ---- square root (a >= 0) ---------------------------------------------------------

inline int sqrt_error_sign(double a, double s) {
  if (a >= 0x1p-968) {
    const double r = std::fma(-s, s, a);  // a - s^2
    return (r > 0) - (r < 0);
  }
  const double as = a * 0x1p600, ss = s * 0x1p300;  // both exact
  const double r = std::fma(-ss, ss, as);
  return (r > 0) - (r < 0);
}

inline double sqrt_down(double a) {
  const double s = std::sqrt(a);
  if (a == 0 || std::isinf(a)) return s;
  return sqrt_error_sign(a, s) < 0 ? next_down(s) : s;
}

inline double sqrt_up(double a) {
  const double s = std::sqrt(a);
  if (a == 0 || std::isinf(a)) return s;
  return sqrt_error_sign(a, s) > 0 ? next_up(s) : s;
}

}  // namespace sillage::rounding
