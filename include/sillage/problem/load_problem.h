#pragma once
// Reads and validates a problem file (TOML, docs/cli.md): the time domain,
// the data tables (CSV, paths relative to the problem file), the variables,
// the constraints and the output. Every error is a ProblemError
// "file:line:column: found ..., expected ...": unknown keys, wrong types,
// unknown variables in an expression, dimension mismatches, missing columns,
// unreadable CSV rows (the CSV's own file and line).
#include <string>

#include "sillage/problem/problem.h"

namespace sillage {

Problem load_problem(const std::string& path);
// From text in memory; `path` names it in messages and is the base of the
// data paths.
Problem parse_problem(const std::string& text, const std::string& path);

}  // namespace sillage
