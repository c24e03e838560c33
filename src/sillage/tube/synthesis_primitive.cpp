// SynthesisTree, primitive part: the prefix values of L and U (stored every
// kAnchorStep time points, the others recomputed by prefix_lanes.h), their
// range extrema (segment tree over blocks of kBlock time points) and the
// ranks of the unbounded slices. See synthesis_tree.h.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"  // Lanes by value, internal (see prefix_lanes.h)
#endif
#include <algorithm>
#include <cstring>
#include <string>

#include "sillage/error.h"
#include "sillage/tube/prefix_lanes.h"
#include "sillage/tube/segment_tree.h"
#include "sillage/tube/synthesis_tree.h"

namespace sillage {

using detail::Lanes;

namespace {

constexpr double kInf = rounding::kInf;

// A non-empty slice whose lower (upper) bound is infinite: a jump of rank.
bool unbounded(const Interval& s, bool upper) {
  return !s.is_empty() && (upper ? s.ub() == kInf : s.lb() == -kInf);
}

double min(double a, double b) { return b < a ? b : a; }

}  // namespace

// Time-point values around the ends of a query. A block of kBlock time
// points holds kBlock / kAnchorStep segments, each an anchor (stored) and the
// points after it (one chain of steps from the anchor). Only the segments a
// query reads are computed, each once: the chains of one request are
// interleaved (independent), unchecked, and redone step by step with checks
// in the rare case a step was not exact (prefix_lanes.h).
class SynthesisTree::Blocks {
 public:
  Blocks(const SynthesisTree& tree, const View& d) : tree_(tree), d_(d) {}

  // The values at time points from..to (one block) are ready in the returned
  // array, indexed by k - (start of the block).
  const Lanes* values(std::size_t from, std::size_t to) {
    const std::size_t b = from / kBlock, k0 = b * kBlock;
    Slot& s = slot(b);
    const std::size_t j_first = (from - k0) / kAnchorStep, j_last = (to - k0) / kAnchorStep;
    std::uint8_t done[kSegments], need[kSegments];
    for (std::size_t j = j_first; j <= j_last; ++j) {
      done[j] = s.valid[j];
      need[j] = static_cast<std::uint8_t>(j == j_last ? (to - k0) % kAnchorStep + 1 : kAnchorStep);
    }
    detail::LaneMask bad{};
    Lanes chain[kSegments];  // the head of each chain, in registers
    for (std::size_t j = j_first; j <= j_last; ++j) chain[j] = s.v[j * kAnchorStep + done[j] - 1];
    for (std::size_t i = 1; i < kAnchorStep; ++i) {
      for (std::size_t j = j_first; j <= j_last; ++j) {
        if (i >= need[j] || i < done[j]) continue;
        const std::size_t k = k0 + j * kAnchorStep + i;
        detail::advance(chain[j], d_.times[k - 1], d_.times[k], d_.slices[k - 1], bad);
        s.v[k - k0] = chain[j];
      }
    }
    if (detail::any(bad)) {
      for (std::size_t j = j_first; j <= j_last; ++j) {
        for (std::size_t i = std::max<std::size_t>(done[j], 1); i < need[j]; ++i) {
          const std::size_t k = j * kAnchorStep + i;
          s.v[k] = s.v[k - 1];
          detail::advance(s.v[k], d_.times[k0 + k - 1], d_.times[k0 + k], d_.slices[k0 + k - 1]);
        }
      }
    }
    for (std::size_t j = j_first; j <= j_last; ++j) s.valid[j] = std::max(done[j], need[j]);
    return s.v;
  }

  // The value at time point k.
  Lanes point(std::size_t k) { return values(k, k)[k % kBlock]; }

  // Lane-wise minima over the time points lo..hi (none if lo > hi).
  Lanes extrema(std::size_t lo, std::size_t hi) {
    if (lo > hi) return detail::max_lanes();
    auto block_last = [&](std::size_t b) { return std::min((b + 1) * kBlock, tree_.n_ + 1) - 1; };
    const std::size_t bl = lo / kBlock, bh = hi / kBlock;
    // Partial end blocks are scanned, the blocks in between come from the tree.
    const bool part_l = lo != bl * kBlock || (bl == bh && hi != block_last(bl));
    const bool part_h = bh != bl && hi != block_last(bh);
    const std::size_t full_first = part_l ? bl + 1 : bl, full_end = part_h ? bh : bh + 1;
    // All the memory the query reads is requested first, so that it arrives
    // while the end blocks are computed (large trees do not fit in cache).
    detail::prefetch_blocks(tree_.prim_nodes_, full_first, full_end);
    if (part_l) prefetch_block(bl);
    if (part_h) prefetch_block(bh);
    Lanes acc = detail::max_lanes();
    if (part_l) acc = detail::lane_min(acc, scan(lo, bl == bh ? hi : block_last(bl)));
    if (part_h) acc = detail::lane_min(acc, scan(bh * kBlock, hi));
    return detail::fold_blocks(
        tree_.prim_nodes_, full_first, full_end, acc, [](Lanes a, const Lanes& b) { return detail::lane_min(a, b); },
        [](bool take, const Anchor& node) {  // the node, or +inf lanes, without a branch
          const std::int64_t m = -static_cast<std::int64_t>(take);
          return detail::lane_select(detail::LaneMask{m, m, m, m}, load(node), detail::max_lanes());
        });
  }

  // Lane-wise minima over the time points from..to of one block.
  Lanes scan(std::size_t from, std::size_t to) {
    const Lanes* v = values(from, to);
    const std::size_t k0 = from / kBlock * kBlock;
    Lanes m = v[from - k0];
    for (std::size_t k = from + 1; k <= to; ++k) m = detail::lane_min(m, v[k - k0]);
    return m;
  }

  // Requests the data the values of block b are computed from: anchors, times, slices.
  void prefetch_block(std::size_t b) const {
    const std::size_t k0 = b * kBlock, k1 = std::min(k0 + kBlock, tree_.n_);
    __builtin_prefetch(&tree_.anchors_[k0 / kAnchorStep]);
    __builtin_prefetch(&tree_.anchors_[(k1 - 1) / kAnchorStep]);
    __builtin_prefetch(&d_.times[k0]);
    __builtin_prefetch(&d_.times[k1]);
    for (std::size_t k = k0; k < k1; k += 4) __builtin_prefetch(&d_.slices[k]);
    __builtin_prefetch(&d_.slices[k1 - 1]);
  }

  // The prefix values at time t in slice k, with the ranks of both sides.
  struct End {
    Lanes v;
    Rank lower, upper;
  };
  End at(double t, std::size_t k) {
    if (t == d_.times[k + 1]) ++k;  // t = t_N
    End e{point(k), Rank{tree_.count(false, d_, k)}, Rank{tree_.count(true, d_, k)}};
    if (t != d_.times[k] && !d_.slices[k].is_empty()) {
      const Interval& s = d_.slices[k];
      if (s.lb() == -kInf) e.lower.inside = t;  // strictly inside an unbounded slice
      if (s.ub() == kInf) e.upper.inside = t;
      detail::advance(e.v, d_.times[k], t, s);
    }
    return e;
  }

  // The time points of rank r in [first, last]: [lo, hi], false if none.
  bool run(bool upper, std::size_t first, std::size_t last, const Rank& r, std::size_t& lo, std::size_t& hi) const {
    if (first > last || r.inside != -kInf) return false;  // time points are never inside a slice
    auto count = [&](std::size_t k) { return tree_.count(upper, d_, k); };
    const std::uint32_t c = r.passed;
    if (count(first) == c && count(last) == c) {  // the usual case: no unbounded slice inside
      lo = first;
      hi = last;
      return true;
    }
    // Counts are nondecreasing in k: two binary searches.
    std::size_t l = first, h = last + 1;
    while (l < h) {
      const std::size_t m = l + (h - l) / 2;
      if (count(m) < c) l = m + 1; else h = m;
    }
    lo = l;
    h = last + 1;
    while (l < h) {
      const std::size_t m = l + (h - l) / 2;
      if (count(m) <= c) l = m + 1; else h = m;
    }
    if (l == lo) return false;
    hi = l - 1;
    return true;
  }

  // The range of L (upper = false) or U over [a, b], from the values at its
  // ends and the extrema over the time points first..last inside it
  // (`whole`: those over all of them).
  PrimitiveRange range(bool upper, const End& ea, const End& eb, std::size_t first, std::size_t last,
                       const Lanes& whole) {
    const int lo_lane = upper ? 2 : 0, hi_lane = lo_lane + 1;  // lo, and -hi
    auto rank = [upper](const End& e) { return upper ? e.upper : e.lower; };
    auto over = [&](const Rank& c, double& mn, double& mx) {
      double lo = kInf, neg_hi = kInf;
      for (const End* e : {&ea, &eb}) {
        if (rank(*e) != c) continue;
        lo = min(lo, e->v[lo_lane]);
        neg_hi = min(neg_hi, e->v[hi_lane]);
      }
      std::size_t rl = 0, rh = 0;
      if (run(upper, first, last, c, rl, rh)) {
        const Lanes m = (rl == first && rh == last) ? whole : extrema(rl, rh);
        lo = min(lo, m[lo_lane]);
        neg_hi = min(neg_hi, m[hi_lane]);
      }
      mn = lo;
      mx = -neg_hi + 0.0;
    };
    PrimitiveRange r;
    r.rank_first = rank(ea);
    r.rank_last = rank(eb);
    over(r.rank_first, r.min_first, r.max_first);
    if (r.rank_last == r.rank_first) {
      r.min_last = r.min_first;
      r.max_last = r.max_first;
    } else {
      over(r.rank_last, r.min_last, r.max_last);
    }
    return r;
  }

  static Lanes load(const Anchor& a) {
    Lanes v;
    std::memcpy(&v, a.lane, sizeof v);
    return v;
  }
  static Anchor store(const Lanes& v) {
    Anchor a;
    std::memcpy(a.lane, &v, sizeof v);
    return a;
  }

 private:
  static constexpr std::size_t kSegments = kBlock / kAnchorStep;
  struct Slot {
    std::size_t index = static_cast<std::size_t>(-1);  // the block
    std::uint8_t valid[kSegments];                      // points ready in each segment
    Lanes v[kBlock];
  };

  // The slot of block b, its anchors loaded (the oldest slot is reused).
  Slot& slot(std::size_t b) {
    for (Slot& s : slots_) {
      if (s.index == b) return s;
    }
    Slot& s = slots_[next_];
    next_ = (next_ + 1) % kSlots;
    s.index = b;
    for (std::size_t j = 0; j < kSegments; ++j) {
      const std::size_t k = b * kBlock + j * kAnchorStep;
      s.valid[j] = k <= tree_.n_ ? 1 : 0;
      if (k <= tree_.n_) s.v[j * kAnchorStep] = load(tree_.anchors_[k / kAnchorStep]);
    }
    return s;
  }

  static constexpr std::size_t kSlots = 3;  // the blocks of a, of b and one spare
  const SynthesisTree& tree_;
  const View& d_;
  Slot slots_[kSlots];
  std::size_t next_ = 0;
};

void SynthesisTree::build_primitive(const View& d) {
  bool any_lower = false, any_upper = false;
  for (const Interval& s : d.slices) {
    has_empty_ = has_empty_ || s.is_empty();
    any_lower = any_lower || unbounded(s, false);
    any_upper = any_upper || unbounded(s, true);
  }
  const std::size_t points = n_ + 1, nb = (points + kBlock - 1) / kBlock;
  anchors_.resize((points + kAnchorStep - 1) / kAnchorStep);
  prim_nodes_.assign(2 * nb, Blocks::store(detail::max_lanes()));
  if (any_lower) lower_counts_.resize(nb);
  if (any_upper) upper_counts_.resize(nb);
  // Prefix values, left to right, with the operations a query repeats.
  Lanes v = detail::zero_lanes(), block_min = detail::max_lanes();
  std::uint32_t lc = 0, uc = 0;
  for (std::size_t k = 0; k < points; ++k) {
    if (k % kAnchorStep == 0) anchors_[k / kAnchorStep] = Blocks::store(v);
    if (k % kBlock == 0) {
      if (any_lower) lower_counts_[k / kBlock] = lc;
      if (any_upper) upper_counts_[k / kBlock] = uc;
    }
    block_min = detail::lane_min(block_min, v);
    if (k % kBlock == kBlock - 1 || k == n_) {
      prim_nodes_[nb + k / kBlock] = Blocks::store(block_min);
      block_min = detail::max_lanes();
    }
    if (k == n_) break;
    const Interval& s = d.slices[k];
    lc += unbounded(s, false);
    uc += unbounded(s, true);
    detail::advance(v, d.times[k], d.times[k + 1], s);
  }
  detail::build_inner_nodes(prim_nodes_, [](const Anchor& a, const Anchor& b) {
    return Blocks::store(detail::lane_min(Blocks::load(a), Blocks::load(b)));
  });
}

std::uint32_t SynthesisTree::count(bool upper, const View& d, std::size_t k) const {
  const auto& counts = upper ? upper_counts_ : lower_counts_;
  if (counts.empty()) return 0;  // no unbounded slice on this side
  std::uint32_t c = counts[k / kBlock];
  for (std::size_t j = k - k % kBlock; j < k; ++j) c += unbounded(d.slices[j], upper);
  return c;
}

PrimitiveValue SynthesisTree::prefix(bool upper, std::size_t k) const {
  const View d = view("SynthesisTree: prefix value");
  if (k > n_) {
    throw Error("SynthesisTree: prefix value at time point " + std::to_string(k) + ", out of range [0, " +
                std::to_string(n_) + "]");
  }
  Blocks blocks(*this, d);
  const Lanes v = blocks.point(k);
  return {Rank{count(upper, d, k)}, upper ? detail::upper_of(v) : detail::lower_of(v)};
}

PrimitiveValue SynthesisTree::value_at(bool upper, double t) const {
  const View d = view("SynthesisTree: prefix value");
  Blocks blocks(*this, d);
  const Blocks::End e = blocks.at(t, slice_index(d, t));
  return upper ? PrimitiveValue{e.upper, detail::upper_of(e.v)} : PrimitiveValue{e.lower, detail::lower_of(e.v)};
}

void SynthesisTree::ranges(const Interval& t, PrimitiveRange& lower, PrimitiveRange& upper) const {
  if (t.is_empty()) throw Error("SynthesisTree: primitive range over an empty [t]");
  check_interval(t, "SynthesisTree: primitive range");
  const View d = view("SynthesisTree: primitive range");
  const double a = t.lb(), b = t.ub();
  const std::size_t ka = slice_index(d, a), kb = slice_index(d, b);
  Blocks blocks(*this, d);
  // Time points with a < t_k <= b (one equal to b repeats the value at b).
  // Their extrema first: that computes the end blocks, where the values at a
  // and b then come from.
  const std::size_t first = ka + 1, last = kb;
  const Lanes whole = blocks.extrema(first, last);
  const Blocks::End ea = blocks.at(a, ka), eb = blocks.at(b, kb);
  lower = blocks.range(false, ea, eb, first, last, whole);
  upper = blocks.range(true, ea, eb, first, last, whole);
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

}  // namespace sillage
