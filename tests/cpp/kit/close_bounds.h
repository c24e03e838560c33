#pragma once
// Two enclosures of the same set by two paths whose bounds may differ by
// rounding only (e.g. the vectorised sin/cos rows against the scalar
// functions): both empty, or each bound equal or within tol relative
// (absolute below 1).
#include <algorithm>
#include <cmath>

#include "sillage/interval/interval.h"

namespace sillage::test {

inline bool close_bound(double x, double y, double tol) {
  return x == y || std::fabs(x - y) <= tol * std::max(1.0, std::fabs(y));
}

inline bool close_bounds(const Interval& a, const Interval& b, double tol) {
  if (a.is_empty() || b.is_empty()) return a.is_empty() && b.is_empty();
  return close_bound(a.lb(), b.lb(), tol) && close_bound(a.ub(), b.ub(), tol);
}

}  // namespace sillage::test
