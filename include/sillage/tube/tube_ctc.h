#pragma once
// Pointwise constraints on tubes (thesis 3.2.3, Def. 3.3): the chapter-2
// forward-backward contractor of f(x) ∈ [y] applied at every time,
//   f(x_1(t), ..., x_n(t)) ∈ [y]   for all t in [t_0, t_N].
// Slice k is contracted as the box ([x_1](k), ..., [x_n](k)) and gate k as
// the box of the gates ([x_1](t_k), ..., [x_n](t_k)): a trajectory in the
// tubes satisfying the constraint has its values over slice k inside the
// slice box and satisfying f ∈ [y] there, so HC4 never removes them
// (contraction + consistency of Def. 3.3, rounding included).
//
// Before the gate pass, each gate is also intersected with its neighbouring
// slices (x(t_k) lies in both, as slices cover the closed [t_k, t_{k+1}]).
//
// Empty: the tubes hold no trajectory as soon as one slice or gate is empty
// (on input, or proven inconsistent by HC4); then every slice and gate of
// every tube is set empty, the canonical empty tube.
//
// One implementation with the network's TubeCtcNode: contract_time_elements
// (time_box_ctc.h), boxes by chunks, one HC4 batch per chunk for a
// CtcFunction.
#include <utility>
#include <vector>

#include "sillage/ctc/ctc_function.h"
#include "sillage/tube/tube.h"
#include "sillage/tube/tube_vector.h"

namespace sillage {

// Contracts the tubes x (x[i] is variable i of ctc.function()) in place and
// marks those that changed (their version steps). Returns false if the tubes are (now) empty.
// DimensionError if x.size() != ctc.nb_vars() or the tubes are not on the
// same TDomain; Error if a pointer is null or the same tube appears twice.
bool contract(const CtcFunction& ctc, const std::vector<Tube*>& x);
// Same, component i of x being variable i.
bool contract(const CtcFunction& ctc, TubeVector& x);

// Any box contractor, applied the same way (slice boxes, then gate boxes):
// one virtual call per slice and gate, on one reused buffer. A CtcFunction
// takes the path above. The contractor must satisfy Def. 2.1 on boxes for
// the result to be guaranteed.
bool contract(const Ctc& ctc, const std::vector<Tube*>& x);
bool contract(const Ctc& ctc, TubeVector& x);

// Convenience: a CtcFunction bound to tubes (f(x) ∈ y applied at every t).
class CtcTubeFunction {
 public:
  explicit CtcTubeFunction(CtcFunction ctc) : ctc_(std::move(ctc)) {}
  CtcTubeFunction(const Function& f, const IntervalVector& y) : ctc_(f, y) {}
  CtcTubeFunction(const Function& f, const Interval& y) : ctc_(f, y) {}
  explicit CtcTubeFunction(const Function& f) : ctc_(f) {}

  bool contract(const std::vector<Tube*>& x) const { return sillage::contract(ctc_, x); }
  bool contract(TubeVector& x) const { return sillage::contract(ctc_, x); }
  const CtcFunction& ctc() const { return ctc_; }

 private:
  CtcFunction ctc_;
};

}  // namespace sillage
