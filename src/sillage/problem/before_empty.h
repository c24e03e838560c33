#pragma once
// The domains of a failing solve just before the contractor that emptied
// one of them ran (internal; solve_problem keeps them for the reports).
#include <optional>
#include <vector>

#include "sillage/problem/solve_problem.h"

namespace sillage::detail {

// The step that emptied (on `points`, or δ = delta when points is empty)
// built again and contracted with the same budget, cut at failed's
// contractor runs minus one: the propagation is deterministic, so it stops
// right before the run that emptied a domain. Every value it removed was
// removed by a contractor of the problem, hence is in no solution; what is
// left is where the constraints met before the contradiction showed.
// None when the problem was empty on input (no contractor ran) or the run
// differs (the replay empties too).
std::optional<BuiltProblem> before_empty(const Problem& p, const std::vector<double>& points, double delta,
                                         const SolveOptions& o, const ContractStats& failed);

}  // namespace sillage::detail
