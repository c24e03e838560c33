#pragma once
// The stated error bounds of the C++ examples, as example_args.bound in
// Python: SILLAGE_EXAMPLE_TIGHTEN=f (default 1) tightens them, so that the
// tests can make a network empty (f = 0.001: too tight for the truth) and
// check that the example says EMPTY and why, with no truth figures, exit 1.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "sillage/interval/interval.h"

namespace example {

// A value that is not a number >= 0 is bad input (exit 2), never a silent 0.
inline double tighten_factor() {
  const char* f = std::getenv("SILLAGE_EXAMPLE_TIGHTEN");
  if (!f) return 1.0;
  char* end = nullptr;
  const double v = std::strtod(f, &end);
  if (end == f || *end != '\0' || !std::isfinite(v) || v < 0) {
    std::fprintf(stderr, "SILLAGE_EXAMPLE_TIGHTEN: expected a number >= 0, got '%s'\n", f);
    std::exit(2);
  }
  return v;
}

// A radius or an error magnitude times f.
inline double bound(double x) { return x * tighten_factor(); }

// [a, b] reduced to [a, a + f (b - a)]: from one end, not about the middle,
// where the truth often is; a point bound cannot be tighter, so it empties.
inline sillage::Interval bound(const sillage::Interval& x) {
  const double f = tighten_factor();
  if (f == 1) return x;
  if (x.lb() == x.ub()) return sillage::Interval::empty();
  return sillage::Interval(x.lb(), x.lb() + f * (x.ub() - x.lb()));
}

}  // namespace example
