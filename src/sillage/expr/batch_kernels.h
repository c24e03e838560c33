#pragma once
// Interval +, −, ×, ÷, x² and √ for the row loops of the batch evaluator and of the
// batch HC4 (internal header): the bounds come from a rounding policy of
// rounding_policies.h, inlined and without a branch on the rounding error
// (the branch of rounding.h is mispredicted every other time on real data).
//
// The results are those of interval.h bit for bit, signs of zero included,
// so that a batch gives the box-by-box results exactly:
//  - a zero bound is +0, never -0, as interval.h's kernels give it (+ 0.0:
//    a downward-rounding unit gives -0 for an exact zero sum, an upward one
//    -0 for a tiny negative product);
//  - × takes the policy only where it is exact (HardRounding: correctly
//    rounded, as rounding.h); SoftRounding steps one ulp too far below
//    2^-968, so its × stays that of interval.h;
//  - ÷, x² and √ are the kernels of interval.h's operators (arith_kernels.h)
//    on the same path, inlined.
// ScalarOps are the operations of interval.h themselves, for one box.
#include <type_traits>

#include "sillage/interval/interval.h"
#include "sillage/interval/rounding_policies.h"

namespace sillage::detail {

struct ScalarOps {
  static Interval add(const Interval& x, const Interval& y) { return x + y; }
  static Interval sub(const Interval& x, const Interval& y) { return x - y; }
  static Interval mul(const Interval& x, const Interval& y) { return x * y; }
  static Interval div(const Interval& x, const Interval& y) { return x / y; }
  static Interval sqr(const Interval& x) { return sillage::sqr(x); }
  static Interval sqrt(const Interval& x) { return sillage::sqrt(x); }
};

template <class R>
struct RoundedOps {
  // The portable path, whose rows may also run on AVX2 (interval/arith_rows.h).
  static constexpr bool kPortable = std::is_same_v<R, SoftRounding>;

  static Interval add(const Interval& x, const Interval& y) {
    if (x.is_empty() || y.is_empty()) return Interval::empty();
    return Interval::from_bounds_unchecked(R::add_down(x.lb(), y.lb()) + 0.0, R::add_up(x.ub(), y.ub()) + 0.0);
  }

  static Interval sub(const Interval& x, const Interval& y) {
    if (x.is_empty() || y.is_empty()) return Interval::empty();
    return Interval::from_bounds_unchecked(R::sub_down(x.lb(), y.ub()) + 0.0, R::sub_up(x.ub(), y.lb()) + 0.0);
  }

  // The sign cases of interval.h's operator*, the same bound products.
  static Interval mul(const Interval& x, const Interval& y) {
    if constexpr (!kExactMul) {
      return x * y;
    } else {
      if (x.is_empty() || y.is_empty()) return Interval::empty();
      const double a = x.lb(), b = x.ub(), c = y.lb(), d = y.ub();
      const auto make = [](double lo, double hi) { return Interval::from_bounds_unchecked(lo + 0.0, hi + 0.0); };
      if (a >= 0) {
        if (c >= 0) return make(R::mul_down(a, c), R::mul_up(b, d));
        if (d <= 0) return make(R::mul_down(b, c), R::mul_up(a, d));
        return make(R::mul_down(b, c), R::mul_up(b, d));
      }
      if (b <= 0) {
        if (c >= 0) return make(R::mul_down(a, d), R::mul_up(b, c));
        if (d <= 0) return make(R::mul_down(b, d), R::mul_up(a, c));
        return make(R::mul_down(a, d), R::mul_up(a, c));
      }
      if (c >= 0) return make(R::mul_down(a, d), R::mul_up(b, d));
      if (d <= 0) return make(R::mul_down(b, c), R::mul_up(a, c));
      return make(std::min(R::mul_down(a, d), R::mul_down(b, c)), std::max(R::mul_up(a, c), R::mul_up(b, d)));
    }
  }

  static Interval div(const Interval& x, const Interval& y) {
    return of(div_bounds<Kernel>(x.lb(), x.ub(), y.lb(), y.ub()));
  }
  static Interval sqr(const Interval& x) { return of(sqr_bounds<Kernel>(x.lb(), x.ub())); }
  static Interval sqrt(const Interval& x) { return of(sqrt_bounds<Kernel>(x.lb(), x.ub())); }

 private:
  static constexpr bool kExactMul = !std::is_same_v<R, SoftRounding>;
  // The policy of interval.h's operators on this path (with_rounding in arith_kernels.h).
  using Kernel = std::conditional_t<std::is_same_v<R, SoftRounding>, BranchFreeRounding, R>;
  static Interval of(BoundPair b) { return Interval::from_bounds_unchecked(b.lo, b.hi); }
};

// f(ops) with the operations of the rounding policy in use (hardware_rounding()).
template <class F>
decltype(auto) with_rounded_ops(F&& f) {
#if SILLAGE_HARD_ROUNDING
  if (hardware_rounding()) return f(RoundedOps<HardRounding>{});
#endif
  return f(RoundedOps<SoftRounding>{});
}

}  // namespace sillage::detail
