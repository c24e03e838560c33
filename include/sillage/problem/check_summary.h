#pragma once
// What `sillage check` prints: the network a problem would build, without
// building it (so it stays fast on large problems): the variables with their
// sizes, the constraints with their node counts, and a memory estimate.
#include <string>

#include "sillage/problem/problem.h"

namespace sillage {

// What `sillage check` prints: the variables, constraints, sizes and memory estimate of the
// network.
std::string check_summary(const Problem& p);

}  // namespace sillage
