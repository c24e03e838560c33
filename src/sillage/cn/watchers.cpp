#include "sillage/cn/watchers.h"

namespace sillage::detail {

void Watchers::add(const Watch& w) {
  if (w.first == 0 && w.count == nb_atoms_) {
    whole_.push_back(w);
    return;
  }
  if (at_.size() < nb_atoms_) at_.resize(nb_atoms_);
  for (std::size_t a = w.first; a < w.first + w.count; ++a) at_[a].push_back({w.node, w.range});
}

void Watchers::grow(std::size_t nb_atoms) {
  for (Watch& w : whole_) w.count = nb_atoms;
  // No partial watch covers the new atoms: their lists are empty (at_ grows on the next add).
  nb_atoms_ = nb_atoms;
}

}  // namespace sillage::detail
