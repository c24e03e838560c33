#include "sillage/ctc/q_inter.h"

#include <algorithm>
#include <string>

namespace sillage {

void check_q(int q, const char* where) {
  if (q < 0) throw Error(std::string(where) + ": q must be >= 0 (at most q wrong constraints), got " + std::to_string(q));
}

namespace {

// Exact hull of S = {x : c(x) >= p}, c(x) = #{i : x in [a_i, b_i]}, over the
// non-empty intervals given by sorted lower bounds `a` and sorted upper
// bounds `b` (the same n intervals), 1 <= p <= n.
//
// Why it is exact. Since a_i <= b_i, x in [a_i, b_i] <=> a_i <= x and not
// b_i < x, and b_i < x implies a_i <= x, so
//     c(x) = #{i : a_i <= x} - #{i : b_i < x}.
// c is a step function that only rises at a lower bound (a_i is in its
// interval) and only falls just after an upper bound (b_i is in its interval),
// so S is a finite union of closed intervals: each of them starts at some a_i
// and ends at some b_j. Hence min S = min{a_i : c(a_i) >= p} and
// max S = max{b_j : c(b_j) >= p}, and S is empty when no a_i qualifies.
// Infinite bounds fit the same formula: c(-inf), read as "for every x low
// enough", counts the intervals unbounded below, and symmetrically at +inf.
Interval hull_of_level_set(const std::vector<double>& a, const std::vector<double>& b, std::size_t p) {
  const std::size_t n = a.size();
  // Lowest a_i with c(a_i) >= p, ascending; j = #{b < a_i} by a moving pointer
  // (j <= i + 1: b_k < a_i implies a_k < a_i).
  std::size_t lo = n;
  for (std::size_t i = 0, j = 0; i < n; ++i) {
    if (i + 1 < n && a[i + 1] == a[i]) continue;  // at the last of equal a's, i + 1 = #{a <= a_i}
    while (j < n && b[j] < a[i]) ++j;
    if (i + 1 - j >= p) {
      lo = i;
      break;
    }
  }
  if (lo == n) return Interval::empty();
  // Highest b_i with c(b_i) >= p, descending; above = #{a > b_i} by a moving
  // pointer (i <= n - above: b_k < b_i implies a_k < b_i). S is non-empty, so
  // this loop finds its maximum.
  for (std::size_t i = n, above = 0; i-- > 0;) {
    if (i > 0 && b[i - 1] == b[i]) continue;  // at the first of equal b's, i = #{b < b_i}
    while (above < n && a[n - 1 - above] > b[i]) ++above;
    if (n - above - i >= p) return Interval::from_bounds_unchecked(a[lo], b[i]);
  }
  return Interval::empty();  // not reached
}

// The q-relaxed hull of m intervals of which the non-empty ones have lower
// bounds a and upper bounds b (reordered here); the m - a.size() others are empty.
//
// A shortcut first: with a_(p) the p-th smallest lower bound and b^(p) the
// p-th largest upper bound, S is inside [a_(p), b^(p)] (below a_(p) fewer than
// p intervals have started, above b^(p) fewer than p are left), and when
// c(a_(p)) >= p and c(b^(p)) >= p both ends are in S, so the hull is exactly
// [a_(p), b^(p)]: O(n), the common case of mostly consistent data. Otherwise,
// sort and sweep (hull_of_level_set).
Interval relaxed_hull(std::vector<double>& a, std::vector<double>& b, std::size_t m, int q) {
  const auto uq = static_cast<std::size_t>(q);
  if (uq >= m) return Interval::all_reals();
  const std::size_t p = m - uq, n = a.size();  // p constraints must hold
  if (n < p) return Interval::empty();
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(p - 1), a.end());
  std::nth_element(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(n - p), b.end());
  const double lo = a[p - 1], hi = b[n - p];
  if (hi < lo) return Interval::empty();
  const auto count = [&](double x) {  // c(x), see hull_of_level_set (>= 0)
    std::size_t started = 0, ended = 0;
    for (std::size_t i = 0; i < n; ++i) {
      started += a[i] <= x;
      ended += b[i] < x;
    }
    return started - ended;
  };
  if (count(lo) >= p && count(hi) >= p) return Interval::from_bounds_unchecked(lo, hi);
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return hull_of_level_set(a, b, p);
}

}  // namespace

Interval q_inter(const std::vector<Interval>& xs, int q) {
  check_q(q, "q_inter");
  if (xs.empty()) throw Error("q_inter: needs at least one interval");
  std::vector<double> a, b;
  for (const auto& x : xs) {
    if (x.is_empty()) continue;
    a.push_back(x.lb());
    b.push_back(x.ub());
  }
  return relaxed_hull(a, b, xs.size(), q);
}

IntervalVector q_inter(const std::vector<IntervalVector>& boxes, int q) {
  check_q(q, "q_inter");
  if (boxes.empty()) throw Error("q_inter: needs at least one box");
  const std::size_t n = boxes[0].size();
  for (std::size_t i = 1; i < boxes.size(); ++i) {
    if (boxes[i].size() != n) {
      throw DimensionError("q_inter: box " + std::to_string(i) + " has size " + std::to_string(boxes[i].size()) +
                           ", box 0 has size " + std::to_string(n));
    }
  }
  // An empty box counts against every point, so it adds no bounds in any
  // component (one of its components alone being empty must not matter).
  std::vector<const IntervalVector*> live;
  for (const auto& x : boxes) {
    if (!x.is_empty()) live.push_back(&x);
  }
  IntervalVector result(n);
  std::vector<double> a(live.size()), b(live.size());
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t i = 0; i < live.size(); ++i) {
      a[i] = (*live[i])[k].lb();
      b[i] = (*live[i])[k].ub();
    }
    result[k] = relaxed_hull(a, b, boxes.size(), q);
    if (result[k].is_empty()) return IntervalVector::empty(n);
  }
  return result;
}

}  // namespace sillage
