#include "sillage/tube/primitive_difference.h"

#include "sillage/interval/rounding.h"

namespace sillage::detail {

namespace {

using rounding::kInf;
using rounding::kMax;

// [lo, hi] where an all-infinite range becomes the unbounded interval on its side.
Interval make_range(double lo, double hi) {
  if (lo == kInf) return Interval::from_bounds_unchecked(kMax, kInf);
  if (hi == -kInf) return Interval::from_bounds_unchecked(-kInf, -kMax);
  return Interval::from_bounds_unchecked(lo, hi);
}

// Range of F(s2) - F(s1) over s1 ∈ [t1], s2 ∈ [t2], F = L (the infinite
// parts are -inf) or U (+inf). The ranks decide first: if some pair has
// rank(s2) > rank(s1), an unbounded slice lies inside (s1, s2) and the value
// is infinite; if some pair has equal ranks (then necessarily s2 of the
// extreme rank of [t2] and s1 of the opposite one of [t1]), fin decides; if
// every pair has rank(s2) < rank(s1), every value is infinite the other way.
Interval difference(bool upper, const PrimitiveRange& r1, const PrimitiveRange& r2) {
  const auto d_max = r2.rank_last <=> r1.rank_first;   // the largest rank difference
  const auto d_min = r2.rank_first <=> r1.rank_last;   // the smallest
  double lo, hi;
  if (!upper) {
    lo = d_max > 0 ? -kInf : d_max < 0 ? kInf : rounding::sub_down(r2.min_last, r1.max_first);
    hi = d_min < 0 ? kInf : d_min > 0 ? -kInf : rounding::sub_up(r2.max_first, r1.min_last);
  } else {
    hi = d_max > 0 ? kInf : d_max < 0 ? -kInf : rounding::sub_up(r2.max_last, r1.min_first);
    lo = d_min < 0 ? -kInf : d_min > 0 ? kInf : rounding::sub_down(r2.min_first, r1.max_last);
  }
  return make_range(lo, hi);
}

}  // namespace

std::pair<Interval, Interval> partial_integral_of(const PrimitiveRanges& r1, const PrimitiveRanges& r2) {
  return {difference(false, r1.lower, r2.lower), difference(true, r1.upper, r2.upper)};
}

Interval integral_of(const std::pair<Interval, Interval>& partial, const Interval& t1, const Interval& t2) {
  const auto& [lower, upper] = partial;
  if (lower.is_empty()) return Interval::empty();
  // t1 <= t2 for sure: (3.9). Otherwise the hull of both ranges (tube_integral.h).
  if (t1.ub() <= t2.lb()) return Interval::from_bounds_unchecked(lower.lb(), upper.ub());
  return lower | upper;
}

}  // namespace sillage::detail
