#pragma once
// sillage explain, and the explanation that sillage solve runs on a result
// without solution (docs/cli.md, "Why no solution").
#include <string>

#include "sillage/budget.h"
#include "sillage/problem/explain_empty.h"

namespace sillage::cli {

// The explanation of the failing solve r of p within `seconds` (each trial's contraction under
// `budget`), with a progress line on a terminal unless quiet.
Explanation explain_failure(const Problem& p, const SolveResult& r, double seconds, const Budget& budget, bool quiet);

// Solves the problem file with the options o and, without solution, prints what to relax (within
// `seconds`); exit status 1 then, 0 when there is nothing to explain, 3 when the solve stopped.
int explain(const std::string& file, SolveOptions o, double seconds);

}  // namespace sillage::cli
