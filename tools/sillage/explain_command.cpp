#include "explain_command.h"

#include <unistd.h>

#include <cstdio>

#include "sillage/problem/load_problem.h"

namespace sillage::cli {

Explanation explain_failure(const Problem& p, const SolveResult& r, double seconds, const Budget& budget, bool quiet) {
  ExplainOptions o;
  o.max_seconds = seconds;
  o.budget = budget;
  if (!quiet && isatty(STDERR_FILENO))
    std::fprintf(stderr, "no solution: looking for the statements to relax (at most %g s; --explain-seconds)...\n", seconds);
  return explain_empty(p, r, o);
}

int explain(const std::string& file, SolveOptions o, double seconds) {
  const Problem p = load_problem(file);
  o.keep_before_empty = false;
  check_solve_options(p, o, "--");
  const SolveResult r = solve_problem(p, o);
  if (!r.stopped.empty()) {
    std::fprintf(stderr, "sillage: the solve stopped before its fixed point, nothing to explain: %s\n", r.stopped.c_str());
    return 3;
  }
  if (!r.empty) {
    std::printf("%s: %s", file.c_str(), explain_failure(p, r, seconds, o.budget, true).str().c_str());
    return 0;
  }
  std::printf("%s: NO SOLUTION\n  %s\n", file.c_str(), r.why_empty.c_str());
  std::fputs(explain_failure(p, r, seconds, o.budget, false).str().c_str(), stdout);
  return 1;
}

}  // namespace sillage::cli
