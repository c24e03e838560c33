#pragma once
// Helpers shared by the chapter-5 examples and their benchmark: table
// entries written with two decimals, and doubles in expressions.
#include <cmath>
#include <cstdio>
#include <string>

#include "sillage/interval/interval.h"

namespace example {

// The enclosure of a table entry written with two decimals (the double 15.55
// is not the real 15.55): hundredths divided by 100, rounded outward.
inline sillage::Interval cents(const sillage::Interval& a) {
  return sillage::Interval(std::round(a.lb() * 100), std::round(a.ub() * 100)) / sillage::Interval(100);
}

// A double written exactly (17 significant digits) for an expression.
inline std::string num(double a) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", a);
  return buf;
}

}  // namespace example
