#pragma once
// CtcQEval: position fixes on a tube when some of them may be wrong. The
//  x(t_i) ∈ [z_i], t_i ∈ [t_i], i = 1..m, of a trajectory x with
// x' ∈ [v] are relaxed so that at most q of them may be wrong:
//   - a copy of [x] is contracted by each observation alone (CtcEval with
//     the derivative [v], which carries the fix along the whole tube);
//   - [x] is intersected, gate by gate and slice by slice, with the
//     q-relaxed intersection (q_inter) of the m copies; a copy that came out
//     empty counts as an observation violated by every trajectory of [x].
// Guarantee: a trajectory of [x] (with derivative in [v]) that satisfies at
// least m - q observations lies in the copies of those observations, so at
// each time its value is in m - q of the copies' gates / slices: it is kept.
// q = 0 is the intersection of the m CtcEval contractions; q >= m leaves [x]
// unchanged. The TDomain is never sampled (copies share it): sample it at a
// degenerate t_i beforehand for the tightest result.
#include <cstddef>
#include <vector>

#include "sillage/ctc/ctc_algebra.h"
#include "sillage/interval/interval_vector.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// One fix: x(t) ∈ z for some t ∈ [t], and z satisfies the constraint of
// `ctc` (null: none). A range r to a beacon b is z = IntervalVector(n) with
// ctc = CtcFunction(|z - b|, [r]); a position fix is a bounded z alone.
struct TubeObservation {
  Interval t;
  IntervalVector z;
  CtcPtr ctc = nullptr;  // on z.size() variables
};

class CtcQEval {
 public:
  // q >= 0 (else Error).
  explicit CtcQEval(int q);
  int q() const { return q_; }

  // Contracts x; v is its derivative (same TDomain and size, else
  // DimensionError); each z of the non-empty list obs has x.size()
  // components and each ctc acts on x.size() variables (else Error /
  // DimensionError). Returns the indices of the
  // observations that no trajectory of the input [x] satisfies (their copy
  // came out empty): if at most q observations are wrong, they are wrong.
  std::vector<std::size_t> contract(TubeVector& x, const TubeVector& v, const std::vector<TubeObservation>& obs) const;

 private:
  int q_;
};

}  // namespace sillage
