#pragma once
// Watchers: for one domain, the nodes acting on each of its atoms, and where
// that atom sits among the node's atoms. Small domains (intervals, boxes)
// index every atom; large ones (tubes: 2N+1 atoms, few nodes each) keep the
// list of ranges and scan it, which costs no memory per atom.
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

  explicit Watchers(std::size_t nb_atoms);

  void add(const Watch& w);
  // Calls f(node, position in node) for each watch covering atom a.
  template <class F>
  void for_each(std::size_t a, F&& f) const {
    if (!per_atom_.empty()) {
      for (const std::size_t w : per_atom_[a]) f(watches_[w].node, watches_[w].offset + a - watches_[w].first);
      return;
    }
    for (const Watch& w : watches_) {
      if (a >= w.first && a - w.first < w.count) f(w.node, w.offset + a - w.first);
    }
  }

 private:
  static constexpr std::size_t kIndexedAtoms = 1024;
  std::vector<Watch> watches_;
  std::vector<std::vector<std::size_t>> per_atom_;  // watch indices; empty if not indexed
};

}  // namespace sillage
