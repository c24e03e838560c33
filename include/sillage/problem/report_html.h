#pragma once
// DIR/report.html: one self-contained page (inline SVG and CSS, no script,
// nothing fetched), readable offline: the problem file, the δ schedule, the
// results at the requested times (t0, the middle and tf by default), the
// figures (each tube component over time, the 2-D maps asked in [output],
// the thickness), the truth check and the run statistics.
#include <string>

#include "sillage/problem/explain_empty.h"
#include "sillage/problem/solve_problem.h"

namespace sillage {

// The truth check of [output.truth]: the time points (rows of the truth
// table within [t0, tf]) and those with every component inside the tubes,
// and the first misses. A value in an unbounded (or empty) tube value is a
// miss: such a domain proves nothing.
struct TruthCheck {
  std::size_t samples = 0, inside = 0;
  std::vector<std::string> first_misses;  // up to 10, "x[1] = 3.2 at t = 4 outside [2.9, 3.1]"
};
// The truth check of [output.truth] on the solved domains b (zero samples when the
// problem gives no truth); in Python check_truth(problem, result).
TruthCheck check_truth(const Problem& p, const BuiltProblem& b);

// The page of the solve r of p. No solution: the explanation e at the top when given (what to
// relax, the values proven), and the tubes as they were just before the contradiction
// (r.before_empty) with the blamed statements marked, in place of the empty figures.
std::string report_html(const Problem& p, const SolveResult& r, const Explanation* e = nullptr);

}  // namespace sillage
