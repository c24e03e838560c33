#pragma once
// The upper bound of a slice's polygon and its mirrored lower bound over a
// part of the slice (two upper_envelope<SoftRounding> calls of slice_deriv.h)
// in the two lanes of one SSE register (interval/pair_lanes.h): the same
// operations on the same operands, each lane giving the scalar call's bits.
// Internal header of Tube::eval and Tube::inverse through the derivative,
// whose polygon hulls are CtcEval's inner loop.
#include "sillage/interval/pair_lanes.h"
#include "sillage/interval/rounding.h"

#if SILLAGE_PAIR_LANES

namespace sillage::detail {

struct EnvelopePair {
  using L = PairLanes;
  using P = L::P;

  // SoftRounding's mul_up per lane (branchless_rounding.h): the next double
  // above round-to-nearest when the product is tiny, 0 for a zero factor.
  static P mul_up(P a, P b) {
    const P z = L::both(0.0), p = _mm_add_pd(_mm_mul_pd(a, b), z);
    const P step = _mm_or_pd(L::lt(z, _mm_fmsub_pd(a, b, p)), L::lt(L::abs(p), L::both(0x1p-968)));
    const P zero = _mm_or_pd(_mm_cmpeq_pd(a, z), _mm_cmpeq_pd(b, z));
    return L::select(zero, z, L::step_up(p, step));
  }

  // SoftRounding's div_up per lane (div_up_pos: a >= 0, b > 0 where it matters).
  static P div_up(P a, P b) {
    const P q = _mm_add_pd(_mm_div_pd(a, b), L::both(0.0)), r = _mm_fnmadd_pd(q, b, a);
    const P lo = L::both(0x1p-968), hi = L::both(0x1p1000);
    const P safe = _mm_and_pd(_mm_and_pd(_mm_and_pd(L::le(lo, a), L::le(lo, b)), _mm_and_pd(L::le(lo, q), L::le(b, hi))),
                              L::le(q, hi));
    const P finite = L::lt(q, L::both(rounding::kInf));
    // ((r > 0) | !safe) & (q < inf)
    const P step = _mm_or_pd(_mm_and_pd(L::lt(L::both(0.0), r), finite), _mm_andnot_pd(safe, finite));
    return L::step_up(q, step);
  }

  static P neg(P a) { return _mm_xor_pd(a, L::both(-0.0)); }

  // std::min(a, b) and std::max(a, b): b < a ? b : a and a < b ? b : a.
  static P min(P a, P b) { return L::select(L::lt(b, a), b, a); }
  static P max(P a, P b) { return L::select(L::lt(a, b), b, a); }

  // upper_envelope<SoftRounding>(A, B, P, Q, ...) in each lane.
  static P upper(P A, P B, P Pv, P Q, double tau_lo, double tau_hi, double sig_lo, double sig_hi, double delta_hi) {
    const P z = L::both(0.0), inf = L::both(rounding::kInf), nQ = neg(Q);
    const P f1 = L::add_up(A, mul_up(Pv, L::select(L::lt(z, Pv), L::both(tau_hi), L::both(tau_lo))));
    const P f2 = L::add_up(B, mul_up(nQ, L::select(L::lt(Q, z), L::both(sig_hi), L::both(sig_lo))));
    const P signs = _mm_and_pd(L::lt(z, Pv), L::lt(Q, z));
    const P finite = _mm_and_pd(_mm_and_pd(L::lt(Pv, inf), L::lt(L::both(-rounding::kInf), Q)),
                                _mm_and_pd(L::lt(A, inf), L::lt(B, inf)));
    const P valid = _mm_and_pd(signs, finite);
    const P d = max(L::add_up(L::add_up(B, mul_up(nQ, L::both(delta_hi))), neg(A)), z);  // sub_up(.., A)
    const P diff = neg(L::add_up(neg(Pv), Q));  // sub_down(P, Q)
    const P lambda = min(div_up(Pv, diff), L::both(1.0));
    const P cross = L::add_up(A, mul_up(lambda, d));
    return min(min(f1, f2), L::select(valid, cross, inf));
  }
};

}  // namespace sillage::detail

#endif
