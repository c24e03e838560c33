#pragma once
// PairLanes ([-lo, hi] in one register, pair_lanes.h) over the hardware's
// upward rounding (hardware_rounding.h): one packed instruction per pair
// instead of a packed error-free transformation, exact for every operand.
//
// AVX-512F has a static rounding mode ({ru-sae}) on packed instructions only
// at the 512-bit length, so each runs on the zmm register that holds the
// pair; its upper lanes are whatever the registers held (zeros in VEX code,
// which SILLAGE_PAIR_LANES implies through -mfma; 0 / 0 is NaN there). A
// 128-bit move of the result onto itself then clears them (measured free), so
// that no register is left with nonzero upper bits.
#include "sillage/interval/hardware_rounding.h"
#include "sillage/interval/pair_lanes.h"

#if SILLAGE_PAIR_LANES && SILLAGE_HARD_ROUNDING
#define SILLAGE_HARD_PAIR_LANES 1
#else
#define SILLAGE_HARD_PAIR_LANES 0
#endif

#if SILLAGE_HARD_PAIR_LANES

namespace sillage::detail {

// name(a, b): insn on the pair, upward; "%g" names the zmm register of an
// xmm operand, "%{" escapes a brace.
#define SILLAGE_HARD_PACKED_OP(name, insn)                                                 \
  static P name(P a, P b) {                                                                \
    P r;                                                                                   \
    asm(insn " %{ru-sae%}, %g2, %g1, %g0\n\tvmovapd %x0, %x0" : "=x"(r) : "x"(a), "x"(b)); \
    return r;                                                                              \
  }
struct HardPairLanes : PairLanes {
  SILLAGE_HARD_PACKED_OP(add_up, "vaddpd")
  SILLAGE_HARD_PACKED_OP(div_up, "vdivpd")
  SILLAGE_HARD_PACKED_OP(mul_up_or_nan, "vmulpd")
  // 0·inf (NaN) is 0 for bounds.
  static P mul_up(P a, P b) {
    const P p = mul_up_or_nan(a, b);
    return _mm_and_pd(_mm_cmpord_pd(p, p), p);
  }
  // Exact everywhere: no operand needs a fallback.
  static bool mul_rare(P, P) { return false; }
  static bool div_rare(P, P) { return false; }
};
#undef SILLAGE_HARD_PACKED_OP

}  // namespace sillage::detail

#endif
