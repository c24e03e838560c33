#pragma once
// When did a contraction "really" shrink a domain? Fixed-point loops
// (CtcFixPoint, ContractorNetwork) stop once no domain shrinks by more than a
// relative ratio of its size; this only steers the scheduling, never the rigor
// (every intermediate box is a valid enclosure).
#include <cmath>

#include "sillage/interval/interval_vector.h"

namespace sillage {

// True when `after` (a subset of `before`) is smaller than `before` by more
// than `ratio`:
//  - a bounded interval: its diameter decreased by more than ratio * diam(before);
//  - an unbounded one: an infinite bound became finite, or a finite bound moved
//    by more than ratio * max(1, |bound|);
//  - becoming empty always counts; ratio = 0 counts every change.
// Each counted step shrinks a bounded diameter by a factor (1 - ratio) or moves a
// bound geometrically, so loops built on it terminate for 0 <= ratio < 1.
// Inline: a network asks this for every atom a contractor changed.
inline bool shrank(const Interval& before, const Interval& after, double ratio) {
  if (before.is_empty()) return false;
  if (after.is_empty()) return true;
  if (before == after) return false;
  if (ratio == 0.0) return true;
  if (before.is_bounded()) {
    // The diameters, rounded up as Interval::diam does.
    const double d = rounding::sub_up(before.ub(), before.lb());
    return d - rounding::sub_up(after.ub(), after.lb()) > ratio * d;
  }
  // A finite bound moved by more than ratio * max(1, |bound|), or an infinite one became finite.
  const auto moved = [ratio](double a, double b) {
    return a != b && (std::isinf(a) || std::fabs(b - a) > ratio * std::fmax(1.0, std::fabs(a)));
  };
  return moved(before.lb(), after.lb()) || moved(before.ub(), after.ub());
}
// True when one component shrank in the sense above.
bool shrank(const IntervalVector& before, const IntervalVector& after, double ratio);

// Throws sillage::Error naming `where` unless 0 <= ratio < 1.
void check_ratio(double ratio, const char* where);

}  // namespace sillage
