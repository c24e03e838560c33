#pragma once
// Watchers: for one domain, the nodes to wake when one of its atoms shrinks,
// each with the range of the node that watches it. Watches of the whole
// domain (the usual case for tube contractors) are kept in a list that every
// atom matches, which costs no memory per atom; watches of part of a domain
// (a box component, the few slices a CtcEval looks at) are chained per atom,
// in the order of add(), in one flat array: adding one costs its atoms, not
// the domain's (an online estimator adds an observation at every measurement). A domain that
// gains atoms at its end (a tube whose TDomain grew) keeps its watches: grow().
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
  // Calls f(node, range) for each watch covering atom a: those of the whole
  // domain, then the others, each in the order of add().
  template <class F>
  void for_each(std::size_t a, F&& f) const {
    for (const Watch& w : whole_) f(w.node, w.range);
    if (a >= head_.size()) return;
    for (std::size_t i = head_[a]; i != kNone; i = at_[i].next) f(at_[i].node, at_[i].range);
  }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  struct Entry {
    std::size_t node, range, next;  // next: the atom's next entry, or kNone
  };
  std::size_t nb_atoms_;
  std::vector<Watch> whole_;
  std::vector<std::size_t> head_, tail_;  // per atom, its first and last entry (sized on the first add)
  std::vector<Entry> at_;
};

}  // namespace sillage::detail
