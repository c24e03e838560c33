#pragma once
// SynthesisTree: the array-backed binary tree of thesis 3.3.1 (Fig. 3.9) over
// the N slices of a tube. Built in O(N), it answers in O(log N):
//  - the hull of slice codomains (and of gates) over an index or time range,
//    i.e. [x]([t]) with the semantics of Tube::operator()(Interval);
//  - the range minimum / maximum over t in [t] of the primitives of the lower
//    and upper bounds, L(t) = ∫_{t0}^{t} x^- and U(t) = ∫_{t0}^{t} x^+, which
//    the integrals (3.8)-(3.9) are made of (tube_integral.h).
//
// Rigor. Slice widths are Interval(t_{k+1}) - Interval(t_k); the prefix values
// L(t_k), U(t_k) are summed left to right in outward interval arithmetic, so
// each is an Interval enclosure of the exact real. L and U are piecewise
// linear, so their extrema over [t] = [a, b] are reached at a, at b or at a
// time point inside. The tree stores, per node, the min and max of the lower
// and of the upper ends of those enclosures; min/max are exact operations, so
// a tree query returns bit for bit what a linear scan over the same prefix
// values returns, and [min lo, min hi] encloses the exact minimum.
//
// Unbounded slices. A slice with x^- = -inf makes L infinite from there on,
// yet ∫_{t1}^{t2} x^- is finite when t1 is past it. So each prefix value is
// a pair (rank, fin): the rank says which unbounded slices lie before t (see
// Rank), fin encloses the sum of the finite contributions. A difference
// L(t2)-L(t1) is infinite when the ranks differ and fin(t2) - fin(t1)
// otherwise; hence the range queries report the extrema of fin separately
// over the times whose rank is that of a (the smallest on [t]) and that of b
// (the largest).
//
// Layout. One 64-byte record per time point (t_k, the prefix enclosures, the
// counts, slice k): the ends of a query touch one cache line each. The trees
// are blocked: leaves are scanned by blocks of 8, a bottom-up segment tree
// spans the block summaries, small enough to stay in cache (about 120 bytes
// per slice in all). Prefix sums accumulate rounding: the enclosures widen by
// about N ulps of the largest prefix, still guaranteed.
//
// Empty slices contribute nothing to the sums and are flagged
// (has_empty_slice): a tube with an empty slice holds no trajectory, and the
// integral layer returns empty sets for it.
#include <compare>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "sillage/interval/interval.h"

namespace sillage {

// Where a time stands with respect to the unbounded slices of L (or U):
// `passed` unbounded slices lie entirely before it, and `inside` is the time
// itself when it is strictly inside an unbounded slice (-inf otherwise).
// Ordered lexicographically: s1 < s2 in rank iff an unbounded slice overlaps
// (s1, s2) with positive length, i.e. iff ∫_{s1}^{s2} of the bound is infinite.
struct Rank {
  std::uint32_t passed = 0;
  double inside = -std::numeric_limits<double>::infinity();
  auto operator<=>(const Rank&) const = default;
};

// A prefix value of L or U at one time: its rank, plus the enclosure `fin`
// of the sum of the finite contributions before it.
struct PrimitiveValue {
  Rank rank;
  Interval fin = Interval(0.0);
};

// Extrema of one primitive (L or U) over t in [a, b]. The rank is
// nondecreasing in t: rank_first = rank of a, rank_last = rank of b.
// min_first / max_first enclose the min / max of fin over the times of rank
// rank_first; min_last / max_last over those of rank rank_last (the same set
// when the ranks are equal).
struct PrimitiveRange {
  Rank rank_first, rank_last;
  Interval min_first, max_first, min_last, max_last;
};

class SynthesisTree {
 public:
  // times: t_0 < ... < t_N (N >= 1, finite); slices: N codomains; gates: N+1
  // gate values, or empty (then [x]([t]) uses slices only). Error on sizes or
  // times that are not finite and strictly increasing.
  SynthesisTree(std::span<const double> times, std::span<const Interval> slices,
                std::span<const Interval> gates = {});

  std::size_t nb_slices() const { return points_.size() - 1; }
  double t0() const { return points_.front().t; }
  double tf() const { return points_.back().t; }
  double t(std::size_t k) const { return points_[k].t; }  // t_k, k <= N (unchecked)
  Interval slice(std::size_t k) const {                    // [x](k), k < N (unchecked)
    return Interval::from_bounds_unchecked(points_[k].s_lo, points_[k].s_hi);
  }
  bool has_empty_slice() const { return has_empty_; }
  bool has_gates() const { return !gates_.empty(); }

  // Slice k with t_k <= t < t_{k+1} (N-1 at t_N), as TDomain::slice_index.
  // Error if t is NaN or outside [t_0, t_N]. O(1) on a uniform grid.
  std::size_t slice_index(double t) const;

  // Hull of slices first..last (inclusive; empty if first > last).
  Interval slice_hull(std::size_t first, std::size_t last) const;
  // [x]([t]), the semantics of Tube::operator()(Interval): hull of the slices
  // meeting the interior of [t] and of the gates inside [t]; degenerate [t]:
  // the gate at a time point, else the slice. Error if [t] is not inside
  // [t_0, t_N]; empty [t] -> empty.
  Interval eval(const Interval& t) const;

  // Prefix values at time point t_k (k <= N) and at any time t.
  PrimitiveValue lower_prefix(std::size_t k) const {
    return {{points_[k].lcount}, Interval::from_bounds_unchecked(points_[k].l_lo, points_[k].l_hi)};
  }
  PrimitiveValue upper_prefix(std::size_t k) const {
    return {{points_[k].ucount}, Interval::from_bounds_unchecked(points_[k].u_lo, points_[k].u_hi)};
  }
  PrimitiveValue lower_at(double t) const { return value_at(false, t, slice_index(t)); }
  PrimitiveValue upper_at(double t) const { return value_at(true, t, slice_index(t)); }

  // Extrema of L (lower) and U (upper) over t in [t] (non-empty, inside the
  // domain; Error otherwise). ranges() answers both with one tree walk when
  // no unbounded slice lies inside [t].
  PrimitiveRange lower_range(const Interval& t) const;
  PrimitiveRange upper_range(const Interval& t) const;
  void ranges(const Interval& t, PrimitiveRange& lower, PrimitiveRange& upper) const;

  // Bytes held (benchmarks and diagnostics).
  std::size_t memory_bytes() const;

 private:
  // Node of the primitive tree: min and max of the lower and upper ends of
  // the fin enclosures of L and U over the node's time points. One cache line.
  struct alignas(64) Node {
    double lmin_lo, lmin_hi, lmax_lo, lmax_hi;
    double umin_lo, umin_hi, umax_lo, umax_hi;
    void fold(const Node& b) {
      lmin_lo = b.lmin_lo < lmin_lo ? b.lmin_lo : lmin_lo;
      lmin_hi = b.lmin_hi < lmin_hi ? b.lmin_hi : lmin_hi;
      lmax_lo = b.lmax_lo > lmax_lo ? b.lmax_lo : lmax_lo;
      lmax_hi = b.lmax_hi > lmax_hi ? b.lmax_hi : lmax_hi;
      umin_lo = b.umin_lo < umin_lo ? b.umin_lo : umin_lo;
      umin_hi = b.umin_hi < umin_hi ? b.umin_hi : umin_hi;
      umax_lo = b.umax_lo > umax_lo ? b.umax_lo : umax_lo;
      umax_hi = b.umax_hi > umax_hi ? b.umax_hi : umax_hi;
    }
  };
  // Everything about time point t_k, one cache line: the fin enclosures of
  // L and U, the unbounded-slice counts, and slice k's bounds (empty at t_N).
  struct alignas(64) Point {
    double t;
    double l_lo, l_hi, u_lo, u_hi;
    double s_lo, s_hi;
    std::uint32_t lcount, ucount;
  };
  struct Hull {
    double lo, hi;
    void fold(const Hull& b) {
      lo = b.lo < lo ? b.lo : lo;
      hi = b.hi > hi ? b.hi : hi;
    }
  };

  void check_interval(const Interval& t, const char* where) const;
  PrimitiveValue value_at(bool upper, double t, std::size_t k) const;  // k = slice_index(t)
  Node extrema(std::size_t first, std::size_t last) const;  // over time points, inclusive
  // The time-point sub-range of [first, last] of rank r.
  void run_bounds(bool upper, std::size_t first, std::size_t last, const Rank& r, std::size_t& lo,
                  std::size_t& hi) const;
  PrimitiveRange make_range(bool upper, const PrimitiveValue& va, const PrimitiveValue& vb, std::size_t first,
                            std::size_t last, const Node* whole) const;

  // The trees are blocked: a leaf block of kBlock consecutive leaves is
  // scanned linearly (contiguous memory), a bottom-up segment tree is built
  // over the block summaries (nodes[nb + b] = block b), which keeps the tree
  // small enough to stay in cache.
  std::vector<Point> points_;                    // N+1 time points (the leaves)
  std::vector<Interval> gates_;
  std::vector<Node> nodes_;                      // primitive tree over blocks of time points
  std::vector<Hull> slice_nodes_;                // hull tree over blocks of slices
  std::vector<Hull> eval_leaves_, eval_nodes_;   // slice k ∪ gate k, and its tree
  bool has_empty_ = false;
  double inv_dt_ = 0.0;  // N / (t_N - t_0): slice_index guesses from a uniform grid
};

}  // namespace sillage
