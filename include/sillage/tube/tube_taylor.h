#pragma once
// Primitives of tubes whose integrand is known to be smooth (thesis 3.4:
// "get as close to the true set as rigor allows"). The plain primitive
// (tube_integral.h) integrates each slice as δ_k [x](k), a box: its error per
// slice is δ_k·diam([x](k)), which accumulates. When the integrand is
// x = w + e with w absolutely continuous, w' ∈ [dw](k) on slice k, and a
// bounded noise e(t) ∈ [e], each slice integral is known far better from the
// GATES of w (first-order Taylor form from either end of the slice):
//
//   ∫_slice x ∈ δ (w(t_k) + [e]) + δ²/2 [dw](k)
//            ∩ δ (w(t_{k+1}) + [e]) − δ²/2 [dw](k)
//            ∩ δ ([w](k) + [e]),
//
// since w(t) = w(t_k) + ∫_{t_k}^t w' ∈ w(t_k) + (t − t_k)[dw](k), and the same
// from t_{k+1}. Its width is δ·diam(gate) + δ² diam([dw])/2: second order in δ
// where the plain form is first order. δ is the rigorous slice width.
#include <vector>

#include "sillage/interval/interval.h"
#include "sillage/tube/tube.h"

namespace sillage {

// The increments ∫_{t_k}^{t_{k+1}} (w + e) as above, one per slice.
// DimensionError if w and dw are not on one TDomain.
std::vector<Interval> taylor_increments(const Tube& w, const Tube& dw, const Interval& noise = Interval(0.0));

// The primitive p of x (p' = x) with p(t_0) ∈ x0 and p(t_{k+1}) − p(t_k) ∈
// increments[k]: the gates by a forward then a backward pass
// (p_{k+1} ∩= p_k + I_k, p_k ∩= p_{k+1} − I_k), the slices from both gates
// and the slopes [x](k): (p_k + [0, δ][x](k)) ∩ (p_{k+1} − [0, δ][x](k)).
// `gates` (N+1 values, or empty) are known enclosures of p at the time points
// to intersect with (e.g. from another method); DimensionError on sizes.
Tube primitive_from_increments(const Tube& x, const std::vector<Interval>& increments, const Interval& x0,
                               const std::vector<Interval>& gates = {});

// primitive_from_increments(w + noise, taylor_increments(w, dw, noise), x0).
Tube primitive_taylor(const Tube& w, const Tube& dw, const Interval& x0 = Interval(0.0),
                      const Interval& noise = Interval(0.0));

}  // namespace sillage
