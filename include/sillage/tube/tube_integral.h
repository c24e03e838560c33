#pragma once
// Integrals of tubes (thesis 3.2.2, (3.7)-(3.9)) and the primitive tube.
//
// With L(t) = ∫_{t0}^{t} x^- and U(t) = ∫_{t0}^{t} x^+ (x^-, x^+ the lower
// and upper bounds of the slices):
//  - integral(x, t)        = [L(t), U(t)]                               (3.8)
//  - integral(x, t1, t2)   = the set (3.7) of ∫_{t1}^{t2} x(τ)dτ over the
//    trajectories of the tube: [L(t2)-L(t1), U(t2)-U(t1)] if t1 <= t2, and
//    [U(t2)-U(t1), L(t2)-L(t1)] if t1 > t2 (∫_{t1}^{t2} = -∫_{t2}^{t1});
//  - partial_integral(x, [t1], [t2]) = the pair (range of L(t2)-L(t1), range
//    of U(t2)-U(t1)) over t1 ∈ [t1], t2 ∈ [t2]: the lower- and upper-bound
//    integrals of (3.9). A range whose values are all +inf (resp. -inf), which
//    happens only across an unbounded slice, is given as [max double, +inf]
//    (resp. [-inf, -max double]), the Interval type holding no infinite point;
//  - integral(x, [t1], [t2]) = the hull of integral(x, t1, t2) over t1 ∈ [t1],
//    t2 ∈ [t2]. If ub[t1] <= lb[t2] it is (3.9):
//      [lb(L([t2]) - L([t1])), ub(U([t2]) - U([t1]))]
//    (the min of L(t2)-L(t1) over the box is min L([t2]) - max L([t1]), both
//    ends ranging independently). If the bounds may cross, t1 > t2 is allowed
//    and the lower end may come from U: the result is the hull of both
//    ranges of partial_integral, which is exact (every value lies between
//    L(t2)-L(t1) and U(t2)-U(t1), and both ends are reached).
// Every result encloses the exact set, rounding included (synthesis_tree.h).
// A tube with an empty slice holds no trajectory: its integrals are empty.
// An empty [t] gives an empty result; a time outside [t_0, t_N] is an Error.
//
// Cost: the free functions taking a Tube use the tube's cached SynthesisTree
// (Tube::synthesis_tree: built in O(N) on the first query after a
// modification), then answer in O(log N). TubeAnalysis is a handle on the
// same cached tree. A tree kept from before a modification of its tube throws
// an Error when queried (synthesis_tree.h): it never answers for old data.
#include <memory>
#include <utility>

#include "sillage/interval/interval.h"
#include "sillage/tube/synthesis_tree.h"
#include "sillage/tube/tube.h"

namespace sillage {

// ---- over a synthesis tree ----
Interval integral(const SynthesisTree& x, double t);
Interval integral(const SynthesisTree& x, const Interval& t);
Interval integral(const SynthesisTree& x, double t1, double t2);
Interval integral(const SynthesisTree& x, const Interval& t1, const Interval& t2);
std::pair<Interval, Interval> partial_integral(const SynthesisTree& x, const Interval& t1, const Interval& t2);

// ---- over a tube (through its cached synthesis tree: O(log N) once built) ----
Interval integral(const Tube& x, double t);
Interval integral(const Tube& x, const Interval& t);
Interval integral(const Tube& x, double t1, double t2);
Interval integral(const Tube& x, const Interval& t1, const Interval& t2);
std::pair<Interval, Interval> partial_integral(const Tube& x, const Interval& t1, const Interval& t2);

// The primitive tube p = x0 + ∫_{t0}^{.} x, on x's TDomain. Gates:
// p(t0) = x0, p(t_{k+1}) = p(t_k) + δ_k [x](k) (δ_k the outward width).
// Slice k: every p(t) = p(t_k) + (t - t_k) v with t - t_k ∈ [0, δ_k] and
// v ∈ [x](k), whose hull is p(t_k) + [0, δ_k]·[x](k) = p(t_k) +
// [min(0, δ_k x^-), max(0, δ_k x^+)]: tight, and it holds both gates (the
// backward cone p(t_{k+1}) - [0, δ_k]·[x](k) removes nothing from it). An
// empty x0 or slice gives the empty tube.
Tube primitive(const Tube& x, const Interval& x0 = Interval(0.0));

// The O(log N) queries of one tube through its cached synthesis tree
// (Tube::synthesis_tree: built on first use, rebuilt after a modification).
// The Tube must outlive the analysis (it is referenced, not copied).
class TubeAnalysis {
 public:
  // Analysis of the tube x (kept alive).
  explicit TubeAnalysis(const Tube& x) : x_(&x) {}

  const Tube& tube() const { return *x_; }
  // The current tree (rebuilt if the tube changed since the last call).
  std::shared_ptr<const SynthesisTree> tree() const;

  Interval eval(const Interval& t) const { return tree()->eval(t); }  // [x]([t]), as Tube::operator()
  Interval integral(double t) const { return sillage::integral(*tree(), t); }
  Interval integral(const Interval& t) const { return sillage::integral(*tree(), t); }
  Interval integral(double t1, double t2) const { return sillage::integral(*tree(), t1, t2); }
  Interval integral(const Interval& t1, const Interval& t2) const { return sillage::integral(*tree(), t1, t2); }
  std::pair<Interval, Interval> partial_integral(const Interval& t1, const Interval& t2) const {
    return sillage::partial_integral(*tree(), t1, t2);
  }

 private:
  const Tube* x_;
};

}  // namespace sillage
