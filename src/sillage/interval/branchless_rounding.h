#pragma once
// Directed +, -, ×, ÷, √ without data-dependent branches: the branch-free
// sibling of rounding.h, for hot loops (Interval's arithmetic, CtcDeriv's
// slice rule, polygon hulls, the batch kernels). Internal header.
//
// Why: rounding.h decides "step to the next double or not" with a branch on
// the sign of the rounding error, which is random on real data: on a long
// sweep every other operation is a mispredicted branch (measured: 5-15x
// slower). Here the same error-free transformations feed integer masks.
//
// Two families:
//  - Interval's portable path (BranchFreeRounding in arith_kernels.h): the
//    exactly rounded result for every operand but NaN, outside rare ranges
//    (tiny or huge magnitudes where the residual of the error-free
//    transformation could be inexact) that the *_rare predicates here
//    report, so that the caller can fall back to rounding.h;
//  - add_up ... div_up_pos, the slice rule's: results are those of rounding.h
//    bit for bit (the exact upward-rounded value), except for products below
//    2^-968 in magnitude and quotients with tiny or huge operands, where the
//    next double above the round-to-nearest result is returned (still an
//    upper bound, at most one ulp above).
//
// Preconditions of the second family (they hold for bounds of non-empty intervals: an upper bound
// is never -inf, a lower bound never +inf): no operand is NaN, no operand of
// add_up / mul_up is -inf, and 0·inf is taken as 0. Violating them gives a
// meaningless value (possibly NaN), never undefined behaviour.
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "sillage/interval/rounding.h"

namespace sillage::detail {

// x, or the next double above x when step is true. With step, x must be
// finite and not -0 (x = +0 gives the smallest subnormal).
inline double next_up_if(double x, bool step) {
  const auto i = std::bit_cast<std::uint64_t>(x);
  const std::uint64_t dir = (std::uint64_t{0} - (i >> 63)) | 1u;  // +1, or -1 below zero
  const std::uint64_t mask = std::uint64_t{0} - static_cast<std::uint64_t>(step);
  return std::bit_cast<double>(i + (dir & mask));
}

// x, or the next double below x when step is true (x finite and not +0 with step).
inline double next_down_if(double x, bool step) { return -next_up_if(-x, step); }

// c ? a : b through bit masks: compilers turn a ternary on doubles into a
// branch when they think it predictable, which data-dependent choices are not.
inline double select(bool c, double a, double b) {
  const std::uint64_t mask = std::uint64_t{0} - static_cast<std::uint64_t>(c);
  return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) | (std::bit_cast<std::uint64_t>(b) & ~mask));
}

// min / max of two non-NaN doubles in one instruction: std::min and std::max
// on references are often compiled to branches.
inline double min_nb(double a, double b) {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_min_sd(_mm_set_sd(a), _mm_set_sd(b)));
#else
  return select(b < a, b, a);
#endif
}

inline double max_nb(double a, double b) {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_max_sd(_mm_set_sd(a), _mm_set_sd(b)));
#else
  return select(b > a, b, a);
#endif
}

// Upper bound of a + b (a, b > -inf).
inline double add_up(double a, double b) {
  const double s = a + b;
  // 2Sum (no ordering of the operands, hence no branch): e = a + b - s exactly.
  const double bv = s - a;
  const double e = (a - (s - bv)) + (b - bv);
  // e > 0 implies s finite and nonzero. A finite sum overflowing to -inf
  // (e is then NaN) rounds up to -max. The one other overflow of 2Sum: s
  // finite but bv = s - a = b + (s - (a + b)) past -max (b = -max, s rounded
  // down by half an ulp of 2^1023): e is NaN, s < a + b, so s steps up.
  const bool bv_overflowed = (bv < -rounding::kMax) & (s >= -rounding::kMax);
  return max_nb(next_up_if(s, (e > 0) | bv_overflowed), -rounding::kMax);
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

// ---- where BranchFreeRounding (arith_kernels.h) is exact ----
// The residual of an fma is exact while the result stays above 2^-968 in
// magnitude (and, for ÷, the operands and quotient within [2^-968, 2^1000]):
// the step to the next double then follows the exact sign of the error.
// Infinite results and operands give a NaN residual, hence no step: they are
// exact already (an overflow is reported rare).

// a·b may be inexactly rounded by BranchFreeRounding: tiny nonzero product.
inline bool mul_rare(double a, double b) { return (std::fabs(a * b) < 0x1p-968) & (a != 0) & (b != 0); }

// a / b may be inexactly rounded by BranchFreeRounding: finite nonzero
// operands with an operand or the quotient outside [2^-968, 2^1000].
inline bool div_rare(double a, double b) {
  const double fa = std::fabs(a), fb = std::fabs(b), fq = std::fabs(a / b);
  const double inf = std::numeric_limits<double>::infinity();
  const bool finite_nonzero = (fa > 0) & (fa < inf) & (fb > 0) & (fb < inf);
  const bool safe = (fa >= 0x1p-968) & (fb >= 0x1p-968) & (fb <= 0x1p1000) & (fq >= 0x1p-968) & (fq <= 0x1p1000);
  return finite_nonzero & !safe;
}

// sqrt(a) may be inexactly rounded by BranchFreeRounding: tiny positive a.
inline bool sqrt_rare(double a) { return (a > 0) & (a < 0x1p-968); }

}  // namespace sillage::detail
