#include "sillage/cn/watchers.h"

namespace sillage {

void Watchers::add(const Watch& w) {
  if (w.first == 0 && w.count == nb_atoms_) {
    whole_.push_back(w);
    return;
  }
  if (per_atom_.empty()) per_atom_.resize(nb_atoms_);
  parts_.push_back(w);
  for (std::size_t a = w.first; a < w.first + w.count; ++a) per_atom_[a].push_back(parts_.size() - 1);
}

}  // namespace sillage
