#include "sillage/ctc/ctc_angle_equation.h"

#include <string>
#include <utility>

#include "sillage/error.h"
#include "sillage/interval/angle.h"

namespace sillage {

namespace {

std::size_t checked_size(const std::vector<int>& signs, const Function& f) {
  if (signs.empty()) throw Error("CtcAngleEquation: no angle (signs is empty): use CtcFunction");
  for (std::size_t i = 0; i < signs.size(); ++i)
    if (signs[i] != 1 && signs[i] != -1)
      throw Error("CtcAngleEquation: sign " + std::to_string(i) + " is " + std::to_string(signs[i]) + ", expected +1 or -1");
  if (f.image_dim() != 1)
    throw DimensionError("CtcAngleEquation: f has " + std::to_string(f.image_dim()) + " outputs, expected 1");
  return signs.size() + f.nb_vars();
}

Interval signed_by(int s, const Interval& x) { return s > 0 ? x : -x; }

}  // namespace

CtcAngleEquation::CtcAngleEquation(std::vector<int> signs, const Function& f)
    : Ctc(checked_size(signs, f)), signs_(std::move(signs)), f_(f) {}

std::string CtcAngleEquation::describe() const {
  std::string s = "CtcAngleEquation(";
  for (std::size_t i = 0; i < signs_.size(); ++i) s += (signs_[i] > 0 ? "+a" : "-a") + std::to_string(i + 1) + " ";
  return s + "+ " + f_.expr_str() + " = 0 mod 2pi)";
}

void CtcAngleEquation::contract(IntervalVector& x) const {
  check_dim(x);
  if (x.is_empty()) return x.set_empty();
  const std::size_t m = signs_.size(), n = f_.nb_vars();
  IntervalVector args(n);
  for (std::size_t i = 0; i < n; ++i) args[i] = x[m + i];
  const Interval fx = f_.eval(args);
  // The angles, each from the others and f.
  for (std::size_t j = 0; j < m; ++j) {
    Interval rest = -fx;
    for (std::size_t i = 0; i < m; ++i)
      if (i != j) rest -= signed_by(signs_[i], x[i]);
    x[j] = angle_meet(x[j], signed_by(signs_[j], rest));
    if (x[j].is_empty()) return x.set_empty();
  }
  // f from the angles, then its arguments.
  Interval sum(0.0);
  for (std::size_t i = 0; i < m; ++i) sum += signed_by(signs_[i], x[i]);
  const Interval target = angle_lift(-sum, fx);  // f is real: every copy in [f](x) stays
  if (target.is_empty()) return x.set_empty();
  if (target == fx) return;
  if (!f_.hc4_revise(args, IntervalVector{target}) || args.is_empty()) return x.set_empty();
  for (std::size_t i = 0; i < n; ++i) x[m + i] = args[i];
}

}  // namespace sillage
