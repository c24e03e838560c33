#pragma once
// The bounds of x + y, x - y, x·y, x / y, x², √x (IEEE 1788 set semantics,
// optimal: the exactly rounded bounds) without data-dependent branches, over
// a rounding policy R; Interval's operators choose R once per process
// (hardware_rounding.h). Empty is [+inf, -inf] in and out.
//
// A policy provides add/sub/mul/div/sqrt _down/_up on doubles with directed
// rounding (mul may give NaN for 0·inf, taken as 0 here) and the *_rare
// predicates: where one is true, its results may be off by one ulp and the
// kernel starts over with ScalarRounding (rounding.h, exact everywhere, with
// branches). HardRounding and ScalarRounding have no rare case; the
// branch-free software policy has them only for magnitudes beyond 2^±968.
//
// The case analyses on signs are selections: × takes the min / max of the
// four corner products, ÷ picks the numerator and denominator of each bound
// from the signs (two divisions), x² uses mig(x)² and mag(x)².
#include <algorithm>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "sillage/interval/branchless_rounding.h"
#include "sillage/interval/hardware_rounding.h"
#include "sillage/interval/rounding.h"

namespace sillage::detail {

// The branch-free software policy: error-free transformations and masks.
struct BranchFreeRounding {
  static double add_up(double a, double b) { return detail::add_up(a, b); }
  static double add_down(double a, double b) { return detail::add_down(a, b); }
  static double sub_up(double a, double b) { return detail::sub_up(a, b); }
  static double sub_down(double a, double b) { return detail::sub_down(a, b); }
  static double mul_up_nz(double a, double b) { return mul_up_exact(a, b); }
  static double mul_down_nz(double a, double b) { return mul_down_exact(a, b); }
  static double div_up(double a, double b) { return div_up_exact(a, b); }
  static double div_down(double a, double b) { return div_down_exact(a, b); }
  static double sqrt_up(double a) { return sqrt_up_exact(a); }
  static double sqrt_down(double a) { return sqrt_down_exact(a); }
  static constexpr bool kHasRareCases = true;
  static bool mul_rare(double a, double b) { return detail::mul_rare(a, b); }
  static bool div_rare(double a, double b) { return detail::div_rare(a, b); }
  static bool sqrt_rare(double a) { return detail::sqrt_rare(a); }
};

// rounding.h: exact for every operand, branches on the rounding error; the
// fallback of the rare cases.
struct ScalarRounding {
  static double add_up(double a, double b) { return rounding::add_up(a, b); }
  static double add_down(double a, double b) { return rounding::add_down(a, b); }
  static double sub_up(double a, double b) { return rounding::sub_up(a, b); }
  static double sub_down(double a, double b) { return rounding::sub_down(a, b); }
  static double mul_up_nz(double a, double b) { return rounding::mul_up(a, b); }
  static double mul_down_nz(double a, double b) { return rounding::mul_down(a, b); }
  static double div_up(double a, double b) { return rounding::div_up(a, b); }
  static double div_down(double a, double b) { return rounding::div_down(a, b); }
  static double sqrt_up(double a) { return rounding::sqrt_up(a); }
  static double sqrt_down(double a) { return rounding::sqrt_down(a); }
  static constexpr bool kHasRareCases = false;
  static bool mul_rare(double, double) { return false; }
  static bool div_rare(double, double) { return false; }
  static bool sqrt_rare(double) { return false; }
};

struct BoundPair {
  double lo, hi;
};

// The kernels over ScalarRounding, out of line: the cold fallback of the
// rare cases stays out of the inlined hot path (arith_fallback.cpp).
BoundPair mul_bounds_scalar(double a, double b, double c, double d);
BoundPair div_bounds_scalar(double a, double b, double c, double d);
BoundPair sqr_bounds_scalar(double a, double b);
BoundPair sqrt_bounds_scalar(double a, double b);

// Not a set: [+inf, -inf] and every other lo > hi.
inline bool no_set(double lo, double hi) { return !(lo <= hi); }

// The result, or the empty set; "+ 0.0" turns a -0 bound into +0 (x + (-x)
// rounds to -0 downward, 0 / -3 is -0).
inline BoundPair bounds_or_empty(bool empty, double lo, double hi) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return {select(empty, inf, lo + 0.0), select(empty, -inf, hi + 0.0)};
}

// A corner product: 0·inf is NaN in IEEE arithmetic and 0 for bounds (limits).
// (SSE2: a mask from an unordered compare, so no branch on the data.)
inline double corner(double p) {
#if defined(__SSE2__)
  const __m128d v = _mm_set_sd(p);
  return _mm_cvtsd_f64(_mm_and_pd(_mm_cmpord_sd(v, v), v));
#else
  return select(p == p, p, 0.0);
#endif
}

template <class R>
[[gnu::always_inline]] inline BoundPair add_bounds(double a, double b, double c, double d) {
  return bounds_or_empty(no_set(a, b) | no_set(c, d), R::add_down(a, c), R::add_up(b, d));
}

template <class R>
[[gnu::always_inline]] inline BoundPair sub_bounds(double a, double b, double c, double d) {
  return bounds_or_empty(no_set(a, b) | no_set(c, d), R::sub_down(a, d), R::sub_up(b, c));
}

template <class R>
[[gnu::always_inline]] inline BoundPair mul_bounds(double a, double b, double c, double d) {
  if constexpr (R::kHasRareCases) {
    if (R::mul_rare(a, c) | R::mul_rare(a, d) | R::mul_rare(b, c) | R::mul_rare(b, d)) [[unlikely]] {
      return mul_bounds_scalar(a, b, c, d);
    }
  }
  const double lo = min_nb(min_nb(corner(R::mul_down_nz(a, c)), corner(R::mul_down_nz(a, d))),
                          min_nb(corner(R::mul_down_nz(b, c)), corner(R::mul_down_nz(b, d))));
  const double hi = max_nb(max_nb(corner(R::mul_up_nz(a, c)), corner(R::mul_up_nz(a, d))),
                          max_nb(corner(R::mul_up_nz(b, c)), corner(R::mul_up_nz(b, d))));
  return bounds_or_empty(no_set(a, b) | no_set(c, d), lo, hi);
}

// x / y for x = [a, b], y = [c, d] (2.19)-(2.20). With y >= 0 (c = 0 as the
// limit +0): lo = a / (a >= 0 ? d : c), hi = b / (b > 0 ? c : d); with y <= 0
// (d = 0 as the limit -0): lo = b / (b > 0 ? d : c), hi = a / (a >= 0 ? c : d).
// A zero bound of y then gives the infinite bound by IEEE division. y
// straddling 0 gives the whole line (or [0, 0] when x = [0, 0]); y = [0, 0]
// gives the empty set.
template <class R>
[[gnu::always_inline]] inline BoundPair div_bounds(double a, double b, double c, double d) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  c += 0.0;                                   // the limit from above 0: +0
  const double dn = select(d == 0, -0.0, d);  // the limit from below 0: -0
  const bool pos = c >= 0;
  const double lo_num = select(pos, a, b), hi_num = select(pos, b, a);
  const double lo_den = select(pos, select(a >= 0, d, c), select(b > 0, dn, c));
  const double hi_den = select(pos, select(b > 0, c, d), select(a >= 0, c, dn));
  if constexpr (R::kHasRareCases) {
    if (R::div_rare(lo_num, lo_den) | R::div_rare(hi_num, hi_den)) [[unlikely]] {
      return div_bounds_scalar(a, b, c, d);
    }
  }
  double lo = R::div_down(lo_num, lo_den), hi = R::div_up(hi_num, hi_den);
  const bool straddles = (c < 0) & (d > 0), x_zero = (a == 0) & (b == 0);
  lo = select(straddles, select(x_zero, 0.0, -inf), lo);
  hi = select(straddles, select(x_zero, 0.0, inf), hi);
  return bounds_or_empty(no_set(a, b) | no_set(c, d) | ((c == 0) & (d == 0)), lo, hi);
}

// x² from mig(x) = max(a, -b, 0) and mag(x) = max(-a, b).
template <class R>
[[gnu::always_inline]] inline BoundPair sqr_bounds(double a, double b) {
  const double mig = max_nb(max_nb(a, -b), 0.0), mag = max_nb(-a, b);
  if constexpr (R::kHasRareCases) {
    if (R::mul_rare(mig, mig) | R::mul_rare(mag, mag)) [[unlikely]] return sqr_bounds_scalar(a, b);
  }
  return bounds_or_empty(no_set(a, b), R::mul_down_nz(mig, mig), R::mul_up_nz(mag, mag));
}

// √ of the part of x above 0.
template <class R>
[[gnu::always_inline]] inline BoundPair sqrt_bounds(double a, double b) {
  const double a0 = max_nb(a, 0.0);
  if constexpr (R::kHasRareCases) {
    if (R::sqrt_rare(a0) | R::sqrt_rare(b)) [[unlikely]] return sqrt_bounds_scalar(a, b);
  }
  return bounds_or_empty(no_set(a, b) | (b < 0), R::sqrt_down(a0), R::sqrt_up(b));
}

// f(R{}) with the policy chosen for this process.
template <class F>
[[gnu::always_inline]] inline BoundPair with_rounding(F f) {
#if SILLAGE_HARD_ROUNDING
  if (use_hardware_rounding()) return f(HardRounding{});
#endif
  return f(BranchFreeRounding{});
}

}  // namespace sillage::detail
