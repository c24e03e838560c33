#include "sillage/cn/watchers.h"

namespace sillage {

Watchers::Watchers(std::size_t nb_atoms) {
  if (nb_atoms <= kIndexedAtoms) per_atom_.resize(nb_atoms);
}

void Watchers::add(const Watch& w) {
  watches_.push_back(w);
  if (per_atom_.empty()) return;
  for (std::size_t a = w.first; a < w.first + w.count; ++a) per_atom_[a].push_back(watches_.size() - 1);
}

}  // namespace sillage
