#pragma once
// Private helpers shared by the backward projections (backward_*.cpp).
#include <utility>

#include "sillage/interval/interval.h"

namespace sillage::detail {

// One argument: false when it is empty.
inline bool settle(Interval& x) { return !x.is_empty(); }

// Every argument empty as soon as one is: returns false in that case.
inline bool settle(Interval& x1, Interval& x2) {
  if (x1.is_empty() || x2.is_empty()) {
    x1.set_empty();
    x2.set_empty();
    return false;
  }
  return true;
}

// x contracted to the hull of (x ∩ p.first) ∪ (x ∩ p.second).
inline Interval meet_pieces(const Interval& x, const std::pair<Interval, Interval>& p) {
  return (x & p.first) | (x & p.second);
}

// x contracted to the hull of (x ∩ p) ∪ (x ∩ -p): the two branches of an even function.
inline Interval meet_symmetric(const Interval& x, const Interval& p) { return (x & p) | (x & -p); }

}  // namespace sillage::detail
