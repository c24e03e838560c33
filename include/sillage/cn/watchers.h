#pragma once
// Watchers: for one domain, the nodes to wake when one of its atoms shrinks,
// and where that atom sits among the node's atoms. Watches of the whole
// domain (the usual case for tube contractors) are kept in a list that every
// atom matches, which costs no memory per atom; watches of part of a domain
// (a box component, the few slices a CtcEval looks at) are indexed per atom.
#include <cstddef>
#include <vector>

namespace sillage {

class Watchers {
 public:
  struct Watch {
    std::size_t node;
    std::size_t first, count;  // the atoms of the domain it covers
    std::size_t offset;        // position of atom `first` in the node
  };

  explicit Watchers(std::size_t nb_atoms) : nb_atoms_(nb_atoms) {}

  void add(const Watch& w);
  // Calls f(node, position in node) for each watch covering atom a.
  template <class F>
  void for_each(std::size_t a, F&& f) const {
    for (const Watch& w : whole_) f(w.node, w.offset + a);
    if (per_atom_.empty()) return;
    for (const std::size_t i : per_atom_[a]) f(parts_[i].node, parts_[i].offset + a - parts_[i].first);
  }

 private:
  std::size_t nb_atoms_;
  std::vector<Watch> whole_, parts_;
  std::vector<std::vector<std::size_t>> per_atom_;  // indices in parts_; allocated with the first part
};

}  // namespace sillage
