#pragma once
// The bound audit of the real-data examples: given a ground truth, how much of
// each stated error bound the truth used ("turn rate: max 0.71 rad/s of 2
// allowed (36 %)"). The lines are the library's (sillage/problem/bound_audit.h,
// which also audits a problem file); the examples write their own, from the
// physics of each bound, and print them here.
#include <cstdio>
#include <string>
#include <vector>

#include "sillage/problem/bound_audit.h"

namespace example {

using sillage::AuditLine;
using sillage::audit_percent;
using sillage::audit_text;

// Prints the audit; returns true if no bound is violated by the truth.
inline bool print_audit(const std::string& title, const std::vector<AuditLine>& lines) {
  std::printf("bound audit (%s): how much of each bound the ground truth used\n", title.c_str());
  bool ok = true;
  for (const auto& l : lines) {
    std::printf("  %s\n", audit_text(l).c_str());
    ok = ok && !(audit_percent(l) > 100.0);
  }
  return ok;
}

}  // namespace example
