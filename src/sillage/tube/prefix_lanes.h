#pragma once
// The prefix sums of a synthesis tree (synthesis_tree.h), one step at a time.
//
// L(t_k) and U(t_k) are summed left to right in outward interval arithmetic:
//   L(t_{k+1}) = L(t_k) + (Interval(t_{k+1}) - Interval(t_k)) * [x^-(k), x^-(k)]
// (U likewise with x^+), i.e. with the operators of interval.h. The tree
// stores these enclosures only every few time points and recomputes the
// others when a query needs them, so a step must be fast and give exactly
// the bits of the Interval operators (queries equal a linear scan).
//
// Lanes. The four bounds travel in one vector, all rounded downward:
// (lo L, -hi L, lo U, -hi U), since rounding hi upward is rounding -hi
// downward. The extrema over time points are then four lane-wise minima.
//
// Exactness. The fast path is the algorithm of rounding.h without branches:
// the round-to-nearest result, the sign of its exact error (Fast2Sum for
// sums, an fma residual for products), and a step of the bit pattern to the
// next double below when the exact value lies below; a zero factor gives +0
// as in rounding.h. So it gives the same bits whenever rounding.h takes that
// path: finite results, and products at least 2^-968 in magnitude (below,
// rounding.h rescales first). Every other case (tiny products, overflow,
// unbounded or empty slices, huge widths) is flagged and takes the Interval
// operators themselves. Only the sign of a zero in a -hi lane may differ,
// which "-x + 0.0" erases (upper_of); tests compare both paths bit for bit.
#include <bit>
#include <cmath>
#include <cstdint>

#include "sillage/interval/interval.h"

// Lanes travel by value between inline functions and the internals of
// synthesis_primitive.cpp, all built with the same flags: GCC's note that the
// ABI of 32-byte vector arguments differs without AVX does not apply.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace sillage::detail {

// GCC / Clang vector extensions: plain code on any target, SIMD where there is.
using Lanes = double __attribute__((vector_size(32)));
using LaneMask = std::int64_t __attribute__((vector_size(32)));   // comparisons: 0 or -1
using LaneBits = std::uint64_t __attribute__((vector_size(32)));  // bit patterns (wrapping arithmetic)

inline constexpr double kLaneInf = rounding::kInf;

// The prefix value 0 (L(t_0) = U(t_0) = [0, 0]).
inline Lanes zero_lanes() { return Lanes{0.0, -0.0, 0.0, -0.0}; }
// The neutral element of lane-wise minima.
inline Lanes max_lanes() { return Lanes{kLaneInf, kLaneInf, kLaneInf, kLaneInf}; }

// Lane-wise minimum (exact; no NaN ever reaches it).
inline Lanes lane_min(Lanes a, Lanes b) {
  const LaneMask less = (LaneMask)(b < a);
  return (Lanes)(((LaneMask)b & less) | ((LaneMask)a & ~less));
}

// The enclosures of L and U held by a lane vector. "-x + 0.0" undoes the
// negation of the upper bounds (an upper bound is never -0 in interval.h).
inline Interval lower_of(Lanes v) { return Interval::from_bounds_unchecked(v[0], -v[1] + 0.0); }
inline Interval upper_of(Lanes v) { return Interval::from_bounds_unchecked(v[2], -v[3] + 0.0); }
inline Lanes lanes_of(const Interval& l, const Interval& u) { return Lanes{l.lb(), -l.ub(), u.lb(), -u.ub()}; }

inline Lanes lane_abs(Lanes x) { return (Lanes)((LaneMask)x & 0x7fffffffffffffffLL); }
inline Lanes lane_select(LaneMask m, Lanes a, Lanes b) { return (Lanes)(((LaneMask)a & m) | ((LaneMask)b & ~m)); }

// s, or the double just below s where the exact value is below s (err < 0).
// s is finite and nonzero there: one step of the bit pattern towards -inf.
inline Lanes lane_down_if(Lanes s, Lanes err) {
  const LaneMask below = (LaneMask)(err < 0.0);
  const LaneMask negative = (LaneMask)(s < 0.0);
  return (Lanes)((LaneBits)s + (LaneBits)(below & (-1 - 2 * negative)));  // s > 0: -1, s < 0: +1
}

inline bool any(LaneMask m) { return (m[0] | m[1] | m[2] | m[3]) != 0; }

// The step over [t0, t1] of a slice with finite bounds lo <= hi, fast path.
// Sets in `bad` the lanes where the result may not be exact: then the step,
// and any step computed from its result, must be redone (advance_exact).
// Checking `bad` once after a chain of steps saves a check per step.
inline void advance_fast(Lanes& p, double t0, double t1, double lo, double hi, LaneMask& bad) {
  // Width [w_lo, w_hi] = Interval(t1) - Interval(t0): one sum, rounded both ways.
  const double w = t1 - t0;
  const bool swap = std::fabs(t1) < std::fabs(t0);
  const double big = swap ? -t0 : t1, small = swap ? t1 : -t0;
  const double werr = small - (w - big);
  const auto wbits = std::bit_cast<std::uint64_t>(w);  // w > 0 since t1 > t0
  const double w_lo = std::bit_cast<double>(wbits - static_cast<std::uint64_t>(werr < 0));
  const double w_hi = std::bit_cast<double>(wbits + static_cast<std::uint64_t>(werr > 0));
  // Products, all rounded down: lane k is [w]·s_k with s = (lo, -lo, hi, -hi);
  // interval.h takes w_lo for a factor >= 0, w_hi for a negative one.
  const Lanes s{lo, -lo, hi, -hi};
  const LaneMask nonneg = (LaneMask)(s >= 0.0);
  const Lanes a = lane_select(nonneg, Lanes{w_lo, w_lo, w_lo, w_lo}, Lanes{w_hi, w_hi, w_hi, w_hi});
  const Lanes prod = a * s;
  const Lanes perr{std::fma(a[0], s[0], -prod[0]), std::fma(a[1], s[1], -prod[1]),
                   std::fma(a[2], s[2], -prod[2]), std::fma(a[3], s[3], -prod[3])};
  const LaneMask nonzero = (LaneMask)(s != 0.0);
  const Lanes aprod = lane_abs(prod);
  const Lanes q = (Lanes)((LaneMask)lane_down_if(prod, perr) & nonzero);  // a zero factor gives +0
  // Sums, rounded down (Fast2Sum: the larger operand first, as rounding.h).
  const Lanes sum = p + q;
  const LaneMask q_larger = (LaneMask)(lane_abs(p) < lane_abs(q));
  const Lanes serr = lane_select(q_larger, p, q) - (sum - lane_select(q_larger, q, p));
  bad |= (nonzero & ((LaneMask)(aprod < 0x1p-968) | (LaneMask)(aprod > rounding::kMax))) |
         ~(LaneMask)(lane_abs(sum) <= rounding::kMax) | ~(LaneMask)(a <= 0x1p1000);
  p = lane_down_if(sum, serr);
}

// One step with the Interval operators (the definition; any slice).
inline void advance_exact(Lanes& p, double t0, double t1, const Interval& slice) {
  if (slice.is_empty()) return;  // contributes nothing (the tree flags it)
  const Interval width = Interval(t1) - Interval(t0);
  Interval l = lower_of(p), u = upper_of(p);
  if (slice.lb() != -kLaneInf) l = l + width * Interval::from_bounds_unchecked(slice.lb(), slice.lb());
  if (slice.ub() != kLaneInf) u = u + width * Interval::from_bounds_unchecked(slice.ub(), slice.ub());
  p = lanes_of(l, u);
}

// p := the prefix value at t1 from the one at t0 (t0 < t1), over (part of)
// the slice. The fast path where it applies (bad: see advance_fast), the
// Interval operators otherwise. An unbounded side stays unchanged (its rank
// counts it, see Rank); an empty slice changes nothing.
inline void advance(Lanes& p, double t0, double t1, const Interval& slice, LaneMask& bad) {
  const double lo = slice.lb(), hi = slice.ub();
  if (std::fabs(lo) <= rounding::kMax && std::fabs(hi) <= rounding::kMax) {
    advance_fast(p, t0, t1, lo, hi, bad);
  } else {
    advance_exact(p, t0, t1, slice);
  }
}

// The same, checked: bit for bit the Interval operators.
inline void advance(Lanes& p, double t0, double t1, const Interval& slice) {
  Lanes q = p;
  LaneMask bad{};
  advance(q, t0, t1, slice, bad);
  if (any(bad)) {
    advance_exact(p, t0, t1, slice);
  } else {
    p = q;
  }
}

}  // namespace sillage::detail

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
