#pragma once
// DirtyAtoms: for each node of a network, which of its watched atoms shrank
// since it last ran. One bit per (node, watched atom): an atom woken many
// times is recorded once, with no list to sort or deduplicate, and a node's
// atoms are read back as its sorted positions (NodeRun::dirty) by scanning
// its own few words. The bits of a node follow its watched ranges in order,
// so that positions come out ascending.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "sillage/cn/cn_node.h"

namespace sillage::detail {

class DirtyAtoms {
 public:
  // Lays out the bits of the next node (number nb_nodes()); bit_of[g] is
  // then the bit of the first watched atom of its range g (unused when
  // range g watches nothing).
  void add_node(const CnNode& node, std::vector<std::size_t>& bit_of);
  // Forgets every node (the network rebuilds them on a new layout).
  void clear_nodes();
  std::size_t nb_nodes() const { return wakes_.size(); }
  // Clears every bit and counter (the start of a contract()).
  void reset();

  // Records a wake-up of `node` for its atom at `bit`; true the first time
  // since the node last ran (take).
  bool mark(std::size_t node, std::size_t bit) {
    ++wakes_[node];
    std::uint64_t& w = words_[bit >> 6];
    const std::uint64_t m = std::uint64_t{1} << (bit & 63);
    if (w & m) return false;
    w |= m;
    return true;
  }
  // Wake-ups of `node` since it last ran, repeated atoms included (the
  // Priority scheduling's estimate of its cost).
  std::size_t wakes(std::size_t node) const { return wakes_[node]; }
  // The positions of node's recorded atoms, ascending, into `out` (replaced);
  // clears them.
  void take(std::size_t node, std::vector<std::size_t>& out);

 private:
  // A watched range: bits [bit, bit + count) are node positions [pos, pos + count).
  struct Span {
    std::size_t bit, count, pos;
  };
  std::vector<std::uint64_t> words_;
  std::vector<Span> spans_;
  std::vector<std::size_t> first_span_{0};  // per node, its spans: [first_span_[i], first_span_[i + 1])
  std::vector<std::size_t> wakes_;
};

}  // namespace sillage::detail
