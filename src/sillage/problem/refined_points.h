#pragma once
// The time points of the next step of the automatic δ by time regions
// (DeltaRefinement::Regions, solve_problem.h; internal).
#include <vector>

#include "sillage/problem/build_network.h"

namespace sillage::detail {

// Those of b, and the middle of every slice whose excess thickness over its
// gates (slice diameter minus the larger gate's, summed over the tube
// components with a finite volume: what splitting the slice can remove) is
// above the quantile q of the slices' (every slice if none is: a uniform
// tube is halved). Error unless 0 <= q <= 1.
std::vector<double> refined_points(const BuiltProblem& b, double q);

}  // namespace sillage::detail
