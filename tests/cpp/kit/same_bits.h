#pragma once
// Bit-for-bit equality of intervals (signs of zero included; all empty
// intervals alike), for tests that compare two evaluation paths exactly.
#include <cstring>

#include "sillage/interval/interval.h"

namespace sillage::test {

inline bool same_bits(const Interval& a, const Interval& b) {
  if (a.is_empty() || b.is_empty()) return a.is_empty() && b.is_empty();
  const double x[2] = {a.lb(), a.ub()}, y[2] = {b.lb(), b.ub()};
  return std::memcmp(x, y, sizeof x) == 0;
}

}  // namespace sillage::test
