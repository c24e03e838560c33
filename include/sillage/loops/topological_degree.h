#pragma once
// Topological degree of a planar map over a union of boxes (thesis 6.3.2-6.3.3,
// Theorem 6.1 and Alg. 7-9): deg(f*, Ω) is the winding number around 0 of
// f* along the oriented boundary ∂Ω. It is determined by [f] as soon as
// 0 ∉ [f]([b]) on edges [b] covering ∂Ω, and then deg ≠ 0 proves a zero of
// f* in Ω (6.12), for every f* enclosed by [f].
//
// Improvement over Alg. 8 as printed: an edge on which 0 ∈ [f]([b]) is not a
// failure but is bisected along its length (a sub-edge evaluation is tighter)
// until every piece excludes 0 or a piece is shorter than min_edge_length;
// the test thus concludes far more often. Results never depend on threads.
#include <cstddef>
#include <optional>
#include <vector>

#include "sillage/budget.h"
#include "sillage/loops/plane_function.h"
#include "sillage/paving/contour.h"
#include "sillage/run_result.h"

namespace sillage {

// Tuning of topological_degree.
struct DegreeOptions {
  // A piece shorter than this is not bisected (> 0; in the units of the
  // plane, e.g. seconds for a t-plane).
  double min_edge_length = 1e-9;
  // Cap on the evaluations of [f] for one degree (guards against an edge
  // that holds a true zero: then no subdivision can conclude).
  std::size_t max_evaluations = 1u << 20;
  // Cancellation and time (budget.h); each evaluation counts as a box. Unlike
  // max_evaluations (an inconclusive result), exceeding it throws.
  Budget budget;
};

// The result of topological_degree.
struct DegreeResult {
  // The degree, when every boundary piece excludes 0; nullopt otherwise
  // (the test is inconclusive: nothing is proven, nothing is disproven).
  std::optional<int> degree;
  std::size_t nb_evaluations = 0;   // calls of [f]
  std::size_t nb_pieces = 0;        // boundary pieces of the final cover
  std::size_t nb_unresolved = 0;    // pieces with 0 ∈ [f] at the floor, or left
                                    // unevaluated once max_evaluations is spent
  // True when the degree is known and non-zero: f has a zero in the region.
  bool proves_zero() const { return degree && *degree != 0; }
};

// Degree of f over the region bounded by `loops` (contour.h orientation:
// outer loops counter-clockwise, holes clockwise; the degree is the sum of
// the winding numbers over all loops; any closed loops of axis-aligned edges
// are accepted, the sign following their orientation). Throws Error for an
// empty loop list, an empty or open loop, a slanted or non-finite edge,
// min_edge_length <= 0 or max_evaluations == 0, and when [f] breaks the
// inclusion contract (wrong size, empty, opposite signs on pieces sharing a
// point); the proof of the count is in topological_degree.cpp.
DegreeResult topological_degree(const std::vector<ContourLoop>& loops, const PlaneFunction& f,
                                const DegreeOptions& options = {});
// Same over a union of 2-D boxes with disjoint interiors (its contour()).
DegreeResult topological_degree(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                                const DegreeOptions& options = {});

// A degree with how its computation ended (run_result.h): the DegreeResult of a
// finished run, no value once stopped or cancelled.
using DegreeRun = RunResult<DegreeResult>;
// topological_degree with how it ended, instead of BudgetExceeded or Cancelled
// from options.budget: Converged with the DegreeResult (which may still be
// inconclusive, as above), or Stopped / Cancelled with no value: the degree of
// part of the boundary is no answer.
DegreeRun topological_degree_run(const std::vector<ContourLoop>& loops, const PlaneFunction& f,
                                 const DegreeOptions& options = {});
// The same over a union of 2-D boxes with disjoint interiors.
DegreeRun topological_degree_run(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                                 const DegreeOptions& options = {});

namespace detail {
// The same, counting against a meter shared with the caller (options.budget unused).
DegreeResult topological_degree(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                                const DegreeOptions& options, BudgetMeter& meter);
}  // namespace detail

}  // namespace sillage
