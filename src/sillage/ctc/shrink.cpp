#include "sillage/ctc/shrink.h"

#include <cmath>
#include <string>

namespace sillage {

namespace {

// A finite bound moved from a to b (both may be infinite).
bool bound_moved(double a, double b, double ratio) {
  if (a == b) return false;
  if (std::isinf(a)) return true;  // an infinite bound became finite
  return std::fabs(b - a) > ratio * std::fmax(1.0, std::fabs(a));
}

}  // namespace

bool shrank(const Interval& before, const Interval& after, double ratio) {
  if (before.is_empty()) return false;
  if (after.is_empty()) return true;
  if (before == after) return false;
  if (ratio == 0.0) return true;
  if (before.is_bounded()) {
    const double d = before.diam();
    return d - after.diam() > ratio * d;
  }
  return bound_moved(before.lb(), after.lb(), ratio) || bound_moved(before.ub(), after.ub(), ratio);
}

bool shrank(const IntervalVector& before, const IntervalVector& after, double ratio) {
  check_same_size(before.size(), after.size(), "shrank");
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (shrank(before[i], after[i], ratio)) return true;
  }
  return false;
}

void check_ratio(double ratio, const char* where) {
  if (!(ratio >= 0.0 && ratio < 1.0)) {
    throw Error(std::string(where) + ": ratio must lie in [0, 1), got " + std::to_string(ratio));
  }
}

}  // namespace sillage
