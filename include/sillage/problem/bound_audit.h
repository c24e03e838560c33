#pragma once
// The bound audit: given a ground truth, how much of each stated error bound
// the truth used ("turn rate: max 0.71 rad/s of 4 allowed (18 %)"). It
// reports; it never changes a bound. A bound the truth uses at more than
// 100 % is violated (the guarantee is void); one it uses at nearly 100 % was
// probably read off the file it is applied to. The real-data examples write
// their own lines (examples/cpp/plaza1_bounds.h); audit_problem writes them
// for a problem file with [output.truth], from the file alone (no solve).
#include <string>
#include <vector>

#include "sillage/problem/problem.h"

namespace sillage {

// One bound of the audit.
struct AuditLine {
  std::string name;   // the bound
  std::string unit;   // its unit ("" if none is stated)
  double allowed = 0;  // the stated bound (a magnitude, > 0)
  double used = 0;     // the largest value the truth needs (NaN: not measurable from the truth)
  std::string how;     // how `used` was measured, and where
};

// used / allowed in percent (NaN if not measurable).
double audit_percent(const AuditLine& l);

// "name: max U unit of A allowed (P %; how)", one line, "  <-- VIOLATED" above 100 %.
std::string audit_text(const AuditLine& l);

// The audit of the bounds of a problem file against its truth ([output.truth]; none without one),
// for the variables the truth gives: every bound of a [var] value and 'at', and every eval
// constraint whose expression reads only such variables and its rows' columns. A bound B, an
// interval, is used by the truth's value x as |x - mid(B)| of rad(B) allowed: 100 % at an edge
// of B. An eval row is the interval I of its expression with the truth in place of its variables
// (its columns and their stated errors as the solve reads them): the truth used |mid(I)| of rad(I)
// (0 must be in I), at the best of 9 times spread over the row's time window (stamp ± time_error),
// the worst row reported. Other constraints state bounds the truth does not give (a heading, a
// speed): a line "not measurable" names what is missing.
std::vector<AuditLine> audit_problem(const Problem& p);

}  // namespace sillage
