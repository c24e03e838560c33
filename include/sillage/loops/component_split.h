#pragma once
// Splitting a region of the t-plane into pieces with zero-free boundaries
// (beyond thesis 6.4.3, where a component of degree 0 proves nothing).
//
// A component Ω of degree 0 may hold two zeros of opposite orientations
// (two passes crossing twice), or none. It is refined locally: every box is
// bisected, and the halves on which 0 ∉ [f] are dropped (they hold no zero
// of f*). What is left falls apart into connected components (corners
// connect) where the feasible set allows it; the dropped boxes are the cuts
// between them. Each component is a piece: its degree is computed on its own
// boundary (topological_degree.h, edges refined along their length), and
// its zeros counted (Alg. 10). Pieces that are not yet settled (degree 0 or
// undetermined with no count, or a degree whose count is unknown) are refined
// again, down to max_levels bisections, so that a narrow waist of Ω is cut
// at the precision it needs and nowhere else.
//
// Why it is sound: f* has no zero in Ω outside the pieces, the pieces are
// disjoint compact sets inside Ω, and the boundary of each is proven free of
// zeros when its degree is determined; by excision and additivity of the
// degree, deg(Ω) = Σ deg(pieces) whenever all are determined. A piece of
// degree d ≠ 0 proves a zero in it; a piece whose count is n holds exactly n
// zeros; a region whose boxes are all dropped holds none.
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include "sillage/budget.h"
#include "sillage/loops/plane_function.h"
#include "sillage/loops/zero_tests.h"
#include "sillage/run_result.h"

namespace sillage {

// Tuning of split_region.
struct SplitOptions {
  // Bisections of every box of a piece still to settle: 8 levels refine an
  // eps-paving down to eps/16 (each level halves the boxes' area).
  std::size_t max_levels = 8;
  // Cap on the boxes of one piece being refined (then it stays unsettled).
  std::size_t max_boxes = 1u << 15;
  DegreeOptions degree;  // for the degree of each piece (its budget unused)
  bool count = true;     // count the zeros of each piece (Alg. 10)
  CountOptions count_options;  // (its budget unused)
  Budget budget;         // for the whole split: every evaluation of [f] counts as a box
  // Optional: true for a box proven to lie in the feasible set {0 ∈ [f]}
  // (e.g. the Inner test (6.10) of the t-plane). No cut can cross such a box,
  // so it is kept whole instead of bisected, and so are its halves. It is
  // asked of the boxes of the region only: on the halves made by the
  // refinement it would cost more evaluations than it saves over a few
  // levels. Soundness never depends on it.
  std::function<bool(const IntervalVector&)> inside;
  // A half whose [f] holds 0 farther than this fraction of its width from
  // both bounds, on both components, is not bisected again: its halves would
  // hold 0 as well (cost only, never soundness; 0: bisect every box).
  double deep_margin = 0.05;
};

// One piece of a split region: a union of boxes, disjoint from the other
// pieces, its boundary free of zeros when its degree is determined.
struct SplitPiece {
  // Its boxes.
  std::vector<IntervalVector> boxes;
  IntervalVector t_box = IntervalVector(2, Interval::empty());  // hull of the boxes
  std::optional<int> degree;         // nullopt: undetermined
  std::optional<std::size_t> count;  // exact number of zeros, when proven
  // The degree is known and non-zero: a zero lies in the piece.
  bool proves_zero() const { return degree && *degree != 0; }
};

// The result of split_region.
struct SplitResult {
  // The pieces, ordered by the lower corner of their hull; every zero of f*
  // in the region lies in one of them.
  std::vector<SplitPiece> pieces;
  std::size_t nb_evaluations = 0;  // of [f] for the refinement (the degree and count not included)
  std::size_t nb_levels = 0;       // deepest refinement level reached
  // Σ deg(pieces) when every degree is determined (equals the degree of the region).
  std::optional<int> degree() const;
  // Σ count(pieces) when every piece is counted: the number of zeros in the region.
  std::optional<std::size_t> count() const;
  std::size_t nb_proven() const;   // pieces of non-zero degree
};

// Splits the union of `boxes` (2-D, bounded, disjoint interiors, e.g. a
// component of a paving) as described above. Throws Error for an empty list,
// max_levels == 0 or max_boxes == 0, and the errors of topological_degree and
// count_zeros; BudgetExceeded / Cancelled from options.budget.
SplitResult split_region(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                         const PlaneJacobian& jacobian, const SplitOptions& options = {});

// A split with how its computation ended (run_result.h): the SplitResult of a
// finished run, no value once stopped or cancelled.
using SplitRun = RunResult<SplitResult>;
// split_region with how it ended, instead of BudgetExceeded or Cancelled from
// options.budget: Converged with the SplitResult, or Stopped / Cancelled with
// no value: the pieces assessed so far do not cover the region.
SplitRun split_region_run(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                          const PlaneJacobian& jacobian, const SplitOptions& options = {});

namespace detail {
// The same, counting against a meter shared with the caller (options.budget
// unused), for a region whose degree is already known when `degree` is set
// (and whose zeros could not be counted: not tried again on the same zeros).
// `inside`, if not empty, flags the boxes known to lie in the feasible set
// (then options.inside is not asked).
SplitResult split_region(const std::vector<IntervalVector>& boxes, const PlaneFunction& f,
                         const PlaneJacobian& jacobian, const SplitOptions& options, BudgetMeter& meter,
                         const std::optional<int>& degree, const std::vector<bool>& inside = {});
}  // namespace detail

}  // namespace sillage
