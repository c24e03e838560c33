#pragma once
// The slice rule of CtcDeriv on raw bounds, inline: the polygon of one slice
// given its derivative. An internal header of the tube layer, where
// Tube::eval / Tube::inverse with a derivative read a tube through it; the
// sweeps of CtcDeriv and CtcEval (dynamics/) share it.
//
// On a slice [t_k, t_{k+1}] of width δ, with gates [a] = [x](t_k),
// [b] = [x](t_{k+1}) and derivative bounds [v] = [q, p] (q = v⁻, p = v⁺), a
// trajectory with x' ∈ [v] satisfies, at τ = t - t_k and σ = t_{k+1} - t:
//   x(t) ∈ ([a] + τ[v]) ∩ ([b] - σ[v])                          (the polygon)
// so its upper bound is U(τ) = min(f1, f2), f1 = a⁺ + τp, f2 = b⁺ - σq, and
// its lower one L(τ) = max(a⁻ + τq, b⁻ - σp). When q < 0 < p, f1 increases
// and f2 decreases: the maximum of U over a range of τ is their crossing, or
// the end of the range nearer to it. Otherwise U's maximum over the range is
// at one of its ends. L is the mirror image: L(a, b, q, p) = -U(-a, -b, -p, -q).
//
// Rigor: every bound is computed with directed rounding from enclosures of
// the times involved, and is never below (above, for lower bounds) the exact
// real value. No branch depends on a rounded quantity, and the crossing is
// only used as a bound (it is the maximum of min(f1, f2) over the whole line),
// so an error in "is the crossing inside the range" cannot lose a trajectory.
//
// The rounding is a policy R (interval/rounding_policies.h): software emulation without
// branches, or the hardware's static rounding modes where available (one
// instruction per directed operation). Both give the exact directed results.
#include <algorithm>

#include "sillage/interval/rounding_policies.h"
#include "sillage/interval/rounding.h"

namespace sillage::detail {

inline constexpr double kInf = rounding::kInf;

// δ = t1 - t0 for t0 < t1: lo <= δ <= hi, lo > 0 (a difference of distinct
// doubles is a nonzero multiple of the smallest subnormal).
struct Width {
  double lo, hi;
};
template <class R>
inline Width width(double t0, double t1) {
  return {R::sub_down(t1, t0), R::sub_up(t1, t0)};
}

// [plo, phi] ⊇ δ·[vlo, vhi] for δ in [w.lo, w.hi] (w.lo > 0, v non-empty):
// infinite bounds stay infinite, 0·∞ never occurs.
template <class R>
inline void scale(double vlo, double vhi, Width w, double& plo, double& phi) {
  plo = R::mul_down_nz(vlo, vlo >= 0 ? w.lo : w.hi);
  phi = R::mul_up_nz(vhi, vhi >= 0 ? w.hi : w.lo);
}

// Q < 0 < P with both finite: the two lines of the polygon's upper bound
// cross, and those of its lower bound too.
inline bool straddles(double vlo, double vhi) { return (vlo < 0) & (vhi > 0) & (vlo > -kInf) & (vhi < kInf); }

// The hull [lo, up] of the polygon over the whole slice, from the gates
// [alo, ahi], [blo, bhi], v = [vlo, vhi] and [plo, phi] ⊇ δ[v]. Requires
// bounds of non-empty sets (ahi, bhi > -inf, alo, blo < +inf, vlo <= vhi).
// kConsistent: the gates passed the backward rule (ahi <= RU(bhi - plo),
// alo >= RD(blo - phi)), which saves two max.
//
// Upper bound: max over τ ∈ [0, δ] of min(f1, f2), f1 = a⁺ + τv⁺,
// f2 = b⁺ - σv⁻. Each affine function is largest at an end of the slice, so
// min(max(f1(0), f1(δ)), max(f2(0), f2(δ))) bounds it (and is exact when v
// does not straddle 0). When v⁻ < 0 < v⁺ the lines cross at the maximum
// a⁺ + λ·D, λ = v⁺ / (v⁺ - v⁻) ∈ (0, 1], D = f2(0) - f1(0): the crossing
// bounds min(f1, f2) on the whole line (if D < 0 the maximum is below
// f1(0) = a⁺, used then). The lower bound mirrors it with
// λ' = -v⁻ / (v⁺ - v⁻) = 1 - λ; both use one reciprocal of RD(v⁺ - v⁻)
// (one division per slice instead of two; λ may exceed 1 by an ulp, which
// only loosens the bound).
//
// The crossing is computed always and selected without a branch (whether v
// straddles 0 is data: a branch on it is mispredicted). When a gate bound is
// infinite the crossing is infinite or NaN (inf - inf), and std::min(m, NaN)
// is m (NaN < m is false); likewise for max.
template <class R, bool kConsistent>
inline void polygon_hull(double alo, double ahi, double blo, double bhi, double vlo, double vhi, double plo,
                         double phi, bool straddle, double& lo, double& up) {
  const double inv = R::div_up(1.0, R::sub_down(vhi, vlo));  // garbage unless straddle
  // Upper bound.
  const double f1d = R::add_up(ahi, phi);  // >= f1(δ) = a⁺ + δv⁺
  const double f20 = R::sub_up(bhi, plo);  // >= f2(0) = b⁺ - δv⁻
  const double mu = std::min(std::max(ahi, f1d), std::max(bhi, f20));
  const double du0 = R::sub_up(f20, ahi);
  const double du = kConsistent ? du0 : std::max(du0, 0.0);
  const double cu = R::add_up(ahi, R::mul_up_nz(R::mul_up_nz(vhi, inv), du));
  up = std::min(mu, detail::select(straddle, cu, kInf));
  // Lower bound: min over τ of max(g1, g2), g1 = a⁻ + τv⁻, g2 = b⁻ - σv⁺.
  const double g1d = R::add_down(alo, plo);  // <= g1(δ)
  const double g20 = R::sub_down(blo, phi);  // <= g2(0)
  const double ml = std::max(std::min(alo, g1d), std::min(blo, g20));
  const double dl0 = R::sub_down(g20, alo);  // <= 0 when consistent
  const double dl = kConsistent ? dl0 : std::min(dl0, 0.0);
  // λ' <= RU(-v⁻ · inv); times dl <= 0 rounded down.
  const double cl = R::add_down(alo, R::mul_down_nz(R::mul_up_nz(-vlo, inv), dl));
  lo = std::max(ml, detail::select(straddle, cl, -kInf));
}

// [s] ∩= the polygon hull (widened to hold the gates when kWiden, see below).
template <class R, bool kConsistent, bool kWiden>
inline void hull_into(double alo, double ahi, double blo, double bhi, double vlo, double vhi, double plo, double phi,
                      double& slo, double& shi) {
  double lo, up;
  polygon_hull<R, kConsistent>(alo, ahi, blo, bhi, vlo, vhi, plo, phi, straddles(vlo, vhi), lo, up);
  if constexpr (kWiden) {
    up = std::max(up, std::max(ahi, bhi));
    lo = std::min(lo, std::min(alo, blo));
  }
  shi = std::min(shi, up);
  slo = std::max(slo, lo);
}

// One slice, in place: [a] ∩= [s], [b] ∩= [s], then (kFwd) [b] ∩= [a] + δ[v],
// (kBwd) [a] ∩= [b] - δ[v], then (kEnv) [s] ∩= the hull of the polygon.
// kWiden: both gates are consistent ([b] ⊆ [a] + δ[v] and back, as after a
// forward then a backward pass); the hull contains them in exact arithmetic
// and is widened to contain them after rounding too, so that gates stay
// inside their slices and a second application changes nothing. (With one
// direction only, a gate may stick out of the polygon: no widening then.)
// Returns false if something is (now) empty; the values are then meaningless
// (computed on empty sets: possibly NaN, never undefined behaviour).
//
// contract_slice_scaled is contract_slice with [plo, phi] ⊇ δ[v] given
// (scale<R>, computed ahead for a block of slices); contract_slice below.
template <class R, bool kFwd, bool kBwd, bool kEnv, bool kWiden = false>
inline bool contract_slice_scaled(double& alo, double& ahi, double& blo, double& bhi, double& slo, double& shi,
                                  double vlo, double vhi, double plo, double phi) {
  // An empty slice empties [a] below; an empty [v] must be caught here.
  const bool inputs_ok = vlo <= vhi;
  alo = std::max(alo, slo);
  ahi = std::min(ahi, shi);
  blo = std::max(blo, slo);
  bhi = std::min(bhi, shi);
  if constexpr (kFwd) {
    blo = std::max(blo, R::add_down(alo, plo));
    bhi = std::min(bhi, R::add_up(ahi, phi));
  }
  if constexpr (kBwd) {
    alo = std::max(alo, R::sub_down(blo, phi));
    ahi = std::min(ahi, R::sub_up(bhi, plo));
  }
  const bool ok = inputs_ok & (alo <= ahi) & (blo <= bhi);
  if constexpr (kEnv) hull_into<R, kBwd, kWiden>(alo, ahi, blo, bhi, vlo, vhi, plo, phi, slo, shi);
  return ok;
}

template <class R, bool kFwd, bool kBwd, bool kEnv, bool kWiden = false>
inline bool contract_slice(double& alo, double& ahi, double& blo, double& bhi, double& slo, double& shi, double vlo,
                           double vhi, Width w) {
  double plo, phi;
  scale<R>(vlo, vhi, w, plo, phi);
  return contract_slice_scaled<R, kFwd, kBwd, kEnv, kWiden>(alo, ahi, blo, bhi, slo, shi, vlo, vhi, plo, phi);
}

// The hull step of a FWD_BWD sweep on slice [t0, t1] alone, its gates final
// (the chain of the backward sweep has settled them): [s] ∩= the widened
// hull, as contract_slice<R, false, true, true, true> would give. The
// reference of the hulls computed 4 or 8 slices at a time.
template <class R>
inline void slice_hull(double t0, double t1, double alo, double ahi, double blo, double bhi, double vlo, double vhi,
                       double& slo, double& shi) {
  double plo, phi;
  scale<R>(vlo, vhi, width<R>(t0, t1), plo, phi);
  hull_into<R, true, true>(alo, ahi, blo, bhi, vlo, vhi, plo, phi, slo, shi);
}

// An upper bound of  max over τ in T of min(A + τ·P, B + σ·(-Q)),  σ = δ - τ,
// for a part T of the slice known through enclosures: tau_lo <= min T,
// tau_hi >= max T, sig_lo <= min σ, sig_hi >= max σ (all >= 0), and
// delta_hi >= δ. Requires Q <= P, P > -inf, Q < +inf, A > -inf, B > -inf
// (bounds of non-empty sets). Used by evaluations, not in the sweeps.
template <class R>
inline double upper_envelope(double A, double B, double P, double Q, double tau_lo, double tau_hi, double sig_lo,
                             double sig_hi, double delta_hi) {
  // f1 = A + τP is largest at the right end of T if P > 0, else at the left;
  // f2 = B - σQ at the largest σ if Q < 0, else at the smallest. (A zero
  // factor gives 0, even against an infinite slope.)
  const double f1 = R::add_up(A, R::mul_up(P, P > 0 ? tau_hi : tau_lo));
  const double f2 = R::add_up(B, R::mul_up(-Q, Q < 0 ? sig_hi : sig_lo));
  const bool valid = (P > 0) & (Q < 0) & (P < kInf) & (Q > -kInf) & (A < kInf) & (B < kInf);
  const double d = std::max(R::sub_up(R::add_up(B, R::mul_up(-Q, delta_hi)), A), 0.0);
  const double lambda = std::min(R::div_up(P, R::sub_down(P, Q)), 1.0);
  const double cross = R::add_up(A, R::mul_up(lambda, d));
  return std::min(std::min(f1, f2), valid ? cross : kInf);
}

}  // namespace sillage::detail
