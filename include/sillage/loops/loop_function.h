#pragma once
// LoopFunction: the inter-temporal map of a planar trajectory,
// f(t1, t2) = p(t2) - p(t1), and the enclosures the t-plane needs (thesis
// ch. 6), answered in O(log N) by the synthesis trees of the tubes:
//  - from a 2-D velocity tube v: [f]([t1], [t2]) = ∫_{[t1]}^{[t2]} [v] (6.6)
//    and [J_f] = (-[v]([t1]) | [v]([t2])) (6.18);
//  - from positions p and their derivative w (both 2-D): the tighter
//    [f] = ([p]([t2]) - [p]([t1])) ∩ ∫_{[t1]}^{[t2]} [w] (7.28), and
//    [J_f] = (-[w]([t1]) | [w]([t2])).
// Below, "velocity" means v, or w in the second form.
//
// The trees are built once, at construction, so that every query is const
// and may run concurrently from several threads. A LoopFunction refers to
// the tubes' storage (it does not copy it): the tubes must outlive it and
// stay unmodified, otherwise queries throw an Error (synthesis_tree.h).
#include <array>
#include <memory>
#include <utility>

#include "sillage/interval/interval_matrix.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/loops/plane_function.h"
#include "sillage/tube/synthesis_tree.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

class LoopFunction {
 public:
  // From a 2-D velocity tube (DimensionError otherwise).
  explicit LoopFunction(const TubeVector& v);
  // From 2-D positions p and velocities w, possibly on different TDomains
  // (DimensionError if not 2-D, Error if their time domains do not overlap).
  LoopFunction(const TubeVector& p, const TubeVector& w);

  // True when built from positions p and velocities w (7.28), false from v alone (6.6).
  bool has_positions() const { return static_cast<bool>(p_[0]); }
  // Some tube has an empty slice: it holds no trajectory, hence no loop.
  bool is_empty() const;
  // [t0, tf] where every tube is defined: the t-plane this map lives on is its square.
  const Interval& time_domain() const { return domain_; }

  // [f]([t]) for a t-box [t] = ([t1], [t2]); any order of t1 and t2. Points
  // outside the time domain are not part of f's domain and are ignored
  // (Error if [t] has none inside). An empty [t] gives an empty box.
  IntervalVector operator()(const IntervalVector& t) const;
  // The velocity form ∫_{[t1]}^{[t2]} [v] alone (equal to operator() without positions).
  IntervalVector velocity_form(const IntervalVector& t) const;
  // [J_f]([t]), same conventions.
  IntervalMatrix jacobian(const IntervalVector& t) const;

  // [v]([t]), the velocity hull over [t] ⊂ time_domain() (Error otherwise).
  IntervalVector velocity(const Interval& t) const;
  // Positions relative to the start: with p, [p]([t]); from v alone, the
  // set of ∫_{t0}^{t} v, t ∈ [t], i.e. p(t) - p(t0) with t0 the start of
  // v's time domain. [t] ⊂ time_domain().
  IntervalVector position(const Interval& t) const;
  // The ranges over t1 ∈ [t1], t2 ∈ [t2] of ∫_{t1}^{t2} v^- and of
  // ∫_{t1}^{t2} v^+ (6.11), per component: (lower, upper). The velocity
  // form of [f] is their hull when t1 <= t2 surely.
  std::pair<IntervalVector, IntervalVector> integral_bounds(const Interval& t1, const Interval& t2) const;

  // The same maps as callables for the zero tests (each holds a copy of
  // this LoopFunction, which shares the trees). Where p and w admit no
  // common trajectory ((7.28) empty), function() answers the velocity form,
  // which the zero tests accept (they read an empty image as a bug).
  PlaneFunction function() const;
  PlaneJacobian jacobian_function() const;
  // function(), remembering the primitive ranges of every [t1] and [t2] it
  // has met: the boxes of a paving share their sides, so the zero tests of
  // one region ask the trees a fraction of the times. The same values as
  // function(). Its copies share that memory: call it from one thread at a
  // time (one per region, as TPlane::compute_proofs does).
  PlaneFunction memoized_function() const;

 private:
  using Trees = std::array<std::shared_ptr<const SynthesisTree>, 2>;
  static Trees trees_of(const TubeVector& x, const char* what, const char* where);
  IntervalVector clamp(const IntervalVector& t, const char* where) const;
  void check_inside(const Interval& t, const char* where) const;
  // (7.28): the velocity form f intersected with [p]([t2]) - [p]([t1]).
  IntervalVector with_positions(IntervalVector f, const IntervalVector& t) const;
  // What function() answers on [t], given the velocity form there.
  IntervalVector for_zero_tests(const IntervalVector& t, const IntervalVector& velocity_form) const;

  Trees v_;  // velocity components
  Trees p_;  // position components (null without positions)
  Interval domain_;
};

}  // namespace sillage
