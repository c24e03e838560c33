#pragma once
// DirtyAtoms: for each node of a network, which of its watched atoms shrank
// since it last ran. One bit per (node, watched atom): an atom woken many
// times is recorded once, with no list to sort or deduplicate, and a node's
// atoms are read back as its sorted positions (NodeRun::dirty) by scanning
// its own few words. The bits of a node follow its watched ranges in order,
// so that positions come out ascending. Bits are found by (node, range,
// atom of the domain) and positions from the node's offsets when read, so
// that a node whose ranges grow at their end (a tube that gained slices)
// is laid out again alone (relayout_node), and the other nodes not at all.
// Each range of a node remembers the words it marked since the node last
// ran, so that reading back (and clearing) costs the words marked, not the
// whole layout: a node on whole tubes woken at their last slices (online
// estimation) reads a word or two per tube, not the window.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sillage/cn/cn_node.h"

namespace sillage::detail {

class DirtyAtoms {
 public:
  // Lays out the bits of the next node (number nb_nodes()).
  void add_node(const CnNode& node);
  // Lays out node i again, its watched ranges having grown; its bits are cleared.
  void relayout_node(std::size_t i, const CnNode& node);
  // Forgets every node (the network rebuilds them on a new layout).
  void clear_nodes();
  std::size_t nb_nodes() const { return wakes_.size(); }
  // Clears every bit and counter (the start of a contract()).
  void reset();

  // Records a wake-up of `node` for atom `a` of the domain of its range g
  // (an atom it watches); true the first time since the node last ran (take).
  bool mark(std::size_t node, std::size_t g, std::size_t a) {
    ++wakes_[node];
    Span& s = spans_[first_span_[node] + g];
    const std::size_t bit = s.bit + (a - s.first);
    std::uint64_t& w = words_[node][bit >> 6];
    const std::uint64_t m = std::uint64_t{1} << (bit & 63);
    if (w & m) return false;
    w |= m;
    if (s.lo >= s.hi) ++marked_spans_;
    s.lo = std::min(s.lo, bit >> 6), s.hi = std::max(s.hi, (bit >> 6) + 1);
    return true;
  }
  // Wake-ups of `node` since it last ran, repeated atoms included (the
  // Priority scheduling's estimate of its cost).
  std::size_t wakes(std::size_t node) const { return wakes_[node]; }
  // The positions (in `n`, node number `node`) of its recorded atoms,
  // ascending, into `out` (replaced); clears them.
  void take(std::size_t node, const CnNode& n, std::vector<std::size_t>& out);

 private:
  // Range g's watched atoms [first, first + count) of its domain: bits [bit,
  // bit + count) of the node; the words [lo, hi) hold its marks (lo >= hi: none).
  struct Span {
    std::size_t first, count, bit;
    std::size_t lo = kNoWord, hi = 0;
  };
  static constexpr std::size_t kNoWord = static_cast<std::size_t>(-1);
  // Clears the marked words of span s.
  void clear(std::vector<std::uint64_t>& words, Span& s);
  // The spans of a node from its watched ranges; its number of bits.
  static std::size_t lay_out(const CnNode& node, Span* spans);
  std::vector<std::vector<std::uint64_t>> words_;  // per node, its bits
  std::vector<Span> spans_;                        // per node, one per range
  std::vector<std::size_t> first_span_;            // per node, its spans from spans_[first_span_[i]]
  std::vector<std::size_t> wakes_;
  std::size_t marked_spans_ = 0;  // spans holding marks: none after a propagation that ran to its end
};

}  // namespace sillage::detail
