#pragma once
// GOMNE, the guaranteed outlier minimal number estimator (Jaulin, Walter,
// Didrit 1996): for q = 0, 1, 2, ... the set
//     S_q = {x in [x0] : x satisfies at least m - q of the m constraints}
// is enclosed by CtcQInter(ctcs, q) iterated to a fixed point and, when
// eps is finite, by a paving to precision eps (a box contraction alone
// often cannot prove emptiness); the loop stops at the first q whose
// enclosure is not empty.
//
// What is proven, assuming only that the true state lies in [x0]:
//  - for every q' < q, S_q' is empty, so at least q constraints are wrong:
//    `q` is a guaranteed lower bound on the number of outliers;
//  - if moreover at most q constraints are wrong (GOMNE's hypothesis: the
//    outliers are as few as the data allow), the truth lies in S_q, hence in
//    every leaf union and in `box`;
//  - under that same hypothesis, measurement i is a proven outlier when its
//    contractor empties every leaf: no point of S_q satisfies constraint i,
//    so the truth does not, so measurement i is wrong. Then at most
//    q - outliers.size() of the other measurements are wrong.
// If more than q constraints are actually wrong, `box` and `outliers` carry
// no guarantee (only the lower bound q does).
#include <cstddef>
#include <limits>
#include <vector>

#include "sillage/ctc/ctc_algebra.h"

namespace sillage {

struct GomneOptions {
  // Boxes whose largest side exceeds eps are bisected (depth-first) after
  // contraction; the default, +inf, only contracts. eps > 0; a finite eps
  // needs a bounded [x0].
  double eps = std::numeric_limits<double>::infinity();
  // The largest q tried (clamped to m); q_max >= 0.
  int q_max = std::numeric_limits<int>::max();
  // Fixed-point ratio of the contraction of each box (see shrink.h).
  double ratio = 0.01;
};

// What gomne proved; see gomne.
struct GomneResult {
  // The smallest q whose relaxed set was not proven empty; q_max + 1 when
  // every q <= q_max was (then box is empty and there is no leaf).
  int q = 0;
  // Hull of the leaves: encloses S_q.
  IntervalVector box;
  // Indices (increasing) of the proven outliers, in the sense above.
  std::vector<std::size_t> outliers;
  // The non-empty boxes left by the paving of S_q (just {box} when eps = inf).
  std::vector<IntervalVector> leaves;
  // True when no box is left (more than q_max constraints are wrong).
  bool is_empty() const { return box.is_empty(); }
};

// Throws Error for an empty list, a null contractor, eps <= 0 or NaN,
// q_max < 0, a bad ratio, or a finite eps with an unbounded box;
// DimensionError when a contractor and the box disagree in size.
GomneResult gomne(const std::vector<CtcPtr>& ctcs, const IntervalVector& box, const GomneOptions& options = {});

}  // namespace sillage
