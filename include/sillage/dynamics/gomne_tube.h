#pragma once
// GOMNE over the fixes of a tube (see ctc/gomne.h for boxes): for q = 0, 1,
// ... the tube [x] is contracted by CtcQEval(q) (passes repeated while the
// tube changes, at most max_passes); the loop stops at the first q that does
// not empty it.
//
// What is proven, assuming only that the true trajectory lies in [x] with
// its derivative in [v]:
//  - every q' < q emptied the tube, so at least q fixes are wrong;
//  - if moreover at most q fixes are wrong, the truth lies in `x`, and every
//    index of `outliers` (a fix that no trajectory of the contracted tube
//    satisfies) is a wrong fix.
#include <cstddef>
#include <limits>
#include <vector>

#include "sillage/dynamics/ctc_qeval.h"

namespace sillage {

struct TubeGomneOptions {
  int q_max = std::numeric_limits<int>::max();  // clamped to m; >= 0
  int max_passes = 10;                          // CtcQEval passes per q; >= 1
};

// What gomne_tube proved; see gomne_tube.
struct TubeGomneResult {
  // The smallest q that did not empty the tube; q_max + 1 if all did.
  int q = 0;
  // The contracted tube for that q (empty if all did).
  TubeVector x;
  // Indices (increasing) of the fixes proven wrong, in the sense above.
  std::vector<std::size_t> outliers;
};

// Errors as CtcQEval::contract, and Error for q_max < 0 or max_passes < 1.
TubeGomneResult gomne_tube(const TubeVector& x, const TubeVector& v, const std::vector<TubeObservation>& obs,
                           const TubeGomneOptions& options = {});

}  // namespace sillage
