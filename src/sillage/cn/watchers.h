#pragma once
// Watchers: for one domain, the nodes to wake when one of its atoms shrinks,
// and where that atom sits among the node's atoms. Watches of the whole
// domain (the usual case for tube contractors) are kept in a list that every
// atom matches, which costs no memory per atom; watches of part of a domain
// (a box component, the few slices a CtcEval looks at) are indexed per atom,
// in one flat array (index(), after the last add()).
#include <cstddef>
#include <vector>

namespace sillage::detail {

class Watchers {
 public:
  struct Watch {
    std::size_t node;
    std::size_t first, count;  // the atoms of the domain it covers
    std::size_t offset;        // position of atom `first` in the node
    std::size_t bit = 0;       // the network's dirty bit for atom `first` (one per node and atom)
  };

  explicit Watchers(std::size_t nb_atoms) : nb_atoms_(nb_atoms) {}

  void add(const Watch& w);
  // Builds the per-atom index of the partial watches (cheap when nothing was
  // added since); for_each needs it.
  void index();
  // Calls f(node, position in node, bit) for each watch covering atom a.
  template <class F>
  void for_each(std::size_t a, F&& f) const {
    for (const Watch& w : whole_) f(w.node, w.offset + a, w.bit + a);
    if (begin_.empty()) return;
    // Entries hold offset - first and bit - first (modulo 2^64): adding a gives the atom's.
    for (std::size_t i = begin_[a]; i < begin_[a + 1]; ++i) f(at_[i].node, at_[i].pos + a, at_[i].bit + a);
  }

 private:
  struct Entry {
    std::size_t node, pos, bit;
  };
  std::size_t nb_atoms_;
  std::vector<Watch> whole_, parts_;
  std::size_t indexed_ = 0;          // parts_ in the index
  std::vector<std::size_t> begin_;  // per atom, its entries [begin_[a], begin_[a + 1]) in at_
  std::vector<Entry> at_;
};

}  // namespace sillage::detail
