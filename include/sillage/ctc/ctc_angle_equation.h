#pragma once
// CtcAngleEquation: s_1 a_1 + ... + s_m a_m + f(x) ≡ 0 (modulo 2π), the
// contractor of an equation between angles: a bearing b measured from a
// heading ψ, atan2(y_l - y, x_l - x) - ψ - b ≡ 0, whatever turn ψ is on.
// The a_i are angles known modulo 2π (interval/angle.h), s_i = ±1, f a real
// function (atan2 of the position, the measured bearing and its error).
//
// The box is (a_1, ..., a_m, x_1, ..., x_n). One pass:
//   [a_j] = angle_meet([a_j], s_j (-[f](x) - Σ_{i≠j} s_i [a_i]))
//   [f]'  = angle_lift(-Σ s_i [a_i], [f](x))     (every copy in [f](x): f is real)
//   [x]   by HC4-revise of f(x) ∈ [f]'
// A whole-circle a_i contracts nothing (the sum is then any angle).
#include <vector>

#include "sillage/ctc/ctc.h"
#include "sillage/expr/function.h"

namespace sillage {

class CtcAngleEquation : public Ctc {
 public:
  // signs: s_1..s_m, each +1 or -1 (Error otherwise, or if empty); f the
  // real part, a scalar function (DimensionError otherwise) of the box's
  // last f.nb_vars() components.
  CtcAngleEquation(std::vector<int> signs, const Function& f);

  void contract(IntervalVector& x) const override;
  std::string name() const override { return "CtcAngleEquation"; }
  std::string describe() const override;
  // The signs of the angles, in the box's order.
  const std::vector<int>& signs() const { return signs_; }
  // The real part f.
  const Function& function() const { return f_; }

 private:
  std::vector<int> signs_;
  Function f_;
};

}  // namespace sillage
