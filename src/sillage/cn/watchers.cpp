#include "sillage/cn/watchers.h"

namespace sillage::detail {

void Watchers::add(const Watch& w) {
  if (w.first == 0 && w.count == nb_atoms_) {
    whole_.push_back(w);
    return;
  }
  parts_.push_back(w);
}

void Watchers::grow(std::size_t nb_atoms) {
  for (Watch& w : whole_) w.count = nb_atoms;
  // No partial watch covers the new atoms: their entries are none.
  if (!begin_.empty()) begin_.resize(nb_atoms + 1, begin_.back());
  nb_atoms_ = nb_atoms;
}

void Watchers::index() {
  if (indexed_ == parts_.size()) return;
  indexed_ = parts_.size();
  // Count per atom, then place: the entries of an atom in the order of add().
  begin_.assign(nb_atoms_ + 1, 0);
  for (const Watch& w : parts_)
    for (std::size_t a = w.first; a < w.first + w.count; ++a) ++begin_[a + 1];
  for (std::size_t a = 0; a < nb_atoms_; ++a) begin_[a + 1] += begin_[a];
  at_.resize(begin_[nb_atoms_]);
  std::vector<std::size_t> next(begin_.begin(), begin_.end() - 1);
  for (const Watch& w : parts_) {
    for (std::size_t a = w.first; a < w.first + w.count; ++a) at_[next[a]++] = {w.node, w.range};
  }
}

}  // namespace sillage::detail
