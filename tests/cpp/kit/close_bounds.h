#pragma once
// Two enclosures of the same set by two paths whose bounds may differ by
// rounding only (e.g. the vectorised sin/cos rows against the scalar
// functions): both empty, or each bound equal or within tol relative
// (absolute below 1); or their distance in doubles.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "sillage/interval/interval.h"

namespace sillage::test {

inline bool close_bound(double x, double y, double tol) {
  return x == y || std::fabs(x - y) <= tol * std::max(1.0, std::fabs(y));
}

inline bool close_bounds(const Interval& a, const Interval& b, double tol) {
  if (a.is_empty() || b.is_empty()) return a.is_empty() && b.is_empty();
  return close_bound(a.lb(), b.lb(), tol) && close_bound(a.ub(), b.ub(), tol);
}

// Position of a double on the ordered line of doubles (+0 and -0 both 0).
inline std::int64_t ord(double x) {
  const auto u = std::bit_cast<std::int64_t>(x);
  return u >= 0 ? u : -(u & std::numeric_limits<std::int64_t>::max());
}
// Doubles between x and y (0 for equal ones, infinities included).
inline std::uint64_t ulps_between(double x, double y) {
  const std::int64_t a = ord(x), b = ord(y);
  return a > b ? static_cast<std::uint64_t>(a - b) : static_cast<std::uint64_t>(b - a);
}
// The larger distance in doubles between the bounds of x and y; 0 for two
// empty sets, the largest value for one.
inline std::uint64_t ulps_between(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return x.is_empty() && y.is_empty() ? 0 : std::numeric_limits<std::uint64_t>::max();
  return std::max(ulps_between(x.lb(), y.lb()), ulps_between(x.ub(), y.ub()));
}

}  // namespace sillage::test
