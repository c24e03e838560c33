#pragma once
// Watchers: for one domain, the nodes to wake when one of its atoms shrinks,
// each with the range of the node that watches it. Watches of the whole
// domain (the usual case for tube contractors) are kept in a list that every
// atom matches, which costs no memory per atom; watches of part of a domain
// (a box component, the few slices a CtcEval looks at) are indexed per atom,
// in one flat array (index(), after the last add()). A domain that gains
// atoms at its end (a tube whose TDomain grew) keeps its watches: grow().
#include <cstddef>
#include <vector>

namespace sillage::detail {

class Watchers {
 public:
  struct Watch {
    std::size_t node;
    std::size_t range;         // the node's range on this domain
    std::size_t first, count;  // the atoms of the domain it covers
  };

  explicit Watchers(std::size_t nb_atoms) : nb_atoms_(nb_atoms) {}

  void add(const Watch& w);
  // The domain now has nb_atoms >= its former count, the new ones at the
  // end: the watches of the whole domain cover them, the others do not.
  void grow(std::size_t nb_atoms);
  // Builds the per-atom index of the partial watches (cheap when nothing was
  // added since); for_each needs it.
  void index();
  // Calls f(node, range) for each watch covering atom a.
  template <class F>
  void for_each(std::size_t a, F&& f) const {
    for (const Watch& w : whole_) f(w.node, w.range);
    if (begin_.empty()) return;
    for (std::size_t i = begin_[a]; i < begin_[a + 1]; ++i) f(at_[i].node, at_[i].range);
  }

 private:
  struct Entry {
    std::size_t node, range;
  };
  std::size_t nb_atoms_;
  std::vector<Watch> whole_, parts_;
  std::size_t indexed_ = 0;          // parts_ in the index
  std::vector<std::size_t> begin_;  // per atom, its entries [begin_[a], begin_[a + 1]) in at_
  std::vector<Entry> at_;
};

}  // namespace sillage::detail
