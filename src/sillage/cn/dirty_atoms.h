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
    const Span& s = spans_[first_span_[node] + g];
    const std::size_t bit = s.bit + (a - s.first);
    std::uint64_t& w = words_[node][bit >> 6];
    const std::uint64_t m = std::uint64_t{1} << (bit & 63);
    if (w & m) return false;
    w |= m;
    return true;
  }
  // Wake-ups of `node` since it last ran, repeated atoms included (the
  // Priority scheduling's estimate of its cost).
  std::size_t wakes(std::size_t node) const { return wakes_[node]; }
  // The positions (in `n`, node number `node`) of its recorded atoms,
  // ascending, into `out` (replaced); clears them.
  void take(std::size_t node, const CnNode& n, std::vector<std::size_t>& out);

 private:
  // Range g's watched atoms [first, first + count) of its domain: bits [bit, bit + count) of the node.
  struct Span {
    std::size_t first, count, bit;
  };
  // The spans of a node from its watched ranges; its number of bits.
  static std::size_t lay_out(const CnNode& node, Span* spans);
  std::vector<std::vector<std::uint64_t>> words_;  // per node, its bits
  std::vector<Span> spans_;                        // per node, one per range
  std::vector<std::size_t> first_span_;            // per node, its spans from spans_[first_span_[i]]
  std::vector<std::size_t> wakes_;
};

}  // namespace sillage::detail
