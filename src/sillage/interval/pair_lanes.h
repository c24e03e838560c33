#pragma once
// Both bounds of an interval in one SSE register, the lower one negated:
// [-lo, hi]. Then both bounds of x + y, x·y, x / y round the same way, upward
// (lo = -up(-...)), and one packed error-free transformation gives both: half
// the instructions of two scalar ones, and no trip through the integer
// registers. Internal header of arith_kernels.h (the branch-free portable
// path); each lane gives the bits of branchless_rounding.h's scalar
// functions, with the same rare cases.
//
// Needs SSE4.1 (blends) and FMA (exact residuals), which -mfma brings;
// SILLAGE_PAIR_LANES is 0 without them and the kernels stay scalar.
#if defined(__SSE4_1__) && defined(__FMA__)
#define SILLAGE_PAIR_LANES 1
#include <immintrin.h>
#else
#define SILLAGE_PAIR_LANES 0
#endif

#include "sillage/interval/rounding.h"

#if SILLAGE_PAIR_LANES

namespace sillage::detail {

// The vocabulary, as static members (a struct rather than a namespace of its own).
struct PairLanes {
  using P = __m128d;  // lane 0, lane 1

  static P make(double lane0, double lane1) { return _mm_set_pd(lane1, lane0); }
  static P both(double x) { return _mm_set1_pd(x); }
  static double lane0(P v) { return _mm_cvtsd_f64(v); }
  static double lane1(P v) { return _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)); }
  static P swap(P v) { return _mm_shuffle_pd(v, v, 1); }
  static P neg0(P v) { return _mm_xor_pd(v, make(-0.0, 0.0)); }  // lane 0 negated
  static P abs(P v) { return _mm_andnot_pd(both(-0.0), v); }
  static P select(P m, P a, P b) { return _mm_blendv_pd(b, a, m); }  // m ? a : b, per lane
  static P lt(P a, P b) { return _mm_cmplt_pd(a, b); }
  static P le(P a, P b) { return _mm_cmple_pd(a, b); }
  static P ne(P a, P b) { return _mm_cmpneq_pd(a, b); }  // also true on NaN
  static P either(P m) { return _mm_or_pd(m, swap(m)); }  // lane 0 or lane 1, in both lanes
  static bool any(P m) { return _mm_movemask_pd(m) != 0; }

  // p, or the next double above p in the lanes where m is set (p finite and
  // not -0 there): below 0, up is toward 0.
  static P step_up(P p, P m) {
    const __m128i i = _mm_castpd_si128(p), s = _mm_castpd_si128(m);  // s: -1 or 0 per lane
    const P away = _mm_castsi128_pd(_mm_sub_epi64(i, s)), toward = _mm_castsi128_pd(_mm_add_epi64(i, s));
    return _mm_blendv_pd(away, toward, p);
  }

  // Upper bound of a + b per lane (a, b > -inf): 2Sum, as add_up (its overflow of bv included).
  static P add_up(P a, P b) {
    const P s = _mm_add_pd(a, b), bv = _mm_sub_pd(s, a);
    const P e = _mm_add_pd(_mm_sub_pd(a, _mm_sub_pd(s, bv)), _mm_sub_pd(b, bv));
    const P bv_overflowed = _mm_and_pd(lt(bv, both(-rounding::kMax)), le(both(-rounding::kMax), s));
    return _mm_max_pd(step_up(s, _mm_or_pd(lt(both(0.0), e), bv_overflowed)), both(-rounding::kMax));
  }

  // Upper bound of a·b per lane, 0·inf taken as 0; exact outside mul_rare.
  static P mul_up(P a, P b) {
    const P p = _mm_mul_pd(a, b);
    const P r = step_up(p, lt(both(0.0), _mm_fmsub_pd(a, b, p)));
    return _mm_and_pd(_mm_cmpord_pd(r, r), r);  // NaN (0·inf) to 0
  }

  // Upper bound of a / b per lane; exact outside div_rare. a - q·b has the
  // sign of (a/b - q)·b.
  static P div_up(P a, P b) {
    const P q = _mm_div_pd(a, b), r = _mm_fnmadd_pd(q, b, a), z = both(0.0);
    const P step = _mm_or_pd(_mm_and_pd(lt(z, r), lt(z, b)), _mm_and_pd(lt(r, z), lt(b, z)));
    return step_up(q, step);
  }

  // mul_rare per lane, in any lane: a tiny nonzero product.
  static bool mul_rare(P a, P b) {
    const P z = both(0.0);
    return any(_mm_and_pd(lt(abs(_mm_mul_pd(a, b)), both(0x1p-968)), _mm_and_pd(ne(a, z), ne(b, z))));
  }

  // div_rare per lane, in any lane: finite nonzero operands with an operand or
  // the quotient outside [2^-968, 2^1000].
  static bool div_rare(P a, P b) {
    const P fa = abs(a), fb = abs(b), fq = abs(_mm_div_pd(a, b)), z = both(0.0), inf = both(rounding::kInf);
    const P lo = both(0x1p-968), hi = both(0x1p1000);
    const P finite_nonzero = _mm_and_pd(_mm_and_pd(lt(z, fa), lt(fa, inf)), _mm_and_pd(lt(z, fb), lt(fb, inf)));
    const P safe = _mm_and_pd(_mm_and_pd(_mm_and_pd(le(lo, fa), le(lo, fb)), _mm_and_pd(le(fb, hi), le(lo, fq))),
                              le(fq, hi));
    return any(_mm_andnot_pd(safe, finite_nonzero));
  }

};

}  // namespace sillage::detail

#endif
