#pragma once
// The other zero tests of thesis ch. 6 on a region of the plane:
//  - the interval Newton test N ([Moore 1979], the test of Aubry et al. 2013
//    that the degree test T is compared with, 6.3.1 and 6.4);
//  - the count of zeros (Alg. 10 with the auto-refinement of Remark 6.1).
#include <cstddef>
#include <optional>
#include <vector>

#include "sillage/loops/plane_function.h"
#include "sillage/loops/topological_degree.h"
#include "sillage/run_result.h"

namespace sillage {

// Tuning of newton_test.
struct NewtonOptions {
  std::size_t max_iterations = 20;  // Newton contractions [t] ← [t] ∩ N([t])
};

// The result of newton_test.
struct NewtonResult {
  bool proven = false;   // a unique zero of every f* enclosed exists in `box`
  IntervalVector box;    // the last contracted box (empty: no zero in the input box)
  // Newton contractions done.
  std::size_t nb_iterations = 0;
};

// Interval Newton on a box: N([t]) = m - [J]([t])^{-1} [f](m), m = mid([t]),
// iterated as [t] <- [t] ∩ N([t]) (also after the proof, to tighten the box)
// until a fixed point, 0 ∈ det [J] or max_iterations; proven when some
// N([t]) ⊂ interior([t]) (existence of a zero of f* in [t], unique in the
// input box). An empty result proves there is no zero. The 2x2 systems are
// enclosed by Cramer's rule, plain and preconditioned by mid([J])^{-1}
// (newton_test.cpp). f* is assumed C^1 with J_f* in [J].
NewtonResult newton_test(const IntervalVector& box, const PlaneFunction& f, const PlaneJacobian& jacobian,
                         const NewtonOptions& options = {});

// Tuning of count_zeros.
struct CountOptions {
  double min_width = 1e-9;          // ζ of Remark 6.1: boxes are not bisected below this width
  std::size_t max_boxes = 1u << 16; // cap on the refined boxes
  // Cancellation and time (budget.h); each box examined counts. Unlike
  // max_boxes (an inconclusive result), exceeding it throws.
  Budget budget;
};

// The result of count_zeros.
struct CountResult {
  std::optional<std::size_t> count;  // exact number of zeros in the region, when proven
  std::size_t nb_boxes = 0;          // boxes after the refinement
};

// Alg. 10: if the degree of f over the union `boxes` is d and det [J] keeps a
// constant non-zero sign on every part of the union where f may vanish, f*
// has exactly |d| zeros there. Boxes where det [J] contains 0 are bisected
// (Remark 6.1) down to min_width; sub-boxes where 0 ∉ [f] are dropped (they
// hold no zero). nullopt when this cannot be shown.
CountResult count_zeros(const std::vector<IntervalVector>& boxes, int degree, const PlaneFunction& f,
                        const PlaneJacobian& jacobian, const CountOptions& options = {});

// A count with how its computation ended (run_result.h): the CountResult of a
// finished run, no value once stopped or cancelled.
using CountRun = RunResult<CountResult>;
// count_zeros with how it ended, instead of BudgetExceeded or Cancelled from
// options.budget: Converged with the CountResult (its count may still be
// nullopt, as above), or Stopped / Cancelled with no value: the boxes examined
// so far count nothing.
CountRun count_zeros_run(const std::vector<IntervalVector>& boxes, int degree, const PlaneFunction& f,
                         const PlaneJacobian& jacobian, const CountOptions& options = {});

namespace detail {
// The same, counting against a meter shared with the caller (options.budget unused).
CountResult count_zeros(const std::vector<IntervalVector>& boxes, int degree, const PlaneFunction& f,
                        const PlaneJacobian& jacobian, const CountOptions& options, BudgetMeter& meter);
}  // namespace detail

}  // namespace sillage
