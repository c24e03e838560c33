#pragma once
// Shared checks of the C++ examples. An empty network is an answer (no
// solution fits the bounds and the data), printed with its explanation, never
// a success; a truth check proves something only on a non-empty, bounded
// enclosure ("100 % inside" an empty or unbounded tube proves nothing).
#include <cmath>
#include <cstdio>
#include <string>

#include "example_args.h"
#include "sillage/cn/contractor_network.h"

namespace example {

// "EMPTY: <why>": the answer of an empty network, for the output and the
// RESULT line, which then give no truth or box figures: the domains keep
// their last values (ContractorNetwork), but no solution lies in them.
inline std::string empty_text(const sillage::ContractStats& s) {
  return "EMPTY: " + s.emptiness + " (no solution: the bounds or the data are inconsistent)";
}

// True if the network is not empty; otherwise prints why (empty_text).
inline bool check_stats(const sillage::ContractStats& s, const std::string& label = "") {
  if (!s.empty) return true;
  std::printf("  %s%s\n", label.empty() ? "" : (label + ": ").c_str(), empty_text(s).c_str());
  return false;
}

// The end of an example whose network is empty: the explanation (check_stats)
// and a failed RESULT line, without the truth or box figures that the empty
// domains would give; the example returns this status, 1.
inline int empty_exit(const std::string& name, const sillage::ContractStats& s, const std::string& label = "") {
  check_stats(s, label);
  print_result(name, (label.empty() ? "" : label + ": ") + empty_text(s), false);
  return 1;
}

inline bool enclosure_ok(const sillage::IntervalVector& x) { return !x.is_empty() && !x.is_unbounded(); }
inline bool enclosure_ok(const sillage::Tube& x) {
  const sillage::Interval c = x.codomain();
  return !x.is_empty() && std::isfinite(c.lb()) && std::isfinite(c.ub());
}
inline bool enclosure_ok(const sillage::TubeVector& x) { return !x.is_empty() && enclosure_ok(x.codomain()); }

}  // namespace example
