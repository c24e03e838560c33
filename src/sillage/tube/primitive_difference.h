#pragma once
// Integrals over uncertain times from the primitive ranges of a synthesis
// tree: what partial_integral and integral (tube_integral.h) compute once
// SynthesisTree::ranges has answered for [t1] and [t2]. Separate so that a
// caller meeting the same [t] many times (the zero tests of the t-plane,
// over the boxes of one paving) can keep the ranges and skip the tree.
#include <utility>

#include "sillage/interval/interval.h"
#include "sillage/tube/synthesis_tree.h"

namespace sillage::detail {

// The extrema of L and U over one [t] (SynthesisTree::ranges).
struct PrimitiveRanges {
  PrimitiveRange lower, upper;
};

// The ranges of L(t2) - L(t1) and of U(t2) - U(t1) over t1 ∈ [t1], t2 ∈ [t2],
// given the ranges r1 over [t1] and r2 over [t2] (partial_integral).
std::pair<Interval, Interval> partial_integral_of(const PrimitiveRanges& r1, const PrimitiveRanges& r2);

// The hull of ∫_{t1}^{t2} x over t1 ∈ [t1], t2 ∈ [t2] (integral(x, [t1], [t2]))
// from the pair partial_integral_of gives; [t1], [t2] decide whether t1 <= t2 surely.
Interval integral_of(const std::pair<Interval, Interval>& partial, const Interval& t1, const Interval& t2);

}  // namespace sillage::detail
