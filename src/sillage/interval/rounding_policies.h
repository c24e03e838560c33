#pragma once
// Rounding policies for batched kernels such as the slice rule of CtcDeriv
// (internal header of the interval layer). A policy R provides static add_up, add_down, sub_up,
// sub_down, mul_up, mul_down (0·inf = 0) and div_up (a >= 0, b > 0), each
// returning the exact upward / downward rounded result, for the operands the
// slice rule passes (bounds of non-empty sets, see branchless_rounding.h).
//
//  - SoftRounding: error-free transformations, no data-dependent branch
//    (branchless_rounding.h); portable.
//  - HardRounding (x86-64 with AVX-512F, GCC or Clang): one instruction with a
//    static rounding mode ({ru-sae} / {rd-sae}), no change of the FPU mode.
//    Written as inline assembly so that no translation unit needs AVX-512
//    code generation; it only runs when the CPU reports AVX-512F (checked once,
//    see hardware_rounding()).
#include "sillage/interval/branchless_rounding.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SILLAGE_HARD_ROUNDING 1
#else
#define SILLAGE_HARD_ROUNDING 0
#endif

namespace sillage::detail {

struct SoftRounding {
  static double add_up(double a, double b) { return detail::add_up(a, b); }
  static double add_down(double a, double b) { return detail::add_down(a, b); }
  static double sub_up(double a, double b) { return detail::sub_up(a, b); }
  static double sub_down(double a, double b) { return detail::sub_down(a, b); }
  static double mul_up(double a, double b) { return detail::mul_up(a, b); }
  static double mul_down(double a, double b) { return detail::mul_down(a, b); }
  static double mul_up_nz(double a, double b) { return detail::mul_up(a, b); }
  static double mul_down_nz(double a, double b) { return detail::mul_down(a, b); }
  static double div_up(double a, double b) { return detail::div_up_pos(a, b); }
};

#if SILLAGE_HARD_ROUNDING
// "%{" escapes the braces of the rounding operand in GCC's asm templates;
// AT&T order: op {mode}, src2, src1, dst computes dst = src1 op src2.
#define SILLAGE_DERIV_OP(name, insn, mode)                                      \
  static double name(double a, double b) {                                      \
    double r;                                                                   \
    asm(insn " %{" mode "-sae%}, %2, %1, %0" : "=x"(r) : "x"(a), "x"(b));       \
    return r;                                                                   \
  }
struct HardRounding {
  SILLAGE_DERIV_OP(add_up, "vaddsd", "ru")
  SILLAGE_DERIV_OP(add_down, "vaddsd", "rd")
  SILLAGE_DERIV_OP(sub_up, "vsubsd", "ru")
  SILLAGE_DERIV_OP(sub_down, "vsubsd", "rd")
  SILLAGE_DERIV_OP(div_up, "vdivsd", "ru")
  SILLAGE_DERIV_OP(mul_up_nz, "vmulsd", "ru")
  SILLAGE_DERIV_OP(mul_down_nz, "vmulsd", "rd")
  // Bounds are limits: a zero factor gives 0 even against an infinity.
  static double mul_up(double a, double b) { return (a == 0) | (b == 0) ? 0.0 : mul_up_nz(a, b); }
  static double mul_down(double a, double b) { return (a == 0) | (b == 0) ? 0.0 : mul_down_nz(a, b); }
};
#undef SILLAGE_DERIV_OP
#endif

// True if HardRounding is compiled in and this CPU (and OS) support it.
bool hardware_rounding_available();
// The policy the sweeps use: HardRounding when available, unless switched
// off (tests compare both paths; benchmarks measure both). Thread-safe.
bool hardware_rounding();
void set_hardware_rounding(bool on);

}  // namespace sillage::detail
