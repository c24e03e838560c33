#include "sillage/tube/synthesis_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <ranges>
#include <sstream>
#include <string>

#include "sillage/error.h"

namespace sillage {

namespace {

constexpr double kInf = rounding::kInf;

// A point interval from a finite bound (the caller checked finiteness).
Interval point(double x) { return Interval::from_bounds_unchecked(x, x); }

constexpr std::size_t kBlock = 8;  // leaves per block (a few cache lines, scanned linearly)

// Blocked bottom-up tree: nodes[nb + b] summarizes leaves [b*kBlock, (b+1)*kBlock),
// nodes[p] = nodes[2p] (+) nodes[2p+1]. `leaf(k)` gives leaf k as a node,
// `acc.fold(node)` combines in place (min/max: exact, any order).
template <class N, class Leaf>
std::vector<N> build_blocked(std::size_t nleaves, const N& identity, Leaf leaf) {
  const std::size_t nb = (nleaves + kBlock - 1) / kBlock;
  std::vector<N> nodes(2 * nb, identity);
  for (std::size_t k = 0; k < nleaves; ++k) nodes[nb + k / kBlock].fold(leaf(k));
  for (std::size_t p = nb - 1; p >= 1; --p) {
    nodes[p] = nodes[2 * p];
    nodes[p].fold(nodes[2 * p + 1]);
  }
  return nodes;
}

template <class N, class Leaf>
N query_blocked(const std::vector<N>& nodes, std::size_t first, std::size_t last, const N& identity, Leaf leaf) {
  N acc = identity;
  if (first > last) return acc;
  const std::size_t bf = first / kBlock, bl = last / kBlock;
  if (bl - bf <= 1) {  // at most two blocks: scan
    for (std::size_t k = first; k <= last; ++k) acc.fold(leaf(k));
    return acc;
  }
  for (std::size_t k = first; k < (bf + 1) * kBlock; ++k) acc.fold(leaf(k));
  for (std::size_t k = bl * kBlock; k <= last; ++k) acc.fold(leaf(k));
  const std::size_t nb = nodes.size() / 2;
  for (std::size_t l = bf + 1 + nb, r = bl + nb; l < r; l >>= 1, r >>= 1) {
    if (l & 1) acc.fold(nodes[l++]);
    if (r & 1) acc.fold(nodes[--r]);
  }
  return acc;
}

}  // namespace

SynthesisTree::SynthesisTree(std::span<const double> times, std::span<const Interval> slices,
                             std::span<const Interval> gates) {
  const std::size_t n = slices.size();
  if (n == 0 || times.size() != n + 1) {
    throw DimensionError("SynthesisTree: " + std::to_string(times.size()) + " time points for " +
                         std::to_string(n) + " slices, expected N+1 time points and N >= 1 slices");
  }
  if (!gates.empty() && gates.size() != n + 1) {
    throw DimensionError("SynthesisTree: " + std::to_string(gates.size()) + " gates for " + std::to_string(n) +
                         " slices, expected N+1 (or none)");
  }
  if (n >= (std::size_t{1} << 31)) {
    throw DimensionError("SynthesisTree: too many slices (" + std::to_string(n) + ")");
  }
  for (std::size_t k = 0; k <= n; ++k) {
    if (!std::isfinite(times[k]) || (k > 0 && !(times[k] > times[k - 1]))) {
      throw Error("SynthesisTree: time points must be finite and strictly increasing; t_" + std::to_string(k) +
                  " = " + number_text(times[k]));
    }
  }
  // One cache line per time point: a query end touches one line.
  points_.resize(n + 1);
  gates_.assign(gates.begin(), gates.end());
  inv_dt_ = static_cast<double>(n) / (times[n] - times[0]);
  // Prefix values, left to right, outward.
  Interval l(0.0), u(0.0);
  std::uint32_t lc = 0, uc = 0;
  for (std::size_t k = 0; k <= n; ++k) {
    Point& q = points_[k];
    q.t = times[k];
    q.l_lo = l.lb();
    q.l_hi = l.ub();
    q.u_lo = u.lb();
    q.u_hi = u.ub();
    q.lcount = lc;
    q.ucount = uc;
    if (k == n) {
      q.s_lo = kInf;  // no slice after t_N: empty
      q.s_hi = -kInf;
      break;
    }
    const Interval& s = slices[k];
    q.s_lo = s.lb();
    q.s_hi = s.ub();
    if (s.is_empty()) {
      has_empty_ = true;
      continue;
    }
    const Interval width = Interval(times[k + 1]) - Interval(times[k]);
    if (s.lb() == -kInf) {
      ++lc;
    } else {
      l = l + width * point(s.lb());
    }
    if (s.ub() == kInf) {
      ++uc;
    } else {
      u = u + width * point(s.ub());
    }
  }

  // Primitive tree over the N+1 time points.
  const Node none{kInf, kInf, -kInf, -kInf, kInf, kInf, -kInf, -kInf};
  auto prefix_leaf = [this](std::size_t k) {
    const Point& q = points_[k];
    return Node{q.l_lo, q.l_hi, q.l_lo, q.l_hi, q.u_lo, q.u_hi, q.u_lo, q.u_hi};
  };
  nodes_ = build_blocked(n + 1, none, prefix_leaf);

  // Hull trees. An empty interval has lb = +inf, ub = -inf: neutral for min/max.
  const Hull nothing{kInf, -kInf};
  slice_nodes_ = build_blocked(
      n, nothing, [this](std::size_t k) { return Hull{points_[k].s_lo, points_[k].s_hi}; });
  eval_leaves_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Interval y = gates_.empty() ? slice(k) : (slice(k) | gates_[k]);
    eval_leaves_[k] = {y.lb(), y.ub()};
  }
  eval_nodes_ = build_blocked(n, nothing, [this](std::size_t k) { return eval_leaves_[k]; });
}

std::size_t SynthesisTree::slice_index(double t) const {
  if (!(t >= points_.front().t && t <= points_.back().t)) {
    throw Error("SynthesisTree::slice_index(t): t = " + number_text(t) + " is outside the domain [" +
                number_text(points_.front().t) + ", " + number_text(points_.back().t) + "]");
  }
  const std::size_t n = nb_slices();
  // Guess from a uniform grid, then a few steps; binary search otherwise.
  double g = std::floor((t - points_.front().t) * inv_dt_);
  std::size_t k = g <= 0 ? 0 : (g >= static_cast<double>(n - 1) ? n - 1 : static_cast<std::size_t>(g));
  for (int step = 0; step < 4; ++step) {
    if (points_[k].t > t) {
      --k;  // k > 0 here since points_[0].t <= t
    } else if (k + 1 < n && points_[k + 1].t <= t) {
      ++k;
    } else {
      return k;
    }
  }
  const auto it = std::ranges::upper_bound(points_, t, {}, &Point::t);
  return std::min(static_cast<std::size_t>(it - points_.begin()) - 1, n - 1);
}

Interval SynthesisTree::slice_hull(std::size_t first, std::size_t last) const {
  if (first > last) return Interval::empty();
  if (last >= nb_slices()) {
    throw Error("SynthesisTree::slice_hull: slice " + std::to_string(last) + " out of range [0, " +
                std::to_string(nb_slices()) + ")");
  }
  const Hull h = query_blocked(
      slice_nodes_, first, last, Hull{kInf, -kInf},
      [this](std::size_t k) { return Hull{points_[k].s_lo, points_[k].s_hi}; });
  return Interval::from_bounds_unchecked(h.lo, h.hi);
}

void SynthesisTree::check_interval(const Interval& t, const char* where) const {
  if (!t.is_subset(Interval(points_.front().t, points_.back().t))) {
    throw Error(std::string(where) + ": [t] = " + t.str() + " is not inside the domain [" + number_text(points_.front().t) +
                ", " + number_text(points_.back().t) + "]");
  }
}

Interval SynthesisTree::eval(const Interval& t) const {
  if (t.is_empty()) return Interval::empty();
  check_interval(t, "SynthesisTree::eval([t])");
  const double a = t.lb(), b = t.ub();
  const std::size_t ka = slice_index(a), kb = slice_index(b), n = nb_slices();
  if (a == b) {
    if (a == points_[ka].t || a == points_[ka + 1].t) {  // a time point
      const std::size_t g = a == points_[ka].t ? ka : ka + 1;
      if (!gates_.empty()) return gates_[g];
      return slice_hull(g == 0 ? 0 : g - 1, std::min(g, n - 1));
    }
    return slice(ka);
  }
  // Slices meeting (a, b): ka .. last; gates with a <= t_k <= b, i.e. the
  // inner gates ka+1 .. last (one tree query with their slices), gate ka if
  // t_ka == a and gate last+1 if t_{last+1} <= b.
  const std::size_t last = (points_[kb].t == b) ? kb - 1 : kb;  // kb > ka >= 0 when t_kb == b > a
  const Hull h = query_blocked(eval_nodes_, ka + 1, last, Hull{kInf, -kInf},
                               [this](std::size_t k) { return eval_leaves_[k]; });
  Interval r = Interval::from_bounds_unchecked(h.lo, h.hi) | slice(ka);
  if (!gates_.empty()) {
    if (points_[ka].t == a) r |= gates_[ka];
    if (points_[last + 1].t <= b) r |= gates_[last + 1];
  }
  return r;
}

PrimitiveValue SynthesisTree::value_at(bool upper, double t, std::size_t k) const {
  if (t == points_[k + 1].t) ++k;
  const PrimitiveValue v = upper ? upper_prefix(k) : lower_prefix(k);
  if (t == points_[k].t) return v;
  const Point& q = points_[k];
  if (!(q.s_lo <= q.s_hi)) return v;  // empty slice: flagged, integrals are empty anyway
  const double bound = upper ? q.s_hi : q.s_lo;
  if (std::isinf(bound)) return {{v.rank.passed, t}, v.fin};  // strictly inside an unbounded slice
  return {v.rank, v.fin + (Interval(t) - Interval(points_[k].t)) * point(bound)};
}

SynthesisTree::Node SynthesisTree::extrema(std::size_t first, std::size_t last) const {
  const Node none{kInf, kInf, -kInf, -kInf, kInf, kInf, -kInf, -kInf};
  return query_blocked(
      nodes_, first, last, none,
      [this](std::size_t k) {
        const Point& q = points_[k];
        return Node{q.l_lo, q.l_hi, q.l_lo, q.l_hi, q.u_lo, q.u_hi, q.u_lo, q.u_hi};
      });
}

void SynthesisTree::run_bounds(bool upper, std::size_t first, std::size_t last, const Rank& r, std::size_t& lo,
                               std::size_t& hi) const {
  lo = 1;
  hi = 0;  // empty
  if (first > last || r.inside != -kInf) return;  // time points are never inside a slice
  const std::uint32_t c = r.passed;
  auto count = [upper](const Point& q) { return upper ? q.ucount : q.lcount; };
  if (count(points_[first]) == c && count(points_[last]) == c) {  // the usual case: no unbounded slice inside
    lo = first;
    hi = last;
    return;
  }
  const auto b = points_.begin();
  const auto range = std::ranges::subrange(b + static_cast<std::ptrdiff_t>(first),
                                           b + static_cast<std::ptrdiff_t>(last) + 1);
  const auto l = std::ranges::lower_bound(range, c, {}, count), u = std::ranges::upper_bound(range, c, {}, count);
  if (l == u) return;
  lo = static_cast<std::size_t>(l - b);
  hi = static_cast<std::size_t>(u - b) - 1;
}

PrimitiveRange SynthesisTree::make_range(bool upper, const PrimitiveValue& va, const PrimitiveValue& vb,
                                         std::size_t first, std::size_t last, const Node* whole) const {
  PrimitiveRange r;
  r.rank_first = va.rank;
  r.rank_last = vb.rank;
  // The extrema over one rank: the end values and the time points of that
  // rank. Enclosure of a min: [min lo, min hi].
  auto over = [&](const Rank& c, Interval& mn, Interval& mx) {
    double mn_lo = kInf, mn_hi = kInf, mx_lo = -kInf, mx_hi = -kInf;
    for (const PrimitiveValue* v : {&va, &vb}) {
      if (v->rank != c) continue;
      mn_lo = std::min(mn_lo, v->fin.lb());
      mn_hi = std::min(mn_hi, v->fin.ub());
      mx_lo = std::max(mx_lo, v->fin.lb());
      mx_hi = std::max(mx_hi, v->fin.ub());
    }
    std::size_t lo, hi;
    run_bounds(upper, first, last, c, lo, hi);
    if (lo <= hi) {
      const Node nd = (whole && lo == first && hi == last) ? *whole : extrema(lo, hi);
      mn_lo = std::min(mn_lo, upper ? nd.umin_lo : nd.lmin_lo);
      mn_hi = std::min(mn_hi, upper ? nd.umin_hi : nd.lmin_hi);
      mx_lo = std::max(mx_lo, upper ? nd.umax_lo : nd.lmax_lo);
      mx_hi = std::max(mx_hi, upper ? nd.umax_hi : nd.lmax_hi);
    }
    mn = Interval::from_bounds_unchecked(mn_lo, mn_hi);
    mx = Interval::from_bounds_unchecked(mx_lo, mx_hi);
  };
  over(va.rank, r.min_first, r.max_first);
  if (vb.rank == va.rank) {
    r.min_last = r.min_first;
    r.max_last = r.max_first;
  } else {
    over(vb.rank, r.min_last, r.max_last);
  }
  return r;
}

PrimitiveRange SynthesisTree::lower_range(const Interval& t) const {
  PrimitiveRange l, u;
  ranges(t, l, u);
  return l;
}

PrimitiveRange SynthesisTree::upper_range(const Interval& t) const {
  PrimitiveRange l, u;
  ranges(t, l, u);
  return u;
}

void SynthesisTree::ranges(const Interval& t, PrimitiveRange& lower, PrimitiveRange& upper) const {
  if (t.is_empty()) throw Error("SynthesisTree: primitive range over an empty [t]");
  check_interval(t, "SynthesisTree: primitive range");
  const double a = t.lb(), b = t.ub();
  const std::size_t ka = slice_index(a), kb = slice_index(b);
  const PrimitiveValue la = value_at(false, a, ka), lb = value_at(false, b, kb);
  const PrimitiveValue ua = value_at(true, a, ka), ub = value_at(true, b, kb);
  // Time points with a < t_k <= b (one equal to b repeats the value at b).
  const std::size_t first = ka + 1, last = kb;
  Node whole{};
  const bool walk = first <= last;
  if (walk) whole = extrema(first, last);
  lower = make_range(false, la, lb, first, last, walk ? &whole : nullptr);
  upper = make_range(true, ua, ub, first, last, walk ? &whole : nullptr);
}

std::size_t SynthesisTree::memory_bytes() const {
  return sizeof(*this) + points_.capacity() * sizeof(Point) + gates_.capacity() * sizeof(Interval) +
         nodes_.capacity() * sizeof(Node) +
         (slice_nodes_.capacity() + eval_leaves_.capacity() + eval_nodes_.capacity()) * sizeof(Hull);
}

}  // namespace sillage
