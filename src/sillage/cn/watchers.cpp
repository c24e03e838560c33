#include "sillage/cn/watchers.h"

namespace sillage::detail {

void Watchers::add(const Watch& w) {
  if (w.first == 0 && w.count == nb_atoms_) {
    whole_.push_back(w);
    return;
  }
  if (head_.size() < nb_atoms_) head_.resize(nb_atoms_, kNone), tail_.resize(nb_atoms_, kNone);
  for (std::size_t a = w.first; a < w.first + w.count; ++a) {
    const std::size_t i = at_.size();
    at_.push_back({w.node, w.range, kNone});
    (tail_[a] == kNone ? head_[a] : at_[tail_[a]].next) = i;
    tail_[a] = i;
  }
}

void Watchers::grow(std::size_t nb_atoms) {
  for (Watch& w : whole_) w.count = nb_atoms;
  // No partial watch covers the new atoms: their chains are empty (head_ grows on the next add).
  nb_atoms_ = nb_atoms;
}

}  // namespace sillage::detail
