#pragma once
// Rounding policies for batched kernels such as the slice rule of CtcDeriv
// (internal header of the interval layer). A policy R provides static add_up, add_down, sub_up,
// sub_down, mul_up, mul_down (0·inf = 0) and div_up (a >= 0, b > 0), each
// returning the exact upward / downward rounded result, for the operands the
// slice rule passes (bounds of non-empty sets, see branchless_rounding.h).
//
//  - SoftRounding: error-free transformations, no data-dependent branch
//    (branchless_rounding.h); portable.
//  - HardRounding (x86-64 with AVX-512F, GCC or Clang): hardware_rounding.h.
#include "sillage/interval/arith_kernels.h"
#include "sillage/interval/hardware_rounding.h"

namespace sillage::detail {

// + and - as Interval's portable path; × and ÷ without its exact fallback.
struct SoftRounding : BranchFreeRounding {
  static double mul_up(double a, double b) { return detail::mul_up(a, b); }
  static double mul_down(double a, double b) { return detail::mul_down(a, b); }
  static double mul_up_nz(double a, double b) { return detail::mul_up(a, b); }
  static double mul_down_nz(double a, double b) { return detail::mul_down(a, b); }
  static double div_up(double a, double b) { return detail::div_up_pos(a, b); }
};

// f.template operator()<R>() with the policy this process uses (hardware when
// available): for code templated on R, both paths giving the same bits.
template <class F>
decltype(auto) with_policy(const F& f) {
#if SILLAGE_HARD_ROUNDING
  if (use_hardware_rounding()) return f.template operator()<HardRounding>();
#endif
  return f.template operator()<SoftRounding>();
}

}  // namespace sillage::detail
