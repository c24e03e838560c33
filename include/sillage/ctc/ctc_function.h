#pragma once
// CtcFunction: the contractor of f(x) ∈ [y] by one HC4-revise pass
// (forward-backward propagation over the expression DAG, thesis 2.3.1).
// CtcFunction(f) stands for f(x) = 0. Wrap it in CtcFixPoint to iterate.
#include "sillage/ctc/ctc.h"
#include "sillage/expr/function.h"

namespace sillage {

class CtcFunction : public Ctc {
 public:
  // y.size() must equal f.image_dim() (else DimensionError).
  CtcFunction(const Function& f, const IntervalVector& y);
  // f(x) in the interval y, for a scalar f only (else DimensionError).
  CtcFunction(const Function& f, const Interval& y);
  // f(x) = 0.
  explicit CtcFunction(const Function& f);

  void contract(IntervalVector& x) const override;
  std::string name() const override { return "CtcFunction"; }
  std::string describe() const override { return "CtcFunction(" + f_.expr_str() + ")"; }
  // The function f.
  const Function& function() const { return f_; }
  // The image box [y].
  const IntervalVector& image() const { return y_; }

 private:
  Function f_;
  IntervalVector y_;
};

}  // namespace sillage
