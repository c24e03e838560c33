#pragma once
// CtcT1T2: the inter-temporal contractor C_{t1,t2} of thesis Alg. 11,
// constraint (7.23)-(7.24):
//   p(t1) = p(t2), p' = w, t1 ∈ [t1], t2 ∈ [t2], p(·) ∈ [p](·).
// It is two evaluation constraints sharing their value a = b:
//   [a] = [p]([t1]);  C_eval([t2], [a], [p](·), [w](·));
//   [b] = [p]([t2]);  C_eval([t1], [b], [p](·), [w](·));
// repeated to a fixed point. Any dimension of p (one [t1], [t2] for all
// components). Only the gates and slices that CtcEval reaches are touched:
// no copy of the tube is made; what shrank can be reported per component
// (TubeChanges, as for network nodes).
//
// Fixed point: the loop stops when [t1], [t2], [a] and [b] no longer shrink
// by more than `ratio` (shrink.h; 0: any change). The tube's contraction
// depends on nothing else (CtcEval is a function of [t], [z] and the tube
// around them), so a further pass would only repeat the last one's sweeps.
// The TDomain is never sampled (a degenerate [t] is used as it is).
//
// Inconsistency: [t1], [t2] and [p](·) are set empty and contract returns false.
#include <cstddef>
#include <vector>

#include "sillage/cn/tube_changes.h"
#include "sillage/interval/interval.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// The inter-temporal contractor C_{t1,t2} (thesis Alg. 11, (7.23)-(7.24)): p(t1) = p(t2),
// p' = w. contract(t1, t2, p, w) contracts the Intervals t1, t2 and the tube p in place.
class CtcT1T2 {
 public:
  // ratio in [0, 1) (Error otherwise); max_passes >= 1 bounds the loop.
  explicit CtcT1T2(double ratio = 1e-3, std::size_t max_passes = 100);

  // The fixed-point ratio.
  double ratio() const { return ratio_; }
  // The cap on the passes.
  std::size_t max_passes() const { return max_passes_; }

  // DimensionError if p and w differ in size or TDomain; Error if [t1] or
  // [t2] does not meet p's time domain (they are intersected with it).
  bool contract(Interval& t1, Interval& t2, TubeVector& p, const TubeVector& w) const;
  // Scalar p.
  bool contract(Interval& t1, Interval& t2, Tube& p, const Tube& w) const;
  // On component tubes; changes[i] (one per p[i], or none at all) receives
  // the gates and slices of p[i] that changed. `passes`, if given, receives
  // the number of passes made.
  bool contract(Interval& t1, Interval& t2, const std::vector<Tube*>& p, const std::vector<const Tube*>& w,
                const std::vector<TubeChanges>& changes, std::size_t* passes = nullptr) const;

 private:
  double ratio_;
  std::size_t max_passes_;
};

}  // namespace sillage
