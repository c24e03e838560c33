#pragma once
// The bound audit of the real-data examples: given a ground truth, how much of
// each stated error bound the truth used ("turn rate: max 0.71 rad/s of 2
// allowed (36 %)"). It reports; it never changes a bound. A bound the truth
// uses at 100 % or more is violated; one it uses at nearly 100 % was probably
// read off the file it is applied to.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace example {

struct AuditLine {
  std::string name;     // the bound
  std::string unit;
  double allowed = 0;   // the stated bound (a magnitude, > 0)
  double used = 0;      // the largest value the ground truth needs (NaN: not measurable from the truth)
  std::string how;      // how `used` was measured
};

// used / allowed in percent (NaN if not measurable).
inline double audit_percent(const AuditLine& l) { return 100.0 * l.used / l.allowed; }

// "name: max U unit of A allowed (P %)", one line, "  <-- VIOLATED" at >= 100 %.
inline std::string audit_text(const AuditLine& l) {
  char buf[400];
  if (std::isnan(l.used)) {
    std::snprintf(buf, sizeof buf, "%s: %.4g %s allowed, not measurable from the truth (%s)", l.name.c_str(),
                  l.allowed, l.unit.c_str(), l.how.c_str());
  } else {
    const double p = audit_percent(l);
    std::snprintf(buf, sizeof buf, "%s: max %.4g %s of %.4g allowed (%.0f %%; %s)%s", l.name.c_str(), l.used,
                  l.unit.c_str(), l.allowed, p, l.how.c_str(), p > 100.0 ? "  <-- VIOLATED" : "");
  }
  return buf;
}

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
