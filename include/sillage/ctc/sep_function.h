#pragma once
// SepFunction: the separator of X = { x : f(x) is defined and f(x) ∈ [y] }.
//  - outer: CtcFunction(f, y), one HC4-revise pass;
//  - inner: the hull of the HC4 contractions of x_in onto the closed pieces of
//    the complement of [y] ({f_i <= lb(y_i)} and {f_i >= ub(y_i)}); what it
//    removes satisfies f(x) ∈ interior([y]). Since set-based evaluation ignores
//    the points where f is undefined, a partial f (sqrt, log, /, ...) must also
//    be proven defined on the removed part (DefinitionCheck); when that proof
//    fails, the inner contraction is given up (x_in left as is).
#include "sillage/ctc/ctc_function.h"
#include "sillage/ctc/definition_check.h"
#include "sillage/ctc/sep.h"

namespace sillage {

class SepFunction : public Sep {
 public:
  // X = {x : f(x) in the box y}.
  SepFunction(const Function& f, const IntervalVector& y);
  SepFunction(const Function& f, const Interval& y);  // X = {x : f(x) in y}, scalar f only

  void separate(IntervalVector& x_in, IntervalVector& x_out) const override;
  std::string name() const override { return "SepFunction"; }
  const CtcFunction& ctc_out() const { return outer_; }

 private:
  void contract_in(IntervalVector& x) const;

  CtcFunction outer_;
  DefinitionCheck check_;
};

}  // namespace sillage
