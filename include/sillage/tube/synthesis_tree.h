#pragma once
// SynthesisTree: the array-backed tree of thesis 3.3.1 (Fig. 3.9) over the N
// slices of a tube. Built in O(N), it answers in O(log N):
//  - the hull of slice codomains (and of gates) over an index or time range,
//    i.e. [x]([t]) with the semantics of Tube::operator()(Interval);
//  - the range minimum / maximum over t in [t] of the primitives of the lower
//    and upper bounds, L(t) = ∫_{t0}^{t} x^- and U(t) = ∫_{t0}^{t} x^+, which
//    the integrals (3.8)-(3.9) are made of (tube_integral.h).
//
// The tree of a tube is an index, not a copy (the constructor used by
// Tube::synthesis_tree): it holds summaries only and reads the time points,
// slices and gates in the tube's storage and TDomain. It keeps the TDomain
// alive but not the tube: every query first checks that the tube still
// exists and has not been modified since the build (Tube::version,
// TDomain::sample included), and throws an Error otherwise, so a tree that
// outlives its tube's data never answers from data it was not built from.
// nb_slices(), t0(), tf(), has_empty_slice() and has_gates() describe the
// tree as built and need no check. A tree built from arrays (the span
// constructor) owns a copy of them (40 more bytes per slice).
//
// Rigor. Slice widths are Interval(t_{k+1}) - Interval(t_k); the prefix values
// L(t_k), U(t_k) are summed left to right in outward interval arithmetic, so
// each is an Interval enclosure of the exact real. L and U are piecewise
// linear, so their extrema over [t] = [a, b] are reached at a, at b or at a
// time point inside. A range query returns a lower bound of the minimum (the
// least lower end of the enclosures) and an upper bound of the maximum (the
// greatest upper end); min and max are exact, so a query returns bit for bit
// what a linear scan over the same prefix values returns.
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
// Layout: 20 bytes per slice (a tube holds 32), no copy of the data.
//  - Prefix enclosures of L and U at every 4th time point (8 B/slice), the
//    four bounds in one vector (prefix_lanes.h). A query recomputes the
//    values between two stored ones it needs, from the slices, with the
//    operations of the build: the same bits (tested against the Interval
//    operators, fast path and fallback).
//  - Range extrema: a bottom-up segment tree over blocks of 8 time points,
//    a node holding the minima of the four bounds, upper ones negated (8 B).
//  - Hulls: two segment trees over blocks of 16 slices, of slice ∪ gate for
//    [x]([t]) and of the slices alone for slice_hull (2 + 2 B).
//  - Counts of unbounded slices per block of 8 (0.5 B), only for a side
//    (lower, upper) that has some: none for a tube without unbounded slices.
// A query computes at most the two blocks at its ends (only the part it
// reads), folds O(log N) nodes without branches and requests all the memory
// it reads before computing. Prefix sums accumulate rounding: the enclosures
// widen by about N ulps of the largest prefix, still guaranteed.
//
// Empty slices contribute nothing to the sums and are flagged
// (has_empty_slice): a tube with an empty slice holds no trajectory, and the
// integral layer returns empty sets for it.
#include <compare>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "sillage/interval/interval.h"

namespace sillage {

class TDomain;
struct TubeData;

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
// Over the times of rank rank_first: min_first <= the minimum of fin,
// max_first >= its maximum (the least lower end and the greatest upper end of
// the enclosures); min_last / max_last likewise over the times of rank
// rank_last (the same set when the ranks are equal).
struct PrimitiveRange {
  Rank rank_first, rank_last;
  double min_first = 0.0, max_first = 0.0, min_last = 0.0, max_last = 0.0;
};

class SynthesisTree {
 public:
  // Over copies of the arrays: times t_0 < ... < t_N (N >= 1, finite);
  // slices: N codomains; gates: N+1 gate values, or empty (then [x]([t])
  // uses slices only). Error on sizes or times that are not finite and
  // strictly increasing.
  SynthesisTree(std::span<const double> times, std::span<const Interval> slices,
                std::span<const Interval> gates = {});
  // Over the storage of a tube on td (see Tube::synthesis_tree): queries
  // throw an Error once that storage is destroyed or modified.
  SynthesisTree(std::shared_ptr<const TDomain> td, const std::shared_ptr<const TubeData>& data);

  std::size_t nb_slices() const { return n_; }
  double t0() const { return t0_; }
  double tf() const { return tf_; }
  double t(std::size_t k) const;    // t_k, OutOfRangeError if k > N
  Interval slice(std::size_t k) const;  // [x](k), Error if k >= N
  bool has_empty_slice() const { return has_empty_; }
  bool has_gates() const { return has_gates_; }

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

  // Prefix values at time point t_k (k <= N, Error otherwise) and at any time t.
  PrimitiveValue lower_prefix(std::size_t k) const { return prefix(false, k); }
  PrimitiveValue upper_prefix(std::size_t k) const { return prefix(true, k); }
  PrimitiveValue lower_at(double t) const { return value_at(false, t); }
  PrimitiveValue upper_at(double t) const { return value_at(true, t); }

  // Extrema of L (lower) and U (upper) over t in [t] (non-empty, inside the
  // domain; Error otherwise). ranges() answers both at once.
  PrimitiveRange lower_range(const Interval& t) const;
  PrimitiveRange upper_range(const Interval& t) const;
  void ranges(const Interval& t, PrimitiveRange& lower, PrimitiveRange& upper) const;

  // Error if the tree's tube is gone or was modified since the tree was
  // built, as every query checks: for callers that keep query results.
  void check_current(const char* where) const { view(where); }

  // Bytes held by the tree (with its copies of the arrays, if any; not a tube's storage).
  std::size_t memory_bytes() const;

 private:
  static constexpr std::size_t kAnchorStep = 4;  // prefix values stored at every 4th time point
  static constexpr std::size_t kBlock = 8;       // time points per leaf of the primitive tree
  static constexpr std::size_t kHullBlock = 16;  // slices per leaf of the hull trees

  // The indexed arrays during one query (and what keeps a tube's alive).
  struct View {
    std::span<const double> times;
    std::span<const Interval> slices, gates;
    std::shared_ptr<const TubeData> hold;
  };
  // The prefix enclosures of L and U at one time point: (lo L, -hi L, lo U,
  // -hi U), see prefix_lanes.h. Also the node of the primitive tree (the
  // lane-wise minima over its time points).
  struct alignas(32) Anchor {
    double lane[4];
  };
  struct Hull {
    double lo, hi;
  };
  class Blocks;  // the time-point blocks a range query has computed

  static Hull fold_hull(Hull a, const Hull& b) {
    a.lo = b.lo < a.lo ? b.lo : a.lo;
    a.hi = b.hi > a.hi ? b.hi : a.hi;
    return a;
  }

  void build(const View& d);
  std::vector<Hull> hull_tree(const View& d, bool with_gates);  // nodes over blocks of slices
  View view(const char* where) const;  // the data; Error if a tube's is gone or changed
  void check_interval(const Interval& t, const char* where) const;
  std::size_t slice_index(const View& d, double t) const;
  Interval hull(const View& d, const std::vector<Hull>& nodes, bool with_gates, std::size_t first,
                std::size_t last) const;
  void build_primitive(const View& d);  // anchors, primitive tree, counts
  std::uint32_t count(bool upper, const View& d, std::size_t k) const;  // unbounded slices before t_k
  PrimitiveValue prefix(bool upper, std::size_t k) const;
  PrimitiveValue value_at(bool upper, double t) const;

  // Bound to a tube: its domain (kept alive) and its storage (not), as built.
  std::shared_ptr<const TDomain> td_;
  std::weak_ptr<const TubeData> tube_;
  std::uint64_t version_ = 0;
  bool bound_ = false;
  // Unbound: copies of the arrays.
  std::vector<double> times_;
  std::vector<Interval> slices_, gates_;

  std::size_t n_ = 0;
  double t0_ = 0.0, tf_ = 0.0;
  double inv_dt_ = 0.0;  // N / (t_N - t_0): slice_index guesses from a uniform grid
  bool has_empty_ = false, has_gates_ = false;
  std::vector<Anchor> anchors_;      // prefix values at t_0, t_4, t_8, ...
  std::vector<Anchor> prim_nodes_;   // segment tree over blocks of 8 time points
  std::vector<Hull> eval_nodes_;     // over blocks of 16 slices: slice k ∪ gate k
  std::vector<Hull> slice_nodes_;    // same over the slices alone (empty without gates: eval_nodes_)
  std::vector<std::uint32_t> lower_counts_, upper_counts_;  // per block of 8: unbounded slices before it
};

}  // namespace sillage
