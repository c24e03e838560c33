#pragma once
// When did a contraction "really" shrink a domain? Fixed-point loops
// (CtcFixPoint, ContractorNetwork) stop once no domain shrinks by more than a
// relative ratio of its size; this only steers the scheduling, never the rigor
// (every intermediate box is a valid enclosure).
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
bool shrank(const Interval& before, const Interval& after, double ratio);
// True when one component shrank in the sense above.
bool shrank(const IntervalVector& before, const IntervalVector& after, double ratio);

// Throws sillage::Error naming `where` unless 0 <= ratio < 1.
void check_ratio(double ratio, const char* where);

}  // namespace sillage
