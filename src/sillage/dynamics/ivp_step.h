#pragma once
// One validated step of x' = s·f(x, u), u(t) ∈ [u], by the Taylor method
// with Lohner's QR wrapping control (used by CtcIvp, dynamics/ctc_ivp.h).
//
// The set of states is a parallelepiped with a box of errors,
//   x ∈ c + A·[r]   (c a point, A a point matrix, [r] a box),
// plus the best box known, `box` (its hull, intersected with what the tube
// knows). A step of length [h]:
//  1. a priori enclosure [B] of every solution over [0, h] starting in
//     [X] = box: the Picard–Lindelöf test with ε-inflation, of high order
//     without inputs (Corliss–Rihm: Σ_{k≤p} x_k([X])[0,h]^k +
//     x_{p+1}([B̃])[0,h]^{p+1} ⊆ int [B̃]), of order 1 with inputs
//     ([X] + [0,h]·f([B̃], [u]) ⊆ int [B̃]), which covers every u(t) ∈ [u];
//  2. the Taylor polynomial at the centre with u0 = mid [u] and its
//     remainder x_{p+1}([B̃])·h^{p+1}; the secant matrix M of the
//     polynomial over [X] from the variational coefficients: Σ V_k([X]) h^k,
//     or on a wide set the mean of that sum over K nested boxes around c
//     (about half the second-order overestimation);
//  3. with inputs, the distance from a solution of the inclusion to the
//     solution with u0 from the same start, componentwise by comparison
//     with a Metzler majorant P of s·J_x over [B]: |x - y| ≤ h·e^{Ph}·δ,
//     δ_i ≥ |f_i(x,u) - f_i(x,u0)| (mean value in u over [B] × [u]);
//  4. Lohner's QR update: A' = Q of a QR factorisation of mid(M·A)
//     (columns sorted by their length times the width of [r]), [r'] =
//     Q⁻¹(M·A)[r] + Q⁻¹([z] - c'), with a rigorous enclosure of Q⁻¹.
// With inputs the set carries generators (ivp_generators.h), mapped by M.
// Everything is outward rounded; the box of the new set is also intersected
// with the mean-value form [z] + M([X] - c).
#include <cstddef>
#include <vector>

#include "sillage/expr/taylor.h"
#include "sillage/interval/interval_matrix.h"
#include "sillage/interval/interval_vector.h"

namespace sillage::detail {

struct LohnerSet {
  Vector c;
  IntervalMatrix A;
  IntervalVector r;
  // Input generators (columns g_j, a symbol w_j ∈ [-1, 1] each): the set is
  // c + A·[r] + Σ g_j w_j.
  std::vector<Vector> G;
  IntervalVector box;
  // Zonotope mode (for inputs): the errors of each step become generators
  // too, instead of joining [r] where a shearing flow wraps them step after
  // step; [r] then keeps only rounding-level terms.
  bool zonotope = false;
  // The box itself: c = mid, A = I, [r] = box - c, no generator; in
  // zonotope mode, [r] = 0 and one generator per side of the box.
  static LohnerSet from_box(const IntervalVector& x, bool zonotope = false);
  // An enclosure of c + A·[r] + Σ g_j [-1, 1].
  IntervalVector hull() const;
};

// Not thread-safe (it caches the coefficients at the last centre): one per sweep.
class IvpStepper {
 public:
  IvpStepper(const TaylorOde& ode, int order) : ode_(ode), order_(order) {}

  // A step length for the set's centre, from the last Taylor coefficients:
  // their terms at most `tol` (× max(1, |c|)). +inf if they vanish.
  double suggest(const LohnerSet& set, const IntervalVector& u, double sign, double tol) const;
  // Advances `set` by [h] (h > 0). `range` receives an enclosure of every
  // solution over [0, h]. False (set unchanged) if no a priori enclosure is
  // found or f is not smooth there: retry with a shorter step.
  bool step(LohnerSet& set, const Interval& h, const IntervalVector& u, double sign, IntervalVector& range) const;

 private:
  bool a_priori(const IntervalVector& X, const std::vector<Interval>& xs, const Interval& h, const IntervalVector& u,
                double sign, bool inputs, IntervalVector& B, IntervalVector& last) const;
  // A bound of |x - y| over the step, x with any u(·) ∈ [u], y with u0,
  // from the same start; J = ∂f/∂(x, u) over [B] × [u].
  IntervalVector input_deviation(const IntervalMatrix& J, const Interval& h, const IntervalVector& u,
                                 const IntervalVector& u0, double sign) const;
  // The inputs' share of the step: appends one generator per input to G,
  // adds the remainder box to `extra` and the whole share's hull to `box`.
  bool input_share(const IntervalVector& B, const Vector& c, const Interval& h, const IntervalVector& u,
                   const IntervalVector& u0, double sign, std::vector<Vector>& G, IntervalVector& extra,
                   IntervalVector& box) const;

  // The Taylor coefficients at the centre c with u0 (orders 0..p + 1):
  // suggest() computes them, step() on the same set reuses them.
  bool centre_coefficients(const Vector& c, const IntervalVector& u0, double sign,
                           std::vector<Interval>& cs) const;

  const TaylorOde& ode_;
  int order_;
  // The last centre_coefficients() call (a stepper serves one sweep).
  mutable Vector cache_c_;
  mutable IntervalVector cache_u0_;
  mutable double cache_sign_ = 0.0;
  mutable std::vector<Interval> cache_;
};

}  // namespace sillage::detail
