#pragma once
// Directed rounding by the hardware: AVX-512F instructions with a static
// rounding mode ({ru-sae} / {rd-sae}), one instruction per bound and no change
// of the FPU mode. Written as inline assembly so that no translation unit
// needs AVX-512 code generation; it only runs when the CPU (and OS) support
// AVX-512F, checked once at start-up (see use_hardware_rounding()). The
// results are the exactly rounded ones, for every operand, infinities
// included; 0·inf is NaN here (callers of the interval layer take it as 0).
//
// The path is chosen once per process: hardware when available, unless the
// environment variable SILLAGE_ROUNDING=portable forces the branch-free
// software path (branchless_rounding.h); tests and benchmarks also switch it
// with set_hardware_rounding(). Both paths give the same bounds bit for bit.
#include <atomic>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SILLAGE_HARD_ROUNDING 1
#else
#define SILLAGE_HARD_ROUNDING 0
#endif

namespace sillage::detail {

#if SILLAGE_HARD_ROUNDING
// "%{" escapes the braces of the rounding operand in GCC's asm templates;
// AT&T order: op {mode}, src2, src1, dst computes dst = src1 op src2.
#define SILLAGE_HARD_OP(name, insn, mode)                                       \
  static double name(double a, double b) {                                      \
    double r;                                                                   \
    asm(insn " %{" mode "-sae%}, %2, %1, %0" : "=x"(r) : "x"(a), "x"(b));       \
    return r;                                                                   \
  }
#define SILLAGE_HARD_SQRT(name, mode)                                           \
  static double name(double a) {                                                \
    double r;                                                                   \
    asm("vsqrtsd %{" mode "-sae%}, %1, %1, %0" : "=x"(r) : "x"(a));             \
    return r;                                                                   \
  }
struct HardRounding {
  SILLAGE_HARD_OP(add_up, "vaddsd", "ru")
  SILLAGE_HARD_OP(add_down, "vaddsd", "rd")
  SILLAGE_HARD_OP(sub_up, "vsubsd", "ru")
  SILLAGE_HARD_OP(sub_down, "vsubsd", "rd")
  SILLAGE_HARD_OP(div_up, "vdivsd", "ru")
  SILLAGE_HARD_OP(div_down, "vdivsd", "rd")
  SILLAGE_HARD_OP(mul_up_nz, "vmulsd", "ru")
  SILLAGE_HARD_OP(mul_down_nz, "vmulsd", "rd")
  SILLAGE_HARD_SQRT(sqrt_up, "ru")
  SILLAGE_HARD_SQRT(sqrt_down, "rd")
  // Bounds are limits: a zero factor gives 0 even against an infinity.
  static double mul_up(double a, double b) { return (a == 0) | (b == 0) ? 0.0 : mul_up_nz(a, b); }
  static double mul_down(double a, double b) { return (a == 0) | (b == 0) ? 0.0 : mul_down_nz(a, b); }
  // Exact everywhere: no operand needs a fallback.
  static constexpr bool kHasRareCases = false;
  static bool mul_rare(double, double) { return false; }
  static bool div_rare(double, double) { return false; }
  static bool sqrt_rare(double) { return false; }
};
#undef SILLAGE_HARD_OP
#undef SILLAGE_HARD_SQRT
#endif

// Set once at start-up (AVX-512F present and SILLAGE_ROUNDING not
// "portable"); false before, which selects the software path, as exact.
extern std::atomic<bool> hardware_rounding_on;

// True if HardRounding is compiled in and this CPU (and OS) support it.
bool hardware_rounding_available();
// The path in use: true for HardRounding. Thread-safe; a relaxed load, so
// that the per-operation check costs one predictable branch.
inline bool use_hardware_rounding() { return hardware_rounding_on.load(std::memory_order_relaxed); }
bool hardware_rounding();  // same, out of line (kept for the slice-rule sweeps)
// Switches the path (ignored towards hardware when unavailable); for tests
// and benchmarks, which compare and measure both.
void set_hardware_rounding(bool on);

}  // namespace sillage::detail
