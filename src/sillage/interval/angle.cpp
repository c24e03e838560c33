#include "sillage/interval/angle.h"

#include <algorithm>
#include <cmath>

namespace sillage {

namespace {

// y + k·2π, rounded outward.
Interval shifted(const Interval& y, double k) { return y + Interval(k) * Interval::two_pi(); }

// Where to centre a copy of y inside x: the middle of x, kept 4π inside a
// bound that is infinite so that a copy fits around it.
double centre_of(const Interval& x, const Interval& y) {
  const double four_pi = 2 * Interval::two_pi().ub();
  if (x.is_bounded()) return x.mid();
  if (x.lb() == -INFINITY && x.ub() == INFINITY) return y.mid();
  return x.lb() == -INFINITY ? x.ub() - four_pi : x.lb() + four_pi;
}

}  // namespace

bool angle_is_circle(const Interval& x) {
  return !x.is_empty() && (x.is_unbounded() || x.diam() >= Interval::two_pi().lb());
}

Interval angle_meet(const Interval& x, const Interval& y) {
  if (x.is_empty() || y.is_empty()) return Interval::empty();
  if (angle_is_circle(y)) return x;
  const double two_pi = Interval::two_pi().mid();
  // A whole copy of y inside x, the one nearest x's centre: every common angle is on it.
  const double c = centre_of(x, y);
  const double k0 = std::round((c - y.mid()) / two_pi);
  for (const double k : {k0, k0 - 1, k0 + 1}) {
    const Interval copy = shifted(y, k);
    if (copy.is_subset(x)) return copy;
  }
  // No copy fits: x is narrower than y + 2π, and holds pieces of at most three.
  return angle_lift(y, x);
}

Interval angle_lift(const Interval& y, const Interval& within) {
  if (within.is_empty() || y.is_empty()) return Interval::empty();
  if (angle_is_circle(y) || within.is_unbounded()) return within;
  const double two_pi = Interval::two_pi().mid();
  const double k_lo = std::floor((within.lb() - y.ub()) / two_pi) - 1;
  const double k_hi = std::ceil((within.ub() - y.lb()) / two_pi) + 1;
  if (k_hi - k_lo > 6) {  // many copies: the hull runs from the first piece to the last
    Interval hull = Interval::empty();
    for (const double k : {k_lo, k_lo + 1, k_lo + 2, k_hi - 2, k_hi - 1, k_hi}) hull |= shifted(y, k) & within;
    return hull;
  }
  Interval hull = Interval::empty();
  for (double k = k_lo; k <= k_hi; ++k) hull |= shifted(y, k) & within;
  return hull;
}

bool angle_contains(const Interval& x, double a) {
  if (x.is_empty() || !std::isfinite(a)) return false;
  if (angle_is_circle(x)) return true;
  // An integer k with a + 2kπ ∈ x: k ∈ (x - a) / 2π, rounded outward.
  const Interval k = (x - Interval(a)) / Interval::two_pi();
  return std::floor(k.ub()) >= k.lb();
}

}  // namespace sillage
