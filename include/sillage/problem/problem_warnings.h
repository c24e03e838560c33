#pragma once
// What a valid problem file may state without meaning to: an eval that uses
// no row (a table with only its header, a 'where' that keeps nothing), which
// then solves as if it were not there; values at times between two doubles
// on a tube without a derivative, which bound no gate. `sillage check` and
// `sillage solve` print them, results.json and the report carry them.
#include <string>
#include <vector>

#include "sillage/problem/problem.h"

namespace sillage {

// One sentence per warning, each naming its place in the file; none for a problem that states
// what it seems to.
std::vector<std::string> problem_warnings(const Problem& p);

}  // namespace sillage
