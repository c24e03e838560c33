#pragma once
// The loops of a solved problem ([output] loops, thesis ch. 6): the t-plane
// of its velocity tube (or of its position and velocity tubes, (7.28)),
// detections paved down to eps, then the proofs (degree test, Newton, count).
#include "sillage/loops/tplane.h"
#include "sillage/problem/build_network.h"

namespace sillage {

// The loops asked by p.output.loops over the domains of b. Error if p asks
// none. The paving width: the file's eps, else (tf - t0)/2000 (as thesis 6.4).
TPlane find_loops(const Problem& p, const BuiltProblem& b);

}  // namespace sillage
