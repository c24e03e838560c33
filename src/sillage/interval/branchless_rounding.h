#pragma once
// Upward-rounded +, ×, ÷ without data-dependent branches: the branch-free
// sibling of rounding.h, for hot loops (CtcDeriv's slice rule, polygon
// hulls; internal header).
//
// Why: rounding.h decides "step to the next double or not" with a branch on
// the sign of the rounding error, which is random on real data: on a long
// sweep every other operation is a mispredicted branch (measured: 5-15x
// slower). Here the same error-free transformations feed integer masks.
//
// Results are those of rounding.h bit for bit (the exact upward-rounded
// value), except for products below 2^-968 in magnitude and quotients with
// tiny or huge operands, where the next double above the round-to-nearest
// result is returned (still an upper bound, at most one ulp above).
//
// Preconditions (they hold for bounds of non-empty intervals: an upper bound
// is never -inf, a lower bound never +inf): no operand is NaN, no operand of
// add_up / mul_up is -inf, and 0·inf is taken as 0. Violating them gives a
// meaningless value (possibly NaN), never undefined behaviour.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace sillage::detail {

inline constexpr double kMax = std::numeric_limits<double>::max();

// x, or the next double above x when step is true. With step, x must be
// finite and not -0 (x = +0 gives the smallest subnormal).
inline double next_up_if(double x, bool step) {
  const auto i = std::bit_cast<std::uint64_t>(x);
  const std::uint64_t dir = (std::uint64_t{0} - (i >> 63)) | 1u;  // +1, or -1 below zero
  const std::uint64_t mask = std::uint64_t{0} - static_cast<std::uint64_t>(step);
  return std::bit_cast<double>(i + (dir & mask));
}

// c ? a : b through bit masks: compilers turn a ternary on doubles into a
// branch when they think it predictable, which data-dependent choices are not.
inline double select(bool c, double a, double b) {
  const std::uint64_t mask = std::uint64_t{0} - static_cast<std::uint64_t>(c);
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) | (std::bit_cast<std::uint64_t>(b) & ~mask));
}

// Upper bound of a + b (a, b > -inf).
inline double add_up(double a, double b) {
  const double s = a + b;
  // Fast2Sum on the operands ordered by magnitude: e = a + b - s exactly.
  const bool a_big = std::fabs(a) >= std::fabs(b);
  const double big = a_big ? a : b, small = a_big ? b : a;
  const double e = small - (s - big);
  // e > 0 implies s finite and nonzero. A finite sum overflowing to -inf
  // rounds up to -max.
  const double r = next_up_if(s, e > 0);
  return r < -kMax ? -kMax : r;
}

inline double add_down(double a, double b) { return -add_up(-a, -b); }  // a, b < +inf
inline double sub_up(double a, double b) { return add_up(a, -b); }      // a > -inf, b < +inf
inline double sub_down(double a, double b) { return -add_up(-a, b); }   // a < +inf, b > -inf

// Upper bound of a·b (the product not -inf unless by overflow; 0·inf = 0).
inline double mul_up(double a, double b) {
  const double p = a * b + 0.0;  // + 0.0: an underflow to -0 becomes +0, a valid upper bound
  const double e = std::fma(a, b, -p);  // exact residual unless p is tiny
  const bool tiny = std::fabs(p) < 0x1p-968;
  // An overflow to -inf has e = +inf > 0: the step gives -max.
  const double r = next_up_if(p, (e > 0) | tiny);
  return (a == 0) | (b == 0) ? 0.0 : r;
}

inline double mul_down(double a, double b) { return -mul_up(-a, b); }

// Upper bound of a / b for a >= 0 finite and b > 0 finite.
inline double div_up_pos(double a, double b) {
  const double q = a / b + 0.0;  // a = -0 gives +0 (next_up_if needs it)
  const double r = std::fma(-q, b, a);  // a - q·b, exact in the safe range
  const bool safe = (a >= 0x1p-968) & (b >= 0x1p-968) & (q >= 0x1p-968) & (b <= 0x1p1000) & (q <= 0x1p1000);
  return next_up_if(q, ((r > 0) | !safe) & (q < std::numeric_limits<double>::infinity()));
}

}  // namespace sillage::detail
