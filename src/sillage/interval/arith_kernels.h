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
// The case analyses on signs are selections on SSE masks (Mask below): ×
// picks, for each bound of x, the bound of y that minimises (maximises) the
// product from its sign (four products, one min, one max), ÷ picks the
// numerator and denominator of each bound from the signs (two divisions), x²
// uses mig(x)² and mag(x)².
#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#if defined(__SSE4_1__)
#include <smmintrin.h>
#elif defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "sillage/interval/branchless_rounding.h"
#include "sillage/interval/hard_pair_lanes.h"
#include "sillage/interval/hardware_rounding.h"
#include "sillage/interval/pair_lanes.h"
#include "sillage/interval/rounding.h"

namespace sillage::detail {

// The truth value of a comparison of doubles, kept in an SSE register (all
// ones or all zeros) so that a choice made on it is a blend: a bool would
// travel through the integer registers and back (measured: ÷ 2.5 times slower).
#if defined(__SSE2__)
struct Mask {
  __m128d m;
};
inline Mask operator&(Mask x, Mask y) { return {_mm_and_pd(x.m, y.m)}; }
inline Mask operator|(Mask x, Mask y) { return {_mm_or_pd(x.m, y.m)}; }
inline Mask lt(double a, double b) { return {_mm_cmplt_sd(_mm_set_sd(a), _mm_set_sd(b))}; }
inline Mask le(double a, double b) { return {_mm_cmple_sd(_mm_set_sd(a), _mm_set_sd(b))}; }
inline Mask eq(double a, double b) { return {_mm_cmpeq_sd(_mm_set_sd(a), _mm_set_sd(b))}; }
// !(a <= b): also true when a or b is NaN.
inline Mask not_le(double a, double b) { return {_mm_cmpnle_sd(_mm_set_sd(a), _mm_set_sd(b))}; }
// c ? a : b.
inline double select(Mask c, double a, double b) {
#if defined(__SSE4_1__)
  return _mm_cvtsd_f64(_mm_blendv_pd(_mm_set_sd(b), _mm_set_sd(a), c.m));
#else
  return _mm_cvtsd_f64(_mm_or_pd(_mm_and_pd(c.m, _mm_set_sd(a)), _mm_andnot_pd(c.m, _mm_set_sd(b))));
#endif
}
#else
struct Mask {
  bool m;
};
inline Mask operator&(Mask x, Mask y) { return {x.m & y.m}; }
inline Mask operator|(Mask x, Mask y) { return {x.m | y.m}; }
inline Mask lt(double a, double b) { return {a < b}; }
inline Mask le(double a, double b) { return {a <= b}; }
inline Mask eq(double a, double b) { return {a == b}; }
inline Mask not_le(double a, double b) { return {!(a <= b)}; }
inline double select(Mask c, double a, double b) { return select(c.m, a, b); }
#endif
inline Mask gt(double a, double b) { return lt(b, a); }
inline Mask ge(double a, double b) { return le(b, a); }

// p, or the next double above (below) p where m is set; p finite and, where
// m is set, not -0 (not +0): next_up_if / next_down_if on masks, the bits of
// p incremented or decremented in the SSE register.
#if defined(__SSE4_1__)
inline double step_up(double p, Mask m) {
  const __m128i i = _mm_castpd_si128(_mm_set_sd(p)), s = _mm_castpd_si128(m.m);  // s: -1 or 0
  const __m128d away = _mm_castsi128_pd(_mm_sub_epi64(i, s)), toward = _mm_castsi128_pd(_mm_add_epi64(i, s));
  return _mm_cvtsd_f64(_mm_blendv_pd(away, toward, _mm_set_sd(p)));  // below 0, up is toward 0
}
inline double step_down(double p, Mask m) {
  const __m128i i = _mm_castpd_si128(_mm_set_sd(p)), s = _mm_castpd_si128(m.m);
  const __m128d away = _mm_castsi128_pd(_mm_sub_epi64(i, s)), toward = _mm_castsi128_pd(_mm_add_epi64(i, s));
  return _mm_cvtsd_f64(_mm_blendv_pd(toward, away, _mm_set_sd(p)));
}
#elif defined(__SSE2__)
inline double step_up(double p, Mask m) { return next_up_if(p, _mm_cvtsd_f64(m.m) != 0); }
inline double step_down(double p, Mask m) { return next_down_if(p, _mm_cvtsd_f64(m.m) != 0); }
#else
inline double step_up(double p, Mask m) { return next_up_if(p, m.m); }
inline double step_down(double p, Mask m) { return next_down_if(p, m.m); }
#endif

// The branch-free software policy: error-free transformations and masks.
struct BranchFreeRounding {
  static double add_up(double a, double b) { return detail::add_up(a, b); }
  static double add_down(double a, double b) { return detail::add_down(a, b); }
  static double sub_up(double a, double b) { return detail::sub_up(a, b); }
  static double sub_down(double a, double b) { return detail::sub_down(a, b); }
  // p rounded to nearest, the exact error by an fma, one step on a mask; exact
  // except for the operands the *_rare predicates report.
  static double mul_up_nz(double a, double b) {
    const double p = a * b;
    return step_up(p, gt(std::fma(a, b, -p), 0.0));
  }
  static double mul_down_nz(double a, double b) {
    const double p = a * b;
    return step_down(p, lt(std::fma(a, b, -p), 0.0));
  }
  // a - q·b has the sign of (a/b - q)·b.
  static double div_up(double a, double b) {
    const double q = a / b, r = std::fma(-q, b, a);
    return step_up(q, (gt(r, 0.0) & gt(b, 0.0)) | (lt(r, 0.0) & lt(b, 0.0)));
  }
  static double div_down(double a, double b) {
    const double q = a / b, r = std::fma(-q, b, a);
    return step_down(q, (lt(r, 0.0) & gt(b, 0.0)) | (gt(r, 0.0) & lt(b, 0.0)));
  }
  static double sqrt_up(double a) {
    const double s = std::sqrt(a);
    return step_up(s, gt(std::fma(-s, s, a), 0.0));
  }
  static double sqrt_down(double a) {
    const double s = std::sqrt(a);
    return step_down(s, lt(std::fma(-s, s, a), 0.0));
  }
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
inline Mask no_set(double lo, double hi) { return not_le(lo, hi); }

// The result, or the empty set; "+ 0.0" turns a -0 bound into +0 (x + (-x)
// rounds to -0 downward, 0 / -3 is -0).
inline BoundPair bounds_or_empty(Mask empty, double lo, double hi) {
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

// Both paths compute +, -, ×, ÷ on both bounds at once (pair_lanes.h,
// hard_pair_lanes.h): the kernels below then hold a second, packed body under
// `if constexpr`, over the lanes Lanes<R> of the policy.
template <class R>
struct LanesOf {
  using type = void;
};
#if SILLAGE_PAIR_LANES
template <>
struct LanesOf<BranchFreeRounding> {
  using type = PairLanes;
};
#endif
#if SILLAGE_HARD_PAIR_LANES
template <>
struct LanesOf<HardRounding> {
  using type = HardPairLanes;
};
#endif
template <class R>
using Lanes = typename LanesOf<R>::type;
template <class R>
inline constexpr bool kPairLanes = !std::is_void_v<Lanes<R>>;
// x² and √ on the portable path only: the hardware's two scalar instructions
// are faster for x² (2.0 against 2.4 ns) and √ rounds its bounds apart.
template <class R>
inline constexpr bool kSoftPairLanes = SILLAGE_PAIR_LANES && std::is_same_v<R, BranchFreeRounding>;

#if SILLAGE_PAIR_LANES
// x = [a, b] or y = [c, d] not a set, in both lanes.
inline PairLanes::P pair_no_set(double a, double b, double c, double d) {
  return PairLanes::either(_mm_cmpnle_pd(PairLanes::make(a, c), PairLanes::make(b, d)));
}

// bounds_or_empty for r = [-lo, hi].
inline BoundPair pair_bounds_or_empty(PairLanes::P empty, PairLanes::P r) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  using L = PairLanes;
  const L::P v = L::select(empty, L::make(inf, -inf), _mm_add_pd(L::neg0(r), L::both(0.0)));
  return {L::lane0(v), L::lane1(v)};
}
#endif

template <class R>
[[gnu::always_inline]] inline BoundPair add_bounds(double a, double b, double c, double d) {
#if SILLAGE_PAIR_LANES
  if constexpr (kPairLanes<R>) {  // [-lo, hi] = [-a, b] + [-c, d], upward
    using L = Lanes<R>;
    return pair_bounds_or_empty(pair_no_set(a, b, c, d), L::add_up(L::make(-a, b), L::make(-c, d)));
  }
#endif
  return bounds_or_empty(no_set(a, b) | no_set(c, d), R::add_down(a, c), R::add_up(b, d));
}

template <class R>
[[gnu::always_inline]] inline BoundPair sub_bounds(double a, double b, double c, double d) {
#if SILLAGE_PAIR_LANES
  if constexpr (kPairLanes<R>) {  // [-lo, hi] = [-a, b] + [d, -c], upward
    using L = Lanes<R>;
    return pair_bounds_or_empty(pair_no_set(a, b, c, d), L::add_up(L::make(-a, b), L::make(d, -c)));
  }
#endif
  return bounds_or_empty(no_set(a, b) | no_set(c, d), R::sub_down(a, d), R::sub_up(b, c));
}

// x·y for x = [a, b], y = [c, d]. For a fixed u, min {u·v : v in y} is u·c
// if u >= 0, else u·d (and max the other one); that minimum is concave in u
// (the maximum convex), so over x it is reached at u = a or u = b: two
// products per bound instead of four. A zero u gives 0 whichever v.
template <class R>
[[gnu::always_inline]] inline BoundPair mul_bounds(double a, double b, double c, double d) {
#if SILLAGE_PAIR_LANES
  if constexpr (kPairLanes<R>) {
    // [-a·a_lo, a·a_hi] and [-b·b_lo, b·b_hi] upward, then the larger of each lane.
    using L = Lanes<R>;
    using P = typename L::P;
    const P cd = L::make(c, d), dc = L::swap(cd);
    const P xa = L::make(-a, a), ya = L::select(L::le(L::both(0.0), L::both(a)), cd, dc);
    const P xb = L::make(-b, b), yb = L::select(L::le(L::both(0.0), L::both(b)), cd, dc);
    if (L::mul_rare(xa, ya) | L::mul_rare(xb, yb)) [[unlikely]] return mul_bounds_scalar(a, b, c, d);
    return pair_bounds_or_empty(pair_no_set(a, b, c, d), _mm_max_pd(L::mul_up(xa, ya), L::mul_up(xb, yb)));
  }
#endif
  const Mask a_nn = ge(a, 0.0), b_nn = ge(b, 0.0);
  const double a_lo = select(a_nn, c, d), a_hi = select(a_nn, d, c);
  const double b_lo = select(b_nn, c, d), b_hi = select(b_nn, d, c);
  if constexpr (R::kHasRareCases) {
    if (R::mul_rare(a, a_lo) | R::mul_rare(a, a_hi) | R::mul_rare(b, b_lo) | R::mul_rare(b, b_hi)) [[unlikely]] {
      return mul_bounds_scalar(a, b, c, d);
    }
  }
  const double lo = min_nb(corner(R::mul_down_nz(a, a_lo)), corner(R::mul_down_nz(b, b_lo)));
  const double hi = max_nb(corner(R::mul_up_nz(a, a_hi)), corner(R::mul_up_nz(b, b_hi)));
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
  const double dn = select(eq(d, 0.0), -0.0, d);  // the limit from below 0: -0
#if SILLAGE_PAIR_LANES
  if constexpr (kPairLanes<R>) {
    // Lane 0 the lower bound, lane 1 the upper one: the numerators [a, b]
    // (swapped for y <= 0) and s = [lo_num >= 0, hi_num > 0] (tested as
    // >= the smallest subnormal) choose the denominators of the scalar body.
    using L = Lanes<R>;
    using P = typename L::P;
    constexpr double tiny = std::numeric_limits<double>::denorm_min();
    const P pos = L::le(L::both(0.0), L::both(c));
    const P num = L::select(pos, L::make(a, b), L::make(b, a));
    const P s = L::le(L::select(pos, L::make(0.0, tiny), L::make(tiny, 0.0)), num);
    const P den = L::select(s, L::make(dn, c), L::make(c, dn));  // with c >= 0, d = 0 is the empty case
    if (L::div_rare(num, den)) [[unlikely]] return div_bounds_scalar(a, b, c, d);
    const P straddles = _mm_and_pd(L::lt(L::both(c), L::both(0.0)), L::lt(L::both(0.0), L::both(d)));
    const P x_zero = _mm_and_pd(_mm_cmpeq_pd(L::both(a), L::both(0.0)), _mm_cmpeq_pd(L::both(b), L::both(0.0)));
    const P q = L::div_up(L::neg0(num), den);
    const P r = L::select(straddles, L::select(x_zero, L::both(0.0), L::both(inf)), q);
    const P y_zero = _mm_and_pd(_mm_cmpeq_pd(L::both(c), L::both(0.0)), _mm_cmpeq_pd(L::both(d), L::both(0.0)));
    return pair_bounds_or_empty(_mm_or_pd(pair_no_set(a, b, c, d), y_zero), r);
  }
#endif
  const Mask pos = ge(c, 0.0), a_nn = ge(a, 0.0), b_pos = gt(b, 0.0);
  const double lo_num = select(pos, a, b), hi_num = select(pos, b, a);
  const double lo_den = select(pos, select(a_nn, d, c), select(b_pos, dn, c));
  const double hi_den = select(pos, select(b_pos, c, d), select(a_nn, c, dn));
  if constexpr (R::kHasRareCases) {
    if (R::div_rare(lo_num, lo_den) | R::div_rare(hi_num, hi_den)) [[unlikely]] {
      return div_bounds_scalar(a, b, c, d);
    }
  }
  double lo = R::div_down(lo_num, lo_den), hi = R::div_up(hi_num, hi_den);
  const Mask straddles = lt(c, 0.0) & gt(d, 0.0), x_zero = eq(a, 0.0) & eq(b, 0.0);
  lo = select(straddles, select(x_zero, 0.0, -inf), lo);
  hi = select(straddles, select(x_zero, 0.0, inf), hi);
  return bounds_or_empty(no_set(a, b) | no_set(c, d) | (eq(c, 0.0) & eq(d, 0.0)), lo, hi);
}

// x² from mig(x) = max(a, -b, 0) and mag(x) = max(-a, b).
template <class R>
[[gnu::always_inline]] inline BoundPair sqr_bounds(double a, double b) {
  const double mig = max_nb(max_nb(a, -b), 0.0), mag = max_nb(-a, b);
#if SILLAGE_PAIR_LANES
  if constexpr (kSoftPairLanes<R>) {  // [-mig·mig, mag·mag] upward (the hardware's two scalar products are faster)
    using L = PairLanes;
    const L::P x = L::make(-mig, mag), y = L::make(mig, mag);
    if (L::mul_rare(x, y)) [[unlikely]] return sqr_bounds_scalar(a, b);
    return pair_bounds_or_empty(_mm_cmpnle_pd(L::both(a), L::both(b)), L::mul_up(x, y));
  }
#endif
  if constexpr (R::kHasRareCases) {
    if (R::mul_rare(mig, mig) | R::mul_rare(mag, mag)) [[unlikely]] return sqr_bounds_scalar(a, b);
  }
  return bounds_or_empty(no_set(a, b), R::mul_down_nz(mig, mig), R::mul_up_nz(mag, mag));
}

// √ of the part of x above 0.
template <class R>
[[gnu::always_inline]] inline BoundPair sqrt_bounds(double a, double b) {
  const double a0 = max_nb(a, 0.0);
#if SILLAGE_PAIR_LANES
  if constexpr (kSoftPairLanes<R>) {  // √[a0, b], lane 0 stepped down, lane 1 up
    using L = PairLanes;
    using P = L::P;
    const P x = L::make(a0, b), s = _mm_sqrt_pd(x), r = _mm_fnmadd_pd(s, s, x);  // x - s², exact
    const P tiny = _mm_and_pd(L::lt(L::both(0.0), x), L::lt(x, L::both(0x1p-968)));  // sqrt_rare
    if (L::any(tiny)) [[unlikely]] return sqrt_bounds_scalar(a, b);
    const P empty = _mm_or_pd(_mm_cmpnle_pd(L::both(a), L::both(b)), L::lt(L::both(b), L::both(0.0)));
    return pair_bounds_or_empty(empty, L::step_up(L::neg0(s), L::lt(L::both(0.0), L::neg0(r))));
  }
#endif
  if constexpr (R::kHasRareCases) {
    if (R::sqrt_rare(a0) | R::sqrt_rare(b)) [[unlikely]] return sqrt_bounds_scalar(a, b);
  }
  return bounds_or_empty(no_set(a, b) | lt(b, 0.0), R::sqrt_down(a0), R::sqrt_up(b));
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
