#include <string>

#include "sillage/error.h"
#include "sillage/loops/plane_evaluation.h"
#include "sillage/loops/zero_tests.h"

// Why |d| is the number of zeros (Alg. 10 with Remark 6.1's refinement).
//
// The refinement splits Ω into boxes that either hold no zero of f*
// (0 ∉ [f](box)) or on which det [J](box) has a constant sign s ≠ 0 — the
// same s on every such box, else nothing is concluded. Every zero x of f* in
// Ω then has det J_f*(x) ∈ det [J](box), of sign s: 0 is a regular value of
// f* on Ω, the zeros are isolated, finitely many in the compact Ω, none on
// ∂Ω (the degree d is defined), and d = Σ_x sign det J_f*(x) = s N by the
// definition of the degree [Milnor 1997, p. 27]. So N = |d|, and when d ≠ 0
// its sign must be s: a contradiction (or d ≠ 0 with no box left, i.e. no
// zero at all) cannot happen for a true inclusion function and the degree of
// this same f; we then answer nullopt rather than a count.

namespace sillage {

CountResult count_zeros(const std::vector<IntervalVector>& boxes, int degree, const PlaneFunction& f,
                        const PlaneJacobian& jacobian, const CountOptions& options) {
  BudgetMeter meter(options.budget, "count_zeros");
  return detail::count_zeros(boxes, degree, f, jacobian, options, meter);
}

CountRun count_zeros_run(const std::vector<IntervalVector>& boxes, int degree, const PlaneFunction& f,
                         const PlaneJacobian& jacobian, const CountOptions& options) {
  BudgetMeter meter(options.budget, "count_zeros");
  return detail::run_metered<CountResult>(
      meter, [&] { return detail::count_zeros(boxes, degree, f, jacobian, options, meter); });
}

CountResult detail::count_zeros(const std::vector<IntervalVector>& boxes, int degree, const PlaneFunction& f,
                                const PlaneJacobian& jacobian, const CountOptions& options, BudgetMeter& meter) {
  if (boxes.empty()) throw Error("count_zeros: no box (the region is empty)");
  if (!(options.min_width > 0)) {
    throw Error("count_zeros: min_width must be positive, got " + number_text(options.min_width));
  }
  for (const auto& b : boxes) detail::check_plane_box(b, "count_zeros");

  CountResult result;
  std::vector<IntervalVector> stack;
  for (auto it = boxes.rbegin(); it != boxes.rend(); ++it) {
    if (!it->is_empty()) stack.push_back(*it);
  }
  std::size_t leaves = stack.size();  // boxes of the current refinement of Ω
  int sign = 0;                        // of det [J] where f may vanish; 0: no such box yet
  while (!stack.empty()) {
    const IntervalVector b = stack.back();
    stack.pop_back();
    meter.add();
    const IntervalVector y = detail::eval_plane_function(f, b, "count_zeros");
    if (!y[0].contains(0.0) || !y[1].contains(0.0)) continue;  // no zero of f* in b
    const Interval det = detail::determinant2(detail::eval_plane_jacobian(jacobian, b, "count_zeros"));
    if (det.contains(0.0)) {
      // Remark 6.1: a smaller box gives a tighter Jacobian.
      if (b.max_diam() < options.min_width || leaves >= options.max_boxes) {
        result.nb_boxes = leaves;
        return result;
      }
      auto [lo, hi] = b.bisect();
      stack.push_back(std::move(hi));
      stack.push_back(std::move(lo));
      ++leaves;
      continue;
    }
    const int s = det.lb() > 0 ? 1 : -1;
    if (sign != 0 && s != sign) {  // zeros of both orientations may exist: d does not count them
      result.nb_boxes = leaves;
      return result;
    }
    sign = s;
  }
  result.nb_boxes = leaves;
  if (sign == 0) {
    // f* has no zero in Ω at all.
    if (degree == 0) result.count = 0;
    return result;
  }
  if (degree == 0 || (degree > 0) == (sign > 0)) result.count = static_cast<std::size_t>(degree < 0 ? -degree : degree);
  return result;
}

}  // namespace sillage
